// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/stream.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "dfchaos/errors.hpp"
#include "kit/output.hpp"

namespace dfchaos::sweep {

namespace fs = std::filesystem;

void StdoutStream::write(std::string_view text) {
  if (text.empty()) return;
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::ferror(stdout))
    throw kit::OutputError(std::string("cannot write the output: ") + std::strerror(errno), false);
}

void StdoutStream::commit() {
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) throw kit::OutputError(std::string("cannot write the output: ") + std::strerror(errno), false);
}

AtomicFile::AtomicFile(const fs::path& path, const std::string& option)
    : path_(kit::output_target(path, option)), tmp_(kit::unique_temporary(path_)), guard_(tmp_), option_(option) {
  // The file the shell opened as standard output or error (`--out /dev/stdout > f`, or `> f` and
  // `--out f`) would be replaced by the rename and the other output lost: refused.
  struct stat target {};
  if (::stat(path_.c_str(), &target) == 0)
    for (int fd : {1, 2}) {
      struct stat open_fd {};
      if (::fstat(fd, &open_fd) == 0 && open_fd.st_dev == target.st_dev && open_fd.st_ino == target.st_ino)
        throw kit::OutputError(option + ": " + path.string() + " is the file of standard " + (fd == 1 ? "output" : "error") +
                                   " (it would be replaced and what is written there lost)",
                               true);
    }
  file_ = std::fopen(tmp_.c_str(), "wx");  // exclusive: never reuses a name
  if (!file_) {
    const int err = errno;
    throw kit::OutputError(option + ": cannot create a file beside " + path_.string() + ": " + std::strerror(err), kit::is_bad_path_errno(err));
  }
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  if (!committed_) ::unlink(tmp_.c_str());
}

void AtomicFile::write(std::string_view text) {
  if (!file_) throw kit::OutputError(option_ + ": cannot write " + path_.string() + ": already closed", false);
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size())
    throw kit::OutputError(option_ + ": cannot write " + path_.string() + ": " + std::strerror(errno), false);
}

void AtomicFile::commit() {
  if (!file_) throw kit::OutputError(option_ + ": cannot write " + path_.string() + ": already closed", false);
  const bool flushed = std::fflush(file_) == 0 && !std::ferror(file_) && ::fsync(::fileno(file_)) == 0;
  const int err = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) throw kit::OutputError(option_ + ": cannot write " + path_.string() + ": " + std::strerror(err), false);
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
    throw kit::OutputError(option_ + ": cannot rename into " + path_.string() + ": " + std::strerror(errno), false);
  committed_ = true;
  guard_.release();
}

void write_file_atomically(const fs::path& path, std::string_view content, const std::string& option) {
  AtomicFile f(path, option);
  f.write(content);
  f.commit();
}

void require_regular_file(const std::string& option, const fs::path& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw InvalidParameter(option, "cannot read " + path.string() + ": no such file");
  if (!fs::is_regular_file(st))
    throw InvalidParameter(option, path.string() + " is not a regular file (a sweep file or chunk is; not a pipe, FIFO, device or directory)");
}

std::string read_file(const std::string& option, const fs::path& path) {
  require_regular_file(option, path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidParameter(option, "cannot read " + path.string() + ": " + std::strerror(errno));
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InvalidParameter(option, "cannot read " + path.string());
  return s.str();
}

}  // namespace dfchaos::sweep
