// SPDX-License-Identifier: GPL-3.0-or-later
#include "reading.hpp"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace recheck {

// ---- reading ---------------------------------------------------------------------------------------

const json& field(const json& j, const std::string& key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw Malformed("missing field '" + where + key + "'");
  return j.at(key);
}

/// Whether s has the form -?0x H(.H+)? p[+-]?D{1,6} (H a hexadecimal digit, D a decimal digit).
bool is_hex_float(const std::string& s) {
  std::size_t i = 0;
  const auto digits = [&](auto is_digit, std::size_t at_most) {
    std::size_t n = 0;
    while (i < s.size() && n < at_most && is_digit(static_cast<unsigned char>(s[i]))) ++i, ++n;
    return n;
  };
  const auto hex = [](int c) { return std::isxdigit(c) != 0; };
  const auto dec = [](int c) { return std::isdigit(c) != 0; };
  if (i < s.size() && s[i] == '-') ++i;
  if (s.compare(i, 2, "0x") != 0) return false;
  i += 2;
  if (digits(hex, 1) != 1) return false;
  if (i < s.size() && s[i] == '.') {
    ++i;
    if (digits(hex, s.size()) == 0) return false;
  }
  if (i >= s.size() || s[i] != 'p') return false;
  ++i;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t e = digits(dec, 6);
  return e >= 1 && i == s.size();
}

/// An exact hexadecimal floating-point string ("0x1.8p-3"), parsed exactly at kPrecision bits.
Num exact(const json& j, const std::string& where) {
  if (!j.is_string()) throw Malformed("'" + where + "' is not a string");
  const std::string s = j.get<std::string>();
  if (!is_hex_float(s)) throw Malformed("'" + where + "' = '" + s + "' is not an exact hexadecimal float");
  Num n;
  char* end = nullptr;
  if (mpfr_strtofr(n.x, s.c_str(), &end, 16, MPFR_RNDN) != 0 || *end != '\0')
    throw Malformed("'" + where + "' = '" + s + "' is not exact at " + std::to_string(kPrecision) + " bits");
  return n;
}

/// An exact hexadecimal float that is a double: std::strtod reads it, and reads it exactly.
double exact_double(const json& j, const std::string& where) {
  const Num n = exact(j, where);
  const std::string s = j.get<std::string>();
  char* end = nullptr;
  const double d = std::strtod(s.c_str(), &end);
  if (*end != '\0' || !std::isfinite(d) || mpfr_cmp_d(n.x, d) != 0) throw Malformed("'" + where + "' = '" + s + "' is not exactly a double");
  return d;
}

/// A parameter {"hex": ..., "decimal": ...}: the hex string is the number (the decimal is for humans).
double parameter(const json& j, const std::string& key, const std::string& where) {
  return exact_double(field(field(j, key, where), "hex", where + key + "."), where + key + ".hex");
}

/// A certificate held inside another (`where` names it, e.g. "witnesses.arc_l1"): an object of this
/// format and version whose statement is `statement`, as a file of its own must be.
void require_embedded(const json& j, const std::string& statement, const std::string& where) {
  if (!j.is_object()) throw Malformed("'" + where + "' is not an embedded certificate (an object)");
  const json& f = field(j, "format", where + ".");
  if (!f.is_string() || f.get<std::string>() != kFormat) throw Malformed("'" + where + ".format' is not \"" + std::string(kFormat) + "\"");
  const json& v = field(j, "version", where + ".");
  if (!v.is_number_integer() || v.get<long long>() != kVersion)
    throw Malformed("'" + where + ".version' is " + v.dump() + " (this checker reads version " + std::to_string(kVersion) + ")");
  const json& st = field(j, "statement", where + ".");
  if (!st.is_string() || st.get<std::string>() != statement) throw Malformed("'" + where + "' is not a " + statement + " certificate");
}

/// field of the format (docs/certificates.md), an exact double > 0.
double require_amplitude(const json& c) {
  const json& p = field(c, "parameters", "");
  const double a = parameter(p, "a", "parameters.");
  if (!(a > 0)) throw Malformed("'parameters.a' is not a positive number");
  return a;
}

/// An array of `n` exact doubles.
std::vector<double> doubles(const json& j, std::size_t n, const std::string& where) {
  if (!j.is_array() || j.size() != n) throw Malformed("'" + where + "' is not an array of " + std::to_string(n) + " numbers");
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) v.push_back(exact_double(j[i], where + "[" + std::to_string(i) + "]"));
  return v;
}

/// n as a normalised hexadecimal float ("0x1.8p-3", as certificates write it), exactly.
std::string hex(const Num& n) {
  if (mpfr_zero_p(n.x)) return "0x0p+0";
  mpfr_exp_t e = 0;
  char* bits = mpfr_get_str(nullptr, &e, 2, 0, n.x, MPFR_RNDN);  // n = 0.bits * 2^e, exact
  std::string b = bits, out = b[0] == '-' ? "-0x1" : "0x1";
  mpfr_free_str(bits);
  b = b.substr(b[0] == '-' ? 2 : 1);  // the bits after the leading 1
  while (!b.empty() && b.back() == '0') b.pop_back();
  if (!b.empty()) out += '.';
  for (std::size_t i = 0; i < b.size(); i += 4) out += "0123456789abcdef"[std::stoi((b.substr(i, 4) + "000").substr(0, 4), nullptr, 2)];
  return out + (e - 1 >= 0 ? "p+" : "p") + std::to_string(e - 1);
}

/// A pair [x, y] of exact numbers.
std::pair<Num, Num> exact_pair(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2) throw Malformed("'" + where + "' is not an array of 2 numbers");
  return {exact(j[0], where + "[0]"), exact(j[1], where + "[1]")};
}

/// The parameters (a, b, q) of a certificate at a point.
std::tuple<double, double, double> read_point(const json& c) {
  const json& p = field(c, "parameters", "");
  return {parameter(p, "a", "parameters."), parameter(p, "b", "parameters."), parameter(p, "q", "parameters.")};
}

std::pair<double, double> read_a_q(const json& c) {
  const json& p = field(c, "parameters", "");
  return {parameter(p, "a", "parameters."), parameter(p, "q", "parameters.")};
}

/// A list of exact doubles (the grid's cuts: at least two; whether they increase from 0 is a step).
std::vector<double> cuts(const json& j, const std::string& where, bool grid) {
  if (!j.is_array() || j.size() < (grid ? 2U : 1U))
    throw Malformed("'" + where + "' is not an array of at least " + (grid ? "2 numbers" : "1 number"));
  std::vector<double> v;
  for (std::size_t i = 0; i < j.size(); ++i) v.push_back(exact_double(j[i], where + "[" + std::to_string(i) + "]"));
  return v;
}

std::string dec(double x) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {  // the fewest digits that read back as x
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

std::string exact_text(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", x);
  return std::string(buf) + " (" + dec(x) + ")";
}

std::string range_text(double lo, double hi) { return "[" + dec(lo) + ", " + dec(hi) + "]"; }

}  // namespace recheck
