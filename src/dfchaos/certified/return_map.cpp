// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/return_map.hpp"

#include <cmath>

namespace dfchaos::certified {

const char* t_case_name(TCase c) {
  switch (c) {
    case TCase::ScenarioAB: return "free";
    case TCase::ScenarioBC: return "stop";
    case TCase::Unproved: return "none";
  }
  return "none";
}

MapStepProof certify_T(const ParameterBalls& m, const StartSet& set, Budget& budget, const Lemma1Proof* lemma1, bool record,
                       const FirstHitOptions* t1_options) {
  MapStepProof r;
  FirstHitOptions options = t1_options ? *t1_options : FirstHitOptions{};
  options.record = record;
  r.t1 = certify_T1(m, set, budget, options);
  r.tests += r.t1.stats.tests;
  if (!r.t1.verdict) {
    r.verdict = r.t1.verdict;
    return r;
  }
  r.theta2 = certify_theta2(m, set, r.t1, budget, record, t1_options != nullptr);
  r.tests += r.theta2.stats.tests;
  // Where theta2 is not a proved simple zero, T may still be proved constant: the first stop lies
  // in a stop arc (certify_stop_arc).
  auto try_stop_arc = [&](const Outcome& why) {
    r.stop_arc = certify_stop_arc(m, set, r.t1, budget, record);
    const StopArcProof& s = r.stop_arc;
    r.tests += s.stats.tests;
    if (!s.verdict) {
      r.verdict = Outcome::fail(why.step, why.detail + "; stop-arc test: " + s.verdict.describe());
      return r;
    }
    if (s.needs_lemma1) {
      Lemma1Proof own;
      if (!lemma1) {
        own = certify_lemma1(m);
        lemma1 = &own;
      }
      if (!lemma1->verdict) {
        r.verdict = Outcome::fail("T: stop until t0 needs Lemma 1", lemma1->verdict.describe());
        return r;
      }
      r.used_lemma1 = true;
    }
    r.t_case = TCase::ScenarioBC;
    r.turn = s.k;
    r.theta2_phase = Ball::hull(s.from, s.tau) - Ball(static_cast<double>(s.k)) * m.two_pi;
    r.T = m.t2;
    r.constant_t2 = true;
    r.verdict = Outcome::ok();
    return r;
  };
  if (!r.theta2.verdict) return try_stop_arc(r.theta2.verdict);
  const Ball& lo = r.theta2.u_lo;
  const Ball& hi = r.theta2.u_hi;
  // Scenarios A, B: [t1 + 2 pi k, t3 + 2 pi k).
  {
    const long long k = static_cast<long long>(std::floor((lo.mid() - m.t1.mid()) / (2 * M_PI)));
    const Ball shift = Ball(static_cast<double>(k)) * m.two_pi;
    if (le(m.t1 + shift, lo) && lt(hi, m.t3 + shift)) {
      r.t_case = TCase::ScenarioAB;
      r.turn = k;
      r.theta2_phase = r.theta2.enclosure - shift;
      if (lt(hi - shift, m.t2)) {
        r.T = m.t2;
        r.constant_t2 = true;
      } else {
        r.T = max(r.theta2_phase, m.t2);
      }
      r.verdict = Outcome::ok();
      return r;
    }
  }
  // Scenarios B, C: [t3 + 2 pi k, t2 + 2 pi (k + 1)).
  {
    const long long k = static_cast<long long>(std::floor((lo.mid() - m.t3.mid()) / (2 * M_PI)));
    const Ball shift = Ball(static_cast<double>(k)) * m.two_pi;
    if (le(m.t3 + shift, lo) && lt(hi, m.t2 + shift + m.two_pi)) {
      r.t_case = TCase::ScenarioBC;
      r.turn = k;
      r.theta2_phase = r.theta2.enclosure - shift;
      // Lemma 1 is needed unless the whole enclosure lies in [t1, t2) of the next turn (scenario B).
      if (!le(m.t1 + shift + m.two_pi, lo)) {
        Lemma1Proof own;
        if (!lemma1) {
          own = certify_lemma1(m);
          lemma1 = &own;
        }
        if (!lemma1->verdict) {
          r.verdict = Outcome::fail("T: stop until t0 needs Lemma 1", lemma1->verdict.describe());
          return r;
        }
        r.used_lemma1 = true;
      }
      r.T = m.t2;
      r.constant_t2 = true;
      r.verdict = Outcome::ok();
      return r;
    }
  }
  return try_stop_arc(Outcome::fail(
      "T: chain", "the phase of theta2, " + r.theta2.enclosure.str(12) + ", is not inside one arc [t1, t3) or [t3, t2 + 2 pi) (T may jump at t3)"));
}

BallProof BallProof::of(const StartSet& set, const ParameterBox& box, MapStepProof T) {
  BallProof b;
  b.box = box;
  b.T = std::move(T);
  b.at_t2 = set.kind == StartSet::Kind::AtT2;
  b.from_t2 = set.lo_is_t2;
  if (!b.at_t2) {
    b.theta_lo = b.from_t2 ? Ball(set.lo.upper()) : set.lo;  // exact (from_t2: not used)
    b.theta_hi = set.hi;
  }
  return b;
}

bool derivative_T(const ParameterBalls& m, const StartSet& set, const MapStepProof& t, Ball& dT) {
  if (!t.verdict || t.t_case != TCase::ScenarioAB || !lt(m.t2, t.theta2_phase)) return false;
  const Ball th = set.hull(m);
  const Ball& th1 = t.t1.enclosure;
  const Ball& th2 = t.theta2.enclosure;
  const Ball F_theta = m.F(th);
  const Ball v1 = dG1_dt(m, th, th1, m.b);
  if (!v1.is_positive()) return false;
  const Ball dth1 = F_theta * (th1 - th) / v1;
  const Ball den = m.F(th2) - m.q;
  if (!den.is_negative()) return false;
  dT = (F_theta - m.q * dth1) / den;
  return dT.is_finite();
}

}  // namespace dfchaos::certified
