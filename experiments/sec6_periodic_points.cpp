// SPDX-License-Identifier: GPL-3.0-or-later
/// @file sec6_periodic_points.cpp
/// @brief Section 6: for m = 1..20 a point of minimal period m with itinerary (0...01)^infinity, at a
/// parameter set where the covering of Lemma 4 holds; built by the backward (inverse-branch) form of
/// the nested segments, and checked step by step.
#include <algorithm>
#include <cmath>
#include <vector>

#include "dfchaos/errors.hpp"
#include "dfchaos/orbit.hpp"
#include "dfchaos/symbolic.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"
#include "kit/grid.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {
constexpr double kStepTol = 1e-10;      // |T(x_j) - x_{j+1}| and the literal |T^m(p) - p|
constexpr double kDistinctTol = 1e-12;  // orbit points closer than this are not distinct doubles
}  // namespace

const Experiment experiment{
    .title = "Section 6: periodic points of every period with itinerary (0..01)",
    .paper = {"Section 6", "Eq. (20)", "Theorem 1", "Lemma 4", "Section 10"},
    .tests = {"test_symbolic", "test_covering"},
    .options = {real("b", 0.01, "b/a (a = 1); below 1e-6 the orbits need more precision than the double-precision checks resolve, and the cost grows")
                    .range(1e-6, 0.5)
                    .recorded_as("b_over_a"),
                real("q", 0.95, "q/a; assumption (2) asks sin(vartheta0) < q/a < 1").range(1e-3, 1).recorded_as("q_over_a"),
                count("m-max", 20, "largest period").range(1, 200).fast_value(6)},
    .outputs = {data("", "periodic points of T with itinerary (0^(m-1) 1)^infinity"), data("orbits", "their orbits"),
                data("cobweb*", "cobweb path of the period-3 orbit (itinerary 001); only when m-max >= 3"), data("graph", "T on [t2, t3)"),
                data("segments", "the covering segments J0, J1 of Lemma 4 and the target [t2, 3pi/2] they cover"),
                data("continuity", "the ends of K0, K1 (T(K_i) = [t2, 3pi/2]) at b/a (1 + delta): how far they move"),
                latex("sec6_periodic", "per period: first point, step residual, expansion, closest points")},
    .body = [](Run& run) {
      const double b = run.real("b"), q = run.real("q");
      const int m_max = run.count_int("m-max");
      const Parameters p(1.0, b, q);
      const Lemma4Covering c = require_lemma4_covering(p);
      const InverseBranch g[2] = {make_inverse_branch(p, c.J0), make_inverse_branch(p, c.J1)};
      const double gap = std::min(std::fabs(g[1].k_at_t2 - g[0].k_at_t2), std::fabs(g[1].k_at_top - g[0].k_at_top));

      Table t({"m", "x0", "max_step_residual", "itinerary_ok", "min_separation", "log_expansion", "literal_Tm_residual"});
      Table orbits({"m", "j", "x_j", "letter"});
      Table cobweb({"x", "y"});  // the staircase (x_j, x_j) -> (x_j, x_{j+1}) of the period-3 orbit
      LatexTable tex("rrrrr", {"$m$", "$p$ (first point)", "$\\max_j|T(x_j)-x_{j+1}|$", "$\\ln|(T^m)'(p)|$", "closest points"});
      int bad = 0, separated = 0;
      double worst_res = 0;
      for (int m = 1; m <= m_max; ++m) {
        const std::string w = std::string(static_cast<std::size_t>(m - 1), '0') + "1";
        const ItineraryOrbit orb = periodic_orbit(p, g, w);
        // Literal T^m(p) - p: meaningful only while the expansion exp(log_expansion) times the
        // rounding of p stays below the step tolerance.
        double literal = NAN;
        if (orb.log_expansion + std::log(4e-16) < std::log(kStepTol)) {
          literal = std::fabs(T_power(p, orb.x[0], m) - orb.x[0]);
        }
        t.row({static_cast<long long>(m), orb.x[0], orb.max_step_residual, static_cast<long long>(orb.itinerary_ok), orb.min_separation,
               orb.log_expansion, literal});
        if (m == 3) {
          for (int j = 0; j < m; ++j) {
            const double xj = orb.x[static_cast<std::size_t>(j)], xn = orb.x[static_cast<std::size_t>((j + 1) % m)];
            cobweb.row({xj, xj}).row({xj, xn});
          }
          cobweb.row({orb.x[0], orb.x[0]});
        }
        for (int j = 0; j < m; ++j)
          orbits.row({static_cast<long long>(m), static_cast<long long>(j), orb.x[static_cast<std::size_t>(j)],
                      std::string(1, w[static_cast<std::size_t>(j)])});
        tex.row({std::to_string(m), format_significant(orb.x[0], 16), format_significant(orb.max_step_residual, 2),
                 format_significant(orb.log_expansion, 4),
                 // two points closer than kDistinctTol are not told apart in double precision
                 m == 1                              ? std::string("---")
                 : orb.min_separation > kDistinctTol ? format_significant(orb.min_separation, 2)
                                                     : std::string("unresolved")});
        if (!(orb.itinerary_ok && orb.max_step_residual < kStepTol && (std::isnan(literal) || literal < kStepTol))) ++bad;
        if (m == 1 || orb.min_separation > kDistinctTol) ++separated;
        worst_res = std::max(worst_res, orb.max_step_residual);
      }
      // For the cobweb figure: the graph of T at the same parameters (on [t2, t3): the last point
      // of the linear axis, t3, is left out), and the segments.
      Table graph({"theta", "T"});
      const double t2 = *p.t2(), t3 = *p.t3();
      const int n_graph = run.fast() ? 400 : 20000;
      const Axis theta = Axis::linear(t2, t3, n_graph + 1);
      for (int i = 0; i < n_graph; ++i) graph.row({theta[i], T(p, theta[i])});
      Table segments({"name", "lo", "hi"});
      segments.row({std::string("J0"), c.J0.lo, c.J0.hi});
      segments.row({std::string("J1"), c.J1.lo, c.J1.hi});
      segments.row({std::string("target"), t2, 1.5 * pi});
      segments.row({std::string("domain"), t2, t3});
      run.out.table("graph", graph, "T on [t2, t3) at " + p.describe());
      run.table("segments", segments);
      run.out.macro("SecSixDistinctTol", kDistinctTol, 2);
      run.out.macro("SecSixJzeroLo", c.J0.lo, 6);
      run.out.macro("SecSixJzeroHi", c.J0.hi, 6);
      run.out.macro("SecSixJoneLo", c.J1.lo, 6);
      run.out.macro("SecSixJoneHi", c.J1.hi, 6);
      run.out.macro("SecSixB", b, 6);
      run.out.macro("SecSixQ", q, 6);
      run.latex("sec6_periodic", tex.render());
      run.out.table("", t, "periodic points of T with itinerary (0^(m-1) 1)^infinity at " + p.describe());
      run.table("orbits", orbits);
      if (cobweb.rows()) run.out.table("cobweb", cobweb, "cobweb path of the period-3 orbit (itinerary 001)");

      // The Remark after Lemma 4: inside each J_i a segment K_i with T(K_i) = [t2, 3pi/2] exactly,
      // T monotone on it (the inverse branch g_i of symbolic.hpp is defined on the whole target).
      double image_error = 0;
      bool monotone = true;
      for (const InverseBranch& gi : g) {
        image_error = std::max({image_error, circle_distance(T(p, gi.k_at_t2), t2), std::fabs(T(p, gi.k_at_top) - gi.top)});
        monotone = monotone && gi.monotone;
      }
      run.out
          .claim("lemma4.remark_exact_image", "Lemma 4, Remark", EvidenceKind::Sampled,
                 "Each J_i contains a segment K_i on which T is monotone with T(K_i) = [t2, 3pi/2] exactly: T = t2 at one end, "
                 "T = 3pi/2 at the other to {tol}, monotone on a grid of K_i.")
          .evidence("end_image_error", image_error)
          .evidence("monotone_on_grid", monotone)
          .tolerance(kStepTol)
          .holds(image_error <= kStepTol && monotone);

      // Section 10: the segments can be chosen to depend continuously on the parameters. The ends of
      // K0, K1 (edges of the T = t2 arc and the preimage of 3pi/2, found by bisection) at b/a (1 + delta)
      // against those at b/a, for delta = 1e-3 ... 1e-12, starting from the same J_i (the ends move at a rate that grows like
      // a/b, so at small b/a only the smaller deltas keep K inside J).
      Table cont({"delta", "K0_t2_end", "K0_top_end", "K1_t2_end", "K1_top_end", "max_end_shift", "shift_over_delta", "K_exact"});
      cont.row({0.0, g[0].k_at_t2, g[0].k_at_top, g[1].k_at_t2, g[1].k_at_top, 0.0, NAN, 1LL});
      std::vector<double> shifts, deltas;
      for (double delta : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}) {
        const Parameters pd(1.0, b * (1 + delta), q);
        try {
          const InverseBranch h[2] = {make_inverse_branch(pd, c.J0), make_inverse_branch(pd, c.J1)};
          // The ends must still map exactly onto t2 and 3pi/2 at the new parameters: once an end of
          // K has moved out of the unperturbed J_i the search stops at J_i's end, and delta is too large.
          bool exact = true;
          for (const InverseBranch& hi : h)
            exact = exact && circle_distance(T(pd, hi.k_at_t2), *pd.t2()) <= kStepTol && std::fabs(T(pd, hi.k_at_top) - hi.top) <= kStepTol;
          const double shift = std::max({std::fabs(h[0].k_at_t2 - g[0].k_at_t2), std::fabs(h[0].k_at_top - g[0].k_at_top),
                                         std::fabs(h[1].k_at_t2 - g[1].k_at_t2), std::fabs(h[1].k_at_top - g[1].k_at_top)});
          if (exact) {
            shifts.push_back(shift);
            deltas.push_back(delta);
          }
          cont.row({delta, h[0].k_at_t2, h[0].k_at_top, h[1].k_at_t2, h[1].k_at_top, shift, shift / delta, static_cast<long long>(exact)});
        } catch (const GaveUp&) {
          cont.row({delta, NAN, NAN, NAN, NAN, NAN, NAN, 0LL});
        }
      }
      run.table("continuity", cont);
      // Continuity, as far as a finite computation shows it: over the deltas where K is still exact
      // (at least the three smallest), the shift decreases with delta, roughly in proportion
      // (shift / delta varies by less than a factor 100).
      bool cont_ok = deltas.size() >= 3;
      double ratio_lo = INFINITY, ratio_hi = 0;
      for (std::size_t k = 0; k < shifts.size(); ++k) {
        ratio_lo = std::min(ratio_lo, shifts[k] / deltas[k]);
        ratio_hi = std::max(ratio_hi, shifts[k] / deltas[k]);
        if (k > 0 && !(shifts[k] < shifts[k - 1])) cont_ok = false;
      }
      run.out.macro("SecSixContLargestDelta", deltas.empty() ? 0.0 : deltas.front(), 1);
      run.out.macro("SecSixContSmallestDelta", deltas.empty() ? 0.0 : deltas.back(), 1);
      run.out
          .claim("sec10.segments_continuous", "Section 10", EvidenceKind::Sampled,
                 "The segments K0, K1 can be chosen to depend continuously on the parameters: when b/a changes by a factor 1 + delta, "
                 "for the deltas among 1e-3 ... 1e-12 at which they still map exactly onto [t2, 3pi/2] (at least three), their ends "
                 "move less and less, roughly in proportion to delta.")
          .evidence("deltas_exact", static_cast<long long>(deltas.size()))
          .evidence("shift_over_delta_min", ratio_lo)
          .evidence("shift_over_delta_max", ratio_hi)
          .holds(cont_ok && ratio_hi < 100 * ratio_lo);

      run.out
          .claim("sec6.periodic_points", "Section 6, Eq. (20), Theorem 1", EvidenceKind::Sampled,
                 "For every period m up to the largest tried there is a periodic orbit with itinerary (0^(m-1)1)^infinity: every point lies in its "
                 "segment K_0 or K_1, and T sends each point to the next to within {tol}.")
          .parameter("b_over_a", b)
          .parameter("q_over_a", q)
          .parameter("m_max", m_max)
          .evidence("periods_checked", m_max)
          .evidence("failures", bad)
          .evidence("max_step_residual", worst_res)
          .evidence("gap_between_K0_and_K1", gap)
          .tolerance(kStepTol)
          .holds(bad == 0);
      run.out
          .claim("sec6.minimal_period", "Section 6", EvidenceKind::Sampled,
                 "Each of these orbits has minimal period m: K0 and K1 are disjoint (gap far above the residuals) and a shift of "
                 "the word 0^(m-1)1 by 0 < j < m differs from it, so T^j(p) != p.")
          .evidence("periods_checked", m_max)
          .evidence("gap_between_K0_and_K1", gap)
          .evidence("max_step_residual", worst_res)
          .holds(bad == 0 && gap > 1e3 * worst_res);
      // Not expected: the expansion |T'|^m puts the points of a long 0-run closer than double precision.
      run.out
          .claim("sec6.numerically_distinct", "Section 6 (numerics)", EvidenceKind::Sampled,
                 "The orbit points are also told apart in double precision (separation > {tol}) for every m; a period whose "
                 "points come closer is one double precision cannot decide (their minimal period separates them), not a failure.")
          .ours()
          .not_expected()
          .evidence("periods_separated", separated)
          .evidence("periods", m_max)
          .tolerance(kDistinctTol)
          .cases(m_max, 0, m_max - separated);
      run.out.macro("SecSixPeriods", std::to_string(m_max));
      run.out.macro("SecSixSeparated", std::to_string(separated));
      run.out.macro("SecSixMaxResidual", format_significant(worst_res, 2));
      run.out.macro("SecSixLogExpansionPerStep", orbits.rows() ? format_significant(periodic_orbit(p, g, "01").log_expansion / 2, 3) : "");
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
