// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/merge.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>

#include "dfchaos/errors.hpp"
#include "kit/output.hpp"
#include "sweep/header.hpp"
#include "sweep/seal.hpp"

namespace dfchaos::sweep {

namespace {

constexpr const char* kOption = "sweep-merge";
/// File descriptors kept free for everything else while the shard files are open.
constexpr rlim_t kSpareDescriptors = 64;

std::unique_ptr<std::ifstream> open(const std::string& file) {
  require_regular_file(kOption, file);  // before opening: a FIFO would block the open
  auto in = std::make_unique<std::ifstream>(file, std::ios::binary);
  if (!*in) throw InvalidParameter(kOption, "cannot read " + file + ": " + std::strerror(errno));
  return in;
}

/// Raises the soft limit on open files to hold `n` of them, as far as the hard limit allows.
void allow_open_files(std::size_t n) {
  rlimit lim{};
  if (::getrlimit(RLIMIT_NOFILE, &lim) != 0) return;
  const rlim_t want = static_cast<rlim_t>(n) + kSpareDescriptors;
  if (lim.rlim_cur != RLIM_INFINITY && lim.rlim_cur < want) {
    lim.rlim_cur = lim.rlim_max == RLIM_INFINITY ? want : std::min(want, lim.rlim_max);
    ::setrlimit(RLIMIT_NOFILE, &lim);
  }
}

}  // namespace

void merge_shards(const std::vector<std::string>& files, Stream& out) {
  if (files.empty()) throw InvalidParameter(kOption, "give the shard files of one sweep");
  if (static_cast<long long>(files.size()) > kMaxMergeFiles)
    throw InvalidParameter(kOption, "at most " + std::to_string(kMaxMergeFiles) + " shard files (got " + std::to_string(files.size()) + ")");
  allow_open_files(files.size());
  // Pass 1: every file checked whole (seal, header, every row), nothing written.
  std::vector<ParsedHeader> headers;
  std::vector<std::unique_ptr<std::ifstream>> in;
  std::vector<std::streampos> first_row;
  std::vector<Seal> seals;
  std::vector<long long> by_shard;  // file number of each shard index, -1 while missing
  for (std::size_t f = 0; f < files.size(); ++f) {
    in.push_back(open(files[f]));
    const CheckedFile checked = check_sweep_file(kOption, files[f], *in.back());
    headers.push_back(checked.header);
    first_row.push_back(checked.first_row);
    seals.push_back(checked.seal);
    const ParsedHeader& h = headers.back();
    if (!h.shard) throw InvalidParameter(kOption, files[f] + " is not a shard file (no '" + std::string(kShardPrefix) + "i/N' line)");
    if (h.common != headers[0].common)
      throw InvalidParameter(kOption, files[f] + " is a shard of another sweep than " + files[0] + " (their headers differ: spec or build)");
    if (h.shard->count != headers[0].shard->count)
      throw InvalidParameter(kOption, files[f] + " is shard " + h.shard->canonical() + " but " + files[0] + " is shard " +
                                          headers[0].shard->canonical() + " (mixed shard counts)");
    if (by_shard.empty()) by_shard.assign(static_cast<std::size_t>(h.shard->count), -1);
    auto& slot = by_shard[static_cast<std::size_t>(h.shard->index)];
    if (slot >= 0)
      throw InvalidParameter(kOption,
                             "shard " + h.shard->canonical() + " given twice (" + files[static_cast<std::size_t>(slot)] + " and " + files[f] + ")");
    slot = static_cast<long long>(f);
  }
  for (std::size_t s = 0; s < by_shard.size(); ++s)
    if (by_shard[s] < 0)
      throw InvalidParameter(kOption, "shard " + std::to_string(s) + "/" + std::to_string(by_shard.size()) + " is missing (" +
                                          std::to_string(files.size()) + " of " + std::to_string(by_shard.size()) + " shard files given)");
  // Pass 2: the header without the shard line, then cell k from shard k mod N, then the seal.
  const long long cells = headers[0].cells;
  Sealer sealer;
  out.write(headers[0].common);
  sealer.add(headers[0].common, 0);
  const std::size_t n = by_shard.size();
  // Each shard is digested again as it is copied: a shard rewritten in place since pass 1 is
  // caught before the output gets its seal.
  std::vector<std::unique_ptr<Sealer>> again;
  for (std::size_t f = 0; f < files.size(); ++f) {
    again.push_back(std::make_unique<Sealer>());
    in[f]->clear();
    in[f]->seekg(0);
    std::string head(static_cast<std::size_t>(first_row[f]), '\0');
    if (!in[f]->read(head.data(), static_cast<std::streamsize>(head.size())))
      throw kit::OutputError("sweep-merge: " + files[f] + " changed while being merged", false);
    again[f]->add(head, 0);
  }
  std::string row, buffer;
  constexpr std::size_t kFlushBytes = 1 << 20;
  long long buffered = 0;
  auto flush = [&] {
    out.write(buffer);
    sealer.add(buffer, buffered);
    buffer.clear();
    buffered = 0;
  };
  for (long long k = 0; k < cells; ++k) {
    const auto f = static_cast<std::size_t>(by_shard[static_cast<std::size_t>(k) % n]);
    if (!std::getline(*in[f], row) || !row_problem(row, k, headers[0].columns).empty())
      throw kit::OutputError("sweep-merge: " + files[f] + " changed while being merged", false);
    row += '\n';
    again[f]->add(row, 1);
    buffer += row;
    ++buffered;
    if (buffer.size() >= kFlushBytes) flush();
  }
  flush();
  for (std::size_t f = 0; f < files.size(); ++f)
    if (again[f]->line() != seal_line(seals[f].rows, seals[f].sha256))
      throw kit::OutputError("sweep-merge: " + files[f] + " changed while being merged (no seal written)", false);
  out.write(sealer.line());
}

}  // namespace dfchaos::sweep
