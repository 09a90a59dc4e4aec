// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/seal.hpp"

#include <sstream>
#include <vector>

#include "dfchaos/errors.hpp"

namespace dfchaos::sweep {

namespace {
constexpr std::string_view kSealMiddle = " rows, sha256 ";
constexpr std::string_view kSealEnd = " (of every byte above this line)";
/// Longest seal line: the prefix, 19 digits, the middle, 64 hex digits, the end.
constexpr std::size_t kMaxSealLine = 160;
constexpr std::size_t kDigestDigits = 64;

/// The start of the last line of `text` (which ends in '\n'), or npos when text is one line.
std::size_t last_line_start(std::string_view text) {
  if (text.size() < 2) return std::string_view::npos;
  const std::size_t nl = text.rfind('\n', text.size() - 2);
  return nl == std::string_view::npos ? 0 : nl + 1;
}
}  // namespace

std::string seal_line(long long rows, const std::string& sha256_hex) {
  return std::string(kSealPrefix) + std::to_string(rows) + std::string(kSealMiddle) + sha256_hex + std::string(kSealEnd) + "\n";
}

std::optional<Seal> parse_seal_line(std::string_view line) {
  if (line.size() > kMaxSealLine || line.substr(0, kSealPrefix.size()) != kSealPrefix) return std::nullopt;
  const std::size_t mid = line.find(kSealMiddle);
  if (mid == std::string_view::npos) return std::nullopt;
  const std::string_view count = line.substr(kSealPrefix.size(), mid - kSealPrefix.size());
  if (count.empty() || count.size() > 18) return std::nullopt;
  Seal s;
  for (char c : count) {
    if (c < '0' || c > '9') return std::nullopt;
    s.rows = s.rows * 10 + (c - '0');
  }
  s.sha256 = std::string(line.substr(mid + kSealMiddle.size(), kDigestDigits));
  // Exactly what seal_line writes: no leading zeros, lowercase hex, nothing before or after.
  if (seal_line(s.rows, s.sha256) != std::string(line) + "\n") return std::nullopt;
  for (char c : s.sha256)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return std::nullopt;
  return s;
}

void Sealer::add(std::string_view text, long long rows) {
  digest_.update(text);
  rows_ += rows;
}

SealedFile check_file_seal(const std::string& option, const std::string& file, std::istream& in) {
  const std::string incomplete = file + " has no seal (it does not end in a '" + std::string(kSealPrefix) +
                                 "...' line: cut short, still being written, or written by a dfchaos older than seals)";
  in.clear();
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  if (!in || end < 0) throw InvalidParameter(option, "cannot read " + file);
  const auto size = static_cast<std::uintmax_t>(end);
  // The tail, where the seal line must be.
  const std::uintmax_t tail_size = std::min<std::uintmax_t>(size, kMaxSealLine + 2);
  std::string tail(static_cast<std::size_t>(tail_size), '\0');
  in.seekg(static_cast<std::streamoff>(size - tail_size));
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  if (!in) throw InvalidParameter(option, "cannot read " + file);
  if (tail.empty() || tail.back() != '\n') throw InvalidParameter(option, incomplete);
  std::size_t start = last_line_start(tail);
  if (start == std::string_view::npos || (start == 0 && tail_size < size)) throw InvalidParameter(option, incomplete);
  const auto seal = parse_seal_line(std::string_view(tail).substr(start, tail.size() - start - 1));
  if (!seal) throw InvalidParameter(option, incomplete);
  const std::uintmax_t body = size - tail_size + start;
  // The digest of the body, read in blocks.
  kit::Sha256 digest;
  in.seekg(0);
  std::vector<char> block(1 << 20);
  for (std::uintmax_t left = body; left > 0;) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uintmax_t>(left, block.size()));
    in.read(block.data(), static_cast<std::streamsize>(n));
    if (!in) throw InvalidParameter(option, "cannot read " + file + " (it changed while being read?)");
    digest.update(std::string_view(block.data(), n));
    left -= n;
  }
  if (digest.hex() != seal->sha256)
    throw InvalidParameter(option, file + " is damaged (its bytes do not match the sha256 of its '" + std::string(kSealPrefix) + "...' line)");
  in.seekg(0);
  return SealedFile{*seal, body};
}

std::string_view check_text_seal(const std::string& option, const std::string& what, std::string_view text, Seal& seal) {
  std::istringstream in{std::string(text)};  // one check for files and texts: check_file_seal's
  const SealedFile sealed = check_file_seal(option, what, in);
  seal = sealed.seal;
  return text.substr(0, static_cast<std::size_t>(sealed.body_bytes));
}

}  // namespace dfchaos::sweep
