// SPDX-License-Identifier: GPL-3.0-or-later
/// @file thm2_windows.cpp
/// @brief Theorem 2 along the b/a axis: every superstable window of t2 (an interval of b/a on which
/// T(t2) = t2, period 1) at fixed q/a, found in floating point and then *proved* over the whole
/// interval in ball arithmetic, both edges enclosed to a relative width of at most kEdgeRel, each edge
/// with the border collision that ends the window.
///
/// **Windows.** superstable_windows() follows theta2(t2) in b/a and joins adjacent (21) and (22)
/// pieces (join_windows), sharpens each end (sharpen_interval_end) and hands the interval to
/// prove_window() (certified/superstable.hpp):
/// T = t2 on [t2(b), t2(b) + eps_b] for every b of an inner interval (b-boxes), T(t2) != t2 at one b
/// just outside each end. So every window's edges lie in the two certified brackets.
///
/// **Border collisions.** At each edge the window ends because the first progression from t2 stops at
/// the edge of a stop plateau (theta2(t2) crosses t2 or t3 modulo 2pi; at t3 the flight from t2 meets
/// the delimiter tangentially, docs/certified.md), or because T1(t2) jumps (a discontinuity of T1
/// passes through t2). The kind is
/// read at the two ends of the certified bracket, in floating point (sampled: the crossing inside the
/// bracket is inferred from the two ends, not proved).
///
/// **Independent check.** A grid uniform in a/b, not used to find the windows: at every grid point
/// inside a certified inner interval the floating T(t2) must be t2, and at every grid point where the
/// floating T(t2) = t2 the point must lie in a certified window (between its outer points).
///
/// **Continuation.** From below each window the fixed point of T in Lemma 4's J1 (itinerary 1) is
/// followed up in b (continuation.hpp) until it ends. Where it ends by reaching t2, T(t2) = t2 there:
/// the end must lie in the certified bracket of a window's left edge (sampled). For the first
/// kCertifiedFollows starts every step is proved to exist over its interval of b (certified/periodic.hpp).
///
/// **The law.** The spacing of consecutive window centres in a/b and the windows' widths in a/b are
/// fitted as c0 + c1 (b/a) (least squares over the windows with b/a <= kFitMaxRatio): c0 is the limit
/// as b/a -> 0, a sampled law; every spacing is compared with 2 pi / |cos t2|, the growth of the flight
/// time from t2.
///
/// Outputs: data/thm2_windows.tsv (one row per window), data/thm2_windows-law.tsv (the fit), macros, a
/// certified claim (cert.thm2.all_windows) with one certificate per window (statement window), and
/// sampled claims for the grid check and the edges' kinds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/periodic.hpp"
#include "dfchaos/certified/superstable.hpp"
#include "dfchaos/continuation.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/superstable.hpp"
#include "dfchaos/symbolic.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"
#include "kit/output.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {

/// The edge brackets asked of prove_window (it widens them x10 up to 4 times if a proof fails) and the
/// largest relative width (in - out)/in the claim accepts.
constexpr double kProveRel = 4e-13;
constexpr double kEdgeRel = 1e-12;
/// An impact velocity below this at the outer end of a bracket (of relative width <= 1e-12) is a
/// tangential contact (at transversal edges it is of order 0.1).
constexpr double kTangential = 1e-5;
/// The fixed point's continuation (below) is certified step by step for the first this many windows.
constexpr std::size_t kCertifiedFollows = 3;
/// The law is fitted on the windows with b/a at most this (the asymptotic part, a/b >= 100).
constexpr double kFitMaxRatio = 0.01;
/// T1(t2) moving by more than this across a bracket (of relative width <= 1e-12) while theta2(t2) crosses
/// no plateau edge is a jump: a new contact of the flight from t2 (grazing).
constexpr double kJump = 1e-6;

/// Why a window ends at one edge (read at the two ends of its bracket).
struct EdgeKind {
  /// "plateau_t2" or "plateau_t3" (theta2(t2) crosses that end of a stop plateau), "grazing_at_t3"
  /// (it crosses t3 where the flight from t2 meets the delimiter tangentially), "grazing" (T1(t2)
  /// jumps) or "unclassified"
  std::string kind;
  double T1_jump = 0;  ///< |T1(t2)| change between the ends
  double v_out = 0;    ///< the impact velocity of the flight from t2 at the outer end (0: tangential)
};

/// The edge between b_in (T(t2) = t2, proved) and b_out (T(t2) != t2, proved), read in floating point:
/// first whether theta2(t2) mod 2pi lies on the two sides of t2 or t3 (it left the stop plateau
/// through it), else whether T1(t2) jumps (a new, tangential contact of the flight from t2).
EdgeKind edge_kind(double q, double b_in, double b_out) {
  const Parameters p_in(1.0, b_in, q), p_out(1.0, b_out, q);
  const MapStep in = return_map_step(p_in, p_in.t2_required()), out = return_map_step(p_out, p_out.t2_required());
  EdgeKind e;
  e.T1_jump = std::fabs(out.hit.theta1 - in.hit.theta1);
  e.v_out = out.hit.hit_velocity;
  const std::pair<const char*, double> plateau_edges[] = {{"plateau_t2", p_out.t2_required()}, {"plateau_t3", p_out.t3_required()}};
  for (const auto& [name, B] : plateau_edges)
    if ((in.theta2.phase - B) * (out.theta2.phase - B) < 0) {
      // Through t3 with an impact velocity near 0: the flight from t2 grazes the delimiter at t3.
      e.kind = std::string(name) == "plateau_t3" && std::fabs(e.v_out) < kTangential ? "grazing_at_t3" : name;
      return e;
    }
  e.kind = e.T1_jump > kJump ? "grazing" : "unclassified";
  return e;
}

/// Least squares y = c0 + c1 x.
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double c1 = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {(sy - c1 * sx) / n, c1};
}

}  // namespace

const Experiment experiment{
    .title = "Theorem 2 along the b/a axis: every superstable window of t2 proved, with its border collisions",
    .paper = {"Theorem 2"},
    .tests = {"test_certified"},
    .options = {real("q", 0.85, "q/a of the line").range(0.73, 0.99),
                real("b-lo", 1e-3, "lower end of the b/a range").range(1e-4, 0.4).fast_value(0.003),
                real("b-hi", 0.1, "upper end of the b/a range (above b-lo)").range(2e-4, 0.45).fast_value(0.0034),
                count("samples", 5000, "samples of theta2(t2), uniform in a/b, for the window search").range(2, 10'000'000).fast_value(300),
                count("grid", 100000, "independent grid points (uniform in a/b) for the two-sided check").range(2, 100'000'000).fast_value(2000)},
    .outputs = {data("", "one row per superstable window: floating ends, certified edge brackets, the edges' border collisions"),
                data("law", "the fitted law of the windows' spacing and width in a/b"),
                data("fixed_point", "the fixed point of T in J1 followed up in b from below each window: how and where it ends"),
                certificate("cert.thm2.all_windows--*", "per window (cert.thm2.all_windows--wNNN), the window certificate")},
    .body = [](Run& run) {
      Output& out = run.out;
      const double q = run.real("q"), b_lo = run.real("b-lo"), b_hi = run.real("b-hi");
      const long long grid = run.count("grid");
      if (!(b_hi > b_lo)) throw InvalidParameter("b-hi", "b-hi > b-lo = " + format_double(b_lo), b_hi);
      const std::vector<SuperstableInterval> windows = join_windows(superstable_windows(1.0, q, b_lo, b_hi, static_cast<int>(run.count("samples"))));
      const std::size_t n = windows.size();
      std::vector<certified::WindowProof> proofs(n);
#pragma omp parallel for schedule(dynamic)
      for (std::size_t k = 0; k < n; ++k) {
        const double lo = sharpen_interval_end(1.0, q, windows[k].b_lo, true), hi = sharpen_interval_end(1.0, q, windows[k].b_hi, false);
        proofs[k] = certified::prove_window(1.0, q, lo, hi, kProveRel, true);
      }

      Table t({"window",     "b_float_lo",   "b_float_hi",    "conditions", "proved",      "left_out",        "left_in",
               "right_in",   "right_out",    "left_rel",      "right_rel",  "min_eps",     "boxes",           "left_kind",
               "right_kind", "left_T1_jump", "right_T1_jump", "left_v_out", "right_v_out", "centre_a_over_b", "width_a_over_b"});
      Json records = Json::array();
      long long proved = 0, narrow = 0;
      long long kind_count[5] = {0, 0, 0, 0, 0};  // plateau_t2, plateau_t3, grazing_at_t3, grazing, unclassified
      double worst_rel = 0;
      std::vector<double> centres, widths;  // in a/b, of the proved windows
      for (std::size_t k = 0; k < n; ++k) {
        const certified::WindowProof& w = proofs[k];
        const SuperstableInterval& j = windows[k];
        const std::string conditions = j.has21 && j.has22 ? "21+22" : (j.has21 ? "21" : "22");
        Json rec = certify::to_json(1.0, q, w);
        rec.set("window", static_cast<long long>(k + 1));
        records.push(rec);
        if (!w.verdict.proved) {
          t.row({static_cast<long long>(k + 1),
                 j.b_lo,
                 j.b_hi,
                 conditions,
                 0LL,
                 NAN,
                 NAN,
                 NAN,
                 NAN,
                 NAN,
                 NAN,
                 NAN,
                 0LL,
                 std::string("-"),
                 std::string("-"),
                 NAN,
                 NAN,
                 NAN,
                 NAN,
                 NAN,
                 NAN});
          continue;
        }
        ++proved;
        const double left_rel = (w.left_in - w.left_out) / w.left_in, right_rel = (w.right_out - w.right_in) / w.right_in;
        worst_rel = std::max({worst_rel, left_rel, right_rel});
        if (left_rel <= kEdgeRel && right_rel <= kEdgeRel) ++narrow;
        const EdgeKind L = edge_kind(q, w.left_in, w.left_out), R = edge_kind(q, w.right_in, w.right_out);
        for (const EdgeKind* e : {&L, &R}) {
          const int idx = e->kind == "plateau_t2" ? 0 : e->kind == "plateau_t3" ? 1 : e->kind == "grazing_at_t3" ? 2 : e->kind == "grazing" ? 3 : 4;
          ++kind_count[idx];
        }
        // In a/b the window is [1/right, 1/left]: centre and width from the inner interval.
        const double centre = 0.5 * (1 / w.left_in + 1 / w.right_in), width = 1 / w.left_in - 1 / w.right_in;
        centres.push_back(centre);
        widths.push_back(width);
        char part[32];
        std::snprintf(part, sizeof part, "--w%03zu", k + 1);
        run.certificate(std::string("cert.thm2.all_windows") + part,
                        certify::certificate_text(certify::certificate_window(1.0, q, w, certify::statement_window())));
        t.row({static_cast<long long>(k + 1),
               j.b_lo,
               j.b_hi,
               conditions,
               1LL,
               w.left_out,
               w.left_in,
               w.right_in,
               w.right_out,
               left_rel,
               right_rel,
               w.min_eps,
               static_cast<long long>(w.boxes),
               L.kind,
               R.kind,
               L.T1_jump,
               R.T1_jump,
               L.v_out,
               R.v_out,
               centre,
               width});
      }
      run.table("", t);

      // ---- the fixed point of T in J1 followed in b (continuation.hpp) -------------------------------
      // From below each proved window (the middle, in log, of the gap to the window before it) the fixed
      // point of itinerary 1 over Lemma 4's J0, J1 is followed up in b until it ends. Where a fixed point
      // reaches t2, T(t2) = t2: its end [b_last, b_lost] must meet the certified bracket of a window's
      // left edge.
      std::vector<long long> cont_steps(n, -1), cont_certified(n, -1), cont_window(n, 0);
      std::vector<double> cont_start(n, NAN), cont_last(n, NAN), cont_lost(n, NAN);
      std::vector<std::string> cont_end(n, "-");
#pragma omp parallel for schedule(dynamic)
      for (std::size_t k = 0; k < n; ++k) {
        const certified::WindowProof& w = proofs[k];
        if (!w.verdict.proved) continue;
        const double below = k == 0 || !proofs[k - 1].verdict.proved ? w.left_out * (1 - 1e-3) : std::sqrt(proofs[k - 1].right_out * w.left_out);
        cont_start[k] = below;
        try {
          const ItineraryOrbit start = periodic_orbit(Parameters(1.0, below, q), "1");
          const OrbitBranch br = follow_periodic_orbit(1.0, q, below, start.x, b_hi);
          cont_end[k] = branch_end_name(br.end);
          cont_last[k] = br.points.back().b;
          cont_lost[k] = br.b_lost;
          cont_steps[k] = static_cast<long long>(br.points.size()) - 1;
          if (k < kCertifiedFollows) {
            const std::vector<int> c = certified::prove_branch_steps(1.0, q, br);
            cont_certified[k] = std::count(c.begin(), c.end(), 1);
          }
        } catch (const InvalidParameter&) {
          cont_end[k] = "no_start";  // no covering at the start: no fixed point of J1 to follow
        } catch (const GaveUp&) {
          cont_end[k] = "no_start";
        }
      }
      Table cont({"start_below_window", "b_start", "end", "b_last", "b_lost", "window_at_end", "steps", "certified_steps"});
      long long followed = 0, at_t2 = 0, at_t2_met = 0;
      for (std::size_t k = 0; k < n; ++k) {
        if (!proofs[k].verdict.proved) continue;
        if (cont_end[k] != "no_start") ++followed;
        if (cont_end[k] == "reaches_t2") {
          ++at_t2;
          for (std::size_t i = 0; i < n && cont_window[k] == 0; ++i)
            if (proofs[i].verdict.proved && cont_last[k] <= proofs[i].left_in && cont_lost[k] >= proofs[i].left_out)
              cont_window[k] = static_cast<long long>(i + 1);
          if (cont_window[k] > 0) ++at_t2_met;
        }
        cont.row({static_cast<long long>(k + 1), cont_start[k], cont_end[k], cont_last[k], cont_lost[k], cont_window[k], cont_steps[k],
                  cont_certified[k]});
      }
      run.table("fixed_point", cont);

      // ---- the independent two-sided grid check -----------------------------------------------------
      long long grid_in = 0, grid_in_bad = 0, grid_super = 0, grid_super_outside = 0, grid_failed = 0;
      for (long long g = 0; g < grid; ++g) {
        const double r = 1 / b_hi + (1 / b_lo - 1 / b_hi) * static_cast<double>(g) / static_cast<double>(grid - 1);
        const double b = 1 / r;
        bool super = false;
        try {
          const Parameters p(1.0, b, q);
          super = T(p, p.t2_required()) == p.t2_required();  // a stop sends a whole arc to t2 exactly
        } catch (const std::exception&) {
          ++grid_failed;
          continue;
        }
        bool inside = false, near = false;
        for (std::size_t k = 0; k < n && !near; ++k) {
          const certified::WindowProof& w = proofs[k];
          if (!w.verdict.proved) continue;
          inside = inside || (b >= w.left_in && b <= w.right_in);
          near = b >= w.left_out && b <= w.right_out;
        }
        if (inside) {
          ++grid_in;
          if (!super) ++grid_in_bad;
        }
        if (super) {
          ++grid_super;
          if (!near) ++grid_super_outside;
        }
      }

      // ---- the law: spacing and width in a/b, each fitted as c0 + c1 (b/a) for b/a <= kFitMaxRatio ----
      // The flight from rest at t2 returns after about -(a/b) cos t2 (x = -a sin t + b (t - t2)^2 +
      // a cos t2 (t - t2) + ...): theta2(t2) gains 2 pi each time a/b grows by 2 pi / |cos t2|, so
      // consecutive windows should be that far apart in a/b; the fit's c0 is the limit as b/a -> 0.
      Table law({"quantity", "c0", "c1", "max_relative_residual", "points", "max_relative_deviation_from_flight_time"});
      double spacing_c0 = NAN, spacing_dev = NAN, width_c0 = NAN, width_c1 = NAN;
      const auto fitted = std::count_if(centres.begin(), centres.end(), [](double c) { return 1 / c <= kFitMaxRatio; });
      if (fitted >= 3) {
        std::vector<std::size_t> order(centres.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return centres[x] < centres[y]; });
        std::vector<double> gx, gy, wx, wy;
        spacing_dev = 0;
        for (std::size_t i = 0; i + 1 < order.size(); ++i) {
          const double c0 = centres[order[i]], c1 = centres[order[i + 1]], gap = c1 - c0, b_mid = 2 / (c0 + c1);
          const double predicted = 2 * M_PI / std::fabs(std::cos(Parameters(1.0, b_mid, q).t2_required()));
          spacing_dev = std::max(spacing_dev, std::fabs(gap / predicted - 1));
          if (b_mid > kFitMaxRatio) continue;
          gx.push_back(b_mid);
          gy.push_back(gap);
        }
        for (std::size_t i : order) {
          if (1 / centres[i] > kFitMaxRatio) continue;
          wx.push_back(1 / centres[i]);
          wy.push_back(widths[i]);
        }
        const auto residual = [](const std::vector<double>& x, const std::vector<double>& y, double f0, double f1) {
          double r = 0;
          for (std::size_t i = 0; i < x.size(); ++i) r = std::max(r, std::fabs(y[i] - (f0 + f1 * x[i])) / std::fabs(y[i]));
          return r;
        };
        double spacing_c1 = NAN;
        std::tie(spacing_c0, spacing_c1) = fit_line(gx, gy);
        law.row({std::string("spacing_a_over_b"), spacing_c0, spacing_c1, residual(gx, gy, spacing_c0, spacing_c1), static_cast<long long>(gx.size()),
                 spacing_dev});
        std::tie(width_c0, width_c1) = fit_line(wx, wy);
        law.row({std::string("width_a_over_b"), width_c0, width_c1, residual(wx, wy, width_c0, width_c1), static_cast<long long>(wx.size()), NAN});
      }
      run.table("law", law);

      // ---- macros and claims -------------------------------------------------------------------------
      out.macro("WinQ", format_shortest(q));
      out.macro("WinBLo", latex_number(format_shortest(b_lo)));
      out.macro("WinBHi", latex_number(format_shortest(b_hi)));
      out.macro("WinCount", std::to_string(n));
      out.macro("WinProved", std::to_string(proved));
      out.macro("WinWorstRel", latex_number(format_significant(worst_rel, 2)));
      out.macro("WinEdgeRel", latex_number(format_shortest(kEdgeRel)));
      out.macro("WinKindTwo", std::to_string(kind_count[0]));
      out.macro("WinKindThree", std::to_string(kind_count[1]));
      out.macro("WinKindGrazingThree", std::to_string(kind_count[2]));
      out.macro("WinKindGrazing", std::to_string(kind_count[3]));
      out.macro("WinKindOther", std::to_string(kind_count[4]));
      out.macro("WinGrid", std::to_string(grid));
      out.macro("WinGridInside", std::to_string(grid_in));
      out.macro("WinGridSuper", std::to_string(grid_super));
      out.macro("WinSpacing", spacing_c0, 6);
      out.macro("WinSpacingDeviation", latex_number(format_significant(spacing_dev, 2)));
      out.macro("WinWidthLimit", width_c0, 3);
      // with its sign, to follow WinWidthLimit in "limit slope b/a"
      out.macro("WinWidthSlope", (width_c1 >= 0 ? "+" : "") + format_significant(width_c1, 3));
      out.macro("WinCoveredPercent", 100 * width_c0 / spacing_c0, 2);
      out.macro("WinFitMaxRatio", format_shortest(kFitMaxRatio));

      const std::string statement = "At q/a = " + format_shortest(q) + ", every window of b/a in [" + format_shortest(b_lo) + ", " +
                                    format_shortest(b_hi) + "] with T(t2) = t2 is proved, edges to " + format_shortest(kEdgeRel) + " relative.";
      auto& c = out.claim("cert.thm2.all_windows", "Theorem 2", EvidenceKind::Certified, statement).ours();
      c.parameter_object(Json::object().set("a", 1.0).set("q", q).set("b_over_a", Json::array().push(b_lo).push(b_hi)));
      c.evidence_object(Json::object()
                            .set("windows_found", static_cast<long long>(n))
                            .set("windows_proved", proved)
                            .set("windows_within_edge_rel", narrow)
                            .set("worst_edge_rel", worst_rel)
                            .set("windows", records));
      c.holds(n > 0 && proved == static_cast<long long>(n) && narrow == proved);

      out.claim("thm2.windows_grid", "Theorem 2", EvidenceKind::Sampled,
                "On a grid of " + std::to_string(grid) + " b/a: T(t2) = t2 in every proved window, nowhere outside.")
          .ours()
          .evidence("grid_points", grid)
          .evidence("grid_failed", grid_failed)
          .evidence("inside_certified", grid_in)
          .evidence("inside_certified_not_superstable", grid_in_bad)
          .evidence("superstable", grid_super)
          .evidence("superstable_outside_certified", grid_super_outside)
          .holds(grid_in_bad == 0 && grid_super_outside == 0 && grid_failed == 0);

      out.claim("thm2.window_edges", "Theorem 2", EvidenceKind::Sampled,
                "Each proved window opens as theta2(t2) crosses t2, closes as it crosses t3 or T1(t2) jumps.")
          .ours()
          .evidence("plateau_t2", kind_count[0])
          .evidence("plateau_t3", kind_count[1])
          .evidence("grazing_at_t3", kind_count[2])
          .evidence("grazing", kind_count[3])
          .evidence("unclassified", kind_count[4])
          .holds(proved > 0 && kind_count[4] == 0);
      out.macro("WinFollowed", std::to_string(followed));
      out.macro("WinFollowedAtTwo", std::to_string(at_t2));
      out.macro("WinFollowedMet", std::to_string(at_t2_met));
      out.claim("thm2.windows_fixed_point", "Theorem 2", EvidenceKind::Sampled,
                "The fixed point in J1, followed up in b, reaches t2 in a proved window's left bracket.")
          .ours()
          .evidence("followed", followed)
          .evidence("ends_at_t2", at_t2)
          .evidence("ends_at_t2_in_a_left_bracket", at_t2_met)
          .evidence("no_start", proved - followed)
          .holds(at_t2 > 0 && at_t2_met == at_t2);
      std::fprintf(stderr, "thm2_windows: %lld of %zu windows proved, worst edge bracket %.2g relative; grid: %lld inside, %lld superstable\n",
                   proved, n, worst_rel, grid_in, grid_super);
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
