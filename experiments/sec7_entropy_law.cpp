// SPDX-License-Identifier: GPL-3.0-or-later
/// @file sec7_entropy_law.cpp
/// @brief Section 7 beyond ln 2: the topological entropy of T bounded from both sides
/// (certified/laps.hpp) along a line of b/a at fixed q/a and along a line of q/a at fixed b/a, and
/// the law it follows as b/a -> 0.
///
/// **The bounds.** At every point prove_entropy_bracket() proves the laps of T and
/// ln rho(covering graph) <= h_top(T) <= ln rho("T(I_j) meets I_k"), refined once by preimages where
/// the gap is wide and the laps are at most kRefineLaps (the refinement costs the square of the laps).
///
/// **The law.** T has about a/(2 pi b) laps (one per branch of T1: Lemma 2's discontinuities are
/// spaced 2 pi apart in h(z) = 2z - (a/b) cos z), so h_top <= ln(a/(2 pi b)) + o(1). The entropy is
/// fitted as h = ln(a/b) - c (least squares on the midpoints of the brackets with b/a <= kFitMax,
/// the asymptotic part): c is a sampled law, each bracket is certified. The claim holds when every
/// bracket there contains ln(a/b) - c up to kLawTolerance.
///
/// Outputs: data/sec7_entropy_law.tsv (one row per point of the two lines), data/sec7_entropy_law-fit.tsv,
/// macros, a certified claim (every bracket proved, no certificate yet) and a sampled claim (the law).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dfchaos/certified/laps.hpp"
#include "dfchaos/errors.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"
#include "kit/grid.hpp"
#include "kit/output.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {

/// The law is fitted on the points with b/a at most this.
constexpr double kFitMax = 3e-3;
/// The law holds when ln(a/b) - c lies within this of every bracket with b/a <= kFitMax.
constexpr double kLawTolerance = 0.01;
/// Refinement by preimages only up to this many laps (its cost grows with their square).
constexpr long long kRefineLaps = 50;

/// One point of a line.
struct Row {
  double q = 0, b = 0;
  certified::EntropyBracket e;
};

}  // namespace

const Experiment experiment{
    .title = "Section 7: the entropy of T bounded from both sides along b/a and q/a, and its law as b/a -> 0",
    .paper = {"Section 7"},
    .tests = {"test_certified"},
    .options = {real("q", 0.85, "q/a of the line in b/a").range(0.73, 0.99),
                real("b-lo", 3e-4, "lower end of the line in b/a").range(1e-5, 0.1).fast_value(1e-3),
                real("b-hi", 0.05, "upper end of the line in b/a (above b-lo)").range(2e-5, 0.2).fast_value(3e-3),
                count("nb", 40, "values of b/a, log-spaced in [b-lo, b-hi]").range(2, 1000).fast_value(4),
                real("b", 1e-3, "b/a of the line in q/a").range(1e-5, 0.1).fast_value(0.01),
                real("q-lo", 0.73, "lower end of the line in q/a").range(0.05, 0.99),
                real("q-hi", 0.99, "upper end of the line in q/a (above q-lo)").range(0.06, 0.999),
                count("nq", 14, "values of q/a, uniform in [q-lo, q-hi]").range(2, 1000).fast_value(3)},
    .outputs = {data("", "the bounds of h_top(T) at each point of the two lines (line = b: along b/a; line = q: along q/a)"),
                data("fit", "the law h = ln(a/b) - c fitted on the line in b/a")},
    .body = [](Run& run) {
      Output& out = run.out;
      const double q = run.real("q"), b_lo = run.real("b-lo"), b_hi = run.real("b-hi"), b_q = run.real("b");
      const double q_lo = run.real("q-lo"), q_hi = run.real("q-hi");
      if (!(b_hi > b_lo)) throw InvalidParameter("b-hi", "b-hi > b-lo = " + format_double(b_lo), b_hi);
      if (!(q_hi > q_lo)) throw InvalidParameter("q-hi", "q-hi > q-lo = " + format_double(q_lo), q_hi);
      const Axis bs = Axis::log(b_lo, b_hi, run.count_int("nb")), qs = Axis::linear(q_lo, q_hi, run.count_int("nq"));
      std::vector<Row> rows;
      for (int i = 0; i < bs.size(); ++i) rows.push_back({q, bs[i], {}});
      const std::size_t along_b = rows.size();
      for (int i = 0; i < qs.size(); ++i) rows.push_back({qs[i], b_q, {}});
      // Each bracket runs on all threads (its parts in parallel); the points one after the other.
      certified::LapOptions opt;
      opt.max_refined = kRefineLaps * kRefineLaps;
      for (Row& r : rows) r.e = certified::prove_entropy_bracket(1.0, r.b, r.q, opt);

      Table t({"line", "q_over_a", "b_over_a", "proved", "laps", "refined_pieces", "h_lower", "h_upper", "log_a_over_b", "log_a_over_2pi_b",
               "failed_step"});
      long long proved = 0, above_ln2 = 0;
      std::vector<double> x, y;  // ln(a/b), midpoint, on the fitted part
      for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        const bool ok = r.e.verdict.proved;
        proved += ok ? 1 : 0;
        above_ln2 += ok && r.e.h_lower() > std::log(2.0) ? 1 : 0;
        const double L = std::log(1.0 / r.b);
        t.row({std::string(k < along_b ? "b" : "q"), r.q, r.b, static_cast<long long>(ok), static_cast<long long>(r.e.partition.laps.size()),
               r.e.refined_pieces, ok ? r.e.h_lower() : NAN, ok ? r.e.h_upper() : NAN, L, std::log(1.0 / (2 * M_PI * r.b)),
               ok ? std::string("-") : r.e.verdict.step});
        if (k < along_b && ok && r.b <= kFitMax) x.push_back(L), y.push_back(0.5 * (r.e.h_lower() + r.e.h_upper()));
      }
      run.table("", t);
      // h = L - c: c is the mean of L - h over the fitted part.
      double c = NAN, worst = 0;
      if (!x.empty()) {
        c = 0;
        for (std::size_t i = 0; i < x.size(); ++i) c += x[i] - y[i];
        c /= static_cast<double>(x.size());
        for (std::size_t k = 0; k < along_b; ++k) {
          const Row& r = rows[k];
          if (!r.e.verdict.proved || r.b > kFitMax) continue;
          const double law = std::log(1.0 / r.b) - c;
          worst = std::max({worst, r.e.h_lower() - law, law - r.e.h_upper()});
        }
      }
      Table fit({"quantity", "c", "points", "b_over_a_max", "worst_distance", "log_3pi"});
      fit.row({std::string("log_a_over_b_minus_h"), c, static_cast<long long>(x.size()), kFitMax, worst, std::log(3 * M_PI)});
      run.table("fit", fit);

      out.macro("LawQ", format_shortest(q));
      out.macro("LawBLo", latex_number(format_shortest(b_lo)));
      out.macro("LawBHi", latex_number(format_shortest(b_hi)));
      out.macro("LawB", latex_number(format_shortest(b_q)));
      out.macro("LawQLo", format_shortest(q_lo));
      out.macro("LawQHi", format_shortest(q_hi));
      out.macro("LawPoints", std::to_string(rows.size()));
      out.macro("LawProved", std::to_string(proved));
      out.macro("LawFitMax", latex_number(format_shortest(kFitMax)));
      out.macro("LawFitPoints", std::to_string(x.size()));
      out.macro("LawC", std::isfinite(c) ? format_significant(c, 4) : std::string("--"));
      out.macro("LawWorst", latex_number(format_significant(worst, 2)));
      out.macro("LawTolerance", format_shortest(kLawTolerance));
      out.macro("LawLogThreePi", format_significant(std::log(3 * M_PI), 4));

      // The points where the laps are not proved are named with their failed step in the data; at
      // the known ones the progression's velocity touches zero at t0 (a jump of theta2 the cells do
      // not handle, certified/laps.hpp).
      long long ordered = 0;
      for (const Row& r : rows) ordered += r.e.verdict.proved && r.e.h_lower() <= r.e.h_upper() ? 1 : 0;
      out.claim("cert.sec7.entropy_law_points", "Section 7", EvidenceKind::Certified,
                "Both bounds of h_top(T) proved at " + std::to_string(proved) + " of " + std::to_string(rows.size()) + " points of the two lines.")
          .ours()
          .evidence("points", static_cast<long long>(rows.size()))
          .evidence("proved", proved)
          .evidence("lower_above_ln2", above_ln2)
          .evidence("ordered", ordered)
          .holds(proved > 0 && ordered == proved);
      out.claim("sec7.entropy_law", "Section 7", EvidenceKind::Sampled,
                "For b/a <= " + format_shortest(kFitMax) + " at q/a = " + format_shortest(q) + ", ln(a/b) - c (c fitted) lies within " +
                    format_shortest(kLawTolerance) + " of every certified bracket of h_top(T).")
          .ours()
          .evidence("c", c)
          .evidence("fitted_points", static_cast<long long>(x.size()))
          .evidence("worst_distance", worst)
          .evidence("log_3pi", std::log(3 * M_PI))
          .holds(x.size() >= 3 && worst <= kLawTolerance);
      std::fprintf(stderr, "sec7_entropy_law: %lld of %zu brackets proved; c = %.4f (worst distance %.3g)\n", proved, rows.size(), c, worst);
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
