// SPDX-License-Identifier: GPL-3.0-or-later
/// @file sec7_symbolic.cpp
/// @brief Section 7: every binary word of length n <= 12 is realised by an orbit through K0, K1
/// (so 2^n words), the coding H satisfies H o T = S o H along them, hence the entropy bound ln 2.
/// The entropy itself is bounded from both sides in certified_claims (certified/laps.hpp).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "dfchaos/covering.hpp"
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
    .tests = {"test_symbolic"},
    .options = {real("b", 0.01, "b/a (a = 1); below 1e-6 the orbits need more precision than the double-precision checks resolve, and the cost grows")
                    .range(1e-6, 0.5)
                    .recorded_as("b_over_a"),
                real("q", 0.95, "q/a; assumption (2) asks sin(vartheta0) < q/a < 1").range(1e-3, 1).recorded_as("q_over_a"),
                count("n-max", 12, "longest word length").range(1, 20).fast_value(5)},
    .outputs = {data("words", "binary words realised by orbits through K0, K1"),
                data("cylinders", "the widest cylinder J_w = {x : itinerary starts with w} per word length")},
    .body = [](Run& run) {
      const double b = run.real("b"), q = run.real("q");
      const int n_max = run.count_int("n-max");
      const Parameters p(1.0, b, q);
      const Lemma4Covering c = require_lemma4_covering(p);
      const InverseBranch g[2] = {make_inverse_branch(p, c.J0), make_inverse_branch(p, c.J1)};

      // A word is realised when its orbit stays in K_{w_j} with one-step residuals below kStepTol;
      // undecided (precision) when a residual exceeds kStepTol but not what double precision alone
      // produces along that orbit (|T'| times the ulps of the points: ItineraryOrbit::precision_floor);
      // missing otherwise.
      Table words({"n", "words", "realised", "undecided_precision", "max_step_residual", "max_precision_floor"});
      long long missing = 0, undecided = 0;
      double worst = 0, worst_floor = 0;
      for (int n = 1; n <= n_max; ++n) {
        long long realised = 0, undecided_n = 0;
        double res = 0, floor_n = 0;
        for_each_word(p, g, n, [&](const ItineraryOrbit& orb) {
          // H o T = S o H: the orbit of x0 visits K_{w_j} at step j, so T(x0) = x1 has itinerary S(w).
          if (orb.itinerary_ok && orb.max_step_residual < kStepTol)
            ++realised;
          else if (orb.itinerary_ok && orb.max_step_residual <= orb.precision_floor)
            ++undecided_n;
          res = std::max(res, orb.max_step_residual);
          floor_n = std::max(floor_n, orb.precision_floor);
        });
        words.row({static_cast<long long>(n), 1LL << n, realised, undecided_n, res, floor_n});
        missing += (1LL << n) - realised - undecided_n;
        undecided += undecided_n;
        worst = std::max(worst, res);
        worst_floor = std::max(worst_floor, floor_n);
      }
      run.out.table("words", words, "binary words realised by orbits through K0, K1 at " + p.describe());

      // Continuity of the coding H (Section 7): the points whose itineraries begin with a word w form
      // the cylinder g_{w_0} o ... o g_{w_{k-1}}([t2, 3pi/2]); H is continuous on J when the widest
      // cylinder of length k shrinks to 0 as k grows (nearby points share long itinerary prefixes).
      Table cyl({"k", "widest_cylinder", "ratio_to_previous"});
      const int k_max = std::min(n_max, run.fast() ? 4 : 8);
      std::vector<double> widest(static_cast<std::size_t>(k_max) + 1, 0.0);
      auto descend = [&](auto&& self, int depth, double lo, double hi) -> void {
        if (depth > 0) widest[static_cast<std::size_t>(depth)] = std::max(widest[static_cast<std::size_t>(depth)], std::fabs(hi - lo));
        if (depth == k_max) return;
        for (const InverseBranch& gi : g) self(self, depth + 1, inverse(p, gi, lo), inverse(p, gi, hi));
      };
      // Words are applied from their last letter inwards: descending prepends letters, which
      // enumerates the same set of cylinders.
      descend(descend, 0, *p.t2(), g[0].top);
      // A width below a few dozen ulps of the phases is the resolution of the inverse branches, not
      // the width of a cylinder: ratios are taken only between resolved widths. At small b/a the
      // cylinders fall below that resolution within a few letters; with fewer than two resolved
      // ratios double precision cannot decide the claim (inconclusive, never fails).
      const double resolution = 64 * DBL_EPSILON * p.t3_required();
      bool shrinking = true;
      double worst_ratio = 0;
      int resolved_ratios = 0, k_resolved = 0;
      for (int k = 1; k <= k_max; ++k) {
        const double wk = widest[static_cast<std::size_t>(k)], wprev = widest[static_cast<std::size_t>(k - 1)];
        const bool resolved = k > 1 && wk > resolution && wprev > resolution;
        const double r = resolved ? wk / wprev : NAN;
        if (resolved) {
          ++resolved_ratios;
          k_resolved = k;
          worst_ratio = std::max(worst_ratio, r);
          if (!(r < 1)) shrinking = false;
        }
        cyl.row({static_cast<long long>(k), wk, r});
      }
      run.table("cylinders", cyl);
      run.out.macro("SecSevenCylinderShrink", worst_ratio > 0 ? 1.0 / worst_ratio : 0.0, 2);
      auto& coding = run.out
                         .claim("sec7.coding_continuous", "Section 7", EvidenceKind::Sampled,
                                "The coding H is continuous on J: the widest set of points sharing an itinerary prefix of length k shrinks, with "
                                "each added letter, to at most {tol} of its width (k up to 8), so nearby points of J share long prefixes.")
                         .evidence("widest_ratio", worst_ratio)
                         .evidence("k_max", k_max)
                         .evidence("widest_at_k_max", widest[static_cast<std::size_t>(k_max)])
                         .evidence("resolution", resolution)
                         .evidence("resolved_ratios", resolved_ratios)
                         .evidence("k_resolved", k_resolved)
                         .tolerance(0.5);
      if (resolved_ratios < 2)
        coding.inconclusive("only " + std::to_string(resolved_ratios) + " ratio(s) of cylinder widths lie above the resolution " +
                            format_double(resolution) + " of the inverse branches in double precision");
      else
        coding.holds(shrinking && worst_ratio <= 0.5);

      const std::string why = std::to_string(undecided) + " words have one-step residuals above " + format_double(kStepTol) +
                              " but below what double precision resolves along their orbits (up to " + format_double(worst_floor) + ")";
      auto& all =
          run.out.claim("sec7.all_words", "Section 7", EvidenceKind::Sampled,
                        "Every binary word of length n, up to the largest length tried, is the itinerary of an orbit through K0, K1 (2^n words).");
      all.parameter("b_over_a", b)
          .parameter("q_over_a", q)
          .parameter("n_max", n_max)
          .evidence("missing_words", missing)
          .evidence("undecided_words", undecided)
          .evidence("max_step_residual", worst)
          .evidence("max_precision_floor", worst_floor)
          .evidence("words_checked", (1LL << (n_max + 1)) - 2);
      if (missing == 0 && undecided > 0) all.inconclusive(why);
      all.holds(missing == 0);
      run.out.macro("SecSevenNmax", std::to_string(n_max));
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
