// SPDX-License-Identifier: GPL-3.0-or-later
/// @file paper.hpp
/// @brief The paper's formulas as the checker uses them, written again from the paper (no code of the
/// prover): the whole of what a reader must audit against the paper's equations.
#pragma once

#include "interval.hpp"

namespace recheck {

// ---- the formulas, from the paper ----------------------------------------------------------------

/// Eq. (1): f(x) = pi - x - cot(x/2); its zero in (0, pi/2] is vartheta0.
inline Iv f_eq1(const Iv& x) { return pi() - x - cot(0.5 * x); }
/// f'(x) = -1 + 1 / (2 sin^2(x/2)).
inline Iv f_eq1_slope(const Iv& x) {
  const Iv s = sin(0.5 * x);
  return Iv(1.0) / (2.0 * (s * s)) - Iv(1.0);
}
/// Section 2, Eq. (3): the force F(t) = a sin t + 2b, its slope F'(t) = a cos t and F''(t) = -a sin t.
inline Iv F(const Iv& a, const Iv& b, const Iv& t) { return a * sin(t) + 2.0 * b; }
inline Iv F_slope(const Iv& a, const Iv& t) { return a * cos(t); }
inline Iv F_curvature(const Iv& a, const Iv& t) { return -(a * sin(t)); }
/// Section 2: t0 = arcsin((q - 2b)/a) where F = q rises, t1 = pi - t0 where it falls;
/// t2 = pi + arcsin(2b/a) where F = 0 falls, t3 = 2 pi - arcsin(2b/a) where it rises.
inline Iv t0(const Iv& a, const Iv& b, const Iv& q) { return asin((q - 2.0 * b) / a); }
inline Iv t1(const Iv& a, const Iv& b, const Iv& q) { return pi() - t0(a, b, q); }
inline Iv t2(const Iv& a, const Iv& b) { return pi() + asin(2.0 * b / a); }
inline Iv t3(const Iv& a, const Iv& b) { return 2.0 * pi() - asin(2.0 * b / a); }
/// Eq. (7): the velocity of the progression from rest at t0, u(t) = a cos t0 - a cos t + 2c (t - t0),
/// 2c = 2b - q.
inline Iv u_from_t0(const Iv& a, const Iv& b, const Iv& q, const Iv& t) {
  const Iv s = t0(a, b, q);
  return a * cos(s) - a * cos(t) + (2.0 * b - q) * (t - s);
}
/// Eq. (8): u(t2), its value at t2.
inline Iv u_at_t2(const Iv& a, const Iv& b, const Iv& q) { return u_from_t0(a, b, q, t2(a, b)); }
/// Eq. (11): the flight from rest at theta, G1(theta, t) = b (t - theta)^2 - a sin t + a cos theta
/// (t - theta) + a sin theta (zero at the impact T1); its t-derivative is
/// dG1(theta, t) = 2b (t - theta) - a cos t + a cos theta, and d2G1/dt2 = F(t).
inline Iv G1(const Iv& a, const Iv& b, const Iv& th, const Iv& t) { return b * sqr(t - th) - a * sin(t) + a * cos(th) * (t - th) + a * sin(th); }
inline Iv dG1(const Iv& a, const Iv& b, const Iv& th, const Iv& t) { return 2.0 * b * (t - th) - a * cos(t) + a * cos(th); }
/// Eq. (17): the progression after the impact at theta1, G2(theta, theta1, t) = 2b (theta1 - theta)
/// + a cos theta + (2b - q)(t - theta1) - a cos t (zero at the stop theta2); dG2/dt = F(t) - q.
inline Iv G2(const Iv& a, const Iv& b, const Iv& q, const Iv& th, const Iv& th1, const Iv& t) {
  return 2.0 * b * (th1 - th) + a * cos(th) + (2.0 * b - q) * (t - th1) - a * cos(t);
}

/// The symmetric tangencies (proof of Lemma 2, Eq. 14): h(z) = 2z - (a/b) cos z = (2k+1) pi.
inline Iv h_tangency(const Iv& a, const Iv& b, const Iv& z) { return 2.0 * z - a / b * cos(z); }
/// (2k+1) pi.
inline Iv odd_pi(long long k) { return Iv(static_cast<double>(2 * k + 1)) * pi(); }

}  // namespace recheck
