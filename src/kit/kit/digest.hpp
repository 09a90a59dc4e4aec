// SPDX-License-Identifier: GPL-3.0-or-later
/// @file digest.hpp
/// @brief SHA-256 digests (OpenSSL's libcrypto) of the text the project writes, so that a file read
/// back can be told from a damaged one: a changed, missing or added byte changes the digest.
#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace dfchaos::kit {

/// An incremental SHA-256 digest (FIPS 180-4), computed by OpenSSL's EVP interface.
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  /// Adds bytes to the digested text.
  void update(std::string_view bytes);
  /// The digest of everything added so far, as 64 lowercase hexadecimal digits; the digest may be
  /// updated further and asked again.
  std::string hex() const;

 private:
  struct Context;
  std::unique_ptr<Context> ctx_;
};

/// The SHA-256 digest of `bytes` in hexadecimal.
std::string sha256_hex(std::string_view bytes);

}  // namespace dfchaos::kit
