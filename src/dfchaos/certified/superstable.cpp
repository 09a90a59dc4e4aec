// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/superstable.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include "dfchaos/certified/bisect.hpp"
#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/oracle.hpp"
#include "dfchaos/certified/vartheta0.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/stop.hpp"
#include "dfchaos/superstable.hpp"

namespace dfchaos::certified {

namespace {

/// The turn k that reduces a theta2 enclosure x into [t1, t1 + 2 pi) (by its midpoint).
long long phase_turn_of(const ParameterBalls& m, const Ball& x) { return static_cast<long long>(std::floor((x.mid() - m.t1.mid()) / (2 * M_PI))); }

/// The phase of a theta2 enclosure: x - 2 pi phase_turn_of(x).
Ball phase_of(const ParameterBalls& m, const Ball& x) { return x - Ball(static_cast<double>(phase_turn_of(m, x))) * m.two_pi; }

MapStepProof T_at_t2(const ParameterBalls& m, Budget& budget, bool record = false) {
  return certify_T(m, StartSet::from_t2(m, m.t2.upper()), budget, nullptr, record);
}

}  // namespace

int superstable_condition(const ParameterBalls& m, const MapStepProof& t) {
  if (!t.theta2.verdict) return -1;
  const Ball P = phase_of(m, t.theta2.enclosure);
  if (lt(m.t1, P) && lt(P, m.t2)) return 21;
  if (lt(m.t3, P) && lt(P, m.t0 + m.two_pi)) return 22;
  if (le(m.t2, P) && le(P, m.t3)) return 0;
  return -1;
}

SuperstableProof prove_superstable(double a, double b, double q, double eps_try, bool record) {
  const auto start = std::chrono::steady_clock::now();
  SuperstableProof r;
  auto finish = [&](Outcome v) {
    r.verdict = std::move(v);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  };
  const ParameterBalls m(ParameterBox::point(a, b, q));
  if (Outcome v = m.admissible(); !v) return finish(v);
  {
    static const Vartheta0 v0 = certify_vartheta0(128);
    r.eq2 = lt(2.0 * m.b, m.a) && lt(m.a * v0.sine, m.q) && lt(m.q, m.a);
    r.eq23 = lt(m.q, m.a);
  }
  Budget budget;
  const MapStepProof at = T_at_t2(m, budget, record);
  if (!at.verdict) return finish(Outcome::fail("Theorem 2: T at t2", at.verdict.describe()));
  if (record) {
    r.at.push_back(BallProof::of(StartSet::from_t2(m, m.t2.upper()), m.box(), at));
    if (at.theta2.verdict) r.phase_turn = phase_turn_of(m, at.theta2.enclosure);
  }
  r.T1 = at.t1.enclosure;
  r.theta2 = at.theta2.enclosure;
  r.theta2_phase = phase_of(m, at.theta2.enclosure);
  r.condition = superstable_condition(m, at);
  if (r.condition == 0)
    return finish(
        Outcome::refute("Theorem 2: (21) or (22)", "theta2(t2) mod 2pi = " + r.theta2_phase.str(12) + " lies in [t2, t3]: T(t2) = " + at.T.str(10)));
  if (r.condition < 0) return finish(Outcome::fail("Theorem 2: (21) or (22)", "undecided: theta2(t2) mod 2pi = " + r.theta2_phase.str(12)));
  if (!at.constant_t2) return finish(Outcome::fail("Theorem 2: T(t2) = t2", "T(t2) = " + at.T.str(10)));
  // epsilon: cover [t2, t2 + eps] with closed balls on which T = t2.
  double eps = eps_try;
  if (std::isnan(eps)) {
    if (!oracle::attempt([&] { eps = 0.9 * dfchaos::superstable_check(dfchaos::Parameters(a, b, q), 20000).epsilon; })) eps = 0;
    if (!(eps > 0)) eps = 1e-4;
  }
  const double t2_up = m.t2.upper();
  std::string last_failure;
  for (int attempt = 0; attempt < 12; ++attempt, eps *= 0.5) {
    const double hi = t2_up + eps;
    // A cell [lo, hi]; lo NaN: the ball starts exactly at t2.
    int balls = 0;
    bool used_l1 = false;
    r.cover.clear();
    auto check = [&](const Span& c, int) {
      const StartSet set = std::isnan(c.first) ? StartSet::from_t2(m, c.second) : StartSet::interval(c.first, c.second);
      MapStepProof t = certify_T(m, set, budget, nullptr, record);
      if (t.verdict && t.constant_t2) {
        ++balls;
        used_l1 = used_l1 || t.used_lemma1;
        if (record) r.cover.push_back(BallProof::of(set, m.box(), std::move(t)));
        return CellVerdict::proved();
      }
      Outcome why = Outcome::fail("", "on " + set.describe() + ": " + (t.verdict ? "T not constant" : t.verdict.describe()));
      return budget.exhausted() ? CellVerdict::stop(std::move(why)) : CellVerdict::split(std::move(why));
    };
    auto split = [&](const Span& c, int) -> std::optional<std::pair<Span, Span>> {
      const double from = std::isnan(c.first) ? t2_up : c.first;
      const double mid = 0.5 * (from + c.second);
      if (!(mid > from && mid < c.second)) return std::nullopt;
      return std::make_pair(Span(c.first, mid), Span(mid, c.second));
    };
    if (const Outcome covered = cover(Span(NAN, hi), check, split, 24); !covered) {
      last_failure = covered.detail;
      continue;
    }
    r.eps = eps;
    r.balls = balls;
    r.used_lemma1 = used_l1 || at.used_lemma1;
    // The balls proved Lemma 1 each on its own; a certificate holds it once, over the point.
    if (record && r.used_lemma1) r.lemma1 = certify_lemma1(ParameterBalls(ParameterBox::point(a, b, q)));
    return finish(Outcome::ok());
  }
  return finish(Outcome::fail("Theorem 2: epsilon", "T = t2 on [t2, t2 + eps] not proved for any eps tried (last: " + last_failure + ")"));
}

WindowProof prove_window(double a, double q, double b_lo, double b_hi, double rel, bool record) {
  const auto start = std::chrono::steady_clock::now();
  WindowProof r;
  r.b_lo_float = b_lo;
  r.b_hi_float = b_hi;
  auto finish = [&](Outcome v) {
    r.verdict = std::move(v);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  };
  const double mid = 0.5 * (b_lo + b_hi);
  r.inside = prove_superstable(a, mid, q, 0.0 / 0.0, record);
  if (!r.inside.verdict) return finish(Outcome::fail("window: inside", r.inside.verdict.describe()));
  std::string last;
  for (int attempt = 0; attempt < 4; ++attempt, rel *= 10) {
    r.left_out = b_lo * (1 - rel);
    r.left_in = b_lo * (1 + rel);
    r.right_in = b_hi * (1 - rel);
    r.right_out = b_hi * (1 + rel);
    if (!(r.left_in < r.right_in)) {
      last = "window narrower than the edge brackets";
      break;
    }
    // Outer points: T(t2) certainly differs from t2.
    bool outer_ok = true;
    r.outer.clear();
    for (int side = 0; side < 2 && outer_ok; ++side) {
      const ParameterBalls mo(ParameterBox::point(a, side == 0 ? r.left_out : r.right_out, q));
      Budget budget;
      const MapStepProof t = T_at_t2(mo, budget, record);
      if (record) r.outer.push_back(BallProof::of(StartSet::from_t2(mo, mo.t2.upper()), mo.box(), t));
      Ball& T = side == 0 ? r.T_left_out : r.T_right_out;
      T = t.T;
      if (!t.verdict || t.constant_t2 || !lt(mo.t2, t.T)) {
        last = std::string("T(t2) != t2 not proved at b = ") + format_double(side == 0 ? r.left_out : r.right_out) + ": " + t.verdict.describe();
        outer_ok = false;
      }
    }
    if (!outer_ok) continue;
    // Inside: b-boxes on which T(t2(b)) = t2.
    int boxes = 0;
    r.box_proofs.clear();
    Budget budget;
    budget.max_tests = 20'000'000;
    auto check = [&](const Span& c, int) {
      // T = t2 on [t2(b), t2(b_hi) + e] for every b of the box, with the largest e tried that is
      // proved (from the middle's epsilon, halved): t2 is superstable at each b, with eps >= e.
      const ParameterBalls mb(ParameterBox{a, c.first, c.second, q, q});
      MapStepProof t;
      StartSet set;
      for (double e = r.inside.eps; e > 1e-15 * r.inside.eps; e *= 0.25) {
        set = StartSet::from_t2(mb, mb.t2_at_b_hi.upper() + e);
        t = certify_T(mb, set, budget, nullptr, record);
        if ((t.verdict && t.constant_t2) || budget.exhausted()) break;
      }
      if (t.verdict && t.constant_t2) {
        ++boxes;
        const double eps_box = (set.hi - mb.t2_at_b_hi).lower();  // <= h - t2(b) for every b of the box
        r.min_eps = boxes == 1 ? eps_box : std::min(r.min_eps, eps_box);
        if (record) r.box_proofs.push_back(BallProof::of(set, mb.box(), std::move(t)));
        return CellVerdict::proved();
      }
      Outcome why = Outcome::fail(
          "", "T(t2(b)) = t2 not proved for b in [" + format_double(c.first) + ", " + format_double(c.second) + "]: " + t.verdict.describe());
      return boxes > 20000 || budget.exhausted() ? CellVerdict::stop(std::move(why)) : CellVerdict::split(std::move(why));
    };
    if (const Outcome inside = cover(Span(r.left_in, r.right_in), check, halve, 48); !inside) {
      last = inside.detail;
      continue;
    }
    r.boxes = boxes;
    bool used_lemma1 = false;  // a certificate holds Lemma 1 once, over [left_in, right_in] x {q}
    for (const BallProof& p : r.box_proofs) used_lemma1 = used_lemma1 || p.T.used_lemma1;
    if (used_lemma1) r.lemma1 = certify_lemma1(ParameterBalls(ParameterBox{a, r.left_in, r.right_in, q, q}));
    return finish(Outcome::ok());
  }
  return finish(Outcome::fail("window: edges", last));
}

Theorem2Counterexample prove_theorem2_counterexample(double a, double b, double q, bool record) {
  Theorem2Counterexample r;
  const ParameterBalls m(ParameterBox::point(a, b, q));
  if (Outcome v = m.admissible(); !v) {
    r.verdict = v;
    return r;
  }
  static const Vartheta0 v0 = certify_vartheta0(128);
  if (!(lt(2.0 * m.b, m.a) && lt(m.a * v0.sine, m.q) && lt(m.q, m.a))) {
    r.verdict = Outcome::fail("Theorem 2 counterexample: (2)", "assumptions (2) not proved");
    return r;
  }
  Budget budget;
  const StartSet set = StartSet::from_t2(m, m.t2.upper());
  FirstHitOptions t1_options;
  t1_options.record = record;
  const FirstHitProof t1 = certify_T1(m, set, budget, t1_options);
  if (!t1.verdict) {
    r.verdict = t1.verdict;
    return r;
  }
  const Theta2Proof th = certify_theta2(m, set, t1, budget, record);
  if (!th.verdict) {
    r.verdict = th.verdict;
    return r;
  }
  r.theta2_phase = phase_of(m, th.enclosure);
  if (!(lt(m.t3, r.theta2_phase) && lt(r.theta2_phase, m.t0 + m.two_pi))) {
    r.verdict = Outcome::fail("Theorem 2 counterexample: (22)", "theta2(t2) mod 2pi = " + r.theta2_phase.str(12));
    return r;
  }
  auto u = [&](const Ball& t) { return model::progression_velocity_from_rest(m.a, m.two_c, m.t0, t); };
  r.u_at_t2 = u(m.t2);
  r.u_at_t3 = u(m.t3);
  if (!r.u_at_t2.is_positive() || !r.u_at_t3.is_negative()) {
    r.verdict = Outcome::fail("Theorem 2 counterexample: u(t2) > 0 > u(t3)", "u(t2) = " + r.u_at_t2.str(8) + ", u(t3) = " + r.u_at_t3.str(8));
    return r;
  }
  // t4 by bisection on the sign of u in [t2, t3] (u decreasing there).
  r.T = enclose_sign_change(u, m.t2.upper_ball(), m.t3.lower_ball(), 200);
  r.verdict = Outcome::ok();
  if (record) {
    MapStepProof step;  // the T1 and theta2 proofs from t2; the phase's turn in `turn`
    step.verdict = Outcome::ok();
    step.t1 = t1;
    step.theta2 = th;
    step.t_case = TCase::Unproved;  // T(t2) = t4 comes from scenario D, not from a case of certify_T
    step.turn = phase_turn_of(m, th.enclosure);
    r.at.push_back(BallProof::of(set, m.box(), std::move(step)));
  }
  return r;
}

}  // namespace dfchaos::certified
