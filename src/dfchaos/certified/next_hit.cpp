// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/next_hit.hpp"

#include <cmath>
#include <stdexcept>

#include "dfchaos/certified/oracle.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

// ---- start sets ---------------------------------------------------------------------------------

StartSet StartSet::interval(double lo, double hi) {
  if (!(lo <= hi)) throw std::invalid_argument("StartSet::interval: lo <= hi required");
  StartSet s;
  s.lo = Ball(lo);
  s.hi = Ball(hi);
  return s;
}

StartSet StartSet::balls(const Ball& lo, const Ball& hi) {
  StartSet s;
  s.lo = lo.mid_ball();
  s.hi = hi.mid_ball();
  return s;
}

StartSet StartSet::from_t2(const ParameterBalls& m, double hi) {
  StartSet s;
  s.lo = m.t2;
  s.hi = Ball(hi);
  s.lo_is_t2 = true;
  return s;
}

StartSet StartSet::at_t2() {
  StartSet s;
  s.kind = Kind::AtT2;
  return s;
}

Ball StartSet::theta_min(const ParameterBalls& m) const { return kind == Kind::AtT2 || lo_is_t2 ? m.t2_at_b_lo : lo; }
Ball StartSet::theta_max(const ParameterBalls& m) const { return kind == Kind::AtT2 ? m.t2_at_b_hi : hi; }
Ball StartSet::hull(const ParameterBalls& m) const { return kind == Kind::AtT2 ? m.t2 : Ball::hull(lo, hi); }

Outcome StartSet::valid(const ParameterBalls& m) const {
  if (kind == Kind::AtT2) return Outcome::ok();
  if (!le(lo, hi) && !lo_is_t2) return Outcome::fail("start set", "lo <= hi not proved");
  if (lo_is_t2) {
    // Every b has a start: t2(b) <= t2(b_hi) <= hi. The min corner is t2(b_lo), inside the ball lo.
    if (!le(m.t2_at_b_hi, hi)) return Outcome::fail("start set", "t2(b) <= theta_hi not proved at b_hi");
  } else if (!le(m.t2_at_b_hi, lo)) {
    return Outcome::fail("start set", "t2 <= theta not proved at theta = " + lo.mid_str(17));
  }
  const Ball t3_hi = model::t3(m.a, m.b_hi);
  if (!lt(hi, t3_hi)) return Outcome::fail("start set", "theta < t3 not proved at theta = " + hi.mid_str(17));
  return Outcome::ok();
}

std::string StartSet::describe() const {
  if (kind == Kind::AtT2) return "theta = t2(b)";
  if (lo_is_t2) return "theta in [t2, " + hi.mid_str(17) + "]";
  if (arb_equal(lo.get(), hi.get())) return "theta = " + lo.mid_str(17);
  return "theta in [" + lo.mid_str(17) + ", " + hi.mid_str(17) + "]";
}

// ---- G1 -----------------------------------------------------------------------------------------

Ball G1(const ParameterBalls& m, const Ball& theta, const Ball& t, const Ball& b) { return model::G1(m.a, b, theta, t); }

Ball dG1_dt(const ParameterBalls& m, const Ball& theta, const Ball& t, const Ball& b) { return model::dG1_dt(m.a, b, theta, t); }

namespace {

/// \f$s \mapsto G_1(\theta, \theta + s; b)\f$ at a (nearly) thin corner, with its quadratic envelope.
class FlightGap final : public NegativityTarget {
 public:
  FlightGap(const ParameterBalls& m, const Ball& theta, const Ball& b) : m_(m), theta_(theta), b_(b) { sin_cos(theta, st_, ct_); }
  Ball value(const Ball& s) const override { return model::G1_from_start(m_.a, b_, st_, ct_, s, theta_ + s); }
  Ball slope(const Ball& s) const override { return model::dG1_dt_from_start(m_.a, b_, ct_, s, theta_ + s); }
  Ball curvature(const Ball& s) const override { return model::F(m_.a, b_, theta_ + s); }
  bool envelope_negative(const Ball& lo, const Ball& hi) const override {
    // U >= G1, convex in s: negative at both ends means negative in between.
    auto U = [&](const Ball& s) { return model::G1_envelope_from_start(m_.a, b_, st_, ct_, s); };
    return U(lo).is_negative() && U(hi).is_negative();
  }
  std::string variable() const override { return "s"; }

 private:
  const ParameterBalls& m_;
  Ball theta_, b_, st_, ct_;
};

/// \f$t \mapsto -\partial_t G_1(\theta, t; b)\f$ (negative = the root is simple).
class MinusVelocity final : public NegativityTarget {
 public:
  MinusVelocity(const ParameterBalls& m, const Ball& theta, const Ball& b) : m_(m), theta_(theta), b_(b), ct_(cos(theta)) {}
  Ball value(const Ball& t) const override { return -model::dG1_dt_from_start(m_.a, b_, ct_, t - theta_, t); }
  Ball slope(const Ball& t) const override { return -model::F(m_.a, b_, t); }
  Ball curvature(const Ball& t) const override { return -model::dF_dt(m_.a, t); }
  std::string variable() const override { return "t"; }

 private:
  const ParameterBalls& m_;
  Ball theta_, b_, ct_;
};

Ball delta_for(const Ball& x) {
  const double scale = std::max(1.0, std::fabs(x.mid()));
  return Ball(scale * std::ldexp(1.0, -static_cast<int>(precision() - 24)));
}

}  // namespace

Ball departure_E(const Ball& s_hi) { return Ball::hull(Ball(1.0) / 24.0 - sqr(s_hi) / 720.0, Ball(1.0) / 24.0); }

Ball departure_K(const Ball& s_hi) { return Ball::hull(Ball(-1.0) / 6.0, Ball(-1.0) / 6.0 + sqr(s_hi) / 120.0); }

Outcome prove_departure(const ParameterBalls& m, const StartSet& set, const Ball& s0) {
  if (!s0.is_positive() || !le(s0, Ball(1.0))) return Outcome::fail("T1: departure", "s0 must be in (0, 1]");
  const Ball th = set.hull(m);
  Ball st, ct;
  sin_cos(th, st, ct);
  const Ball S = Ball::hull(Ball(0.0), s0);
  const Ball E = departure_E(s0), K = departure_K(s0);
  const Ball g = -(m.a * st * S * E) - m.a * ct * K;
  // b + (a/2) sin(theta) <= 0 on [t2(b), t3(b)] (the start set was proved valid).
  if (g.is_negative()) return Outcome::ok();
  const Ball F0 = m.b + 0.5 * m.a * st;
  if ((F0 + S * g).is_negative()) return Outcome::ok();
  return Outcome::fail("T1: departure", "G1 < 0 just after theta not proved on s in (0, " + s0.mid_str(6) + "] (g = " + g.str(5) + ")");
}

Ball newton_G1(const ParameterBalls& m, const Ball& theta, const Ball& b, const Ball& guess) {
  const Ball th = theta.mid_ball(), bb = b.mid_ball();
  Ball x = guess.mid_ball();
  const Ball tol = delta_for(x) * Ball(1.0 / 1024.0);
  for (int it = 0; it < 40; ++it) {
    const Ball f = G1(m, th, x, bb), d = dG1_dt(m, th, x, bb);
    if (d.contains(0.0) || !d.is_finite()) break;
    const Ball step = (f / d).mid_ball();
    x = (x - step).mid_ball();
    if (lt(abs(step), tol)) break;
  }
  return x;
}

Outcome certify_no_contact(const ParameterBalls& m, const StartSet& set, const Ball& t_end, Budget& budget,
                           const std::vector<std::pair<Ball, Ball>>& skip, NegativityStats* stats, Ball* s0_used, NegativityRecord* record) {
  if (Outcome v = set.valid(m); !v) return v;
  const Ball th_min = set.theta_min(m), th_max = set.theta_max(m);
  // 1. departure over the whole set.
  const Ball w = (th_max - th_min).upper_ball();
  Ball s0;
  Outcome dep = Outcome::fail("T1: departure", "start set wider than 1/2");
  for (double c : {0.5, 0.125, 1.0 / 32, 1.0 / 256}) {
    s0 = Ball(c);
    if (lt(s0, w)) break;
    dep = prove_departure(m, set, s0);
    if (dep) break;
  }
  if (!dep) return dep;
  if (s0_used) *s0_used = s0;
  // 2. no earlier root at the max corner, s in [s0, t_end - theta_max] minus the skipped windows.
  FlightGap gap(m, th_max, m.b_hi);
  std::vector<std::pair<Ball, Ball>> segs;
  Ball start = s0;
  const Ball s_end = (t_end - th_max).upper_ball();
  for (const auto& [wl, wh] : skip) {
    const Ball a_end = (wl - th_max).upper_ball(), b_start = (wh - th_max).lower_ball();
    if (lt(start, a_end)) segs.emplace_back(start, min(a_end, s_end));
    if (lt(start, b_start)) start = b_start;
  }
  if (lt(start, s_end)) segs.emplace_back(start, s_end);
  for (const auto& [x1, x2] : segs) {
    if (!le(x1, x2)) continue;
    Outcome v = prove_negative(gap, x1, x2, budget, "T1: no earlier root", stats, record);
    if (!v) return v;
  }
  return Outcome::ok();
}

FirstHitProof certify_T1(const ParameterBalls& m, const StartSet& set, Budget& budget, const FirstHitOptions& opt) {
  poll_stop();  // stop.hpp: every first contact isolated is a poll
  FirstHitProof r;
  if (Outcome v = set.valid(m); !v) {
    r.verdict = v;
    return r;
  }
  const Ball th_min = set.theta_min(m), th_max = set.theta_max(m);
  const double a = m.box().a;
  double g_max = opt.guess_at_max, g_min = opt.guess_at_min;
  if (std::isnan(g_max)) g_max = oracle::T1(a, m.box().b_hi, th_max.mid());
  if (std::isnan(g_min)) g_min = oracle::T1(a, m.box().b_lo, th_min.mid());
  if (std::isnan(g_max) || std::isnan(g_min)) {
    r.verdict = Outcome::fail("T1: guess", "the floating-point layer gave no T1 at the corners");
    return r;
  }
  // 3. bracket at the corners.
  const Ball rho_hi = newton_G1(m, th_max, m.b_hi, Ball(g_max));
  const Ball rho_lo = newton_G1(m, th_min, m.b_lo, Ball(g_min));
  bool ok = false;
  Ball d = delta_for(rho_hi);
  for (int k = 0; k < 4 && !ok; ++k, d = d * Ball(std::ldexp(1.0, 24))) {
    r.t_lo = (rho_hi - d).lower_ball();
    ok = G1(m, th_max, r.t_lo, m.b_hi).is_negative();
  }
  if (!ok) {
    r.verdict = Outcome::fail("T1: bracket", "G1 < 0 at the left end of the bracket not proved near t = " + rho_hi.mid_str(20));
    return r;
  }
  ok = false;
  d = delta_for(rho_lo);
  for (int k = 0; k < 4 && !ok; ++k, d = d * Ball(std::ldexp(1.0, 24))) {
    r.t_hi = (rho_lo + d).upper_ball();
    ok = G1(m, th_min, r.t_hi, m.b_lo).is_positive();
  }
  if (!ok) {
    r.verdict = Outcome::fail("T1: bracket", "G1 > 0 at the right end of the bracket not proved near t = " + rho_lo.mid_str(20));
    return r;
  }
  if (!lt(r.t_lo, r.t_hi)) {
    r.verdict = Outcome::fail("T1: bracket", "the corners' roots are out of order (different branches of T1?)");
    return r;
  }
  if (!lt(th_max, r.t_lo)) {  // the monotonicity in theta needs t > theta
    r.verdict = Outcome::fail("T1: bracket", "the bracket does not start after the start phases");
    return r;
  }
  r.enclosure = Ball::hull(r.t_lo, r.t_hi);
  // 4. simple root: dG1/dt > 0 on the bracket at the min corner.
  {
    MinusVelocity mv(m, th_min, m.b_lo);
    Outcome v = prove_negative(mv, r.t_lo, r.t_hi, budget, "T1: simple root (dG1/dt > 0)", &r.stats, opt.record ? &r.simple_root : nullptr);
    if (!v) {
      v.refuted = false;  // the bracket is ours: dG1/dt <= 0 somewhere in it refutes nothing about T1
      r.verdict = v;
      return r;
    }
  }
  // 1-2. departure, and no earlier root.
  if (Outcome v = certify_no_contact(m, set, r.t_lo, budget, opt.skip, &r.stats, &r.s0, opt.record ? &r.no_contact : nullptr); !v) {
    r.verdict = v;
    return r;
  }
  r.v1_at_max = dG1_dt(m, th_max, r.t_lo, m.b_hi);
  r.verdict = Outcome::ok();
  return r;
}

}  // namespace dfchaos::certified
