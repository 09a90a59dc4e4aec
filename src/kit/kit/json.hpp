// SPDX-License-Identifier: GPL-3.0-or-later
/// @file json.hpp
/// @brief The JSON value of the claims files, `--describe`, the certified records and provenance:
/// nlohmann-json's value (object keys in insertion order) with the writing rules of dfchaos.
///
/// The value, its strings and their escaping are nlohmann-json's. The layout of a dump is its
/// indented one (`"key": value`, one element a line, `[]` and `{}` when empty); numbers are written
/// as dfchaos writes every number it prints: integers in decimal, doubles with 17 significant
/// digits (`%.17g`, read back exactly; nlohmann-json would write the shortest form and `1.0` for
/// one), non-finite doubles as null.
#pragma once

#include <string>
#include <utility>

#include <nlohmann/json.hpp>

namespace dfchaos::kit {

/// A JSON value: null, bool, number, string, array, or object whose keys keep their insertion order.
class Json {
 public:
  using Value = nlohmann::ordered_json;  ///< the value underneath

  Json() = default;                                // NOLINT(bugprone-exception-escape): a null value allocates nothing
  Json(bool b) : v_(b) {}                          ///< a boolean
  Json(double d) : v_(d) {}                        ///< a number (non-finite: written as null)
  Json(int i) : v_(static_cast<long long>(i)) {}   ///< an integer
  Json(long i) : v_(static_cast<long long>(i)) {}  ///< an integer
  Json(long long i) : v_(i) {}                     ///< an integer
  Json(const char* s) : v_(std::string(s)) {}      ///< a string
  Json(std::string s) : v_(std::move(s)) {}        ///< a string
  static Json array();                             ///< an empty array
  static Json object();                            ///< an empty object
  /// Sets a key of an object (insertion order is kept; an existing key is overwritten in place).
  /// @throws std::logic_error on a value that is not an object.
  Json& set(const std::string& key, Json value);
  /// Appends to an array. @throws std::logic_error on a value that is not an array.
  Json& push(Json value);
  /// Whether this is an object (with or without keys).
  bool is_object() const { return v_.is_object(); }
  /// Whether this is an object with no keys (or an empty array).
  bool empty() const { return (v_.is_object() || v_.is_array()) && v_.empty(); }
  /// Serialises with `indent` spaces a level (numbers as above), and a final newline.
  std::string dump(int indent = 2) const;
  /// The value, for a reader (e.g. the Python module, which turns it into a dict).
  const Value& value() const { return v_; }

 private:
  Value v_;
};

}  // namespace dfchaos::kit
