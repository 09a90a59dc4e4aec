// SPDX-License-Identifier: GPL-3.0-or-later
/// @file format.hpp
/// @brief Number and text formatting shared by every output: significant digits, LaTeX numbers,
/// LaTeX escapes.
#pragma once

#include <string>

#include "dfchaos/errors.hpp"

namespace dfchaos::kit {

/// Round-trip exact %.17g (from the core: every output prints numbers this way).
using dfchaos::format_double;

/// How every table the project writes (the tool's outputs, the experiments' data files) is read
/// in Python in one call: the column line first, every other line that is not a row starting with
/// '#'. pandas needs float_precision='round_trip' to read each %.17g number back to its double.
inline constexpr const char* kLoadInPython =
    "pandas.read_csv(f, sep='\\t', comment='#', float_precision='round_trip') or\n"
    "numpy.genfromtxt(f, names=True, delimiter='\\t', comments='#', dtype=None, encoding=None)";

/// A number with the given count of significant digits (printf's %.*g).
std::string format_significant(double x, int digits);

/// x > 0 rounded down (never up) to the given count of significant digits, printed as the shortest
/// decimal of that double ("7.82e-05" for 7.8246700263127835e-05): an upper bound of a range printed
/// for people stays inside the proved range. Any other x (0, an unproved bound) is printed as it is.
std::string format_significant_down(double x, int digits);

/// A number in exponent notation ("1.4e-13") as LaTeX (\f$1.4\times10^{-13}\f$); any other text
/// unchanged. Applied to every macro value, so that the report typesets numbers properly.
std::string latex_number(const std::string& text);

/// Escapes text for LaTeX (the ten special characters, and < > | which the default font encoding
/// would print as other glyphs), so that statements and parameter values can be typeset verbatim.
std::string latex_escape(const std::string& text);

}  // namespace dfchaos::kit
