// SPDX-License-Identifier: GPL-3.0-or-later
/// @file certified_region.cpp
/// @brief Theorem 1's covering (Lemma 4) proved over parameter *boxes*:
/// every box of the output is a set of (b/a, q/a) on which, for every parameter, two disjoint
/// certified covering segments J0, J1 exist (the same for the whole box). The band is tiled column by
/// column in q/a, upwards in b/a, with boxes of width about c (b/a)^2 (certified_region in
/// region.hpp). The work is bounded by a number of boxes, so the output is deterministic; the
/// default band is small enough for `make reproduce`, `make certify-band` tiles a larger one.
///
/// Outputs: data/certified_region.tsv (one row per box: proved or not, with the failed step; for a
/// proved box the candidate ends of J0 and J1, with which `dfchaos certify covering --J0 --J1`
/// re-proves that box alone),
/// data/certified_region-columns.tsv (per column: how far it got), macros for the report, a claim
/// with evidence_kind "certified", and the timing in the claims file and bench/certified-region-timing.tex.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <string>
#include <vector>

#include "certify/certificate.hpp"
#include "dfchaos/certified/region.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"
#include "kit/output.hpp"

using namespace dfchaos;
using namespace dfchaos::certified;
using namespace dfchaos::kit;

const Experiment experiment{
    .title = "Theorem 1 (Lemma 4) proved over boxes of parameters",
    .paper = {"Theorem 1", "Lemma 4"},
    .tests = {"test_certified"},
    .options = {real("b-lo", 1.95e-3, "lower end of the band in b/a").range(1e-7, 0.2),
                real("b-hi", 2e-3, "upper end of the band in b/a (above b-lo)").range(1e-7, 0.2),
                real("q-lo", 0.76, "lower end of the band in q/a").range(0.5, 0.999),
                real("q-hi", 0.99, "upper end of the band in q/a (above q-lo)").range(0.5, 0.999),
                count("columns", 23, "columns of equal width in q/a").range(1, 10000).fast_value(2),
                count("max-boxes", 12000, "box proofs attempted in total (bounds the work)").range(1, 100'000'000).fast_value(20),
                count("certificates", 1, "1: write a certificate per column (about 20 kB a proved box); 0: none").range(0, 1)},
    .outputs = {data("", "boxes of (q/a, b/a) on which Lemma 4 is proved for every parameter (proved = 1), or not (failed_step)"),
                data("columns", "how far each column of q/a got in b/a within the box budget"),
                certificate("cert.thm1.region--*",
                            "per column of q/a with a proved box (cert.thm1.region--columnNN), the covering "
                            "certificate of every proved box (statement coverings, docs/certificates.md)")},
    .body = [](Run& run) {
      Output& out = run.out;
      RegionOptions r;
      r.b_lo = run.real("b-lo");
      r.b_hi = run.real("b-hi");
      r.q_lo = run.real("q-lo");
      r.q_hi = run.real("q-hi");
      r.q_columns = run.count_int("columns");
      const long long max_boxes = run.count("max-boxes");
      if (!(r.b_hi > r.b_lo)) throw InvalidParameter("b-hi", "b-hi > b-lo = " + format_double(r.b_lo), r.b_hi);
      if (!(r.q_hi > r.q_lo)) throw InvalidParameter("q-hi", "q-hi > q-lo = " + format_double(r.q_lo), r.q_hi);
      r.max_boxes = max_boxes;
      r.progress = true;
      // Each proved box's certificate, as compact text, kept by column (a box's proof is dropped once written).
      std::vector<std::vector<std::string>> certificates(static_cast<std::size_t>(r.q_columns));
      ProvedBoxSink sink;
      if (run.count("certificates") == 1)
        sink = [&](std::size_t column, const RegionBox&, const CoveringProof& p) { certificates[column].push_back(certify::covering_box_text(p)); };
      const RegionResult res = certify_region(r, sink);
      const std::string statement =
          "For every (b/a, q/a) in the union of the proved boxes of data/certified_region.tsv (a = 1), two disjoint closed segments "
          "J0, J1 of [t2, 3pi/2] (the same for the whole box) carry T continuously onto a set containing [t2, 3pi/2]: the covering of "
          "Lemma 4, hence the chaos of Theorem 1, for every parameter of those boxes.";
      for (std::size_t i = 0; i < res.columns.size(); ++i) {
        if (certificates[i].empty()) continue;
        char part[32];
        std::snprintf(part, sizeof part, "--column%02zu", i + 1);
        const RegionColumn& col = res.columns[i];
        run.certificate(std::string("cert.thm1.region") + part,
                        certify::certificate_coverings_text(r.a, {r.b_lo, r.b_hi}, {col.q_lo, col.q_hi}, certificates[i], statement));
        std::vector<std::string>().swap(certificates[i]);
      }

      Table boxes({"q_lo", "q_hi", "b_lo", "b_hi", "proved", "sub_boxes", "failed_step", "J0_top", "J0_t2", "J1_top", "J1_t2"});
      Table cols({"q_lo", "q_hi", "b_reached", "proved_fraction_of_band", "boxes_proved", "boxes_failed"});
      double proved_area = 0, band_area = (r.b_hi - r.b_lo) * (r.q_hi - r.q_lo);
      Json per_column = Json::array();
      std::vector<double> widths;  // width of each proved box in b/a, over (b/a)^2 at its middle
      for (const auto& c : res.columns) {
        long long np = 0, nf = 0;
        for (const auto& b : c.boxes) {
          const double nan = std::nan("");  // a box not proved has no segments
          boxes.row({b.q_lo, b.q_hi, b.b_lo, b.b_hi, static_cast<long long>(b.proved), static_cast<long long>(b.sub_boxes), b.failed_step,
                     b.proved ? b.J0.theta_top : nan, b.proved ? b.J0.theta_t2 : nan, b.proved ? b.J1.theta_top : nan,
                     b.proved ? b.J1.theta_t2 : nan});
          (b.proved ? np : nf)++;
          if (b.proved) widths.push_back((b.b_hi - b.b_lo) / std::pow(0.5 * (b.b_lo + b.b_hi), 2));
        }
        proved_area += c.proved_length * (c.q_hi - c.q_lo);
        cols.row({c.q_lo, c.q_hi, c.b_reached, c.proved_length / (r.b_hi - r.b_lo), np, nf});
        per_column.push(Json::object().set("q", Json::array().push(c.q_lo).push(c.q_hi)).set("b_reached", c.b_reached).set("seconds", c.seconds));
      }
      run.table("", boxes);
      run.table("columns", cols);
      const double fraction = proved_area / band_area;
      out.macro("RegionBLo", r.b_lo, 4);
      out.macro("RegionBHi", r.b_hi, 4);
      out.macro("RegionQLo", r.q_lo, 4);
      out.macro("RegionQHi", r.q_hi, 4);
      out.macro("RegionColumns", std::to_string(r.q_columns));
      out.macro("RegionBoxesProved", std::to_string(res.boxes_proved));
      out.macro("RegionBoxesFailed", std::to_string(res.boxes_failed));
      out.macro("RegionProvedFraction", fraction, 3);
      out.macro("RegionComplete", res.complete ? "yes" : "no");
      if (!widths.empty()) {  // the median width of a proved box, in units of (b/a)^2
        std::nth_element(widths.begin(), widths.begin() + static_cast<std::ptrdiff_t>(widths.size() / 2), widths.end());
        out.macro("RegionMedianWidth", widths[widths.size() / 2], 2);
      } else {
        out.macro("RegionMedianWidth", "---");
      }

      auto& c = out.claim("cert.thm1.region", "Theorem 1, Lemma 4", EvidenceKind::Certified, statement);
      c.parameter_object(Json::object()
                             .set("b_over_a", Json::array().push(r.b_lo).push(r.b_hi))
                             .set("q_over_a", Json::array().push(r.q_lo).push(r.q_hi))
                             .set("columns", r.q_columns)
                             .set("max_boxes", static_cast<long long>(max_boxes)));
      c.evidence_object(Json::object()
                            .set("boxes_proved", res.boxes_proved)
                            .set("boxes_not_proved", res.boxes_failed)
                            .set("proved_fraction_of_band", fraction)
                            .set("band_complete", res.complete)
                            .set("seconds", res.seconds)
                            .set("columns", per_column));
      if (res.boxes_proved == 0) c.evidence("failure", "no box was proved");
      c.holds(res.boxes_proved > 0);
      write_atomically(out.root() / "bench" / "certified-region-timing.tex",
                       "% generated by experiment certified_region; timings vary, not in the manifest\n\\newcommand{\\dfcRegionSeconds}{" +
                           format_significant(res.seconds, 3) + "}\n");
      std::fprintf(stderr, "certified_region: %ld boxes proved, %ld not, %.1f%% of the band, %.1f s\n", res.boxes_proved, res.boxes_failed,
                   100 * fraction, res.seconds);
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
