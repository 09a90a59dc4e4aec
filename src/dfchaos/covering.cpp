#include "dfchaos/covering.hpp"

#include <cmath>

#include "dfchaos/errors.hpp"
#include "dfchaos/next_hit.hpp"

namespace dfchaos {

LabelledStep continuity_label(const Parameters& p, double theta) {
  LabelledStep r;
  r.step = return_map_step(p, theta);
  r.label.t1_branch = r.step.hit.maxima_before;
  const long double since = elapsed(Instant::at_phase(*p.t3()), r.step.theta2);  // theta2 - t3 (turn 0)
  r.label.t3_passed = static_cast<long long>(std::floor(since / two_pi_l));
  r.label.scenario_d = r.step.scenario == Scenario::D || r.step.scenario == Scenario::Dprime;
  return r;
}

namespace {

/// Re-checks a candidate on a fine grid: one label throughout, and T moving between neighbours by
/// no more than a bound that a jump to or from t2 (of size >= gap) would break.
bool verify_segment(const Parameters& p, CoveringSegment& s, int n) {
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
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    // At least search.scan points per branch, and at least the density of a uniform grid of
    // search.uniform points on [lo, hi] (wide branches near t2 hold narrow arcs where T = t2).
    const double width = cuts[c + 1] - cuts[c];
    const int m = std::max(search.scan, static_cast<int>(std::ceil(width / (hi - lo) * search.uniform)));
    for (int j = 0; j < m; ++j) {
      const double th = cuts[c] + (cuts[c + 1] - cuts[c]) * j / m;
      const LabelledStep l = continuity_label(p, th);
      if (!have_run || !(l.label == run_label)) {
        run_label = l.label;
        have_run = true;
        th_t2 = th_top = NAN;
      }
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
      if (l.step.T >= top) { th_top = th; T_top = l.step.T; }
      if (!std::isnan(th_t2) && !std::isnan(th_top)) {
        CoveringSegment s;
        s.lo = std::min(th_t2, th_top);
        s.hi = std::max(th_t2, th_top);
        s.theta_at_t2 = th_t2;
        s.theta_at_top = th_top;
        s.T_at_top = T_top;
        s.label = run_label;
        s.verified = verify_segment(p, s, search.verify);
        th_t2 = th_top = NAN;  // the next segment starts after this one: disjoint
        if (s.verified) {
          out.push_back(s);
          if (search.max_segments > 0 && static_cast<int>(out.size()) >= search.max_segments) return out;
        }
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

}  // namespace dfchaos
