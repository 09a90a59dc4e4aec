/// @file lemma1_progression_stop.cpp
/// @brief Lemma 1: a progression from rest at \f$t_0\f$ stops in \f$[t_1, t_2]\f$ when \f$b < b_0(q)\f$.
/// Measures \f$b_0(q)\f$ on a grid, beside the proof's sufficient condition and the threshold
/// \f$q = a\sin\vartheta_0\f$, and says what happens below the threshold (Scenario D).
#include <algorithm>
#include <cmath>

#include "dfchaos/progression_stop.hpp"
#include "harness.hpp"

using namespace dfchaos;

int main(int argc, char** argv) {
  int nq = 400, nb = 241;
  double ba_min = 1e-5;
  return experiments::run(
      argc, argv, "lemma1_progression_stop", "Lemma 1: where the progression from rest at t0 stops",
      [&](experiments::OptionSet& app) {
        app.add_option("--nq", nq, "grid points of q/a in (0, 1)");
        app.add_option("--nb", nb, "grid points of b/a, log-spaced in [ba-min, 0.49]");
        app.add_option("--ba-min", ba_min, "smallest b/a");
      },
      [&](const experiments::Options& o, ExperimentOutput& out) {
        experiments::require_count("nq", nq, 2, 100000);
        experiments::require_count("nb", nb, 2, 100000);
        experiments::require_range("ba-min", ba_min, 1e-9, 0.1);
        if (o.fast) { nq = std::min(nq, 20); nb = std::min(nb, 13); }
        out.parameter("nq", std::to_string(nq));
        out.parameter("nb", std::to_string(nb));
        out.parameter("ba_min", ba_min);
        const double s0 = std::sin(vartheta0());
        auto ba_at = [&](int j) { return ba_min * std::pow(0.49 / ba_min, static_cast<double>(j) / (nb - 1)); };

        Table curve({"q_over_a", "b0_lemma1", "b0_proof_bound", "holds_at_smallest_b", "outcome_at_smallest_b"});
        Table grid({"q_over_a", "b_over_a", "lemma1_holds", "eq8_velocity_at_t2", "proof_bound", "t4", "next"});
        int mismatch_eq8 = 0, bound_without_lemma = 0, above_threshold_fail = 0, below_threshold_hold = 0, non_interval = 0;
        int n_above = 0;
        double worst_margin = INFINITY;
        for (int i = 0; i < nq; ++i) {
          const double qa = (i + 0.5) / nq;
          double b0 = 0, b0_bound = 0;
          bool still = true, still_bound = true, seen_fail = false;
          std::string outcome_small;
          bool holds_small = false;
          for (int j = 0; j < nb; ++j) {
            const double ba = ba_at(j);
            if (!(qa > 2 * ba) || !(std::fabs(qa - 2 * ba) < 1)) { still = still_bound = false; continue; }
            const Parameters p(1.0, ba, qa);
            const ProgressionFromT0 r = progression_from_t0(p);
            // Second method: the sign of Eq. (8) must agree with the root search.
            if ((r.eq8_velocity_at_t2 <= 0) != r.stops_in_t1_t2) ++mismatch_eq8;
            if (r.proof_bound && !r.stops_in_t1_t2) ++bound_without_lemma;
            if (r.stops_in_t1_t2 && seen_fail) ++non_interval;
            if (!r.stops_in_t1_t2) seen_fail = true;
            if (still && r.stops_in_t1_t2) b0 = ba; else still = false;
            if (still_bound && r.proof_bound) b0_bound = ba; else still_bound = false;
            if (j == 0) {
              holds_small = r.stops_in_t1_t2;
              outcome_small = r.stops_in_t1_t2 ? "stops in [t1,t2]" : (r.next == Regime::Free ? "flies from [t2,t3): scenario D" : "stops again: repeats for ever");
            }
            if (i % std::max(1, nq / 40) == 0)
              grid.row({qa, ba, static_cast<long long>(r.stops_in_t1_t2), r.eq8_velocity_at_t2, r.proof_bound_value, r.t4_value,
                        std::string(r.repeats_for_ever ? "repeats" : regime_code(r.next))});
          }
          if (qa > s0) {
            ++n_above;
            if (!holds_small) ++above_threshold_fail;
            else worst_margin = std::min(worst_margin, qa - s0);
          } else if (holds_small) {
            ++below_threshold_hold;
          }
          // Refine both thresholds by bisection between the last grid point that holds and the next.
          auto refine = [&](double lo, auto pred) {
            if (lo <= 0) return 0.0;
            double hi = lo * std::pow(0.49 / ba_min, 1.0 / (nb - 1));
            if (!(qa > 2 * hi) || pred(Parameters(1.0, hi, qa))) return lo;
            for (int k = 0; k < 60; ++k) {
              const double mid = 0.5 * (lo + hi);
              if (pred(Parameters(1.0, mid, qa))) lo = mid; else hi = mid;
            }
            return lo;
          };
          b0 = refine(b0, [](const Parameters& p) { return progression_from_t0(p).stops_in_t1_t2; });
          b0_bound = refine(b0_bound, [](const Parameters& p) { return progression_from_t0(p).proof_bound; });
          curve.row({qa, b0, b0_bound, static_cast<long long>(holds_small), outcome_small});
        }
        out.table("", curve, "per q/a: largest grid b/a below which Lemma 1 holds at every grid point, and the same for the proof's bound");
        out.table("grid", grid, "Lemma 1 on a (q/a, b/a) grid (every few q/a)");

        Claim agree{"lemma1.eq8_agrees", "Lemma 1, Eq. (8)", "The sign of the velocity at t2 (Eq. 8) and the root search agree on whether the progression stops by t2."};
        agree.evidence.set("mismatches", mismatch_eq8);
        agree.holds = mismatch_eq8 == 0;
        out.claim(agree);

        Claim bound{"lemma1.proof_bound_sufficient", "Lemma 1, proof",
                    "Wherever the proof's bound a + a cos t0 - (q-2b)(pi - t0) < 0 holds, the progression does stop in [t1, t2]."};
        bound.evidence.set("violations", bound_without_lemma);
        bound.holds = bound_without_lemma == 0;
        out.claim(bound);

        Claim small{"lemma1.small_b", "Lemma 1",
                    "For every grid q/a above sin(vartheta0), the progression from rest at t0 stops in [t1, t2] at the smallest b/a of the grid."};
        small.parameters.set("b_over_a", ba_min);
        small.evidence.set("q_points_above_threshold", n_above).set("failures", above_threshold_fail);
        small.holds = above_threshold_fail == 0;
        out.claim(small);

        Claim sharp{"lemma1.threshold_sharp", "Lemma 1, Eq. (9)",
                    "Below q/a = sin(vartheta0) Lemma 1 fails even for the smallest b/a: the threshold of (2) is sharp for this step of the proof."};
        sharp.evidence.set("q_points_below_threshold_where_it_holds", below_threshold_hold);
        sharp.holds = below_threshold_hold == 0;
        sharp.expected = false;
        out.claim(sharp);

        Claim interval{"lemma1.b0_interval", "Lemma 1",
                       "At each q/a the b/a where Lemma 1 holds form an initial interval (0, b0): it never holds again above a failure."};
        interval.evidence.set("reentries", non_interval);
        interval.holds = non_interval == 0;
        interval.expected = false;
        out.claim(interval);

        // b0 at selected q/a, for the report.
        std::string tex = "\\begin{tabular}{rrrr}\n\\toprule\n$q/a$ & $b_0/a$ (Lemma 1) & $b_0/a$ (proof's bound) & ratio\\\\\n\\midrule\n";
        double ratio_min = INFINITY, ratio_max = 0;  // b0 over the proof's bound, over the rows
        for (double qa : {0.73, 0.75, 0.8, 0.85, 0.9, 0.95, 0.99}) {
          auto thr = [&](auto pred) {
            double lo = 0, hi = std::min(0.49, qa / 2);
            if (!pred(Parameters(1.0, ba_min, qa))) return 0.0;
            lo = ba_min;
            for (int k = 0; k < 60; ++k) {
              const double mid = 0.5 * (lo + hi);
              if (mid < qa / 2 && pred(Parameters(1.0, mid, qa))) lo = mid; else hi = mid;
            }
            return lo;
          };
          const double b0 = thr([](const Parameters& p) { return progression_from_t0(p).stops_in_t1_t2; });
          const double bb = thr([](const Parameters& p) { return progression_from_t0(p).proof_bound; });
          tex += format_significant(qa, 3) + " & " + format_significant(b0, 4) + " & " + format_significant(bb, 4) + " & " +
                 (bb > 0 ? format_significant(b0 / bb, 3) : std::string("---")) + "\\\\\n";
          if (bb > 0) {
            ratio_min = std::min(ratio_min, b0 / bb);
            ratio_max = std::max(ratio_max, b0 / bb);
          }
          if (qa == 0.85) { out.macro("LemmaOneBzeroAtEightyFive", b0, 4); out.macro("LemmaOneBoundAtEightyFive", bb, 4); }
        }
        tex += "\\bottomrule\n\\end{tabular}\n";
        out.latex("lemma1_b0", tex);
        out.macro("LemmaOneRatioMin", ratio_min, 3);
        out.macro("LemmaOneRatioMax", ratio_max, 3);
        out.macro("LemmaOneBaMin", ba_min, 3);
        out.macro("LemmaOneThreshold", s0, 6);
        out.macro("LemmaOneReentries", std::to_string(non_interval));
      });
}
