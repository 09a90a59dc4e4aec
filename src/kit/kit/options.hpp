// SPDX-License-Identifier: GPL-3.0-or-later
/// @file options.hpp
/// @brief Typed, declared command-line options: each option is written once, with its default,
/// its admissible range and its value in smoke (`--fast`) mode. From the declaration come the
/// parsing, the range check (one line naming the option, exit 2), the `--help` text, the
/// `--describe` record, the run parameters recorded in every output header, and the bad-input tests.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kit/json.hpp"

namespace dfchaos::kit {

/// The type of an option's value.
enum class OptionType {
  Count,  ///< an integer in [min, max] (written as "400" or "1e5")
  Real,   ///< a finite real in [min, max]
  Reals   ///< one or more finite reals, each in [min, max]
};

/// One declared option `--name VALUE`. Build with count(), real() or reals() and chain the setters.
struct OptionSpec {
  std::string name;                         ///< the flag without dashes, e.g. "ba-min"
  OptionType type = OptionType::Real;       ///< value type
  std::string help;                         ///< what it is, in a few words
  std::vector<double> value;                ///< the default (one element unless Reals)
  double min = 0, max = 0;                  ///< admissible range, inclusive
  std::optional<std::vector<double>> fast;  ///< the default in --fast mode (when not given explicitly)
  std::string record;                       ///< the key under which the value is recorded ("" : the name with '-' -> '_')
  bool recorded = true;                     ///< record the value as a run parameter

  /// Admissible range [lo, hi] (inclusive).
  OptionSpec& range(double lo, double hi) {
    min = lo;
    max = hi;
    return *this;
  }
  /// The default in --fast mode.
  OptionSpec& fast_value(double v) {
    fast = std::vector<double>{v};
    return *this;
  }
  /// The default list in --fast mode (Reals).
  OptionSpec& fast_values(std::vector<double> v) {
    fast = std::move(v);
    return *this;
  }
  /// Records the value under another key (e.g. "q_over_a" for --q).
  OptionSpec& recorded_as(std::string key) {
    record = std::move(key);
    return *this;
  }
  /// Does not record the value as a run parameter (the experiment records what it derives).
  OptionSpec& unrecorded() {
    recorded = false;
    return *this;
  }

  /// The condition the value must satisfy, as printed in errors and help ("2 <= nq <= 100000").
  std::string condition() const;
  /// The key under which the value is recorded.
  std::string record_key() const;
  /// The declaration as JSON (for --describe).
  Json to_json() const;
};

/// An integer option.
OptionSpec count(std::string name, long long default_value, std::string help);
/// A real option.
OptionSpec real(std::string name, double default_value, std::string help);
/// An option taking one or more reals.
OptionSpec reals(std::string name, std::vector<double> default_values, std::string help);

/// The parsed values of declared options.
class OptionValues {
 public:
  /// The value of a Count option. @throws std::logic_error for an undeclared name or another type.
  long long count(const std::string& name) const;
  /// The value of a Real option. @throws std::logic_error likewise.
  double real(const std::string& name) const;
  /// The values of a Reals option. @throws std::logic_error likewise.
  const std::vector<double>& reals(const std::string& name) const;
  /// Whether the option was given on the command line.
  bool given(const std::string& name) const;

  /// Sets the value of an option (parsing). @throws InvalidParameter naming the option when a
  /// value is not a number, not finite, not an integer for a Count, or out of range.
  void set(const OptionSpec& spec, const std::vector<std::string>& text);
  /// Sets the defaults of all options (fast or normal).
  void set_defaults(const std::vector<OptionSpec>& specs, bool fast);

 private:
  struct Entry {
    const OptionSpec* spec;
    std::vector<double> value;
    bool given;
  };
  std::vector<Entry> entries_;
  const Entry& find(const std::string& name, OptionType type) const;
};

/// Parses a number as the user wrote it: the whole text must be a finite number. For a count it
/// must also be an integer ("1e8" is accepted). @throws InvalidParameter naming `name`.
double parse_number(const std::string& name, const std::string& text, bool integer);
/// An integer option in [lo, hi] (parse_number with integer = true); the bounds are printed in
/// shortest form ("1 <= steps <= 1e8"). @throws InvalidParameter naming `name`.
long long parse_count(const std::string& name, const std::string& text, long long lo, long long hi);

}  // namespace dfchaos::kit
