// SPDX-License-Identifier: GPL-3.0-or-later
/// @file thm1_uniform_band.cpp
/// @brief Theorem 1's covering (Lemma 4) proved for *every* b/a below a bound at once, column by column
/// of q/a: the paper's construction on a segment [pi + w_a, pi + w_b] of tangencies, its inequalities
/// (I1)-(I9) proved in ball arithmetic for all b/a in (0, bound] (lemma4_uniform.hpp; the argument
/// from them to Lemma 4 is in docs/certified.md). Per column the largest bound the bounded search of
/// best_lemma4_uniform() finds is kept, with its certificate. The proof's cost does not depend on b/a.
///
/// Outputs: data/thm1_uniform_band.tsv (per column: q/a range, proved, the bound of b/a, the segment),
/// macros for the report (among them the share of the band b/a in [1e-4, 2e-3], q/a in [0.78, 0.99]
/// that the union covers), a certified claim, one certificate per proved column.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/lemma4_uniform.hpp"
#include "dfchaos/errors.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"
#include "kit/output.hpp"

using namespace dfchaos;
using namespace dfchaos::certified;
using namespace dfchaos::kit;

namespace {

/// The band against which the coverage is measured (b/a x q/a): where the sampled plane first found coverings.
constexpr double kBandBLo = 1e-4, kBandBHi = 2e-3, kBandQLo = 0.78, kBandQHi = 0.99;

}  // namespace

const Experiment experiment{
    .title = "Theorem 1 (Lemma 4) proved for every b/a below a bound, per column of q/a",
    .paper = {"Theorem 1", "Lemma 4"},
    .tests = {"test_certified"},
    // q/a below about sin(vartheta0) fails (I9) (Lemma 1), and q/a = 1 with b -> 0 puts t0 at the edge of
    // asin's domain: the columns start at 0.72 and end at 0.999.
    .options = {real("q-lo", 0.72, "lower end of the columns in q/a").range(0.05, 0.99),
                real("q-hi", 0.999, "upper end of the columns in q/a (above q-lo)").range(0.06, 0.999),
                count("columns", 28, "columns of equal width in q/a").range(1, 1000).fast_value(3)},
    .outputs = {data("", "per column of q/a: Lemma 4 proved for every b/a in (0, b_over_a_max] (proved = 1), with the segment used"),
                certificate("cert.thm1.uniform_band--*", "per proved column (cert.thm1.uniform_band--qX.XX), the lemma4-uniform certificate")},
    .body = [](Run& run) {
      Output& out = run.out;
      const double q_lo = run.real("q-lo"), q_hi = run.real("q-hi");
      const int n = run.count_int("columns");
      if (!(q_hi > q_lo)) throw InvalidParameter("q-hi", "q-hi > q-lo = " + format_double(q_lo), q_hi);
      std::vector<Lemma4UniformProof> proofs(static_cast<std::size_t>(n));
      std::vector<double> edges(static_cast<std::size_t>(n) + 1);
      for (int i = 0; i <= n; ++i) edges[static_cast<std::size_t>(i)] = i == n ? q_hi : q_lo + (q_hi - q_lo) * i / n;
#pragma omp parallel for schedule(dynamic)
      for (int i = 0; i < n; ++i)
        proofs[static_cast<std::size_t>(i)] = best_lemma4_uniform(edges[static_cast<std::size_t>(i)], edges[static_cast<std::size_t>(i) + 1]);

      Table t({"q_lo", "q_hi", "proved", "b_over_a_max", "w_lo", "w_hi", "failed_step"});
      Json cols = Json::array();
      long long proved = 0;
      double covered = 0;  // area of the band kBand* inside the union of the proved columns
      for (int i = 0; i < n; ++i) {
        const Lemma4UniformProof& p = proofs[static_cast<std::size_t>(i)];
        const double a = edges[static_cast<std::size_t>(i)], b = edges[static_cast<std::size_t>(i) + 1];
        t.row({a, b, static_cast<long long>(p.verdict.proved), p.verdict.proved ? p.eps_star : std::nan(""), p.w_a, p.w_b,
               p.verdict.proved ? std::string("") : p.verdict.step});
        cols.push(certify::to_json(1.0, p));
        if (!p.verdict.proved) continue;
        ++proved;
        char part[32];
        std::snprintf(part, sizeof part, "--q%.2f", a);
        run.certificate(std::string("cert.thm1.uniform_band") + part,
                        certify::certificate_text(certify::certificate_lemma4_uniform(1.0, p, certify::statement_lemma4_uniform(p))));
        const double qa = std::max(a, kBandQLo), qb = std::min(b, kBandQHi), bb = std::min(p.eps_star, kBandBHi);
        if (qb > qa && bb > kBandBLo) covered += (qb - qa) * (bb - kBandBLo);
      }
      run.table("", t);
      const double fraction = covered / ((kBandQHi - kBandQLo) * (kBandBHi - kBandBLo));
      out.macro("UniformColumns", std::to_string(n));
      out.macro("UniformColumnsProved", std::to_string(proved));
      out.macro("UniformBandFraction", fraction, 3);
      out.macro("UniformBandPercent", 100 * fraction, 3);
      out.macro("UniformBandBLo", latex_number(dfchaos::format_shortest(kBandBLo)));
      out.macro("UniformBandBHi", latex_number(dfchaos::format_shortest(kBandBHi)));
      out.macro("UniformBandQLo", dfchaos::format_shortest(kBandQLo));
      out.macro("UniformBandQHi", dfchaos::format_shortest(kBandQHi));
      out.macro("UniformQLo", dfchaos::format_shortest(q_lo));
      const std::string statement =
          "For every column of q/a proved in data/thm1_uniform_band.tsv and every b/a up to that column's proved bound, Lemma 4 holds, hence "
          "the covering of Theorem 1: the inequalities (I1)-(I9) of docs/certified.md are proved for all these b/a at once; the "
          "argument from them is a proof on paper.";
      auto& c = out.claim("cert.thm1.uniform_band", "Theorem 1, Lemma 4", EvidenceKind::CertifiedArgument, statement).ours();
      c.parameter_object(Json::object().set("q_over_a", Json::array().push(q_lo).push(q_hi)).set("columns", n));
      c.evidence_object(Json::object()
                            .set("columns_proved", proved)
                            .set("columns", cols)
                            .set("band", Json::object()
                                             .set("b_over_a", Json::array().push(kBandBLo).push(kBandBHi))
                                             .set("q_over_a", Json::array().push(kBandQLo).push(kBandQHi)))
                            .set("band_fraction_proved", fraction));
      if (proved == 0) c.evidence("failure", "no column was proved");
      c.holds(proved > 0);
      std::fprintf(stderr, "thm1_uniform_band: %lld of %d columns proved; %.1f%% of the band b/a in [1e-4, 2e-3] x q/a in [0.78, 0.99]\n", proved, n,
                   100 * fraction);
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
