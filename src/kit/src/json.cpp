// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/json.hpp"

#include <cmath>
#include <stdexcept>

#include "dfchaos/errors.hpp"

namespace dfchaos::kit {

Json Json::array() {
  Json j;
  j.v_ = Value::array();
  return j;
}
Json Json::object() {
  Json j;
  j.v_ = Value::object();
  return j;
}
Json& Json::set(const std::string& key, Json value) {
  if (!v_.is_object()) throw std::logic_error("Json::set on a non-object");
  v_[key] = std::move(value.v_);
  return *this;
}
Json& Json::push(Json value) {
  if (!v_.is_array()) throw std::logic_error("Json::push on a non-array");
  v_.push_back(std::move(value.v_));
  return *this;
}

namespace {

/// Writes v at nesting `depth`: arrays and objects laid out as nlohmann-json's indented dump, doubles
/// with format_double, every other scalar (strings with their escapes) by nlohmann-json.
void write(const Json::Value& v, std::string& out, int indent, int depth) {
  const std::string pad(static_cast<std::size_t>(indent * (depth + 1)), ' '), pad_end(static_cast<std::size_t>(indent * depth), ' ');
  const char* nl = indent > 0 ? "\n" : "";
  if (v.is_number_float()) {
    const double d = v.get<double>();
    out += std::isfinite(d) ? format_double(d) : "null";
  } else if (v.is_array() || v.is_object()) {
    const bool object = v.is_object();
    if (v.empty()) {
      out += object ? "{}" : "[]";
      return;
    }
    out += object ? "{" : "[";
    out += nl;
    std::size_t k = 0;
    for (auto it = v.begin(); it != v.end(); ++it, ++k) {
      out += pad;
      if (object) out += Json::Value(it.key()).dump(-1, ' ', false, Json::Value::error_handler_t::replace) + (indent > 0 ? ": " : ":");
      write(it.value(), out, indent, depth + 1);
      if (k + 1 < v.size()) out += ",";
      out += nl;
    }
    out += pad_end + (object ? "}" : "]");
  } else {
    out += v.dump(-1, ' ', false, Json::Value::error_handler_t::replace);
  }
}

}  // namespace

std::string Json::dump(int indent) const {
  std::string out;
  write(v_, out, indent, 0);
  return out + "\n";
}

}  // namespace dfchaos::kit
