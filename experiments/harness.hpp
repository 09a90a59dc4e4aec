/// @file harness.hpp
/// @brief The command-line shell shared by every experiment: options --out and --fast, error
/// handling (bad input: one line, exit 2, no file written), and the final write of all outputs.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <string>

#include "dfchaos/errors.hpp"
#include "dfchaos/io.hpp"

namespace dfchaos::experiments {

/// Common options of every experiment.
struct Options {
  std::string out = "build";  ///< output root: data/, tables/, claims/ are created below it
  bool fast = false;          ///< smoke mode: coarse grids (run by CTest), same code paths
};

/// Parses the command line (common options plus those added by `add_options`), runs `body`, and
/// writes the outputs. Returns the process exit status: 0 all expected claims hold, 1 one fails or
/// a bounded computation gave up, 2 bad input.
inline int run(int argc, char** argv, const std::string& name, const std::string& description,
               const std::function<void(CLI::App&)>& add_options,
               const std::function<void(const Options&, ExperimentOutput&)>& body) {
  CLI::App app{name + ": " + description};
  Options o;
  app.add_option("--out", o.out, "output root (default build)");
  app.add_flag("--fast", o.fast, "smoke mode: coarse grids");
  add_options(app);
  // An empty value would be read as 0 by the option parser: refuse it whatever the option.
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] == '\0') {
      std::fprintf(stderr, "%s: error: %s: empty value (a number is required)\n", name.c_str(), i > 1 ? argv[i - 1] : "argument");
      return 2;
    }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    for (auto& ch : msg)
      if (ch == '\n') ch = ' ';
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), msg.c_str());
    return 2;
  }
  try {
    ExperimentOutput out(name, o.out);
    out.parameter("mode", o.fast ? "fast" : "full");
    body(o, out);
    return out.finish();
  } catch (const InvalidParameter& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    return 2;
  } catch (const GaveUp& e) {
    std::fprintf(stderr, "%s: gave up: %s\n", name.c_str(), e.what());
    return 1;
  }
}

/// Rejects a non-finite or non-positive option value. @throws InvalidParameter.
inline void require_positive(const char* name, double v) {
  if (!std::isfinite(v) || !(v > 0)) throw InvalidParameter(name, std::string(name) + " > 0 and finite", v);
}
/// Rejects a value outside [lo, hi]. @throws InvalidParameter.
inline void require_range(const char* name, double v, double lo, double hi) {
  if (!std::isfinite(v) || v < lo || v > hi)
    throw InvalidParameter(name, format_double(lo) + " <= " + name + " <= " + format_double(hi), v);
}

}  // namespace dfchaos::experiments
