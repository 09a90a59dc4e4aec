// SPDX-License-Identifier: GPL-3.0-or-later
/// @file seal.hpp
/// @brief The seal of a sweep file and of a checkpoint chunk: a last line that states the number
/// of rows and the SHA-256 digest of every byte above it,
///
///     # end: ROWS rows, sha256 HEX (of every byte above this line)
///
/// A file without its seal is incomplete (cut short, or still being written); a file whose seal
/// does not match its bytes is damaged. Either is refused by every reader (`sweep-merge`,
/// `--resume`), never taken for a good file. The digest is OpenSSL's SHA-256 (kit/digest.hpp):
/// no change of one or more bytes above the seal can keep it (short of a deliberate forgery, which
/// a digest does not guard against: it detects damage, it does not authenticate).
#pragma once

#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>

#include "kit/digest.hpp"

namespace dfchaos::sweep {

/// The start of a seal line.
inline constexpr std::string_view kSealPrefix = "# end: ";

/// The seal line (with its '\n') of a text of `rows` rows whose bytes have digest `sha256_hex`.
std::string seal_line(long long rows, const std::string& sha256_hex);

/// What a seal line states.
struct Seal {
  long long rows = 0;  ///< the number of rows it vouches for
  std::string sha256;  ///< the digest of every byte above it
};

/// Parses `line` (without its '\n'): the seal it states, or nothing unless it is exactly a line
/// written by seal_line.
std::optional<Seal> parse_seal_line(std::string_view line);

/// Computes the seal of a text as it is written.
class Sealer {
 public:
  /// Adds text holding `rows` rows (0 for header lines).
  void add(std::string_view text, long long rows);
  /// The seal line of everything added.
  std::string line() const { return seal_line(rows_, digest_.hex()); }
  long long rows() const { return rows_; }  ///< rows added so far

 private:
  kit::Sha256 digest_;
  long long rows_ = 0;
};

/// A sealed file whose seal matched.
struct SealedFile {
  Seal seal;                  ///< what its seal states
  std::uintmax_t body_bytes;  ///< the bytes above the seal line (where the seal line starts)
};

/// Checks the seal of the file open as `in` (named `file` in errors): it ends in a seal line and the
/// digest of every byte above that line is the one stated. Reads it once through `in`, so that
/// the bytes checked are those the caller goes on to read; leaves `in` at its start.
/// @throws InvalidParameter naming `option`: cannot be read, no seal ("incomplete" or written by
///         a dfchaos older than seals), or a digest that does not match ("damaged").
SealedFile check_file_seal(const std::string& option, const std::string& file, std::istream& in);

/// The same for a text in memory (a checkpoint chunk): returns the text above the seal line and
/// sets `seal`. `what` names the text in the errors. @throws InvalidParameter naming `option`.
std::string_view check_text_seal(const std::string& option, const std::string& what, std::string_view text, Seal& seal);

}  // namespace dfchaos::sweep
