// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/checkpoint.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "dfchaos/errors.hpp"
#include "kit/digest.hpp"
#include "kit/output.hpp"
#include "sweep/header.hpp"
#include "sweep/seal.hpp"
#include "sweep/stream.hpp"

namespace dfchaos::sweep {

namespace fs = std::filesystem;

namespace {
constexpr const char* kResumeOption = "resume";
constexpr const char* kHeaderFile = "header";
constexpr const char* kLockFile = "lock";
/// Most entries examined in the directory (chunks are at most kMaxChunks per run; runs may add up).
constexpr long long kMaxEntries = 100'000'000;

std::string chunk_name(const Interval& c) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "chunk-%012lld-%012lld.tsv", c.begin, c.end);
  return buf;
}

/// Parses "chunk-BEGIN-END.tsv"; false for any other name.
bool parse_chunk_name(const std::string& name, Interval& c) {
  long long b = -1, e = -1;
  int used = 0;
  if (std::sscanf(name.c_str(), "chunk-%lld-%lld.tsv%n", &b, &e, &used) != 2 || used != static_cast<int>(name.size())) return false;
  if (name != chunk_name(Interval{b, e})) return false;
  c = Interval{b, e};
  return true;
}
}  // namespace

fs::path Checkpoint::directory(const fs::path& file) { return fs::path(file.string() + ".chunks"); }

Checkpoint::Checkpoint(const fs::path& file, std::string header, const Shard& shard, long long positions, std::vector<std::string> columns)
    : file_(file), dir_(directory(file)), header_(std::move(header)), positions_(positions), shard_(shard), columns_(std::move(columns)) {
  std::error_code ec;
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec)) throw InvalidParameter(kResumeOption, dir_.string() + " exists and is not a directory");
  const bool fresh = !fs::exists(dir_, ec);
  if (fresh) fs::create_directory(dir_, ec);  // in FILE's directory, which must exist (as for --out)
  if (ec) throw kit::OutputError("resume: cannot create " + dir_.string() + " (" + ec.message() + ")", true);
  lock_.fd = ::open((dir_ / kLockFile).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_.fd < 0) throw kit::OutputError("resume: cannot open " + (dir_ / kLockFile).string(), true);
  if (::flock(lock_.fd, LOCK_EX | LOCK_NB) != 0)
    throw InvalidParameter(kResumeOption, dir_.string() + " is in use by another run (one run per FILE at a time)");
  const fs::path header_path = dir_ / kHeaderFile;
  if (fresh || !fs::exists(header_path, ec)) {
    write_file_atomically(header_path, header_, kResumeOption);
  } else if (read_file(kResumeOption, header_path) != header_) {
    throw InvalidParameter(kResumeOption, dir_.string() +
                                              " holds an interrupted run of another spec, build or shard; "
                                              "rerun that command, or remove the directory to start afresh");
  }
  long long seen = 0;
  for (const auto& entry : fs::directory_iterator(dir_, ec)) {
    if (++seen > kMaxEntries) throw InvalidParameter(kResumeOption, dir_.string() + " holds too many files");
    const std::string name = entry.path().filename().string();
    if (name == kHeaderFile || name == kLockFile) continue;
    if (name.find(".tmp.") != std::string::npos) {  // a chunk whose writer was interrupted: never renamed
      fs::remove(entry.path(), ec);
      continue;
    }
    Interval c;
    if (!parse_chunk_name(name, c) || c.begin < 0 || c.end <= c.begin || c.end > positions_)
      throw InvalidParameter(kResumeOption, entry.path().string() + " is not a chunk of this run");
    (void)read_chunk(entry.path(), c);  // refused unless sealed and every row well-formed
    insert(c);
  }
  if (ec) throw kit::OutputError("resume: cannot read " + dir_.string() + " (" + ec.message() + ")", true);
}

Checkpoint::Lock::~Lock() { release(); }

void Checkpoint::Lock::release() {
  if (fd >= 0) ::close(fd);  // releases the flock
  fd = -1;
}

void Checkpoint::insert(const Interval& c) {
  auto it = std::lower_bound(done_.begin(), done_.end(), c, [](const Interval& x, const Interval& y) { return x.begin < y.begin; });
  if ((it != done_.end() && it->begin < c.end) || (it != done_.begin() && std::prev(it)->end > c.begin))
    throw InvalidParameter(kResumeOption, dir_.string() + ": chunk " + chunk_name(c) + " overlaps another");
  done_.insert(it, c);
}

long long Checkpoint::done_positions() const {
  long long n = 0;
  for (const auto& c : done_) n += c.size();
  return n;
}

std::string Checkpoint::read_chunk(const fs::path& path, const Interval& c) const {
  const std::string text = read_file(kResumeOption, path);
  const std::string advice = " (remove this chunk file and rerun: only its cells are computed again)";
  Seal seal;
  std::string_view body;
  try {
    body = check_text_seal(kResumeOption, path.string(), text, seal);
  } catch (const InvalidParameter& e) {
    throw InvalidParameter(kResumeOption, std::string(e.what()).substr(e.parameter().size() + 2) + advice);
  }
  if (body.substr(0, header_.size()) != header_)
    throw InvalidParameter(kResumeOption, path.string() + " is a chunk of another run (its header differs: spec, build or shard)" + advice);
  std::string rows(body.substr(header_.size()));
  if (seal.rows != c.size())
    throw InvalidParameter(kResumeOption, path.string() + " is damaged (its seal counts " + std::to_string(seal.rows) + " rows, its name " +
                                              std::to_string(c.size()) + ")" + advice);
  std::istringstream in(rows);
  try {
    check_rows(kResumeOption, path.string(), in, shard_, c.begin, c.size(), columns_);
  } catch (const InvalidParameter& e) {
    throw InvalidParameter(kResumeOption, std::string(e.what()).substr(e.parameter().size() + 2) + advice);
  }
  if (static_cast<std::size_t>(in.tellg()) != rows.size()) throw InvalidParameter(kResumeOption, path.string() + " is damaged (extra text)" + advice);
  return rows;
}

void Checkpoint::save(const Interval& chunk, std::string_view rows) {
  std::string text = header_;
  text += rows;
  text += seal_line(chunk.size(), kit::sha256_hex(text));
  write_file_atomically(dir_ / chunk_name(chunk), text, kResumeOption);
  insert(chunk);
}

void Checkpoint::assemble() {
  if (!complete()) throw std::logic_error("Checkpoint::assemble before every chunk is done");
  {
    // Every chunk is read back and checked again: a chunk damaged since it was saved is refused.
    AtomicFile out(file_, kResumeOption);
    Sealer sealer;
    out.write(header_);
    sealer.add(header_, 0);
    for (const auto& c : done_) {
      const std::string rows = read_chunk(dir_ / chunk_name(c), c);
      out.write(rows);
      sealer.add(rows, c.size());
    }
    out.write(sealer.line());
    out.commit();
  }
  std::error_code ec;
  lock_.release();
  fs::remove_all(dir_, ec);  // the result is in place; a leftover directory would only be refused as complete
}

}  // namespace dfchaos::sweep
