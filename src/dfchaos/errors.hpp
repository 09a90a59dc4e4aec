// SPDX-License-Identifier: GPL-3.0-or-later
/// @file errors.hpp
/// @brief The two kinds of failure dfchaos reports: bad input, and a bounded search that gave up.
#pragma once

#include <stdexcept>
#include <string>

namespace dfchaos {

/// Bad input: a parameter that breaks a stated condition.
///
/// The message is one line naming the parameter and the condition, e.g.
/// `b: must satisfy 0 < b < a/2 (got 0.7)`. Command-line tools print it and exit with status 2.
class InvalidParameter : public std::invalid_argument {
 public:
  /// @param parameter  name of the offending parameter as the user spells it (`b`, `theta`, ...)
  /// @param condition  the condition it must satisfy, in words or symbols
  /// @param value      the value that was given
  InvalidParameter(const std::string& parameter, const std::string& condition, double value);
  /// The same without a value (for conditions on combinations of parameters).
  InvalidParameter(const std::string& parameter, const std::string& condition);

  /// The name of the offending parameter.
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

/// A bounded computation that reached its bound without an answer (for example a motion that
/// never returns to free flight, or an event count limit). Never thrown for bad input.
class GaveUp : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Formats a double with 17 significant digits (round-trip exact), as used in every output.
std::string format_double(double x);

/// Formats a double for people: the shortest decimal that reads back to the same double ("0.85",
/// not "0.84999999999999998"; std::to_chars), for statements, descriptions and messages. Data
/// columns keep format_double().
std::string format_shortest(double x);

}  // namespace dfchaos
