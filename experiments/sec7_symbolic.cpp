/// @file sec7_symbolic.cpp
/// @brief Section 7: every binary word of length n <= 12 is realised by an orbit through K0, K1
/// (so 2^n words), the coding H satisfies H o T = S o H along them, the entropy bound ln 2, and a
/// lap-count estimate of the topological entropy of T (entropy.hpp).
#include <algorithm>
#include <cmath>

#include "dfchaos/covering.hpp"
#include "dfchaos/entropy.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/symbolic.hpp"
#include "kit/experiment.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {
constexpr double kStepTol = 1e-10;  // |T(x_j) - x_{j+1}| along a realised word
}  // namespace

const Experiment experiment{
    .title = "Section 7: symbolic dynamics on J0, J1",
    .paper = {"Section 7"},
    .tests = {"test_symbolic", "test_entropy"},
    .options = {real("b", 0.01, "b/a (a = 1)").range(0, 0.5).recorded_as("b_over_a"),
                real("q", 0.95, "q/a").range(0, 2).recorded_as("q_over_a"),
                count("n-max", 12, "longest word length").range(1, 20).fast_value(5),
                count("lap-grid", 400000, "grid points for the lap counts of T^n").range(100, 100'000'000).fast_value(20000).unrecorded()},
    .outputs = {data("words", "binary words realised by orbits through K0, K1"),
                data("laps", "laps of T^n counted on a grid of [t2, t3) (monotonicity changes)")},
    .body = [](Run& run) {
      const double b = run.real("b"), q = run.real("q");
      const int n_max = run.count_int("n-max");
      const Parameters p(1.0, b, q);
      p.require_return_map();
      const Lemma4Covering c = lemma4_covering(p);
      if (!c.holds) throw InvalidParameter("b", "a parameter set where the covering of Lemma 4 holds (none found at " + p.describe() + ")");
      const InverseBranch g[2] = {make_inverse_branch(p, c.J0), make_inverse_branch(p, c.J1)};

      Table words({"n", "words", "realised", "max_step_residual"});
      long long missing = 0;
      double worst = 0;
      for (int n = 1; n <= n_max; ++n) {
        long long realised = 0;
        double res = 0;
        for_each_word(p, g, n, [&](const ItineraryOrbit& orb) {
          // H o T = S o H: the orbit of x0 visits K_{w_j} at step j, so T(x0) = x1 has itinerary S(w).
          if (orb.itinerary_ok && orb.max_step_residual < kStepTol) ++realised;
          res = std::max(res, orb.max_step_residual);
        });
        words.row({static_cast<long long>(n), 1LL << n, realised, res});
        missing += (1LL << n) - realised;
        worst = std::max(worst, res);
      }
      run.out.table("words", words, "binary words realised by orbits through K0, K1 at " + p.describe());

      // Lap counts of T^n on [t2, t3): monotone pieces seen on a grid (a lower count).
      Table laps({"n", "laps", "log_laps_over_n"});
      const std::vector<LapCount> counts = lap_counts(p, run.count_int("lap-grid"), run.fast() ? 2 : 3);
      for (const LapCount& l : counts) laps.row({static_cast<long long>(l.n), l.laps, l.entropy_estimate});
      run.table("laps", laps);
      const double h_est = counts.back().entropy_estimate;

      run.out.claim("sec7.all_words", "Section 7", EvidenceKind::Sampled,
                    "Every binary word of length n <= n-max is the itinerary of an orbit through K0, K1 (2^n words).")
          .parameter("b_over_a", b).parameter("q_over_a", q).parameter("n_max", n_max)
          .evidence("missing_words", missing).evidence("max_step_residual", worst)
          .holds(missing == 0);
      run.out.claim("sec7.entropy_bound", "Section 7", EvidenceKind::Sampled,
                    "Hence the topological entropy of T is at least ln 2; the lap counts of T^n give a grid estimate that must not be "
                    "below ln 2.")
          .evidence("ln2", std::log(2.0)).evidence("lap_estimate", h_est)
          .holds(missing == 0 && h_est >= std::log(2.0));
      run.out.macro("SecSevenLapEstimate", h_est, 3);
      run.out.macro("SecSevenNmax", std::to_string(n_max));
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
