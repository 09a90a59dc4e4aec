// SPDX-License-Identifier: GPL-3.0-or-later
/// @file errors.cpp
/// @brief The two kinds of failure (errors.hpp) and the %.17g format of every output.
#include "dfchaos/errors.hpp"

#include <charconv>
#include <cstdio>

namespace dfchaos {

InvalidParameter::InvalidParameter(const std::string& parameter, const std::string& condition, double value)
    : std::invalid_argument(parameter + ": must satisfy " + condition + " (got " + format_shortest(value) + ")"), parameter_(parameter) {}

InvalidParameter::InvalidParameter(const std::string& parameter, const std::string& condition)
    : std::invalid_argument(parameter + ": " + condition), parameter_(parameter) {}

std::string format_shortest(double x) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  std::string s(buf, r.ptr);
  // to_chars writes at least two exponent digits ("1e-04"): drop the leading zeros ("1e-4").
  const std::size_t e = s.find('e');
  if (e != std::string::npos) {
    std::size_t d = e + 1;
    if (d < s.size() && (s[d] == '-' || s[d] == '+')) ++d;
    std::size_t z = d;
    while (z + 1 < s.size() && s[z] == '0') ++z;
    s.erase(d, z - d);
    if (s[e + 1] == '+') s.erase(e + 1, 1);
  }
  return s;
}

std::string format_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace dfchaos
