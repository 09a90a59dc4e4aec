/// @file plane_lyapunov.cpp
/// @brief Beyond the paper: the Lyapunov exponent \f$\lambda = \frac1N\sum_n \ln|T'(\theta_n)|\f$ of
/// an orbit of T over the (q/a, b/a) plane of thm1_parameter_plane (q/a the cell centres of
/// (sin vartheta0, 1), b/a log-spaced in [1e-4, 0.1]), computed by the sweep engine (the cells of
/// `dfchaos sweep --observables lyapunov` with its default orbit: from t2 + (t3 - t2)/2, 1000 steps
/// discarded, 1000 averaged). \f$\lambda = -\infty\f$ marks an orbit that meets a stop (T' = 0 on a
/// stop arc); such an orbit goes on as the orbit of t2, and in those cells t2_cycle (superstable.hpp)
/// says whether that orbit closes, within kCycleMaxPeriod steps, on a superstable cycle that double
/// precision resolves (the superstable regime of Theorem 2); \f$\lambda > 0\f$ the expanding regime where
/// Theorem 1's covering is found. Every cell is independent: the output does not depend on the
/// number of threads, and equals the sweep tool's (tested by plane_lyapunov_vs_sweep).
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/superstable.hpp"
#include "kit/experiment.hpp"
#include "kit/grid.hpp"
#include "sweep/cell.hpp"
#include "sweep/spec.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {
/// The longest cycle through t2 looked for in a cell whose orbit meets a stop.
constexpr long long kCycleMaxPeriod = 1000;
std::string g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
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
      sweep::Spec spec;
      spec.a = 1;
      spec.q_over_a = sweep::Range::parse("q-range", g17(sin_vartheta0()) + ":1:" + std::to_string(n) + ":mid");
      spec.b_over_a = sweep::Range::parse("b-range", "1e-4:0.1:" + std::to_string(n) + ":log");
      spec.observables = sweep::ObservableSet::parse("observables", "lyapunov");
      spec.validate();
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
        if (!ok) { ++n_err; continue; }
        if (std::isinf(v.lyapunov) && v.lyapunov < 0) ++n_stop;
        else if (v.lyapunov > 0) ++n_pos;
        else ++n_neg;
        if (v.lyapunov > lmax) { lmax = v.lyapunov; qmax = v.q_over_a; bmax = v.b_over_a; }
      }
      run.table("", t);

      // The cells whose orbit met a stop: does the orbit of t2 close on a resolved superstable cycle?
      std::vector<std::pair<double, double>> stop_cells;  // (q/a, b/a)
      for (const auto& c : values)
        if (!c.failed && c.value.status == sweep::CellStatus::Ok && std::isinf(c.value.lyapunov) && c.value.lyapunov < 0)
          stop_cells.push_back({c.value.q_over_a, c.value.b_over_a});
      const auto cycles = sweep_list<T2Cycle, std::pair<double, double>>(
          stop_cells, [](const std::pair<double, double>& c) { return t2_cycle(Parameters(1.0, c.second, c.first), kCycleMaxPeriod); },
          "plane_lyapunov t2 cycles");
      long long n_resolved = 0, n_unresolved_return = 0;
      for (const auto& c : cycles) {
        if (c.failed) continue;
        if (c.value.resolved) ++n_resolved;
        else if (c.value.period > 0) ++n_unresolved_return;
      }
      const long long n_cells = spec.cells();
      run.out.claim("plane.lyapunov_both_regimes", "Theorems 1 and 2", EvidenceKind::Sampled,
                    "Over the plane, orbits with a positive Lyapunov exponent (the expanding regime of Theorem 1) and orbits "
                    "that meet a stop arc, where T' = 0 and lambda is minus infinity, both occur.")
          .ours()
          .evidence("cells", n_cells).evidence("positive", n_pos).evidence("stop", n_stop)
          .evidence("finite_nonpositive", n_neg)
          .evidence("errors", n_err).evidence("max_lyapunov", lmax).evidence("max_at_q_over_a", qmax).evidence("max_at_b_over_a", bmax)
          .holds(n_pos > 0 && n_stop > 0);
      // Not expected: a finding. An orbit that meets a stop goes on as the orbit of t2, which need not be periodic.
      run.out.claim("plane.stop_cells_superstable", "Theorem 2 (beyond)", EvidenceKind::Sampled,
                    "In every cell whose orbit meets a stop, the orbit of t2 closes, within " + std::to_string(kCycleMaxPeriod) +
                        " steps, on a superstable cycle resolved in double precision (superstable.hpp, t2_cycle): lambda = minus "
                        "infinity there is the superstable regime of Theorem 2.")
          .ours().not_expected()
          .evidence("stop", n_stop).evidence("resolved_cycle", n_resolved).evidence("return_not_resolved", n_unresolved_return)
          .evidence("no_return", n_stop - n_resolved - n_unresolved_return)
          .holds(n_resolved == n_stop);
      run.out.claim("plane.lyapunov_computed", "Theorem 1", EvidenceKind::Sampled,
                    "Every cell's orbit was followed without error.")
          .ours()
          .evidence("errors", n_err)
          .holds(n_err == 0);
      run.out.macro("LyapN", std::to_string(n));
      run.out.macro("LyapCells", std::to_string(n_cells));
      run.out.macro("LyapPositive", std::to_string(n_pos));
      run.out.macro("LyapStop", std::to_string(n_stop));
      run.out.macro("LyapStopResolved", std::to_string(n_resolved));
      run.out.macro("LyapStopUnresolvedReturn", std::to_string(n_unresolved_return));
      run.out.macro("LyapCycleMaxPeriod", std::to_string(kCycleMaxPeriod));
      run.out.macro("LyapNonpositive", std::to_string(n_neg));
      run.out.macro("LyapMax", lmax, 3);
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
