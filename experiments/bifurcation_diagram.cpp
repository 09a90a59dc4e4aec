// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bifurcation_diagram.cpp
/// @brief Beyond the paper: orbit diagrams of T (phases after a transient) against b/a at fixed q/a
/// and against q/a at fixed b/a, with the Lyapunov exponent of T (the mean of ln|T'| along the
/// orbit, T' from the implicit function theorem on Eqs. 11 and 17; see map_derivative.hpp) on the
/// same axis. T' is checked against central finite differences on a grid of phases. Since T is
/// constant (= t2) on the arcs where the motion stops, an orbit that meets such an arc continues as
/// the orbit of t2: the diagram shows where that orbit is periodic (a superstable cycle through t2)
/// and its period, and whether double precision resolves that cycle (superstable.hpp, t2_cycle: the
/// error allowed to T, propagated with |T'|, must stay well inside every stop arc on the way).
/// (Stops of scenarios D and D' send their arcs to another phase; period_of_t2 counts returns to t2.)
#include <algorithm>
#include <cmath>
#include <vector>

#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/map_derivative.hpp"
#include "dfchaos/orbit_diagram.hpp"
#include "dfchaos/superstable.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"
#include "kit/grid.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {
constexpr double kDerivativeRelTol = 1e-4;  // T' (implicit function theorem) against central differences
struct Point {
  double b, q;
};
}  // namespace

const Experiment experiment{
    .title = "orbit diagrams of T with the Lyapunov exponent",
    .paper = {"Eq. (11)", "Eq. (17)", "Lemma 3", "Theorem 2"},
    .tests = {"test_beyond"},
    .options = {count("nb", 400, "values of b/a, log-spaced in [1e-3, 0.2]").range(2, 100000).fast_value(12),
                count("nq", 300, "values of q/a in [0.5, 0.99]").range(2, 100000).fast_value(12),
                count("transient", 500, "steps discarded").range(0, 10'000'000).fast_value(50),
                count("keep", 64, "phases kept per parameter value").range(1, 10000).fast_value(16),
                real("q", 0.85, "q/a of the b/a sweep").range(0.5, 0.999).recorded_as("q_of_b_sweep"),
                real("b", 0.01, "b/a of the q/a sweep").range(1e-5, 0.2).recorded_as("b_of_q_sweep")},
    .outputs = {data("orbits", "phases of the orbit of T after the transient, per parameter value"),
                data("lyapunov",
                     "Lyapunov exponent (-inf when a step has T' = 0), steps with a stop, period of the computed cycle through t2 (0: none seen), "
                     "whether double precision resolves that cycle (1: a superstable cycle; 0: none, or a cycle of the rounding) and "
                     "its margin (superstable.hpp, t2_cycle)"),
                data("derivative-check", "T' by the implicit function theorem against central differences (every 10th compared phase)")},
    .body = [](Run& run) {
      const int nb = run.count_int("nb"), nq = run.count_int("nq"), transient = run.count_int("transient"), keep = run.count_int("keep");
      const double q_fixed = run.real("q"), b_fixed = run.real("b");
      const int averaged = 4 * keep;

      // The two sweeps: (b/a, q/a) per value, computed in parallel; each value is independent. A
      // value where the map is not defined (e.g. an eternal stick-slip) is recorded as failed.
      std::vector<Point> pts;
      const Axis b_axis = Axis::log_ratio(1e-3, 200.0, nb), q_axis = Axis::linear(0.5, 0.99, nq);
      for (int j = 0; j < nb; ++j) pts.push_back({b_axis[j], q_fixed});
      for (int j = 0; j < nq; ++j) pts.push_back({b_fixed, q_axis[j]});
      const auto st = sweep_list<OrbitDiagramColumn, Point>(
          pts,
          [&](const Point& pt) {
            const Parameters p(1.0, pt.b, pt.q);
            return orbit_diagram_column(p, orbit_diagram_start(p), transient, averaged, keep);
          },
          "orbit diagram");
      Table diagram({"sweep", "b_over_a", "q_over_a", "theta"});
      Table lyap({"sweep", "b_over_a", "q_over_a", "lyapunov", "flat_steps", "period_of_t2", "t2_cycle_resolved", "t2_cycle_margin",
                  "penetration_rate", "failed"});
      long long superstable = 0, returns = 0, positive = 0, fails = 0;
      long long shortest_unresolved = 0;  // the shortest computed return to t2 that is not resolved (0: none)
      double best_unresolved_margin = 0;  // the largest margin among those returns
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const std::string sweep = i < static_cast<std::size_t>(nb) ? "b" : "q";
        if (st[i].failed) {
          ++fails;
          lyap.row({sweep, pts[i].b, pts[i].q, NAN, 0LL, 0LL, 0LL, NAN, NAN, 1LL});
          continue;
        }
        const OrbitStatistics& s = st[i].value.orbit;
        const StopCycle& c = st[i].value.cycle;
        for (double th : s.tail) diagram.row({sweep, pts[i].b, pts[i].q, th});
        lyap.row({sweep, pts[i].b, pts[i].q, s.lyapunov, s.flat_steps, s.period_of_t2, static_cast<long long>(c.resolved),
                  s.period_of_t2 > 0 ? c.margin : NAN, s.penetration_rate, 0LL});
        if (s.period_of_t2 > 0) ++returns;
        if (c.resolved) ++superstable;
        if (s.period_of_t2 > 0 && !c.resolved) {
          shortest_unresolved = shortest_unresolved == 0 ? s.period_of_t2 : std::min(shortest_unresolved, s.period_of_t2);
          best_unresolved_margin = std::max(best_unresolved_margin, c.margin);
        }
        if (std::isfinite(s.lyapunov) && s.lyapunov > 0) ++positive;
      }
      run.table("orbits", diagram);
      run.table("lyapunov", lyap);

      // T' against central differences, on phases where the step and its neighbours are on one branch.
      Table fd({"b_over_a", "theta", "dT_implicit", "dT_finite_difference", "relative_difference"});
      double worst = 0;
      long long compared = 0;
      for (double ba : {0.05, 0.01, 1e-3}) {
        const Parameters p(1.0, ba, q_fixed);
        const double t2 = *p.t2(), t3 = *p.t3();
        const int n = run.fast() ? 50 : 2000;
        const Axis theta = Axis::linear(t2, t3, n + 1);  // the interior points 1..n-1 are used
        for (int i = 1; i < n; ++i) {
          const double th = theta[i];
          const LabelledStep c = continuity_label(p, th);
          const MapDerivative d = map_derivative(p, c.step);
          if (d.flat || !std::isfinite(d.dT)) continue;
          const double h = 1e-6 / std::max(1.0, std::fabs(d.dT));
          if (!p.in_map_domain(th - h) || !p.in_map_domain(th + h)) continue;
          const LabelledStep lo = continuity_label(p, th - h), hi = continuity_label(p, th + h);
          if (!(lo.label == c.label) || !(hi.label == c.label) || lo.step.scenario != Scenario::A || hi.step.scenario != Scenario::A) continue;
          const double dT_fd = (hi.step.T - lo.step.T) / (2 * h);
          const double rel = std::fabs(dT_fd - d.dT) / std::max(1.0, std::fabs(d.dT));
          worst = std::max(worst, rel);
          ++compared;
          if (i % 10 == 0) fd.row({ba, th, d.dT, dT_fd, rel});
        }
      }
      run.table("derivative-check", fd);
      run.out.macro("BifSuperstableValues", std::to_string(superstable));
      run.out.macro("BifReturnsToTTwo", std::to_string(returns));
      run.out.macro("BifReturnsUnresolved", std::to_string(returns - superstable));
      run.out.macro("BifUnresolvedShortestPeriod", std::to_string(shortest_unresolved));
      run.out.macro("BifUnresolvedBestMargin", best_unresolved_margin, 2);
      run.out.macro("BifCycleSafety", kStopCycleSafety, 2);
      run.out.macro("BifCycleStepError", kStopCycleStepError, 1);
      run.out.macro("BifValues", std::to_string(pts.size()));
      run.out.macro("BifQ", dfchaos::format_shortest(q_fixed));
      run.out.macro("BifB", latex_number(dfchaos::format_shortest(b_fixed)));
      run.out.macro("BifPositiveLyapunov", std::to_string(positive));
      run.out.macro("BifDerivativeWorst", worst, 2);
      run.out.macro("BifDerivativeCompared", std::to_string(compared));

      run.out
          .claim("bif.derivative", "Eqs. (11), (17) (beyond)", EvidenceKind::Sampled,
                 "The derivative of T from the implicit function theorem agrees with central finite differences to {tol} (relative) "
                 "wherever T is smooth.")
          .ours()
          .evidence("phases_compared", compared)
          .evidence("worst_relative_difference", worst)
          .tolerance(kDerivativeRelTol)
          .holds(compared > 0 && worst < kDerivativeRelTol);
      // Not expected: a finding, not an assertion of the paper.
      run.out
          .claim("bif.collapse_onto_t2", "Lemma 3, Theorem 2 (beyond)", EvidenceKind::Sampled,
                 "After the transient, the orbit of a typical phase has met an arc where T = t2 and continues as the orbit of t2; "
                 "at most parameter values that orbit is a superstable cycle through t2 (T' = 0 on it: a Lyapunov exponent of minus infinity), "
                 "resolved in double precision (the error propagated along it stays " +
                     format_tolerance(kStopCycleSafety) + " times inside every stop arc it uses).")
          .ours()
          .not_expected()
          .parameter("safety", kStopCycleSafety)
          .evidence("parameter_values", static_cast<long long>(pts.size()))
          .evidence("superstable_cycle_through_t2", superstable)
          .evidence("computed_returns_to_t2", returns)
          .evidence("returns_not_resolved", returns - superstable)
          .evidence("positive_lyapunov", positive)
          .evidence("map_undefined", fails)
          .holds(superstable * 2 > static_cast<long long>(pts.size()));
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
