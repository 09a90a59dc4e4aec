// SPDX-License-Identifier: GPL-3.0-or-later
/// @file cmd_orbit_diagram.cpp
/// @brief `dfchaos orbit-diagram`: the phases of the orbit of T after a transient, per parameter
/// cell of a (q/a, b/a) grid given as the sweep's axes, with each cell's marks (orbit_diagram.hpp).
#include <string>
#include <vector>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "sweep/orbit_diagram.hpp"
#include "sweep/range.hpp"

namespace dfchaos::cli {

Command add_orbit_diagram(CLI::App& app) {
  auto* cmd = app.add_subcommand("orbit-diagram", "phases of the orbit of T after a transient, per cell of a (q/a, b/a) grid, cells marked");
  const OrbitDiagramSettings d;  // the defaults
  struct Opts {
    std::string a = "1", q_range, b_range, theta0, transient, steps, keep;
  };
  auto o = std::make_shared<Opts>(
      Opts{"1", "", "", format_shortest(d.theta0_fraction), std::to_string(d.transient), std::to_string(d.steps), std::to_string(d.keep)});
  cmd->add_option("-a,--a", o->a, "forcing amplitude a [default 1]; only q/a and b/a matter")->type_name("FLOAT");
  cmd->add_option("--q-range", o->q_range, "q/a axis LO:HI:N[:lin|log|mid] or one value (as sweep)")->required()->type_name("LO:HI:N[:KIND]");
  cmd->add_option("--b-range", o->b_range, "b/a axis LO:HI:N[:lin|log|mid] or one value (as sweep)")->required()->type_name("LO:HI:N[:KIND]");
  cmd->add_option("--theta0-fraction", o->theta0, "orbit start theta_0 = t2 + f (t3 - t2), f in [0, 1) (default " + o->theta0 + ", the report's)")
      ->type_name("F");
  cmd->add_option("--transient", o->transient, "steps discarded, 0 <= N <= 1e8 (default " + o->transient + ")")->type_name("N");
  cmd->add_option("--steps", o->steps, "steps averaged for the Lyapunov exponent, 1 <= N <= 1e8, at least --keep (default " + o->steps + ")")
      ->type_name("N");
  cmd->add_option("--keep", o->keep, "phases written per cell (the last ones), 1 <= K <= 1e5 (default " + o->keep + ")")->type_name("K");
  cmd->footer(
      "Output (tab-separated, %.17g; after the column line, # lines: the version and the settings), one row per kept phase,\n"
      "cells in the order q/a outer, b/a inner, each streamed when computed:\n"
      "  q_over_a, b_over_a  the cell\n"
      "  k             the index of the phase among the kept ones (0 the earliest)\n"
      "  theta         the phase T^(transient + steps - keep + k)(theta_0)\n"
      "  lyapunov      the cell's Lyapunov exponent over the averaged steps; -inf when a step stopped (T' = 0)\n"
      "  period_of_t2  when the orbit reached t2 and came back: the return time, else 0\n"
      "  superstable   1 when that return is a superstable cycle through t2 that double precision resolves\n"
      "                (Theorem 2; the propagated error stays well inside every stop arc: superstable.hpp), else 0\n"
      "Bounds, refused (exit 2) before any output: at most 1e8 rows and 1e9 evaluations of T (cells x (transient + steps)).\n"
      "Every cell must have T defined (b/a >= 1e-12, q/a > 2 b/a). A cell whose computation gives up ends the output\n"
      "after the rows before it (exit 1, one line on stderr). Threads: OMP_NUM_THREADS; the rows do not depend on them.");
  return {cmd, [o] {
            const double a = number("a", o->a);
            const sweep::Range qr = sweep::Range::parse("q-range", o->q_range), br = sweep::Range::parse("b-range", o->b_range);
            OrbitDiagramSettings set;
            set.theta0_fraction = number("theta0-fraction", o->theta0);
            set.transient = count("transient", o->transient, 0, 100'000'000);
            set.steps = count("steps", o->steps, 1, 100'000'000);
            set.keep = count("keep", o->keep, 1, 100'000);
            set.validate();
            sweep::check_orbit_diagram_size(static_cast<double>(qr.size()), static_cast<double>(br.size()), set);  // before the axes are built
            std::vector<double> q(static_cast<std::size_t>(qr.size())), b(static_cast<std::size_t>(br.size()));
            for (long long i = 0; i < qr.size(); ++i) q[static_cast<std::size_t>(i)] = qr[i];
            for (long long i = 0; i < br.size(); ++i) b[static_cast<std::size_t>(i)] = br[i];
            Writer w;
            bool started = false;  // the column line and the header go out with the first cell: bad input leaves no output
            sweep::orbit_diagram(a, q, b, set, [&](long long i, const OrbitDiagramColumn& c) {
              if (!started) {
                w.row({"q_over_a", "b_over_a", "k", "theta", "lyapunov", "period_of_t2", "superstable"});
                w.provenance("orbit-diagram: phases of the orbit of T after a transient, per cell",
                             {{"a", format_shortest(a)},
                              {"q_over_a", qr.canonical()},
                              {"b_over_a", br.canonical()},
                              {"theta0-fraction", format_shortest(set.theta0_fraction)},
                              {"transient", std::to_string(set.transient)},
                              {"steps", std::to_string(set.steps)},
                              {"keep", std::to_string(set.keep)}});
                started = true;
              }
              const auto nb = static_cast<long long>(b.size());
              const std::string qs = format_double(q[static_cast<std::size_t>(i / nb)]), bs = format_double(b[static_cast<std::size_t>(i % nb)]),
                                lyap = format_double(c.orbit.lyapunov), period = std::to_string(c.orbit.period_of_t2),
                                superstable = c.cycle.resolved ? "1" : "0";
              for (std::size_t k = 0; k < c.orbit.tail.size(); ++k)
                w.row({qs, bs, std::to_string(k), format_double(c.orbit.tail[k]), lyap, period, superstable});
            });
            w.flush();
            return 0;
          }};
}

}  // namespace dfchaos::cli
