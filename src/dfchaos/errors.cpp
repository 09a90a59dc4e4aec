// SPDX-License-Identifier: GPL-3.0-or-later
/// @file errors.cpp
/// @brief The two kinds of failure (errors.hpp) and the %.17g format of every output.
#include "dfchaos/errors.hpp"

#include <charconv>
#include <cstdio>

namespace dfchaos {

InvalidParameter::InvalidParameter(const std::string& parameter, const std::string& condition, double value)
    : std::invalid_argument(parameter + ": must satisfy " + condition + " (got " + format_double(value) + ")"), parameter_(parameter) {}

InvalidParameter::InvalidParameter(const std::string& parameter, const std::string& condition)
    : std::invalid_argument(parameter + ": " + condition), parameter_(parameter) {}

std::string format_shortest(double x) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string format_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace dfchaos
