// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/progression_stop.hpp"

#include <cmath>
#include <stdexcept>

#include "dfchaos/bisect.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/regime_chain.hpp"

namespace dfchaos {

ProgressionFromT0 progression_from_t0(const Parameters& p) {
  p.require_return_map();
  if (!p.t0()) throw InvalidParameter("q", "|q - 2b| < a so that F - q changes sign (t0 defined)", p.q());
  const double t0 = *p.t0(), t1 = *p.t1(), t2 = *p.t2(), t3 = *p.t3(), a = p.a();
  ProgressionFromT0 r;
  const ProgressionMotion m(p, Instant::at_phase(t0), 0.0, 0.0);
  const auto root = first_upcrossing(m.minus_velocity());
  if (!root) throw std::logic_error("progression_from_t0: a progression with q > 2b always stops (a bug)");
  r.t4 = root->t;
  r.t4_value = root->t.value();
  // t2 of the same period as t0 (t0 < t1 < t2 when q > 2b, since then t0 in (0, pi/2)).
  const double t2_after = t2 > t0 ? t2 : t2 + two_pi;
  const double t1_after = t1 > t0 ? t1 : t1 + two_pi;
  r.eq8_velocity_at_t2 = model::progression_velocity_from_rest(a, model::two_c(p.b(), p.q()), t0, t2_after);
  r.stops_in_t1_t2 = r.t4_value >= t1_after && r.t4_value <= t2_after;
  r.proof_bound_value = a + a * std::cos(t0) - (p.q() - 2 * p.b()) * (pi - t0);
  r.proof_bound = r.proof_bound_value < 0;
  r.eq9 = 1 + std::cos(t0) - std::sin(t0) * (pi - t0) < 0;
  r.next = phase_in_arc(r.t4.phase, t2, t3) ? Regime::Free : Regime::Stop;
  r.repeats_for_ever = r.next == Regime::Stop && phase_in_arc(r.t4.phase, t3, t0);
  return r;
}

double lemma1_threshold(double q_over_a, double lo, double hi, Lemma1Criterion criterion) {
  auto holds = [&](double ba) {
    if (!(ba < q_over_a / 2)) return false;
    const ProgressionFromT0 r = progression_from_t0(Parameters(1.0, ba, q_over_a));
    return criterion == Lemma1Criterion::StopsInT1T2 ? r.stops_in_t1_t2 : r.proof_bound;
  };
  if (!holds(lo)) return 0.0;
  if (holds(hi)) return hi;
  return bisect(holds, lo, hi, BisectStop{60, 0, 0}).first;
}

}  // namespace dfchaos
