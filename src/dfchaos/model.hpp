// SPDX-License-Identifier: GPL-3.0-or-later
/// @file model.hpp
/// @brief The formulas of the model, written once as templates on the scalar type: the force
/// \f$F\f$, the switching phases \f$t_0, \dots, t_3\f$, the flight gap \f$G_1\f$ and its
/// derivatives and envelope, the progression velocity \f$G_2\f$ and the velocity of a progression
/// from rest.
///
/// Each template is instantiated for `double` and `long double` (the numerical core) and for
/// `certified::Ball` (the certified layer, dfchaos/certified/ball.hpp): a formula of the paper has
/// one definition here, whatever the arithmetic it is evaluated in. The trigonometric functions
/// are found by argument-dependent lookup (`using std::sin` covers the built-in types, the Ball
/// overloads are found beside the Ball type), and \f$\pi\f$ of the arithmetic comes from
/// `Constants<S>`. The operations are written in the order in which the callers evaluated them, so
/// that an instantiation gives the same bits as the expression it replaced (except the core's
/// G2 of return_map.cpp, now wholly in long double, which no output uses).
///
/// Where the core needs more than the plain formula, the accurate form lives beside the object it
/// serves and is tested against the template here: the gap \f$G_1\f$ far from its origin is
/// evaluated by QuadraticPlusHarmonic (roots.hpp: the polynomial re-centred in double-double,
/// the coefficient of \f$s\f$ with a long-double or double-double tail, motion.cpp), and the
/// motions of HarmonicMotion keep elapsed times in long double and phases in double
/// (phase.hpp's Instant).
///
/// Throughout, \f$s = t - \theta\f$ is the elapsed time since the start \f$\theta\f$; the forms
/// "from a start" take \f$\sin\theta\f$, \f$\cos\theta\f$ and \f$s\f$ computed once by the caller
/// (a search evaluates many \f$t\f$ for one start) and the phase \f$t\f$ at which the forcing
/// is evaluated.
#pragma once

#include <cmath>

#include "dfchaos/phase.hpp"

namespace dfchaos::model {

/// \f$\pi\f$ in the arithmetic S: specialised for double and long double here and for
/// certified::Ball in dfchaos/certified/ball.hpp.
template <class S>
struct Constants;

// The double instantiation of t3 doubles pi, which must give two_pi to the bit.
static_assert(2.0 * dfchaos::pi == two_pi);

/// \f$\pi\f$ rounded to double.
template <>
struct Constants<double> {
  static double pi() { return dfchaos::pi; }  ///< \f$\pi\f$
};

/// \f$\pi\f$ rounded to long double.
template <>
struct Constants<long double> {
  static long double pi() { return two_pi_l / 2; }  ///< \f$\pi\f$
};

/// \f$x^2\f$ (the Ball overload, tighter for balls containing 0, is found by argument-dependent
/// lookup).
template <class S>
S sqr(const S& x) {
  return x * x;
}

/// \f$\sin x\f$ and \f$\cos x\f$ (the Ball overload computes both at once).
template <class S>
void sin_cos(const S& x, S& s, S& c) {
  using std::cos;
  using std::sin;
  s = sin(x);
  c = cos(x);
}

// ---- the force (Eqs. 3 and 4) -------------------------------------------------------------------

/// \f$a\sin t + 2k\f$: the force of free flight (\f$2k = 2b\f$, Eq. 3) and of progression
/// (\f$2k = 2c = 2b - q\f$, Eq. 4).
template <class S>
S forcing(const S& a, const S& two_k, const S& t) {
  using std::sin;
  return a * sin(t) + two_k;
}

/// \f$F(t) = a\sin t + 2b\f$ (Eq. 3), also \f$\partial_t^2 G_1\f$ (proof of Lemma 2).
template <class S>
S F(const S& a, const S& b, const S& t) {
  return forcing(a, 2.0 * b, t);
}

/// \f$\partial_t F = a\cos t\f$ (Eq. 3): also \f$\partial_t^3 G_1\f$ and \f$-\partial_t^2\f$ of the velocity
/// deficit \f$-\partial_t G_1\f$ (the curvature a proof of a simple root bounds).
template <class S>
S dF_dt(const S& a, const S& t) {
  using std::cos;
  return a * cos(t);
}

/// \f$2c = 2b - q\f$ (Eq. 4): twice the constant force of a progression.
template <class S>
S two_c(const S& b, const S& q) {
  return 2.0 * b - q;
}

// ---- the switching phases (Section 2) -----------------------------------------------------------

/// \f$\arcsin((q - 2b)/a) \in [-\pi/2, \pi/2]\f$, where \f$F = q\f$ and \f$F\f$ rises: \f$t_0\f$ up
/// to a whole turn (equal to \f$t_0\f$ when \f$q \ge 2b\f$). Defined iff \f$|q - 2b| \le a\f$.
template <class S>
S t0(const S& a, const S& b, const S& q) {
  using std::asin;
  return asin((q - 2.0 * b) / a);
}

/// \f$t_1 = \pi - \arcsin((q - 2b)/a)\f$, where \f$F = q\f$ and \f$F\f$ falls.
template <class S>
S t1(const S& a, const S& b, const S& q) {
  return Constants<S>::pi() - t0(a, b, q);
}

/// \f$\arcsin(2b/a)\f$: the shift of the zeros of \f$F\f$ from \f$\pi\f$ and \f$2\pi\f$.
template <class S>
S zero_shift(const S& a, const S& b) {
  using std::asin;
  return asin(2.0 * b / a);
}

/// \f$t_2 = \pi + \arcsin(2b/a)\f$, where \f$F = 0\f$ and \f$F\f$ falls (defined iff \f$2b \le a\f$).
template <class S>
S t2(const S& a, const S& b) {
  return Constants<S>::pi() + zero_shift(a, b);
}

/// \f$t_3 = 2\pi - \arcsin(2b/a)\f$, where \f$F = 0\f$ and \f$F\f$ rises.
template <class S>
S t3(const S& a, const S& b) {
  return 2.0 * Constants<S>::pi() - zero_shift(a, b);
}

// ---- the flight gap G1 (Eq. 11) ----------------------------------------------------------------

/// \f$G_1(\theta, t) = b s^2 - a\sin t + a\cos\theta\, s + a\sin\theta\f$, \f$s = t - \theta\f$
/// (Eq. 11), from a start: `sin_theta`, `cos_theta` are \f$\sin\theta, \cos\theta\f$ and `t` is
/// \f$t\f$ (or its phase: only \f$\sin t\f$ enters). The position of the mass after a start at rest at
/// the delimiter at \f$\theta\f$ (Eq. 6 with \f$c\f$ replaced by \f$b\f$).
template <class S>
S G1_from_start(const S& a, const S& b, const S& sin_theta, const S& cos_theta, const S& s, const S& t) {
  using std::sin;
  return b * sqr(s) - a * sin(t) + a * cos_theta * s + a * sin_theta;
}

/// \f$G_1(\theta, t)\f$ of Eq. (11).
template <class S>
S G1(const S& a, const S& b, const S& theta, const S& t) {
  S st, ct;
  sin_cos(theta, st, ct);
  return G1_from_start(a, b, st, ct, S(t - theta), t);
}

/// \f$U(s) = b s^2 + a\cos\theta\, s + a\sin\theta + a\f$, from a start (see G1_from_start): the
/// quadratic envelope of the flight gap of Eq. (11). Since \f$-a\sin t \le a\f$, \f$G_1 \le U\f$, and U
/// is convex in \f$s\f$: where U is negative at both ends of an interval of \f$s\f$, the flight
/// cannot touch the delimiter in between. The core's root search uses the same bound for any
/// QuadraticPlusHarmonic, as \f$\alpha s^2 + \beta s + \gamma + R\f$ (roots.hpp; for \f$G_1\f$:
/// \f$\alpha = b\f$, \f$\beta = a\cos\theta\f$, \f$\gamma = a\sin\theta\f$, \f$R = a\f$), where it solves
/// \f$U = 0\f$ for \f$s\f$ instead of evaluating U; test_model checks that the two agree.
template <class S>
S G1_envelope_from_start(const S& a, const S& b, const S& sin_theta, const S& cos_theta, const S& s) {
  return b * sqr(s) + a * cos_theta * s + a * sin_theta + a;
}

/// \f$\partial_t G_1 = 2b s - a\cos t + a\cos\theta\f$, from a start (see G1_from_start): the
/// velocity of the mass; zero at a root of \f$G_1\f$ it is the tangency condition (14).
template <class S>
S dG1_dt_from_start(const S& a, const S& b, const S& cos_theta, const S& s, const S& t) {
  using std::cos;
  return 2.0 * b * s - a * cos(t) + a * cos_theta;
}

/// \f$\partial_t G_1(\theta, t) = 2b(t - \theta) - a\cos t + a\cos\theta\f$.
template <class S>
S dG1_dt(const S& a, const S& b, const S& theta, const S& t) {
  using std::cos;
  return dG1_dt_from_start(a, b, S(cos(theta)), S(t - theta), t);
}

/// \f$\partial_\theta G_1 = -F(\theta)\,s\f$, \f$s = t - \theta\f$ (proof of Lemma 2): positive for
/// \f$\theta \in (t_2, t_3)\f$ and \f$t > \theta\f$.
template <class S>
S dG1_dtheta(const S& a, const S& b, const S& theta, const S& s) {
  return -F(a, b, theta) * s;
}

// ---- the first progression G2 (Eq. 17) and a progression from rest (Eq. 7) ---------------------

/// \f$G_2(\theta, \theta_1, t) = 2b s_1 + a\cos\theta + 2c\, s_{21} - a\cos t\f$ with
/// \f$s_1 = \theta_1 - \theta\f$, \f$s_{21} = t - \theta_1\f$ (Eq. 17): the velocity at \f$t\f$ of the
/// progression that starts with the impact at \f$\theta_1 = T_1(\theta)\f$ (its value at
/// \f$t = \theta_1\f$ is \f$\partial_t G_1(\theta, \theta_1)\f$). `t` may be the phase of \f$t\f$.
template <class S>
S G2_from_start(const S& a, const S& b, const S& two_c, const S& cos_theta, const S& s1, const S& s21, const S& t) {
  using std::cos;
  return 2.0 * b * s1 + a * cos_theta + two_c * s21 - a * cos(t);
}

/// \f$G_2(\theta, \theta_1, t)\f$ of Eq. (17).
template <class S>
S G2(const S& a, const S& b, const S& q, const S& theta, const S& theta1, const S& t) {
  using std::cos;
  return G2_from_start(a, b, two_c(b, q), S(cos(theta)), S(theta1 - theta), S(t - theta1), t);
}

/// \f$G_2\f$ for fixed \f$\theta, \theta_1\f$ as a function of \f$t\f$ alone:
/// \f$G_2 = K + 2c\,t - a\cos t\f$ with the constant \f$K = 2b(\theta_1 - \theta) + a\cos\theta - 2c\,\theta_1\f$
/// (g2_constant()). A search over \f$t\f$ evaluates only the last three terms.
template <class S>
S G2_shifted(const S& a, const S& two_c, const S& constant, const S& t) {
  using std::cos;
  return constant + two_c * t - a * cos(t);
}

/// The constant \f$K\f$ of G2_shifted().
template <class S>
S G2_constant(const S& a, const S& b, const S& two_c, const S& theta, const S& theta1) {
  using std::cos;
  return 2.0 * b * (theta1 - theta) + a * cos(theta) - two_c * theta1;
}

/// \f$\dot x(t) = -a(\cos t - \cos t_s) + 2c(t - t_s)\f$: the velocity of a progression that starts
/// from rest at \f$t_s\f$ (Eq. 7 with \f$t_s = t_0\f$; Eq. 8 is its value at \f$t_2\f$).
template <class S>
S progression_velocity_from_rest(const S& a, const S& two_c, const S& t_s, const S& t) {
  using std::cos;
  return -(a * (cos(t) - cos(t_s))) + two_c * (t - t_s);
}

// ---- the symmetric tangencies (Eq. 14 with theta_1 + theta = pi mod 2 pi) ----------------------

/// \f$h(z) = 2z - (a/b)\cos z\f$: a start \f$z\f$ whose flight touches the delimiter tangentially at
/// \f$\theta_1 = \pi - z \pmod{2\pi}\f$ solves \f$h(z) = (2k+1)\pi\f$ (Eqs. 11 and 14 with \f$b\f$
/// eliminated; next_hit.hpp, symmetric_tangencies()). Decreasing on \f$(t_2, t_3)\f$.
template <class S>
S symmetric_tangency_h(const S& a_over_b, const S& z) {
  using std::cos;
  return 2.0 * z - a_over_b * cos(z);
}

/// The flight \f$s = \theta_1 - z = -(a/b)\cos z\f$ of a symmetric tangency from \f$z\f$.
template <class S>
S symmetric_tangency_flight(const S& a_over_b, const S& z) {
  using std::cos;
  return -(a_over_b * cos(z));
}

}  // namespace dfchaos::model
