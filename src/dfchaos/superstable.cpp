#include "dfchaos/superstable.hpp"

#include <cmath>

#include "dfchaos/errors.hpp"

namespace dfchaos {

SuperstableCheck superstable_check(const Parameters& p, int scan) {
  p.require_return_map();
  if (scan < 2) throw InvalidParameter("scan", "scan >= 2", scan);
  const double t2 = *p.t2(), t3 = *p.t3();
  SuperstableCheck r;
  r.step = return_map_step(p, t2);
  r.theta2_phase = r.step.theta2.phase;
  const bool has_t0 = p.t0().has_value();
  r.eq21 = has_t0 && r.theta2_phase > *p.t1() && r.theta2_phase < t2;
  r.eq22 = r.theta2_phase > t3 || (has_t0 && r.theta2_phase < *p.t0());
  r.impact_velocity = r.step.hit.hit_velocity;
  r.dG2 = p.F(r.theta2_phase) - p.q();
  r.nondegenerate = std::fabs(r.impact_velocity) > 1e-9 && std::fabs(r.dG2) > 1e-9;
  const Assumptions as = p.assumptions();
  r.hypotheses = (as.eq2 && r.eq22) || (as.eq23 && r.eq21);
  r.fixed = r.step.T == t2;
  if (!r.fixed) return r;
  // Width of the component of {T = t2} that starts at t2.
  const double h = (t3 - t2) / scan;
  double lo = t2, hi = NAN;
  for (int i = 1; i < scan; ++i) {
    const double th = t2 + h * i;
    if (T(p, th) != t2) { hi = th; break; }
    lo = th;
  }
  if (std::isnan(hi)) { r.epsilon = t3 - t2; return r; }
  for (int it = 0; it < 100 && hi - lo > 4e-16 * hi; ++it) {
    const double m = 0.5 * (lo + hi);
    if (T(p, m) == t2) lo = m; else hi = m;
  }
  r.epsilon = lo - t2;
  return r;
}

}  // namespace dfchaos
