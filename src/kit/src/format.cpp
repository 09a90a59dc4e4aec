// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/format.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace dfchaos::kit {

std::string format_significant(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string format_significant_down(double x, int digits) {
  if (!(x > 0) || !std::isfinite(x)) return dfchaos::format_shortest(x);  // 0 (an unproved bound) as it is
  const int e = static_cast<int>(std::floor(std::log10(x))) - (digits - 1);
  double m = std::floor(x / std::pow(10.0, e));
  char buf[64];
  for (int i = 0; i < 3; ++i, m -= 1) {  // the division may round up by one unit
    std::snprintf(buf, sizeof buf, "%.0fe%d", m, e);
    if (std::strtod(buf, nullptr) <= x) break;
  }
  return dfchaos::format_shortest(std::strtod(buf, nullptr));
}

std::string latex_number(const std::string& text) {
  // Only a whole number in exponent notation is rewritten, e.g. "1.4e-13" -> 1.4 x 10^{-13}.
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  const auto e = text.find_first_of("eE");
  if (text.empty() || end != text.c_str() + text.size() || e == std::string::npos) return text;
  const std::string mantissa = text.substr(0, e);
  const int exponent = std::atoi(text.c_str() + e + 1);
  const std::string power = "10^{" + std::to_string(exponent) + "}";
  return "\\ensuremath{" + (mantissa == "1" ? power : mantissa + "\\times " + power) + "}";
}

std::string latex_escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '\\': out += "\\textbackslash{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '<': out += "$<$"; break;
      case '>': out += "$>$"; break;
      case '|': out += "$|$"; break;
      case '&':
      case '%':
      case '$':
      case '#':
      case '_':
      case '{':
      case '}':
        out += '\\';
        out += ch;
        break;
      default: out += ch;
    }
  }
  return out;
}

}  // namespace dfchaos::kit
