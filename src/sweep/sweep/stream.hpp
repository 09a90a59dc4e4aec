// SPDX-License-Identifier: GPL-3.0-or-later
/// @file stream.hpp
/// @brief Where a sweep's text goes: standard output, streamed, or a file written atomically
/// (streamed into a uniquely named temporary beside it, renamed into place only when complete).
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "kit/output.hpp"

namespace dfchaos::sweep {

/// A destination of text. A failed write throws kit::OutputError (bad_path() false: exit 1).
class Stream {
 public:
  virtual ~Stream() = default;
  /// Appends text. @throws kit::OutputError
  virtual void write(std::string_view text) = 0;
  /// Completes the output (flushes; renames a file into place). @throws kit::OutputError
  virtual void commit() = 0;
};

/// Standard output, through a large buffer.
class StdoutStream final : public Stream {
 public:
  void write(std::string_view text) override;
  void commit() override;
};

/// A file written atomically: its previous content stays until commit(); an uncommitted temporary
/// is removed by the destructor and by SIGINT, SIGTERM and SIGHUP (kit::TemporaryFileGuard; only
/// SIGKILL or a crash leaves a `.tmp.*` file behind). The rule for `path` is kit::output_target's:
/// a symbolic link is written through, a regular file or a new name is replaced atomically, a
/// directory, device, FIFO or socket is refused.
class AtomicFile final : public Stream {
 public:
  /// Creates the temporary beside the target of `path`. @throws kit::OutputError (bad_path() true
  /// when the target is not a regular file, or its directory does not exist or cannot be written).
  /// `option` names the path in errors ("out", "resume").
  explicit AtomicFile(const std::filesystem::path& path, const std::string& option = "out");
  ~AtomicFile() override;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  void write(std::string_view text) override;
  void commit() override;

 private:
  std::filesystem::path path_, tmp_;
  kit::TemporaryFileGuard guard_;
  std::string option_;  ///< the option that named the path, for messages
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

/// Writes `content` to `path` atomically (an AtomicFile written and committed at once).
void write_file_atomically(const std::filesystem::path& path, std::string_view content, const std::string& option = "out");

/// Requires `path` to be a regular file (symbolic links followed), checked before it is opened: a
/// FIFO would block the open, a device never end. @throws InvalidParameter naming `option`.
void require_regular_file(const std::string& option, const std::filesystem::path& path);

/// The whole content of a regular file. @throws InvalidParameter naming `option` if it is not one
/// or cannot be read.
std::string read_file(const std::string& option, const std::filesystem::path& path);

}  // namespace dfchaos::sweep
