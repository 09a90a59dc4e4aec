// SPDX-License-Identifier: GPL-3.0-or-later
/// @file experiment.hpp
/// @brief An experiment declares itself once, in its own .cpp: title, the paper items it checks,
/// the tests that cross-check the library code it rests on, its options and its outputs, and the
/// body that computes. Everything else — the build target (named after the file), `--help` with
/// defaults and ranges, `--describe`, bad-input handling, provenance, the claims maps — follows
/// from the declaration. See docs/adding-an-experiment.md.
///
/// \code
/// const dfchaos::kit::Experiment experiment{
///     .title = "vartheta0 of Eq. (1)",
///     .paper = {"Eq. (1)"},
///     .tests = {"test_parameters"},
///     .options = {kit::count("samples", 100000, "grid points").range(10, 100000000).fast_value(2000)},
///     .outputs = {kit::data("", "residual of Eq. (1)")},
///     .body = [](kit::Run& run) { ... run.count("samples") ... run.out.claim(...) ... }};
/// DFCHAOS_EXPERIMENT_MAIN(experiment)
/// \endcode
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "dfchaos/errors.hpp"
#include "kit/claim.hpp"
#include "kit/options.hpp"
#include "kit/output.hpp"
#include "kit/table.hpp"

namespace dfchaos::kit {

/// A declared output file of an experiment.
struct OutputSpec {
  std::string kind;         ///< "data" (build/data/NAME[-PART].tsv), "latex" (build/tables/FILE.tex) or
                            ///< "certificate" (build/certificates/FILE.json)
  std::string part;         ///< the part (data) or file name (latex, certificate); a final '*' matches any suffix
  std::string description;  ///< what it holds
  /// Whether a written file matches this declaration.
  bool matches(const std::string& kind, const std::string& part) const;
};
/// A data table `data/NAME.tsv` (part "") or `data/NAME-PART.tsv`.
OutputSpec data(std::string part, std::string description);
/// A LaTeX fragment `tables/FILE.tex`.
OutputSpec latex(std::string file, std::string description);
/// A proof certificate `certificates/FILE.json` (docs/certificates.md).
OutputSpec certificate(std::string file, std::string description);

/// What an experiment's body gets: the option values, the mode, and the outputs.
class Run {
 public:
  Run(const OptionValues& values, bool fast, const std::vector<struct OutputSpec>& outputs, Output& out)
      : values_(values), fast_(fast), outputs_(outputs), out(out) {}
  bool fast() const { return fast_; }                                             ///< smoke mode (coarse grids, same code paths)
  long long count(const std::string& name) const { return values_.count(name); }  ///< a Count option
  /// A Count option that must fit an int (all declared ranges do). @throws std::logic_error otherwise.
  int count_int(const std::string& name) const;
  double real(const std::string& name) const { return values_.real(name); }                        ///< a Real option
  const std::vector<double>& reals(const std::string& name) const { return values_.reals(name); }  ///< a Reals option
  /// The data table `data/NAME[-PART].tsv`, with the description of its declaration.
  /// @throws std::logic_error if the part was not declared.
  void table(const std::string& part, const Table& t);
  /// The LaTeX fragment `tables/FILE.tex`. @throws std::logic_error if it was not declared.
  void latex(const std::string& file, const std::string& tex);
  /// The certificate `certificates/FILE.json` (its whole text). @throws std::logic_error if it was not declared.
  void certificate(const std::string& file, const std::string& json);

 private:
  const OptionValues& values_;
  bool fast_;
  const std::vector<OutputSpec>& outputs_;

 public:
  Output& out;  ///< tables, LaTeX fragments, macros, claims
};

/// The declaration of an experiment.
struct Experiment {
  std::string title;                ///< one line: what it checks
  std::vector<std::string> paper;   ///< the paper items it checks, e.g. "Lemma 1", "Eq. (8)"
  std::vector<std::string> tests;   ///< the test suites that cross-check the code it rests on
  std::vector<OptionSpec> options;  ///< its options (--out and --fast are common to all)
  std::vector<OutputSpec> outputs;  ///< its declared data and LaTeX outputs
  std::function<void(Run&)> body;   ///< the computation

  /// The whole command-line program: parses, runs, writes. Exit status: 0 every expected claim
  /// holds, 1 one fails (or a bounded computation gave up, or a write failed), 2 bad input.
  int main(const std::string& name, int argc, char** argv) const;  // NOLINT(bugprone-exception-escape): a member, not the program's main
  /// The declaration as JSON (`--describe`).
  Json describe(const std::string& name) const;

 private:
  /// main() before its check that stdout received everything.
  int run_main(const std::string& name, int argc, char** argv) const;
};

}  // namespace dfchaos::kit

/// Defines main() for the experiment declared as `decl`; the name is the file name (set by CMake).
#define DFCHAOS_EXPERIMENT_MAIN(decl) \
  int main(int argc, char** argv) { return (decl).main(DFCHAOS_EXPERIMENT_NAME, argc, argv); }
