// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/progression.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "dfchaos/certified/bisect.hpp"
#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/oracle.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

Ball G2(const ParameterBalls& m, const Ball& theta, const Ball& theta1, const Ball& t, const Ball& b, const Ball& q) {
  return model::G2(m.a, b, q, theta, theta1, t);
}

namespace {

/// \f$t \mapsto \pm G_2(\theta, \theta_1, t; b, q)\f$ at fixed corner values.
class Velocity final : public NegativityTarget {
 public:
  Velocity(const ParameterBalls& m, const Ball& theta, const Ball& theta1, const Ball& b, const Ball& q, double sign)
      : m_(m), sign_(sign), two_c_(model::two_c(b, q)), base_(model::G2_constant(m.a, b, two_c_, theta, theta1)) {}
  Ball value(const Ball& t) const override { return sign_ * model::G2_shifted(m_.a, two_c_, base_, t); }
  Ball slope(const Ball& t) const override { return sign_ * model::forcing(m_.a, two_c_, t); }
  Ball curvature(const Ball& t) const override { return sign_ * (m_.a * cos(t)); }
  std::string variable() const override { return "t"; }

 private:
  const ParameterBalls& m_;
  double sign_;
  Ball two_c_, base_;
};

/// \f$t \mapsto a\sin t + 2b - q\f$ (the slope of G2 in t).
class Acceleration final : public NegativityTarget {
 public:
  Acceleration(const ParameterBalls& m, const Ball& b, const Ball& q) : m_(m), two_c_(model::two_c(b, q)) {}
  Ball value(const Ball& t) const override { return model::forcing(m_.a, two_c_, t); }
  Ball slope(const Ball& t) const override { return m_.a * cos(t); }
  Ball curvature(const Ball& t) const override { return -(m_.a * sin(t)); }
  std::string variable() const override { return "t"; }

 private:
  const ParameterBalls& m_;
  Ball two_c_;
};

Ball newton_velocity(const Velocity& v, const Ball& guess) {
  Ball x = guess.mid_ball();
  const Ball tol = Ball(std::max(1.0, std::fabs(x.mid())) * std::ldexp(1.0, -static_cast<int>(precision() - 14)));
  for (int it = 0; it < 40; ++it) {
    const Ball f = v.value(x).mid_ball(), d = v.slope(x).mid_ball();
    if (d.contains(0.0)) break;
    const Ball step = (f / d).mid_ball();
    x = (x - step).mid_ball();
    if (lt(abs(step), tol)) break;
  }
  return x;
}

/// A floating guess of the first zero of `g` after t: march on midpoints (step 1e-2, at most
/// 1e6 steps), then bisect; NaN if no sign change is met.
double first_zero_guess(const Velocity& g, double t) {
  constexpr double kStep = 1e-2;
  double lo = t;
  for (int i = 0; i < 1'000'000; ++i) {
    double hi = lo + kStep;
    if (g.value(Ball(hi)).mid() < 0) {
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        if (g.value(Ball(mid)).mid() < 0) {
          hi = mid;
        } else {
          lo = mid;
        }
      }
      return hi;
    }
    lo = hi;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

Ball delta_for(const Ball& x) { return Ball(std::max(1.0, std::fabs(x.mid())) * std::ldexp(1.0, -static_cast<int>(precision() - 24))); }

}  // namespace

Theta2Proof certify_theta2(const ParameterBalls& m, const StartSet& set, const FirstHitProof& t1, Budget& budget, bool record, bool retry) {
  Theta2Proof r;
  if (!t1.verdict) {
    r.verdict = Outcome::fail("theta2: needs T1", "T1 not proved");
    return r;
  }
  const Ball th_min = set.theta_min(m), th_max = set.theta_max(m);
  const Velocity gmin(m, th_min, t1.t_lo, m.b_lo, m.q_hi, 1.0);
  const Velocity gmax(m, th_max, t1.t_hi, m.b_hi, m.q_lo, 1.0);
  const double a = m.box().a;
  // One proof from floating guesses of theta2 at the two corners.
  auto attempt = [&](double guess_min, double guess_max) {
    Theta2Proof r;
    if (std::isnan(guess_min) || std::isnan(guess_max)) {
      r.verdict = Outcome::fail("theta2: guess", "the floating-point layer gave no theta2 at the corners");
      return r;
    }
    const Ball rho_min = newton_velocity(gmin, Ball(guess_min));
    const Ball rho_max = newton_velocity(gmax, Ball(guess_max));
    bool ok = false;
    Ball d = delta_for(rho_min);
    for (int k = 0; k < 4 && !ok; ++k, d = d * Ball(std::ldexp(1.0, 24))) {
      r.u_lo = (rho_min - d).lower_ball();
      ok = gmin.value(r.u_lo).is_positive();
    }
    if (!ok) {
      r.verdict = Outcome::fail("theta2: bracket", "G2 > 0 at the left end not proved near t = " + rho_min.mid_str(20));
      return r;
    }
    ok = false;
    d = delta_for(rho_max);
    for (int k = 0; k < 4 && !ok; ++k, d = d * Ball(std::ldexp(1.0, 24))) {
      r.u_hi = (rho_max + d).upper_ball();
      ok = gmax.value(r.u_hi).is_negative();
    }
    if (!ok) {
      r.verdict = Outcome::fail("theta2: bracket", "G2 < 0 at the right end not proved near t = " + rho_max.mid_str(20));
      return r;
    }
    if (!lt(t1.t_hi, r.u_lo)) {
      r.verdict = Outcome::fail("theta2: bracket", "the theta2 bracket does not start after the T1 enclosure");
      return r;
    }
    if (!lt(r.u_lo, r.u_hi)) {
      r.verdict = Outcome::fail("theta2: bracket", "the corners' stops are out of order");
      return r;
    }
    r.enclosure = Ball::hull(r.u_lo, r.u_hi);
    // G2 > 0 from the impact to u_lo: the first zero is not earlier.
    const Velocity minus_gmin(m, th_min, t1.t_lo, m.b_lo, m.q_hi, -1.0);
    // (Failures of the corner functions refute nothing: they mix the corners of the set.)
    if (Outcome v = prove_negative(minus_gmin, t1.t_lo, r.u_lo, budget, "theta2: no earlier stop", &r.stats, record ? &r.no_earlier_stop : nullptr);
        !v) {
      v.refuted = false;
      r.verdict = v;
      return r;
    }
    // dG2/dt < 0 on the bracket: a simple zero.
    const Acceleration acc(m, m.b_hi, m.q_lo);
    if (Outcome v = prove_negative(acc, r.u_lo, r.u_hi, budget, "theta2: simple zero (F - q < 0)", &r.stats, record ? &r.simple_zero : nullptr); !v) {
      v.refuted = false;
      r.verdict = v;
      return r;
    }
    r.verdict = Outcome::ok();
    return r;
  };
  Theta2Proof first =
      attempt(oracle::theta2(a, m.box().b_lo, m.box().q_hi, th_min.mid()), oracle::theta2(a, m.box().b_hi, m.box().q_lo, th_max.mid()));
  if (first.verdict || !retry) return first;
  // The floating layer follows its own T1, which near a discontinuity of T1 may be the other
  // branch (or a proof may skip a window on purpose): then guess from this proof's T1 instead.
  // If that fails too, the first failure is reported.
  Theta2Proof second = attempt(first_zero_guess(gmin, t1.t_lo.mid()), first_zero_guess(gmax, t1.t_hi.mid()));
  return second.verdict ? second : first;
}

StopArcProof certify_stop_arc(const ParameterBalls& m, const StartSet& set, const FirstHitProof& t1, Budget& budget, bool record) {
  StopArcProof r;
  if (!t1.verdict) {
    r.verdict = Outcome::fail("stop arc: needs T1", "T1 not proved");
    return r;
  }
  const Ball th_min = set.theta_min(m), th_max = set.theta_max(m);
  const Velocity gmin(m, th_min, t1.t_lo, m.b_lo, m.q_hi, 1.0);
  const Velocity gmax(m, th_max, t1.t_hi, m.b_hi, m.q_lo, 1.0);
  const double guess = oracle::theta2(m.box().a, m.box().b_hi, m.box().q_lo, th_max.mid());
  if (std::isnan(guess)) {
    r.verdict = Outcome::fail("stop arc: guess", "the floating-point layer gave no theta2");
    return r;
  }
  const Ball rho = newton_velocity(gmax, Ball(guess));
  bool ok = false;
  Ball d = delta_for(rho);
  for (int k = 0; k < 5 && !ok; ++k, d = d * Ball(std::ldexp(1.0, 16))) {
    r.tau = (rho + d).upper_ball();
    ok = gmax.value(r.tau).is_negative() && lt(t1.t_hi, r.tau);
  }
  if (!ok) {
    r.verdict = Outcome::fail("stop arc: G2 < 0", "no certified negative velocity after the impact near t = " + rho.mid_str(17));
    return r;
  }
  // The turn of tau after t3; tau may have run far out while d grew by 2^16 per try: beyond 2^53 turns
  // no integer turn is meaningful (and the cast to long long would be undefined).
  const double turns = std::floor((r.tau.mid() - m.t3.mid()) / (2 * M_PI));
  if (!(std::fabs(turns) < 0x1p53)) {
    r.verdict = Outcome::fail("stop arc: G2 < 0", "the first certified negative velocity lies beyond 2^53 turns of t3");
    return r;
  }
  r.k = static_cast<long long>(turns);
  const Ball shift = Ball(static_cast<double>(r.k)) * m.two_pi;
  const Ball A = m.t3 + shift, E = m.t2 + shift + m.two_pi;
  if (!lt(r.tau, E)) {
    r.verdict = Outcome::fail("stop arc: end", "the velocity is not proved negative before t2 of the arc");
    return r;
  }
  if (le(A, t1.t_lo)) {
    r.from = t1.t_lo;
    r.from_impact = true;
  } else {
    const Ball A_up = A.upper_ball();
    if (!lt(t1.t_lo, A_up) || !lt(A_up, r.tau)) {
      r.verdict = Outcome::fail("stop arc: start", "t3 of the arc not between the impact and the stop");
      return r;
    }
    const Velocity minus_gmin(m, th_min, t1.t_lo, m.b_lo, m.q_hi, -1.0);
    if (Outcome v =
            prove_negative(minus_gmin, t1.t_lo, A_up, budget, "stop arc: no stop before t3", &r.stats, record ? &r.no_stop_before_t3 : nullptr);
        !v) {
      v.refuted = false;
      r.verdict = v;
      return r;
    }
    r.from = A;
    r.from_end = A_up;
  }
  r.needs_lemma1 = !le(m.t1 + shift + m.two_pi, r.from);
  r.verdict = Outcome::ok();
  return r;
}

// ---- Lemma 1 --------------------------------------------------------------------------------------

Ball lemma1_velocity_at_t2(const Ball& a, const Ball& b, const Ball& q) {
  return model::progression_velocity_from_rest(a, model::two_c(b, q), model::t0(a, b, q), model::t2(a, b));
}

namespace {

/// Refines t4 in [t1, t2] for a point box by bisection on the sign of u (decreasing there).
Ball enclose_t4(const ParameterBalls& m) {
  auto u = [&](const Ball& t) { return model::progression_velocity_from_rest(m.a, m.two_c, m.t0, t); };
  return enclose_sign_change(u, m.t1.lower_ball(), m.t2.upper_ball(), 200);
}

}  // namespace

Lemma1Proof certify_lemma1(const ParameterBalls& m, int max_pieces) {
  Lemma1Proof r;
  if (Outcome v = m.admissible(); !v) {
    r.verdict = v;
    return r;
  }
  bool first = true;
  auto check = [&](const Lemma1SubBox& p, int) {
    if (++r.pieces > max_pieces)
      return CellVerdict::stop(Outcome::fail("Lemma 1: u(t2) < 0", "more than " + std::to_string(max_pieces) + " sub-boxes needed"));
    const Ball u = lemma1_velocity_at_t2(m.a, Ball::interval(p.b_lo, p.b_hi), Ball::interval(p.q_lo, p.q_hi));
    r.u_at_t2 = first ? u : Ball::hull(r.u_at_t2, u);
    first = false;
    if (u.is_negative()) {
      r.sub_boxes.push_back(p);
      return CellVerdict::proved();
    }
    if (u.is_positive())
      return CellVerdict::stop(Outcome::refute("Lemma 1: u(t2) < 0 (Eq. 8)", "u(t2) = " + u.str(8) + " > 0 at b in [" + format_double(p.b_lo) + ", " +
                                                                                 format_double(p.b_hi) + "], q in [" + format_double(p.q_lo) + ", " +
                                                                                 format_double(p.q_hi) + "]"));
    return CellVerdict::split(Outcome::fail(
        "Lemma 1: u(t2) < 0 (Eq. 8)", "undecided at b = " + format_double(p.b_lo) + ", q = " + format_double(p.q_lo) + ": u(t2) = " + u.str(8)));
  };
  // Halves in b while the box is at least a quarter as wide in b as in q, else in q.
  auto split = [](const Lemma1SubBox& p, int) -> std::optional<std::pair<Lemma1SubBox, Lemma1SubBox>> {
    const double bm = 0.5 * (p.b_lo + p.b_hi), qm = 0.5 * (p.q_lo + p.q_hi);
    const bool split_b = (p.b_hi - p.b_lo) >= (p.q_hi - p.q_lo) * 0.25 && bm > p.b_lo && bm < p.b_hi;
    const bool split_q = !split_b && qm > p.q_lo && qm < p.q_hi;
    if (split_b) return std::make_pair(Lemma1SubBox{p.b_lo, bm, p.q_lo, p.q_hi}, Lemma1SubBox{bm, p.b_hi, p.q_lo, p.q_hi});
    if (split_q) return std::make_pair(Lemma1SubBox{p.b_lo, p.b_hi, p.q_lo, qm}, Lemma1SubBox{p.b_lo, p.b_hi, qm, p.q_hi});
    return std::nullopt;
  };
  if (Outcome v = cover(Lemma1SubBox{m.box().b_lo, m.box().b_hi, m.box().q_lo, m.box().q_hi}, check, split, std::numeric_limits<int>::max()); !v) {
    r.verdict = std::move(v);
    return r;
  }
  r.t4 = m.box().is_point() ? enclose_t4(m) : Ball::hull(m.t1, m.t2);
  r.verdict = Outcome::ok();
  return r;
}

Lemma1Bound lemma1_b0_lower_bound(double a, double q, double resolution, int max_pieces) {
  Lemma1Bound r;
  const Ball A(a), Q(q);
  auto u_at = [&](double b) { return lemma1_velocity_at_t2(A, Ball(b), Q); };
  if (!u_at(0.0).is_negative()) {
    r.verdict = Outcome::fail("Lemma 1: b0(q)", "u(t2) < 0 not proved at b = 0 (needs q > a sin(vartheta0), Eq. 9)");
    return r;
  }
  // Floating estimate of the first sign change (bisection on the certified sign where decidable).
  double lo = 0, hi = std::min(0.5 * q, 0.5 * a) * (1 - 1e-12);
  if (u_at(hi).is_negative()) {
    r.b_float = hi;
  } else {
    // March to the first b where u is not negative, then bisect.
    const int n = 4096;
    double prev = 0;
    for (int i = 1; i <= n; ++i) {
      const double b = hi * i / n;
      if (!u_at(b).is_negative()) {
        lo = prev;
        hi = b;
        break;
      }
      prev = b;
    }
    r.b_float = bisect([&](double b) { return u_at(b).is_negative(); }, lo, hi, {.max_iterations = 200, .rel_tol = 1e-17}).first;
  }
  double b_low = r.b_float * (1 - resolution);
  for (int attempt = 0; attempt < 20; ++attempt, b_low *= 0.9) {
    // Admissibility on [0, b_low]: 2b < a, q > 2b, q - 2b < a.
    const Ball Bmax(b_low);
    if (!(lt(2.0 * Bmax, A) && lt(2.0 * Bmax, Q) && lt(Q, A))) continue;
    int pieces = 0;
    r.b_pieces.clear();
    // A failed attempt is not reported (the next, smaller b_low is tried): its outcomes are empty.
    auto check = [&](const Span& c, int) {
      if (++pieces > max_pieces) return CellVerdict::stop(Outcome::fail("", ""));
      const Ball u = lemma1_velocity_at_t2(A, Ball::interval(c.first, c.second), Q);
      if (u.is_negative()) {
        r.b_pieces.push_back({c.first, c.second, q, q});
        return CellVerdict::proved();
      }
      return u.is_positive() ? CellVerdict::stop(Outcome::fail("", "")) : CellVerdict::split(Outcome::fail("", ""));
    };
    const bool ok = cover(Span(0.0, b_low), check, halve, std::numeric_limits<int>::max()).proved;
    if (ok) {
      r.b_low = b_low;
      r.pieces = pieces;
      r.verdict = Outcome::ok();
      return r;
    }
  }
  r.verdict = Outcome::fail("Lemma 1: b0(q)", "no b_low proved within 20 attempts below " + format_double(r.b_float));
  return r;
}

}  // namespace dfchaos::certified
