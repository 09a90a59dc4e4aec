// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/return_map.hpp"
#include "sweep/range.hpp"

namespace dfchaos::cli {

namespace {
/// Most phases of --grid and --arc.
constexpr long long kMaxMapGrid = 10'000'000;
}  // namespace

Command add_map(CLI::App& app) {
  auto* cmd = app.add_subcommand("map", "T1 and T at given phases of [t2, t3)");
  struct Opts {
    ModelOptions m;
    std::vector<std::string> theta, grid;
    std::string arc;
  };
  auto o = std::make_shared<Opts>();
  o->m.add_to(cmd);
  auto* t = cmd->add_option("--theta", o->theta, "phases in [t2, t3), one or more")->type_name("FLOAT ...");
  auto* g = cmd->add_option("--grid", o->grid,
                            "LO:HI:N[:lin|log|mid]: N phases from LO to HI, both included (lin, the default; log: log-spaced;\n"
                            "mid: the N cell centres), as a sweep's axes; every phase in [t2, t3), 1 <= N <= 10^7")
                ->expected(1, 3)
                ->type_name("LO:HI:N[:KIND]");
  auto* a = cmd->add_option("--arc", o->arc, "N: the N phases t2 + (t3-t2) i/N, i = 0..N-1 (all of [t2, t3); 1 <= N <= 10^7)")->type_name("N");
  t->excludes(g)->excludes(a);
  g->excludes(a);
  cmd->footer(
      "Output columns (tab-separated, one row per phase, %.17g; after the column line, # lines: the version and the settings):\n"
      "  theta        the start phase (at rest at the delimiter, Eq. 10)\n"
      "  T1           the next hit T1(theta) as an instant (Eq. 11; may exceed 2 pi)\n"
      "  T            the return map T(theta) in [t2, t3) (Lemma 3)\n"
      "  scenario     the chain of regimes of Section 3: A f>p>f, B f>p>s>f, C f>p>s>p>s>f, D f>p>s>p>f, "
      "C' f>s>p>s>f, D' f>s>p>f; G: a grazing touch (the flight touches the delimiter with zero velocity inside [t2, t3) "
      "and flies on, so T = T1 mod 2 pi)\n"
      "  elapsed      the time from theta to the next start of free flight\n"
      "  penetration  the advance of the delimiter during that time\n"
      "With --physical: T1_s and elapsed_s in seconds (divided by OMEGA), penetration_m in metres; theta and T stay\n"
      "phases in radians (docs/units.md).\n"
      "Accuracy (docs/accuracy.md; checked against a 40-digit reference by the test precision_reference):\n"
      "  needs b/a >= " +
      format_shortest(kMinMapRatio) +
      " (refused below, exit 2).\n"
      "  T: within 1e-11 of the exact T(theta) (radians); within 1e-9 down to a relative distance of\n"
      "     1e-11 from a discontinuity of T1; at a discontinuity either one-sided value may be returned.\n"
      "  T1, elapsed: within 1e-11 plus the rounding of the printed double (relative 2.2e-16); near a\n"
      "     discontinuity of T1 as T.\n"
      "  scenario: exact except where T is discontinuous.  penetration: to 1e-7 (against ODE integration).\n"
      "Rows are streamed as computed: a phase at which the computation gives up (exit 1, one line on stderr) ends\n"
      "the output after the rows of the phases before it.");
  return {cmd, [o] {
            const Parameters p = o->m.model();
            p.require_return_map();
            const double t2 = p.t2_required(), t3 = p.t3_required();
            std::vector<double> th;
            if (!o->grid.empty()) {
              if (o->grid.size() != 1)
                throw InvalidParameter("grid", "write the grid as one word LO:HI:N[:lin|log|mid] (HI included, as in sweep), not 'LO HI N'");
              const sweep::Range r = sweep::Range::parse("grid", o->grid[0], kMaxMapGrid);
              th.reserve(static_cast<std::size_t>(r.size()));
              for (long long i = 0; i < r.size(); ++i) th.push_back(r[i]);
              for (double x : th) p.require_in_map_domain(x, "grid");
            } else if (!o->arc.empty()) {
              const long long n = count("arc", o->arc, 1, kMaxMapGrid);
              th.reserve(static_cast<std::size_t>(n));
              for (long long i = 0; i < n; ++i) th.push_back(t2 + (t3 - t2) * static_cast<double>(i) / static_cast<double>(n));
            } else {
              for (const auto& s : o->theta) th.push_back(number("theta", s));
            }
            if (th.empty()) throw InvalidParameter("theta", "give --theta X [X ...], --grid LO:HI:N or --arc N");
            for (double x : th) p.require_in_map_domain(x, "theta");  // every input checked before any output
            const Units u = o->m.units();
            std::vector<Setting> settings = o->m.settings(p);
            if (!o->grid.empty())
              settings.emplace_back("grid", sweep::Range::parse("grid", o->grid[0], kMaxMapGrid).canonical());
            else if (!o->arc.empty())
              settings.emplace_back("arc", std::to_string(th.size()) + "  (t2 + (t3 - t2) i / N, i = 0..N-1)");
            else
              settings.emplace_back("theta", std::to_string(th.size()) + (th.size() == 1 ? " phase" : " phases") + " given");
            Writer w;
            w.row({"theta", u.time("T1"), "T", "scenario", u.time("elapsed"), u.length("penetration")});
            w.provenance("map: T1 and T at given phases of [t2, t3)", settings);
            for (double x : th) {
              const auto s = return_map_step(p, x);
              w.row({format_double(x), format_double(u.seconds(s.hit.theta1)), format_double(s.T), scenario_name(s.scenario),
                     format_double(u.seconds(s.elapsed)), format_double(s.penetration)});
            }
            w.flush();
            return 0;
          }};
}

}  // namespace dfchaos::cli
