/// @file thm2_superstable.cpp
/// @brief Theorem 2 (Section 8): where conditions (21) or (22) hold, t2 is a superstable fixed point
/// of T. All superstable windows of b/a in [1e-3, 0.1] at fixed q/a, each with its width epsilon,
/// found by following theta2(t2) continuously (superstable.hpp) and checked against a plain grid.
#include <cmath>

#include "dfchaos/superstable.hpp"
#include "harness.hpp"

using namespace dfchaos;

int main(int argc, char** argv) {
  int samples = 5000, grid_points = 20000;
  std::vector<double> qas{0.85, 0.95, 0.6};
  return experiments::run(
      argc, argv, "thm2_superstable", "Theorem 2: superstable fixed point t2, windows in b/a",
      [&](experiments::OptionSet& app) {
        app.add_option("--samples", samples, "samples of theta2(t2), uniform in a/b, for the window search");
        app.add_option("--grid", grid_points, "independent grid points (uniform in a/b) for the cross-check");
        app.add_option("--q", qas, "values of q/a");
      },
      [&](const experiments::Options& o, ExperimentOutput& out) {
        experiments::require_count("samples", samples, 2, 10'000'000);
        experiments::require_count("grid", grid_points, 2, 10'000'000);
        for (double q : qas) experiments::require_range("q", q, 0.003, 1.0 - 1e-12);
        if (o.fast) { samples = std::min(samples, 500); grid_points = std::min(grid_points, 400); }
        out.parameter("samples", std::to_string(samples));
        out.parameter("grid", std::to_string(grid_points));
        const double b_lo = 1e-3, b_hi = 0.1;
        Table windows({"q_over_a", "b_lo", "b_hi", "condition", "b_mid", "epsilon_mid", "theorem2_hypotheses_mid"});
        Table summary({"q_over_a", "windows", "windows_21", "windows_22", "windows_at_4x_samples", "grid_points_in_conditions",
                       "grid_points_outside_windows", "smallest_epsilon", "widest_window_relative"});
        long long total = 0, mismatch_grid = 0, not_super = 0, unstable_count = 0;
        double smallest_eps = INFINITY;
        for (double qa : qas) {
          const auto w = superstable_windows(1.0, qa, b_lo, b_hi, samples);
          const auto w4 = superstable_windows(1.0, qa, b_lo, b_hi, 4 * samples);
          if (w4.size() != w.size()) ++unstable_count;
          long long n21 = 0, n22 = 0;
          double eps_min = INFINITY, widest = 0;
          for (const auto& x : w) {
            (x.condition == 21 ? n21 : n22)++;
            const double mid = 0.5 * (x.b_lo + x.b_hi);
            const SuperstableCheck c = superstable_check(Parameters(1.0, mid, qa), o.fast ? 2000 : 20000);
            windows.row({qa, x.b_lo, x.b_hi, static_cast<long long>(x.condition), mid, c.epsilon, static_cast<long long>(c.hypotheses)});
            if (c.hypotheses && !(c.fixed && c.epsilon > 0)) ++not_super;
            if (c.hypotheses) eps_min = std::min(eps_min, c.epsilon);
            widest = std::max(widest, (x.b_hi - x.b_lo) / mid);
          }
          // Independent: a plain grid uniform in a/b; every point where (21) or (22) holds must lie
          // in a window of the same condition.
          long long in_cond = 0, outside = 0;
          std::size_t k = 0;
          std::vector<SuperstableWindow> sorted = w;
          for (int j = 0; j < grid_points; ++j) {
            const double r = 10.0 + 990.0 * j / (grid_points - 1);
            const double ba = 1.0 / r;
            const SuperstableCheck c = superstable_check(Parameters(1.0, ba, qa), 2);
            const int cond = c.eq21 ? 21 : (c.eq22 ? 22 : 0);
            if (cond == 0) continue;
            ++in_cond;
            bool inside = false;
            for (k = 0; k < sorted.size(); ++k)
              if (ba >= sorted[k].b_lo && ba <= sorted[k].b_hi && sorted[k].condition == cond) { inside = true; break; }
            if (!inside) ++outside;
          }
          mismatch_grid += outside;
          total += static_cast<long long>(w.size());
          smallest_eps = std::min(smallest_eps, eps_min);
          summary.row({qa, static_cast<long long>(w.size()), n21, n22, static_cast<long long>(w4.size()), in_cond, outside, eps_min, widest});
          if (qa == 0.85) {
            out.macro("ThmTwoWindowsEightyFive", std::to_string(w.size()));
            out.macro("ThmTwoWidestEightyFive", widest, 2);
          }
        }
        out.table("windows", windows, "every window of b/a in [1e-3, 0.1] where (21) or (22) holds, with epsilon at its middle");
        out.table("", summary, "per q/a: window counts, the resolution check, and the independent grid check");

        Claim thm{"thm2.superstable", "Theorem 2",
                  "In every window where the hypotheses ((2) and (22), or (21) and (23)) hold, T sends a whole interval "
                  "[t2, t2 + epsilon) to t2 (checked at each window's middle)."};
        thm.evidence.set("windows", total).set("not_superstable", not_super).set("smallest_epsilon", smallest_eps);
        thm.holds = total > 0 && not_super == 0;
        out.claim(thm);

        Claim grid{"thm2.grid_agrees", "Theorem 2 (numerics)",
                   "Every point of an independent grid where (21) or (22) holds lies inside a window found, with the same condition."};
        grid.evidence.set("grid_points_outside_windows", mismatch_grid);
        grid.holds = mismatch_grid == 0;
        out.claim(grid);

        Claim res{"thm2.windows_resolved", "Theorem 2 (numerics)", "The list of windows is unchanged when the samples are quadrupled."};
        res.evidence.set("q_values_with_a_different_count", unstable_count);
        res.holds = unstable_count == 0;
        out.claim(res);
        out.macro("ThmTwoWindows", std::to_string(total));
      });
}
