/// @file thm2_superstable.cpp
/// @brief Theorem 2 (Section 8): where conditions (21) or (22) hold, t2 is a superstable fixed point
/// of T. All superstable windows of b/a in [1e-3, 0.1] at fixed q/a, each with its width epsilon.
#include <cmath>

#include "dfchaos/superstable.hpp"
#include "harness.hpp"

using namespace dfchaos;

int main(int argc, char** argv) {
  int nb = 40000;
  std::vector<double> qas{0.85, 0.95, 0.6};
  return experiments::run(
      argc, argv, "thm2_superstable", "Theorem 2: superstable fixed point t2, windows in b/a",
      [&](CLI::App& app) {
        app.add_option("--nb", nb, "grid points of b/a in [1e-3, 0.1], uniform in a/b");
        app.add_option("--q", qas, "values of q/a");
      },
      [&](const experiments::Options& o, ExperimentOutput& out) {
        if (o.fast) nb = std::min(nb, 400);
        if (nb < 2 || nb > 1'000'000) throw InvalidParameter("nb", "2 <= nb <= 10^6", nb);
        for (double q : qas) experiments::require_range("q", q, 1e-6, 1.0 - 1e-12);
        out.parameter("nb", std::to_string(nb));
        Table grid({"q_over_a", "b_over_a", "theta2_phase", "eq21", "eq22", "hypotheses", "fixed", "epsilon", "impact_velocity", "dG2"});
        Table windows({"q_over_a", "b_lo", "b_hi", "condition", "b_mid", "epsilon_mid", "grid_points"});
        long long half_grid_windows = 0;
        long long hyp_points = 0, hyp_not_superstable = 0, degenerate = 0, fixed_without_hyp = 0, n_windows = 0;
        double min_eps = INFINITY;
        // Uniform in a/b from 1000 to 10: the windows recur with period about 2 pi / |cos t2| in a/b
        // (the phase of T1(t2) ~ (a/b)|cos t2| turns once per period), so this spacing resolves each.
        auto ba_at = [&](int j) { return 1.0 / (1000.0 - 990.0 * static_cast<double>(j) / (nb - 1)); };
        for (double qa : qas) {
          int start = -1;
          std::string cond, half_cond;
          auto condition_of = [&](const SuperstableCheck& c) { return c.eq21 ? "(21)" : (c.eq22 ? "(22)" : ""); };
          auto close_window = [&](int end_excl) {
            if (start < 0) return;
            // Refine both ends by bisection on the condition.
            auto holds = [&](double ba) {
              const SuperstableCheck c = superstable_check(Parameters(1.0, ba, qa), 200);
              return std::string(condition_of(c)) == cond;
            };
            auto refine = [&](double in, double outside) {
              for (int k = 0; k < 50; ++k) {
                const double m = 0.5 * (in + outside);
                if (holds(m)) in = m; else outside = m;
              }
              return in;
            };
            const double lo = start > 0 ? refine(ba_at(start), ba_at(start - 1)) : ba_at(0);
            const double hi = end_excl < nb ? refine(ba_at(end_excl - 1), ba_at(end_excl)) : ba_at(nb - 1);
            const double mid = std::sqrt(lo * hi);
            const SuperstableCheck cm = superstable_check(Parameters(1.0, mid, qa));
            windows.row({qa, lo, hi, cond, mid, cm.epsilon, static_cast<long long>(end_excl - start)});
            ++n_windows;
            start = -1;
          };
          for (int j = 0; j < nb; ++j) {
            const double ba = ba_at(j);
            const Parameters p(1.0, ba, qa);
            if (!(qa > 2 * ba)) { close_window(j); continue; }
            const SuperstableCheck c = superstable_check(p, o.fast ? 2000 : 20000);
            grid.row({qa, ba, c.theta2_phase, static_cast<long long>(c.eq21), static_cast<long long>(c.eq22),
                      static_cast<long long>(c.hypotheses), static_cast<long long>(c.fixed), c.epsilon, c.impact_velocity, c.dG2});
            if (c.hypotheses) {
              ++hyp_points;
              if (!(c.fixed && c.epsilon > 0)) ++hyp_not_superstable;
              else min_eps = std::min(min_eps, c.epsilon);
              if (!c.nondegenerate) ++degenerate;
            } else if (c.fixed && c.epsilon > 0) {
              ++fixed_without_hyp;
            }
            const std::string cc = condition_of(c);
            if (j % 2 == 0) {  // the same scan on every other point: does the window count change?
              if (!cc.empty() && cc != half_cond) ++half_grid_windows;
              half_cond = cc;
            }
            if (cc != cond || cc.empty()) close_window(j);
            if (!cc.empty() && start < 0) { start = j; cond = cc; }
          }
          close_window(nb);
        }
        out.table("grid", grid, "Theorem 2 at each grid point");
        out.table("windows", windows, "maximal windows of b/a where (21) or (22) holds, ends refined by bisection");

        Claim thm{"thm2.superstable", "Theorem 2",
                  "Wherever (2) and (22), or (21) and (23), hold on the grid, T sends a whole interval [t2, t2 + epsilon) to t2."};
        thm.evidence.set("grid_points_with_hypotheses", hyp_points).set("not_superstable", hyp_not_superstable)
            .set("smallest_epsilon", min_eps);
        thm.holds = hyp_points > 0 && hyp_not_superstable == 0;
        out.claim(thm);

        Claim nd{"thm2.nondegenerate", "Section 8", "At every grid point with the hypotheses, both roots are simple (robustness)."};
        nd.evidence.set("degenerate_points", degenerate);
        nd.holds = degenerate == 0;
        out.claim(nd);

        Claim only{"thm2.only_by_hypotheses", "Theorem 2 (converse, beyond)",
                   "On the grid, t2 is superstable only where (21) or (22) holds."};
        only.evidence.set("superstable_without_conditions", fixed_without_hyp);
        only.holds = fixed_without_hyp == 0;
        only.expected = false;
        out.claim(only);
        out.macro("ThmTwoWindows", std::to_string(n_windows));
        Claim res{"thm2.windows_resolved", "Theorem 2 (numerics)",
                  "The window count is converged: using every other grid point finds at least 95% as many windows."};
        res.evidence.set("windows", n_windows).set("windows_on_half_grid", half_grid_windows);
        res.holds = static_cast<double>(half_grid_windows) >= 0.95 * static_cast<double>(n_windows);
        res.expected = false;
        out.claim(res);
      });
}
