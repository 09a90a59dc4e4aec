/// @file harness.hpp
/// @brief The command-line shell shared by every experiment: options --out and --fast, error
/// handling (bad input: one line, exit 2, no file written), and the final write of all outputs.
/// The command-line parser (CLI11) is used only in harness.cpp: including it costs seconds of
/// compilation per file, so experiments see it through the small OptionSet below.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/io.hpp"

namespace dfchaos::experiments {

/// Common options of every experiment.
struct Options {
  std::string out = "build";  ///< output root: data/, tables/, claims/ are created below it
  bool fast = false;          ///< smoke mode: coarse grids (run by CTest), same code paths
};

/// The options of one experiment, declared before parsing (a thin front to the parser).
class OptionSet {
 public:
  explicit OptionSet(void* app) : app_(app) {}
  /// Declares `--name VALUE` bound to `value` (its current value is the default).
  void add_option(const std::string& flag, double& value, const std::string& help);
  void add_option(const std::string& flag, int& value, const std::string& help);        ///< the same for an integer
  void add_option(const std::string& flag, long long& value, const std::string& help);  ///< the same for a long integer
  void add_option(const std::string& flag, std::vector<double>& values, const std::string& help);  ///< one or more numbers

 private:
  void* app_;  ///< the CLI::App of harness.cpp
};

/// Parses the command line (common options plus those added by `add_options`), runs `body`, and
/// writes the outputs. Returns the process exit status: 0 all expected claims hold, 1 one fails or
/// a bounded computation gave up, 2 bad input.
int run(int argc, char** argv, const std::string& name, const std::string& description,
        const std::function<void(OptionSet&)>& add_options, const std::function<void(const Options&, ExperimentOutput&)>& body);

/// Rejects a non-finite or non-positive option value. @throws InvalidParameter.
inline void require_positive(const char* name, double v) {
  if (!std::isfinite(v) || !(v > 0)) throw InvalidParameter(name, std::string(name) + " > 0 and finite", v);
}
/// Rejects a value outside [lo, hi]. @throws InvalidParameter.
inline void require_range(const char* name, double v, double lo, double hi) {
  if (!std::isfinite(v) || v < lo || v > hi)
    throw InvalidParameter(name, format_double(lo) + " <= " + name + " <= " + format_double(hi), v);
}

/// Rejects a count (grid size, step number, ...) outside [lo, hi]. @throws InvalidParameter.
inline void require_count(const char* name, long long v, long long lo, long long hi) {
  if (v < lo || v > hi)
    throw InvalidParameter(name, std::to_string(lo) + " <= " + name + " <= " + std::to_string(hi), static_cast<double>(v));
}

/// Lemma 4's covering at p, for the experiments that build on it (Sections 6, 7 and 10).
/// @throws InvalidParameter (naming b) when no covering is found: those experiments need one.
inline Lemma4Covering lemma4_covering_or_reject(const Parameters& p) {
  Lemma4Covering c = lemma4_covering(p);
  if (!c.holds) throw InvalidParameter("b", "a parameter set where the covering of Lemma 4 holds (none found at " + p.describe() + ")");
  return c;
}

}  // namespace dfchaos::experiments
