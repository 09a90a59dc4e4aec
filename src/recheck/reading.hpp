// SPDX-License-Identifier: GPL-3.0-or-later
/// @file reading.hpp
/// @brief Reading a certificate: the format's constants, the two ways a check ends early (a malformed
/// file, a step not verified) and the readers of exact numbers and fields.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "interval.hpp"

namespace recheck {

using json = nlohmann::json;

constexpr const char* kFormat = "dfchaos-certificate";
constexpr int kVersion = 1;
/// Largest certificate read (bytes): the largest that `make reproduce` writes is a few megabytes.
constexpr long long kMaxBytes = 256LL << 20;

/// The certificate cannot be read as one of the format (exit 2).
struct Malformed : std::runtime_error {
  using std::runtime_error::runtime_error;
};
/// A step of the proof was not re-verified (exit 1).
struct Failed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// j[key], which must be present (`where` prefixes the key in the message). @throws Malformed.
const json& field(const json& j, const std::string& key, const std::string& where);
/// Whether s has the form -?0x H(.H+)? p[+-]?D{1,6} (H a hexadecimal digit, D a decimal digit).
bool is_hex_float(const std::string& s);
/// An exact hexadecimal floating-point string ("0x1.8p-3"), parsed exactly at kPrecision bits.
Num exact(const json& j, const std::string& where);
/// An exact hexadecimal float that is a double: std::strtod reads it, and reads it exactly.
double exact_double(const json& j, const std::string& where);
/// A parameter {"hex": ..., "decimal": ...}: the hex string is the number (the decimal is for humans).
double parameter(const json& j, const std::string& key, const std::string& where);
/// A certificate held inside another (`where` names it, e.g. "witnesses.arc_l1"): an object of this
/// format and version whose statement is `statement`, as a file of its own must be.
void require_embedded(const json& j, const std::string& statement, const std::string& where);
/// The certificate's `parameters.a`, a field of the format (docs/certificates.md): an exact double
/// > 0. @throws Malformed otherwise.
double require_amplitude(const json& c);
/// An array of `n` exact doubles.
std::vector<double> doubles(const json& j, std::size_t n, const std::string& where);
/// x as the verdict line shows a number of the certificate: the fewest decimal digits (at most 17)
/// that read back as the same double, so the decimal names the certificate's number exactly.
std::string dec(double x);
/// x exactly in hexadecimal, then in decimal: "0x1.48p-14 (7.8246700263127835e-05)".
std::string exact_text(double x);
/// [lo, hi] in decimal (each end read back exactly).
std::string range_text(double lo, double hi);

/// n as a normalised hexadecimal float ("0x1.8p-3", as certificates write it), exactly.
std::string hex(const Num& n);
/// A pair [x, y] of exact numbers.
std::pair<Num, Num> exact_pair(const json& j, const std::string& where);
/// The parameters (a, b, q) of a certificate at a point.
std::tuple<double, double, double> read_point(const json& c);
/// The parameters (a, q) of a certificate about a range of b at fixed a and q (b0, window).
std::pair<double, double> read_a_q(const json& c);
/// A list of exact doubles (the grid's cuts: at least two; whether they increase from 0 is a step).
std::vector<double> cuts(const json& j, const std::string& where, bool grid = true);

/// Checks an embedded certificate with `check`; a malformed field or a failed step inside it is named
/// with the place of the embedded certificate ("witnesses.arc_l1: 'parameters.a' ...").
template <class Check>
long embedded(const std::string& where, Check&& check) {
  try {
    return check();
  } catch (const Failed& e) {
    throw Failed(where + ": " + e.what());
  } catch (const Malformed& e) {
    throw Malformed(where + ": " + e.what());
  }
}

/// The amplitude a of a certificate whose statement is about the ratios b/a and q/a only: still a

}  // namespace recheck
