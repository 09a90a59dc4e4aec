// SPDX-License-Identifier: GPL-3.0-or-later
/// @file plane_lyapunov.cpp
/// @brief Beyond the paper: the Lyapunov exponent \f$\lambda = \frac1N\sum_n \ln|T'(\theta_n)|\f$ of
/// an orbit of T over the (q/a, b/a) plane of thm1_parameter_plane (q/a the cell centres of
/// (sin vartheta0, 1), b/a log-spaced in [1e-4, 0.1]), computed by the sweep engine (the cells of
/// `dfchaos sweep --observables lyapunov` with its default orbit: from t2 + (t3 - t2)/2, 1000 steps
/// discarded, 1000 averaged). \f$\lambda = -\infty\f$ marks an orbit that meets a stop (T' = 0 on a
/// stop arc); such an orbit goes on as the orbit of the stop's image (t2 in scenarios B and C), and
/// in those cells stop_cycle (superstable.hpp) says whether that orbit closes, within kCycleMaxPeriod
/// steps, on a superstable cycle that double precision resolves; \f$\lambda > 0\f$ the expanding regime where
/// Theorem 1's covering is found. Every cell is independent: the output does not depend on the
/// number of threads, and equals the sweep tool's (tested by plane_lyapunov_vs_sweep).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/superstable.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"
#include "kit/grid.hpp"
#include "sweep/cell.hpp"
#include "sweep/spec.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {
/// The longest cycle through t2 looked for in a cell whose orbit meets a stop.
constexpr long long kCycleMaxPeriod = 1000;
/// The shift for the second check of a cycle's verdict (1000 times below stop_cycle's error per step).
constexpr double kNudge = 1e-12;
}  // namespace

const Experiment experiment{
    .title = "The Lyapunov exponent of T over the (q/a, b/a) plane",
    .paper = {"Theorem 1", "Theorem 2", "Section 8"},
    .tests = {"test_sweep", "plane_lyapunov_vs_sweep", "test_beyond"},
    .options = {count("n", 160, "grid points on each axis (q/a cell centres of (sin vartheta0, 1); b/a log-spaced in [1e-4, 0.1])")
                    .range(2, 2000)
                    .fast_value(8)},
    .outputs = {data("", "lyapunov: mean ln|T'| over 1000 steps after 1000 discarded (-inf: a step stops); status ok or error")},
    .body = [](Run& run) {
      const long long n = run.count_int("n");
      const sweep::Spec spec = sweep::report_plane(n, "lyapunov");
      std::vector<long long> cells(static_cast<std::size_t>(spec.cells()));
      for (long long k = 0; k < spec.cells(); ++k) cells[static_cast<std::size_t>(k)] = k;
      const auto values = sweep_list<sweep::CellValues, long long>(
          cells, [&spec](const long long& k) { return sweep::evaluate_cell(spec, k); }, "plane_lyapunov");

      Table t({"q_over_a", "b_over_a", "status", "lyapunov"});
      long long n_pos = 0, n_neg = 0, n_stop = 0, n_err = 0;
      double lmax = -INFINITY, qmax = NAN, bmax = NAN;
      for (const auto& c : values) {
        // evaluate_cell never throws for a failure of its cell; a failure of the harness still counts.
        const bool ok = !c.failed && c.value.status == sweep::CellStatus::Ok;
        const sweep::CellValues& v = c.value;
        t.row({v.q_over_a, v.b_over_a, std::string(ok ? "ok" : c.failed ? "error" : sweep::status_name(v.status)), v.lyapunov});
        if (!ok) {
          ++n_err;
          continue;
        }
        if (std::isinf(v.lyapunov) && v.lyapunov < 0)
          ++n_stop;
        else if (v.lyapunov > 0)
          ++n_pos;
        else
          ++n_neg;
        if (v.lyapunov > lmax) {
          lmax = v.lyapunov;
          qmax = v.q_over_a;
          bmax = v.b_over_a;
        }
      }
      run.table("", t);

      // The cells whose orbit met a stop: it goes on as the orbit of that stop's image (t2, or the
      // image of a stop of scenario D or D'). Does that orbit close on a resolved superstable cycle?
      std::vector<const sweep::CellValues*> stop_cells;
      for (const auto& c : values)
        if (!c.failed && c.value.status == sweep::CellStatus::Ok && std::isinf(c.value.lyapunov) && c.value.lyapunov < 0)
          stop_cells.push_back(&c.value);
      // With each verdict, the second check (stop_cycle_survives_shift): does the orbit, moved by
      // kNudge after its first step (far inside the error budget), close at the same step?
      struct Cycle {
        StopCycle cycle;
        bool not_t2 = false;  // the last stop's image is not t2
        bool nudged_same = false;
      };
      const auto cycles = sweep_list<Cycle, const sweep::CellValues*>(
          stop_cells,
          [](const sweep::CellValues* const& v) {
            const Parameters p(1.0, v->b_over_a, v->q_over_a);
            Cycle r{stop_cycle(p, v->stop_image, kCycleMaxPeriod), v->stop_image != *p.t2(), false};
            if (r.cycle.period > 0) r.nudged_same = stop_cycle_survives_shift(p, r.cycle, kNudge);
            return r;
          },
          "plane_lyapunov stop cycles");
      long long n_resolved = 0, n_unresolved_return = 0, n_resolved_nudged_same = 0, n_unresolved_nudged_same = 0;
      long long n_not_t2 = 0, n_cycle_failed = 0;
      long long n_unresolved_lost = 0;  // not resolved because the error was lost (StopCycle::lost), not for a narrow arc
      long long n_no_return_lost = 0;   // no stop image repeated, and the error was lost on the way
      // The cells that decide against plane.stop_cells_superstable (no return with the error kept
      // small, or the search gave up), as (q/a, b/a): a reader can rerun them one by one.
      std::vector<std::pair<double, double>> against_at;
      Json counterexamples = Json::array();
      for (std::size_t i = 0; i < cycles.size(); ++i) {
        const auto& c = cycles[i];
        if (c.failed || (!c.value.cycle.resolved && c.value.cycle.period == 0 && !c.value.cycle.lost)) {
          against_at.emplace_back(stop_cells[i]->q_over_a, stop_cells[i]->b_over_a);
          counterexamples.push(Json::array().push(stop_cells[i]->q_over_a).push(stop_cells[i]->b_over_a));
        }
      }
      for (const auto& c : cycles) {
        if (c.failed) {
          ++n_cycle_failed;
          continue;
        }
        n_not_t2 += c.value.not_t2;
        if (c.value.cycle.resolved) {
          ++n_resolved;
          n_resolved_nudged_same += c.value.nudged_same;
        } else if (c.value.cycle.period > 0) {
          ++n_unresolved_return;
          n_unresolved_nudged_same += c.value.nudged_same;
          n_unresolved_lost += c.value.cycle.lost;
        } else {
          n_no_return_lost += c.value.cycle.lost;
        }
      }
      const long long n_cells = spec.cells();
      const long long n_no_return = n_stop - n_cycle_failed - n_resolved - n_unresolved_return;
      run.out
          .claim("plane.lyapunov_both_regimes", "Theorems 1 and 2", EvidenceKind::Sampled,
                 "Over the plane, orbits with a positive Lyapunov exponent (the expanding regime of Theorem 1) and orbits "
                 "that meet a stop arc, where T' = 0 and lambda is minus infinity, both occur.")
          .ours()
          .evidence("cells", n_cells)
          .evidence("positive", n_pos)
          .evidence("stop", n_stop)
          .evidence("finite_nonpositive", n_neg)
          .evidence("errors", n_err)
          .evidence("max_lyapunov", lmax)
          .evidence("max_at_q_over_a", qmax)
          .evidence("max_at_b_over_a", bmax)
          .holds(n_pos > 0 && n_stop > 0);
      // Not expected: a finding. An orbit that meets a stop goes on as the orbit of the stop's image,
      // which need not be periodic.
      run.out
          .claim("plane.stop_cells_superstable", "Section 8, Theorem 2 (beyond)", EvidenceKind::Sampled,
                 "In every cell whose orbit meets a stop, the orbit of the last stop's image closes, within " + std::to_string(kCycleMaxPeriod) +
                     " steps, on a superstable cycle (followed by stop_cycle, superstable.hpp): there lambda = minus infinity marks "
                     "an attracting cycle. A cell decides against it when its orbit keeps its propagated error small and does not close "
                     "(or the search gives up); a cell whose error was lost, or whose stop arc is narrower than the safety margin, is "
                     "undecided in double precision.")
          .ours()
          .not_expected()
          .parameter("max_steps", kCycleMaxPeriod)
          .parameter("safety", kStopCycleSafety)
          .parameter("step_error", kStopCycleStepError)
          .evidence("stop", n_stop)
          .evidence("image_not_t2", n_not_t2)
          .evidence("resolved_cycle", n_resolved)
          .evidence("return_not_resolved", n_unresolved_return)
          .evidence("return_not_resolved_error_lost", n_unresolved_lost)
          .evidence("no_return", n_no_return)
          .evidence("no_return_error_lost", n_no_return_lost)
          .evidence("failed", n_cycle_failed)
          .evidence("counterexamples_q_b", counterexamples)
          // A cell decides against the claim only where its orbit kept its error small and still did not
          // close (no return within the bound, error not lost), or where the search gave up; a cycle seen
          // after the error was lost, or on an arc narrower than the safety margin, is one double
          // precision cannot decide.
          .cases(n_stop, n_no_return - n_no_return_lost + n_cycle_failed, n_stop - n_resolved - (n_no_return - n_no_return_lost) - n_cycle_failed)
          .holds(n_stop > 0 && n_resolved == n_stop);
      Claim& nudged =
          run.out
              .claim("plane.stop_cycles_nudged", "Section 8 (beyond)", EvidenceKind::Sampled,
                     "Second check of stop_cycle's verdicts: in every cell where it resolves the cycle, the orbit moved by " +
                         format_tolerance(kNudge) + " after its first step closes the cycle at the same step (stop_cycle_survives_shift).")
              .ours()
              .evidence("resolved", n_resolved)
              .evidence("resolved_nudged_same", n_resolved_nudged_same)
              .evidence("not_resolved_returns", n_unresolved_return)
              .evidence("not_resolved_nudged_same", n_unresolved_nudged_same);
      if (n_resolved == 0) nudged.not_expected();  // nothing resolved (a coarse grid): nothing to check
      nudged.holds(n_resolved > 0 && n_resolved_nudged_same == n_resolved);
      run.out.claim("plane.lyapunov_computed", "Theorem 1", EvidenceKind::Sampled, "Every cell's orbit was followed without error.")
          .ours()
          .evidence("cells", n_cells)
          .evidence("errors", n_err)
          .holds(n_err == 0);
      run.out.macro("LyapN", std::to_string(n));
      run.out.macro("LyapCells", std::to_string(n_cells));
      run.out.macro("LyapPositive", std::to_string(n_pos));
      run.out.macro("LyapStop", std::to_string(n_stop));
      run.out.macro("LyapStopResolved", std::to_string(n_resolved));
      run.out.macro("LyapStopUnresolvedReturn", std::to_string(n_unresolved_return));
      run.out.macro("LyapCycleMaxPeriod", std::to_string(kCycleMaxPeriod));
      run.out.macro("LyapLostAt", latex_number(dfchaos::format_shortest(kStopCycleLostAt)));
      run.out.macro("LyapUnresolvedNudgedSame", std::to_string(n_unresolved_nudged_same));
      run.out.macro("LyapResolvedNudgedSame", std::to_string(n_resolved_nudged_same));
      run.out.macro("LyapStopNotTTwo", std::to_string(n_not_t2));
      run.out.macro("LyapUnresolvedLost", std::to_string(n_unresolved_lost));
      run.out.macro("LyapUnresolvedNarrow", std::to_string(n_unresolved_return - n_unresolved_lost));
      run.out.macro("LyapNoReturn", std::to_string(n_no_return));
      run.out.macro("LyapNoReturnLost", std::to_string(n_no_return_lost));
      run.out.macro("LyapStopCounterexamples", std::to_string(n_no_return - n_no_return_lost + n_cycle_failed));
      {  // where they are: the first few cells against the claim, as (q/a, b/a) to 4 significant digits
         // (enough to find the cell on this grid and on make plane-hires's); the report words them
        std::string cells;
        const std::size_t shown = std::min<std::size_t>(against_at.size(), 4);
        for (std::size_t i = 0; i < shown; ++i)
          cells += std::string(i ? ", " : "") + "$(" + format_significant(against_at[i].first, 4) + ", " +
                   latex_number(format_significant(against_at[i].second, 4)) + ")$";
        run.out.macro("LyapStopCounterexampleCells", cells);
        run.out.macro("LyapStopCounterexampleShown", std::to_string(shown));
        run.out.macro("LyapStopCounterexampleAll", std::to_string(against_at.size()));
      }
      run.out.macro("LyapNudge", kNudge, 1);
      run.out.macro("LyapNonpositive", std::to_string(n_neg));
      run.out.macro("LyapMax", lmax, 3);
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
