/// @file json.hpp
/// @brief A minimal JSON value for the claims files and `--describe` (no parsing, only writing).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace dfchaos::kit {

/// A JSON value: null, bool, number, string, array, or object whose keys keep their insertion order.
class Json {
 public:
  Json() = default;
  Json(bool b) : v_(b) {}                                  ///< a boolean
  Json(double d) : v_(d) {}                                ///< a number (non-finite: null)
  Json(int i) : v_(static_cast<long long>(i)) {}           ///< an integer
  Json(long i) : v_(static_cast<long long>(i)) {}          ///< an integer
  Json(long long i) : v_(i) {}                             ///< an integer
  Json(const char* s) : v_(std::string(s)) {}              ///< a string
  Json(std::string s) : v_(std::move(s)) {}                ///< a string
  static Json array();                                     ///< an empty array
  static Json object();                                    ///< an empty object
  /// Sets a key of an object (insertion order is kept; an existing key is overwritten in place).
  /// @throws std::logic_error on a value that is not an object.
  Json& set(const std::string& key, Json value);
  /// Appends to an array. @throws std::logic_error on a value that is not an array.
  Json& push(Json value);
  /// Whether this is an object (with or without keys).
  bool is_object() const;
  /// Whether this is an object with no keys (or an empty array).
  bool empty() const;
  /// Serialises: numbers in %.17g (round-trip exact), non-finite numbers as null, a final newline.
  std::string dump(int indent = 2) const;

 private:
  using Array = std::vector<Json>;
  using Object = std::vector<std::pair<std::string, Json>>;
  std::variant<std::nullptr_t, bool, double, long long, std::string, std::shared_ptr<Array>, std::shared_ptr<Object>> v_ =
      nullptr;
  void dump_to(std::string& out, int indent, int depth) const;
};

}  // namespace dfchaos::kit
