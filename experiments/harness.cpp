/// @file harness.cpp
/// @brief The experiments' shell (see harness.hpp): the only file of the experiments that includes
/// the command-line parser CLI11.
#include "harness.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

namespace dfchaos::experiments {

void OptionSet::add_option(const std::string& flag, double& value, const std::string& help) {
  static_cast<CLI::App*>(app_)->add_option(flag, value, help);
}
void OptionSet::add_option(const std::string& flag, int& value, const std::string& help) {
  static_cast<CLI::App*>(app_)->add_option(flag, value, help);
}
void OptionSet::add_option(const std::string& flag, long long& value, const std::string& help) {
  static_cast<CLI::App*>(app_)->add_option(flag, value, help);
}

void OptionSet::add_option(const std::string& flag, std::vector<double>& values, const std::string& help) {
  static_cast<CLI::App*>(app_)->add_option(flag, values, help);
}

int run(int argc, char** argv, const std::string& name, const std::string& description,
        const std::function<void(OptionSet&)>& add_options, const std::function<void(const Options&, ExperimentOutput&)>& body) {
  CLI::App app{name + ": " + description};
  Options o;
  app.add_option("--out", o.out, "output root (default build)");
  app.add_flag("--fast", o.fast, "smoke mode: coarse grids");
  OptionSet options(&app);
  add_options(options);
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

}  // namespace dfchaos::experiments
