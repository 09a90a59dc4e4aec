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

namespace dfchaos::sweep {

namespace {

constexpr const char* kOption = "sweep-merge";
/// File descriptors kept free for everything else while the shard files are open.
constexpr rlim_t kSpareDescriptors = 64;

std::unique_ptr<std::ifstream> open(const std::string& file) {
  auto in = std::make_unique<std::ifstream>(file, std::ios::binary);
  if (!*in) throw InvalidParameter(kOption, "cannot read " + file + ": " + std::strerror(errno));
  return in;
}

/// Whether the file's last byte is a newline (a file cut short would not end in one).
bool ends_in_newline(const std::string& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() <= 0) return false;
  in.seekg(-1, std::ios::end);
  return in.get() == '\n';
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
  // Pass 1: headers and every row checked, nothing written.
  std::vector<ParsedHeader> headers;
  std::vector<std::unique_ptr<std::ifstream>> in;
  std::vector<long long> by_shard;  // file number of each shard index, -1 while missing
  for (std::size_t f = 0; f < files.size(); ++f) {
    in.push_back(open(files[f]));
    headers.push_back(read_header(kOption, files[f], *in.back()));
    const ParsedHeader& h = headers.back();
    if (!h.shard) throw InvalidParameter(kOption, files[f] + " is not a shard file (no '" + std::string(kShardPrefix) + "i/N' line)");
    if (h.common != headers[0].common)
      throw InvalidParameter(kOption, files[f] + " is a shard of another sweep than " + files[0] + " (their headers differ: spec or build)");
    if (h.shard->count != headers[0].shard->count)
      throw InvalidParameter(kOption, files[f] + " is shard " + h.shard->canonical() + " but " + files[0] + " is shard " +
                                          headers[0].shard->canonical() + " (mixed shard counts)");
    if (by_shard.empty()) by_shard.assign(static_cast<std::size_t>(h.shard->count), -1);
    auto& slot = by_shard[static_cast<std::size_t>(h.shard->index)];
    if (slot >= 0) throw InvalidParameter(kOption, "shard " + h.shard->canonical() + " given twice (" + files[static_cast<std::size_t>(slot)] + " and " + files[f] + ")");
    slot = static_cast<long long>(f);
  }
  for (std::size_t s = 0; s < by_shard.size(); ++s)
    if (by_shard[s] < 0)
      throw InvalidParameter(kOption, "shard " + std::to_string(s) + "/" + std::to_string(by_shard.size()) + " is missing (" +
                                          std::to_string(files.size()) + " of " + std::to_string(by_shard.size()) + " shard files given)");
  const long long cells = headers[0].cells;
  const std::size_t fields = headers[0].fields;
  std::vector<std::streampos> first_row;
  for (std::size_t f = 0; f < files.size(); ++f) {
    const Shard& sh = *headers[f].shard;
    first_row.push_back(in[f]->tellg());
    std::string row;
    const long long rows = sh.size(cells);
    for (long long p = 0; p < rows; ++p) {
      if (!std::getline(*in[f], row))
        throw InvalidParameter(kOption, files[f] + " has " + std::to_string(p) + " of the " + std::to_string(rows) + " rows of shard " + sh.canonical() + " (incomplete)");
      if (!row_matches(row, sh.cell(p), fields))
        throw InvalidParameter(kOption, files[f] + ": row " + std::to_string(p + 1) + " is not the complete row of cell " + std::to_string(sh.cell(p)));
    }
    if (std::getline(*in[f], row)) throw InvalidParameter(kOption, files[f] + " has more rows than the " + std::to_string(rows) + " of shard " + sh.canonical());
    if (!ends_in_newline(files[f])) throw InvalidParameter(kOption, files[f] + " does not end in a newline (cut short)");
  }
  // Pass 2: the header without the shard line, then cell k from shard k mod N.
  out.write(headers[0].common);
  const std::size_t n = by_shard.size();
  for (std::size_t f = 0; f < files.size(); ++f) {
    in[f]->clear();
    in[f]->seekg(first_row[f]);
  }
  std::string row, buffer;
  constexpr std::size_t kFlushBytes = 1 << 20;
  for (long long k = 0; k < cells; ++k) {
    auto& src = *in[static_cast<std::size_t>(by_shard[static_cast<std::size_t>(k) % n])];
    if (!std::getline(src, row)) throw kit::OutputError("sweep-merge: a shard file changed while being merged", false);
    buffer += row;
    buffer += '\n';
    if (buffer.size() >= kFlushBytes) {
      out.write(buffer);
      buffer.clear();
    }
  }
  out.write(buffer);
}

}  // namespace dfchaos::sweep
