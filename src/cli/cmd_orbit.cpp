// SPDX-License-Identifier: GPL-3.0-or-later
#include <unistd.h>

#include <chrono>
#include <cmath>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/limits.hpp"
#include "dfchaos/orbit.hpp"

namespace dfchaos::cli {

Command add_orbit(CLI::App& app) {
  auto* cmd = app.add_subcommand("orbit", "iterate T from a phase, with elapsed time and the delimiter's advance");
  struct Opts {
    ModelOptions m;
    std::string theta0, steps;
  };
  auto o = std::make_shared<Opts>();
  o->m.add_to(cmd);
  cmd->add_option("--theta0", o->theta0, "the initial phase, in [t2, t3)")->required()->type_name("FLOAT");
  cmd->add_option("--steps", o->steps, "number of steps, 1 <= steps <= 1e8 (written as an integer or like 1e8)")->required()->type_name("N");
  cmd->footer(
      "Output columns (tab-separated, one row per step, streamed as computed, %.17g; after the column line, # lines: the version and\n"
      "the settings):\n"
      "  n            the step number (0 is the initial phase)\n"
      "  theta        the iterate theta_n = T^n(theta0)\n"
      "  scenario     the scenario of the step from theta_n (see 'dfchaos map --help'; G is a grazing touch)\n"
      "  elapsed      the duration of that step\n"
      "  penetration  the advance of the delimiter during that step\n"
      "  time         the time at which theta_n starts (theta0 at n = 0)\n"
      "  y            the delimiter position at that time (0 at n = 0)\n"
      "With --physical: elapsed_s and time_s in seconds (divided by OMEGA), penetration_m and y_m in metres;\n"
      "theta0 and theta stay phases in radians (docs/units.md).\n"
      "Memory does not grow with the number of steps; progress goes to stderr when it is a terminal.\n"
      "Rows are streamed as computed: a step at which the computation gives up (exit 1, one line on stderr) ends\n"
      "the output after the rows of the steps before it.\n"
      "Accuracy (docs/accuracy.md): needs b/a >= " +
      format_shortest(kMinMapRatio) +
      ". Each step is one evaluation of T with the\n"
      "accuracy stated by 'dfchaos map --help'; along an orbit these errors are amplified by |T'| (large for small b/a),\n"
      "so a long orbit is a faithful pseudo-orbit, not the exact orbit of theta0. time and y sum elapsed and penetration\n"
      "in long double.");
  return {cmd, [o] {
            const Parameters p = o->m.model();
            p.require_return_map();
            const double theta0 = number("theta0", o->theta0);
            p.require_in_map_domain(theta0, "theta0");
            const long long steps = count("steps", o->steps, 1, kMaxOrbitSteps);
            const bool progress = ::isatty(2) && steps >= 100000;
            const auto start = std::chrono::steady_clock::now();
            Writer w;
            const Units u = o->m.units();
            w.row({"n", "theta", "scenario", u.time("elapsed"), u.length("penetration"), u.time("time"), u.length("y")});
            std::vector<Setting> settings = o->m.settings(p);
            settings.emplace_back("theta0", format_shortest(theta0));
            settings.emplace_back("steps", std::to_string(steps));
            w.provenance("orbit: iterates of T from theta0", settings);
            const Orbit orbit(p, theta0, steps);
            for (auto it = orbit.begin(); it != orbit.end(); ++it) {
              const long long n = it.n();
              w.row({std::to_string(n), format_double(it->theta), scenario_name(it->scenario), format_double(u.seconds(it->elapsed)),
                     format_double(it->penetration), format_double(u.seconds(static_cast<double>(it.time()))),
                     format_double(static_cast<double>(it.y()))});
              if (progress && (n + 1) % 100000 == 0) {
                const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                std::fprintf(stderr, "\rorbit: %lld/%lld steps, about %.0f s left   ", n + 1, steps, sec / (n + 1) * (steps - n - 1));
              }
            }
            if (progress) std::fprintf(stderr, "\n");
            w.flush();
            return 0;
          }};
}

}  // namespace dfchaos::cli
