// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/covering.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "dfchaos/bisect.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/next_hit.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos {

LabelledStep continuity_label(const Parameters& p, double theta) {
  LabelledStep r;
  r.step = return_map_step(p, theta);
  r.label.t1_branch = t1_branch(p, r.step);
  const long double since = elapsed(Instant::at_phase(*p.t3()), r.step.theta2);  // theta2 - t3 (turn 0)
  r.label.t3_passed = static_cast<long long>(std::floor(since / two_pi_l));
  r.label.scenario_d = r.step.scenario == Scenario::D || r.step.scenario == Scenario::Dprime;
  return r;
}

namespace {

/// \f$\psi = \theta_2 - t_2\f$ of a step, with \f$\theta\f$ in turn 0: where the first progression
/// stops, measured from \f$t_2\f$ (CoveringMethod::Branchwise).
long double psi_of(const Parameters& p, const MapStep& step) { return elapsed(Instant::at_phase(*p.t2()), step.theta2); }

/// Re-checks a candidate on a fine grid: one label throughout, and T moving between neighbours by
/// no more than a bound that a jump to or from t2 (of size >= gap) would break. With
/// `psi_direction` = +1 or -1, \f$\psi\f$ must also move monotonically in that direction.
bool recheck_segment(const Parameters& p, CoveringSegment& s, int n, int psi_direction = 0) {
  if (n < 2) return true;
  double prev_T = NAN;
  long double prev_psi = 0;
  double max_step = 0;
  for (int i = 0; i <= n; ++i) {
    const double th = s.lo + (s.hi - s.lo) * i / n;
    const LabelledStep l = continuity_label(p, th);
    if (!(l.label == s.label)) return false;
    const long double psi = psi_direction != 0 ? psi_of(p, l.step) : 0;
    if (i > 0) {
      max_step = std::max(max_step, std::fabs(l.step.T - prev_T));
      if ((psi_direction > 0 && psi < prev_psi) || (psi_direction < 0 && psi > prev_psi)) return false;
    }
    prev_T = l.step.T;
    prev_psi = psi;
  }
  // The image spans at least top - t2; on n steps a continuous T moves that far in total. A single
  // step carrying more than half of the whole span is taken as a possible jump.
  return max_step <= 0.5 * (s.T_at_top - *p.t2()) || n < 4;
}

/// Looks for a phase with T = t2 on [lo, hi] (one continuity branch, label `label`) by a
/// golden-section minimisation of T: on a branch T >= t2, equal to t2 exactly on the arcs where the
/// progression ends before t2 (scenario B). Those arcs can be far narrower than any grid step
/// (widths of 1e-6 and less at small b/a), while T falls towards them continuously, so following
/// the descent finds them where sampling does not. Points of another branch count as +infinity.
/// Bounded: 60 evaluations. Returns NaN when no such phase was met.
double t2_arc_by_descent(const Parameters& p, double lo, double hi, const ContinuityLabel& label) {
  const double t2 = *p.t2();
  constexpr double kGolden = 0.6180339887498949;
  auto value = [&](double th, bool& at_t2) {
    const LabelledStep l = continuity_label(p, th);
    at_t2 = l.label == label && l.step.T == t2;
    return l.label == label ? l.step.T : INFINITY;
  };
  bool hit = false;
  double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
  double f1 = value(x1, hit);
  if (hit) return x1;
  double f2 = value(x2, hit);
  if (hit) return x2;
  for (int it = 0; it < 58 && x1 < x2; ++it) {
    if (f1 <= f2) {  // the minimum lies in [lo, x2]
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kGolden * (hi - lo);
      f1 = value(x1, hit);
      if (hit) return x1;
    } else {  // in [x1, hi]
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kGolden * (hi - lo);
      f2 = value(x2, hit);
      if (hit) return x2;
    }
  }
  return NAN;
}

/// The cuts lo < z_1 < ... < hi: the symmetric tangencies (next_hit.hpp) strictly inside (lo, hi).
/// @throws GaveUp when there are more than `max_branches` branches (before finding any cut).
std::vector<double> branch_cuts(const Parameters& p, double lo, double hi, long long max_branches) {
  const long long branches = symmetric_tangency_count(p, lo, hi) + 1;
  if (branches > max_branches)
    throw GaveUp("work budget: [" + format_double(lo) + ", " + format_double(hi) + "] holds " + std::to_string(branches) +
                 " branches of T1 at b/a = " + format_double(p.b() / p.a()) + ", more than this search's budget of " + std::to_string(max_branches) +
                 " (max_branches; docs/reliability.md)");
  std::vector<double> cuts{lo};
  for (const auto& z : symmetric_tangencies(p, lo, hi))
    if (z.z > lo && z.z < hi) cuts.push_back(z.z);
  cuts.push_back(hi);
  return cuts;
}

/// CoveringMethod::Dense.
std::vector<CoveringSegment> dense_segments(const Parameters& p, double lo, double hi, double top, const CoveringSearch& search) {
  const double t2 = *p.t2();
  // Scan each continuity branch of T1 separately: their widths range over orders of magnitude
  // (about 2 pi b / (a |sin z|)), and the breakpoints are known in closed form (next_hit.hpp).
  const std::vector<double> cuts = branch_cuts(p, lo, hi, search.max_branches);

  std::vector<CoveringSegment> out;
  ContinuityLabel run_label;
  bool have_run = false;
  double th_t2 = NAN, th_top = NAN, T_top = NAN;  // latest grid points of the current run
  // A candidate is complete when the current run has a phase with T = t2 and one with T >= top.
  auto close_segment = [&]() {
    CoveringSegment s;
    s.lo = std::min(th_t2, th_top);
    s.hi = std::max(th_t2, th_top);
    s.theta_at_t2 = th_t2;
    s.theta_at_top = th_top;
    s.T_at_top = T_top;
    s.label = run_label;
    s.rechecked = recheck_segment(p, s, search.recheck);
    th_t2 = th_top = NAN;  // the next segment starts after this one: disjoint
    if (s.rechecked) out.push_back(s);
    return s.rechecked && search.max_segments > 0 && static_cast<int>(out.size()) >= search.max_segments;
  };
  // The arc where T = t2 often sits at an end of a run, where T plunges to t2 within a small
  // fraction of a grid step just before the label changes (or rises from it just after). When a
  // run has reached the top but not t2, those end gaps are searched by descent (once each).
  double prev_th = NAN;         // the previous sample
  double gap_start_lo = NAN;    // the gap before the current run's first sample
  bool start_gap_open = false;  // that gap not yet searched, and no segment formed in this run
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    // At least search.scan points per branch, and at least the density of a uniform grid of
    // search.uniform points on [lo, hi] (wide branches near t2 hold narrow arcs where T = t2).
    const double width = cuts[c + 1] - cuts[c];
    const int m = std::max(search.scan, static_cast<int>(std::ceil(width / (hi - lo) * search.uniform)));
    for (int j = 0; j < m; ++j) {
      poll_stop();  // stop.hpp: every sample of the search is a poll
      const double th = cuts[c] + (cuts[c + 1] - cuts[c]) * j / m;
      const LabelledStep l = continuity_label(p, th);
      if (!have_run || !(l.label == run_label)) {
        // The run ends: if it reached the top but not t2, look for the arc between its last sample
        // and this one (points of the new label do not count).
        if (have_run && search.descend && std::isnan(th_t2) && !std::isnan(th_top) && !std::isnan(prev_th)) {
          th_t2 = t2_arc_by_descent(p, prev_th, th, run_label);
          if (!std::isnan(th_t2) && close_segment()) return out;
        }
        run_label = l.label;
        have_run = true;
        th_t2 = th_top = NAN;
        gap_start_lo = prev_th;
        start_gap_open = !std::isnan(prev_th);
      }
      prev_th = th;
      if (l.step.T == t2) {
        th_t2 = th;
      } else if (l.step.T < t2 + 0.05 * (top - t2)) {
        // T comes close to t2: the arc where it equals t2 (scenario B) may be narrower than the
        // grid step. Look for it on a fine local grid, within the same label run.
        const double h = (cuts[c + 1] - cuts[c]) / m;
        for (int k = -search.refine; k <= search.refine; ++k) {
          const double u = th + h * k / search.refine;
          if (u < cuts[c] || u >= cuts[c + 1]) continue;
          const LabelledStep lu = continuity_label(p, u);
          if (lu.label == run_label && lu.step.T == t2) {
            th_t2 = u;
            break;
          }
        }
      }
      if (l.step.T >= top) {
        th_top = th;
        T_top = l.step.T;
        // The top is reached but no t2 yet: the arc may hide in the gap before the run's first sample.
        if (std::isnan(th_t2) && start_gap_open && search.descend) {
          start_gap_open = false;
          th_t2 = t2_arc_by_descent(p, gap_start_lo, th, run_label);
        }
      }
      if (!std::isnan(th_t2) && !std::isnan(th_top)) {
        start_gap_open = false;
        if (close_segment()) return out;
      }
    }
  }
  return out;
}

/// One sample of the branchwise search: the labelled step and its \f$\psi\f$.
struct BranchSample {
  double theta = 0;
  LabelledStep l;
  long double psi = 0;
};

BranchSample branch_sample(const Parameters& p, double theta) {
  BranchSample s{theta, continuity_label(p, theta), 0};
  s.psi = psi_of(p, s.l.step);
  return s;
}

/// Bisection between the samples `below` and `above` of one branch for a sample that `accept`s;
/// a sample that is not accepted replaces `below` where `is_below` holds, `above` otherwise.
/// Bounded (bisect_bracket): 80 halvings, or until the phases meet in the last bit (then gives up: nullopt).
template <class Accept, class IsBelow>
std::optional<BranchSample> seek(const Parameters& p, BranchSample below, BranchSample above, Accept accept, IsBelow is_below) {
  std::optional<BranchSample> found;
  bisect_bracket(
      std::move(below), std::move(above), 80,
      [&p](const BranchSample& lo, const BranchSample& hi) -> std::optional<BranchSample> {
        const double m = 0.5 * (lo.theta + hi.theta);
        if (m == lo.theta || m == hi.theta) return std::nullopt;
        return branch_sample(p, m);
      },
      [&](const BranchSample& s) -> std::optional<bool> {
        if (!accept(s)) return is_below(s);
        found = s;
        return std::nullopt;  // found: the bisection ends here
      });
  return found;
}

/// CoveringMethod::Branchwise; nullopt when a branch does not show the structure it relies on.
std::optional<std::vector<CoveringSegment>> branchwise_segments(const Parameters& p, double lo, double hi, double top, const CoveringSearch& search) {
  const double t2 = *p.t2(), t3 = *p.t3();
  const std::vector<double> cuts = branch_cuts(p, lo, hi, search.max_branches);
  std::vector<CoveringSegment> out;
  long long previous_branch = 0;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    poll_stop();  // stop.hpp: every branch is a poll
    // The branch [L, R): its ends (just inside: at a cut T1 is the tangency itself) and two inner points.
    const double L = cuts[c], R = cuts[c + 1], w = R - L;
    constexpr double kInside = 1e-9;  // relative distance of the end samples from a cut
    const BranchSample e0 = branch_sample(p, c == 0 ? L : L + kInside * w), e1 = branch_sample(p, R - kInside * w);
    const BranchSample i1 = branch_sample(p, L + w / 3), i2 = branch_sample(p, L + 2 * w / 3);
    const long long branch = e0.l.label.t1_branch;
    // One branch of T1 between the cuts, and a real discontinuity at the cut before it.
    if (e1.l.label.t1_branch != branch || i1.l.label.t1_branch != branch || i2.l.label.t1_branch != branch) return std::nullopt;
    if (c > 0 && previous_branch == branch) return std::nullopt;
    previous_branch = branch;
    // psi monotone on the four samples.
    const int dir = e1.psi > e0.psi ? 1 : -1;
    const auto ordered = [&](long double x, long double y) { return dir > 0 ? x <= y : x >= y; };
    if (!(ordered(e0.psi, i1.psi) && ordered(i1.psi, i2.psi) && ordered(i2.psi, e1.psi))) return std::nullopt;
    const BranchSample& low = dir > 0 ? e0 : e1;   // the end with the least psi
    const BranchSample& high = dir > 0 ? e1 : e0;  // the end with the largest psi
    const auto is_below_level = [](long double level) { return [level](const BranchSample& s) { return s.psi < level; }; };
    std::vector<CoveringSegment> here;
    for (long long m = static_cast<long long>(std::ceil(low.psi / two_pi_l)); m * two_pi_l <= high.psi; ++m) {
      // Stops in the window just below 2 pi m give T = t2; psi in [2 pi m + top - t2, 2 pi m + t3 - t2) T >= top.
      const long double base = m * two_pi_l, level_top = base + (top - t2), level_t3 = base + (t3 - t2);
      if (!(low.psi < base && high.psi >= level_top)) continue;
      // The witnesses are taken inside the branch, not at its end samples: near a tangency T varies
      // like a square root, and a witness 1e-9 from it would be fragile. Where the branch ends
      // inside a target window, only the half of the window away from that end is accepted.
      const long double cap_top = std::min(level_t3, (level_top + high.psi) / 2);
      const auto accept_top = [&](const BranchSample& s) { return s.psi >= level_top && s.psi < cap_top && s.l.step.T >= top; };
      std::optional<BranchSample> at_top = seek(p, low, high, accept_top, is_below_level(cap_top));
      if (!at_top) continue;
      const long double floor_t2 = std::max(level_t3 - two_pi_l, (low.psi + base) / 2);
      const auto accept_t2 = [&](const BranchSample& s) {
        return s.psi >= floor_t2 && s.psi < base && s.l.step.T == t2 && s.l.label == at_top->l.label;
      };
      std::optional<BranchSample> at_t2 = seek(p, low, *at_top, accept_t2, is_below_level(base));
      if (!at_t2) continue;
      CoveringSegment seg;
      seg.lo = std::min(at_t2->theta, at_top->theta);
      seg.hi = std::max(at_t2->theta, at_top->theta);
      seg.theta_at_t2 = at_t2->theta;
      seg.theta_at_top = at_top->theta;
      seg.T_at_top = at_top->l.step.T;
      seg.label = at_top->l.label;
      seg.rechecked = recheck_segment(p, seg, search.recheck, dir);
      if (seg.rechecked) here.push_back(seg);
    }
    std::sort(here.begin(), here.end(), [](const CoveringSegment& x, const CoveringSegment& y) { return x.lo < y.lo; });
    for (const CoveringSegment& seg : here) {
      out.push_back(seg);
      if (search.max_segments > 0 && static_cast<int>(out.size()) >= search.max_segments) return out;
    }
  }
  return out;
}

}  // namespace

std::vector<CoveringSegment> covering_segments(const Parameters& p, double lo, double hi, double top, const CoveringSearch& search,
                                               CoveringSearchStats* stats) {
  p.require_return_map();
  const double t2 = *p.t2(), t3 = *p.t3();
  if (!(lo >= t2 && lo < hi && hi < t3)) throw InvalidParameter("lo, hi", "t2 <= lo < hi < t3");
  if (search.scan < 2) throw InvalidParameter("scan", "scan >= 2", search.scan);
  if (search.uniform < 0) throw InvalidParameter("uniform", "uniform >= 0", search.uniform);
  if (search.max_branches < 1) throw InvalidParameter("max_branches", "max_branches >= 1", static_cast<double>(search.max_branches));
  if (search.method == CoveringMethod::Branchwise) {
    if (auto segs = branchwise_segments(p, lo, hi, top, search)) return *std::move(segs);
    if (stats != nullptr) ++stats->dense_fallbacks;
    CoveringSearch dense;  // the reference search, with the caller's limits (its work per branch is larger)
    dense.max_segments = search.max_segments;
    dense.max_branches = std::max(1LL, search.max_branches / kDenseCostFactor);
    return dense_segments(p, lo, hi, top, dense);
  }
  return dense_segments(p, lo, hi, top, search);
}

Lemma4Covering lemma4_covering(const Parameters& p, const CoveringSearch& search, CoveringSearchStats* stats) {
  p.require_return_map();
  Lemma4Covering r;
  CoveringSearch s = search;
  if (s.max_segments == 0) s.max_segments = 2;
  const auto segs = covering_segments(p, *p.t2(), 1.5 * pi, 1.5 * pi, s, stats);
  r.segments_found = static_cast<int>(segs.size());
  if (segs.size() >= 2) {
    r.holds = true;
    r.J0 = segs[0];
    r.J1 = segs[1];
  }
  return r;
}

Lemma4Covering require_lemma4_covering(const Parameters& p) {
  p.require_eq2();
  p.require_return_map();
  Lemma4Covering c = lemma4_covering(p);
  if (!c.holds) throw InvalidParameter("b", "a parameter set where the covering of Lemma 4 holds (none found at " + p.describe() + ")");
  return c;
}

}  // namespace dfchaos
