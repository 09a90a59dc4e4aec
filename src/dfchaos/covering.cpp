#include "dfchaos/covering.hpp"

#include <cmath>

#include "dfchaos/errors.hpp"
#include "dfchaos/next_hit.hpp"

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

/// Re-checks a candidate on a fine grid: one label throughout, and T moving between neighbours by
/// no more than a bound that a jump to or from t2 (of size >= gap) would break.
bool recheck_segment(const Parameters& p, CoveringSegment& s, int n) {
  if (n < 2) return true;
  double prev_T = NAN;
  double max_step = 0;
  for (int i = 0; i <= n; ++i) {
    const double th = s.lo + (s.hi - s.lo) * i / n;
    const LabelledStep l = continuity_label(p, th);
    if (!(l.label == s.label)) return false;
    if (i > 0) max_step = std::max(max_step, std::fabs(l.step.T - prev_T));
    prev_T = l.step.T;
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

}  // namespace

std::vector<CoveringSegment> covering_segments(const Parameters& p, double lo, double hi, double top,
                                               const CoveringSearch& search) {
  p.require_return_map();
  const double t2 = *p.t2(), t3 = *p.t3();
  if (!(lo >= t2 && lo < hi && hi < t3)) throw InvalidParameter("lo, hi", "t2 <= lo < hi < t3");
  if (search.scan < 2) throw InvalidParameter("scan", "scan >= 2", search.scan);
  if (search.uniform < 0) throw InvalidParameter("uniform", "uniform >= 0", search.uniform);

  // Scan each continuity branch of T1 separately: their widths range over orders of magnitude
  // (about 2 pi b / (a |sin z|)), and the breakpoints are known in closed form (next_hit.hpp).
  std::vector<double> cuts{lo};
  for (const auto& z : symmetric_tangencies(p, lo, hi))
    if (z.z > lo && z.z < hi) cuts.push_back(z.z);
  cuts.push_back(hi);

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
  double prev_th = NAN;               // the previous sample
  double gap_start_lo = NAN;          // the gap before the current run's first sample
  bool start_gap_open = false;        // that gap not yet searched, and no segment formed in this run
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    // At least search.scan points per branch, and at least the density of a uniform grid of
    // search.uniform points on [lo, hi] (wide branches near t2 hold narrow arcs where T = t2).
    const double width = cuts[c + 1] - cuts[c];
    const int m = std::max(search.scan, static_cast<int>(std::ceil(width / (hi - lo) * search.uniform)));
    for (int j = 0; j < m; ++j) {
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

Lemma4Covering lemma4_covering(const Parameters& p, const CoveringSearch& search) {
  p.require_return_map();
  Lemma4Covering r;
  CoveringSearch s = search;
  if (s.max_segments == 0) s.max_segments = 2;
  const auto segs = covering_segments(p, *p.t2(), 1.5 * pi, 1.5 * pi, s);
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
