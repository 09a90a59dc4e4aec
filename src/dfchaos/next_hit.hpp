// SPDX-License-Identifier: GPL-3.0-or-later
/// @file next_hit.hpp
/// @brief The next-hit map \f$T_1\f$ (Section 4, Eq. 11) and its discontinuities (grazing points, Eq. 14).
///
/// From a start at rest at the delimiter at phase \f$\theta \in [t_2, t_3)\f$ (Eq. 10) the mass flies
/// freely; \f$T_1(\theta) = \theta_1 > \theta\f$ is the first zero of
/// \f$G_1(\theta, t) = b(t-\theta)^2 - a\sin t + a\cos\theta\,(t-\theta) + a\sin\theta\f$ (Eq. 11),
/// which is the position \f$x(t)\f$ of the mass (delimiter at 0). \f$T_1\f$ is an instant, not a phase.
#pragma once

#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/roots.hpp"

namespace dfchaos {

/// \f$G_1(\theta, \cdot)\f$ of Eq. (11) as a QuadraticPlusHarmonic with origin \f$\theta\f$ (turn 0).
QuadraticPlusHarmonic G1_function(const Parameters& p, double theta);

/// \f$G_1(\theta, t)\f$ (Eq. 11) at an instant \f$t\f$ (turn counted from \f$\theta\f$'s turn 0): the
/// accurate form of model::G1 (the polynomial re-centred at \f$t\f$ as the root search evaluates it,
/// roots.hpp); test_model checks that the two agree.
double G1(const Parameters& p, double theta, const Instant& t);
/// \f$\partial G_1/\partial t = 2b(t-\theta) - a\cos t + a\cos\theta\f$: the velocity; its zero at a
/// root of \f$G_1\f$ is the tangency condition (14).
double dG1_dt(const Parameters& p, double theta, const Instant& t);
/// \f$\partial G_1/\partial\theta = -(2b + a\sin\theta)(t - \theta)\f$ (proof of Lemma 2).
double dG1_dtheta(const Parameters& p, double theta, const Instant& t);

/// The first return of the mass to the delimiter after a start at rest at \f$\theta\f$.
struct FirstHit {
  Instant t1;               ///< \f$T_1(\theta)\f$ as turn and phase (turn 0 is \f$\theta\f$'s period)
  double theta1 = 0;        ///< \f$T_1(\theta)\f$ as a real number (for output)
  double hit_velocity = 0;  ///< \f$\partial G_1/\partial t\f$ at \f$T_1\f$; 0 at a grazing (tangential) contact
  long pieces = 0;          ///< monotone pieces examined by the root search
};

/// The first return with the label of its continuity branch of \f$T_1\f$ (next_hit()).
struct NextHit : FirstHit {
  long long maxima_before = 0;  ///< local maxima of \f$G_1(\theta,\cdot)\f$ in \f$(\theta, T_1)\f$: labels the continuity branch
};

/// \f$T_1(\theta)\f$ (Eq. 11). @throws InvalidParameter unless \f$b < a/2\f$ and \f$\theta \in [t_2, t_3)\f$.
NextHit next_hit(const Parameters& p, double theta);

/// Number of local maxima of \f$G_1(\theta, \cdot)\f$ strictly between \f$\theta\f$ and the instant
/// \f$t\f$, in closed form. A maximum needs \f$\partial_t G_1 = 0\f$ with \f$F < 0\f$, i.e. on a piece
/// \f$[t_2 + 2\pi k, t_3 + 2\pi k]\f$, where \f$\partial_t G_1\f$ decreases; it is there iff
/// \f$\partial_t G_1\f$ is positive at the piece's start and negative at its end, two linear
/// conditions on \f$k\f$. The count is constant on each continuity branch of \f$T_1\f$ and drops at
/// each discontinuity, so it identifies the branches.
long long maxima_between(const Parameters& p, double theta, const Instant& t);

/// A discontinuity \f$z\f$ of \f$T_1\f$: the flight from \f$z\f$ touches the delimiter tangentially
/// (\f$G_1 = \partial_t G_1 = 0\f$, Eq. 14). \f$T_1\f$ is decreasing; \f$T_1(z) = T_1(z+0)\f$ is the
/// tangency and \f$T_1(z-0)\f$ the later hit of a flight that just misses.
struct GrazingPoint {
  double z = 0;                   ///< the discontinuity
  double bracket_lo = 0;          ///< left end of the bisection bracket before the Newton polish
  double bracket_hi = 0;          ///< right end of that bracket
  Instant tangency;               ///< \f$T_1(z)\f$
  double t1_left = 0;             ///< \f$T_1(z - 0)\f$ (value), evaluated at bracket_lo
  double t1_right = 0;            ///< \f$T_1(z)\f$ (value)
  double jump = 0;                ///< \f$T_1(z-0) - T_1(z+0) > 0\f$
  double residual_G1 = 0;         ///< \f$G_1(z, T_1(z))\f$ after the polish
  double residual_dG1 = 0;        ///< \f$\partial_t G_1(z, T_1(z))\f$ (Eq. 14) after the polish
  bool newton_converged = false;  ///< whether 2D Newton (Eigen) refined the bisection result
  long long maxima_left = 0;      ///< branch label (maxima of the gap before the hit) left of z
  long long maxima_right = 0;     ///< the same right of z
};

/// All discontinuities of \f$T_1\f$ in \f$[lo, hi] \subset [t_2, t_3)\f$, ascending. The branch label
/// maxima_between is evaluated on a grid of `scan` points; every change of label is isolated by
/// bisection to a few ulp (a change by \f$k>1\f$ yields \f$k\f$ points), then refined by Newton's
/// method on the 2D system \f$G_1 = \partial_t G_1 = 0\f$.
/// Labels are monotone in \f$\theta\f$, so no discontinuity between grid points is missed.
/// @throws InvalidParameter if the interval is not inside \f$[t_2, t_3)\f$ or scan < 2.
std::vector<GrazingPoint> grazing_points(const Parameters& p, double lo, double hi, int scan = 2000);

/// The tangencies of the symmetric family, in closed form. Eliminating \f$b\f$ between \f$G_1 = 0\f$
/// and \f$\partial_t G_1 = 0\f$ (Eq. 14) with \f$s = \theta_1 - \theta\f$ gives
/// \f$\cos\frac{\theta_1+\theta}{2}\,\bigl(s\cos\frac{s}{2} - 2\sin\frac{s}{2}\bigr) = 0\f$.
/// The first factor vanishes when \f$\theta_1 + \theta \equiv \pi \pmod{2\pi}\f$; then
/// \f$\cos\theta_1 = -\cos\theta\f$ exactly (Eq. 16 with no remainder), \f$s = -(a/b)\cos\theta\f$, and
/// \f$\theta\f$ solves \f$h(\theta) = 2\theta - (a/b)\cos\theta = (2k+1)\pi\f$. Since
/// \f$h' = 2 + (a/b)\sin\theta < 0\f$ on \f$(t_2, t_3)\f$ there is one solution per odd multiple of
/// \f$\pi\f$ in \f$h([lo, hi])\f$, found here by bisection. Only \f$\cos\theta < 0\f$ gives \f$s > 0\f$.
/// Whether each is a *first* contact (a discontinuity of \f$T_1\f$) is for the caller to check.
struct SymmetricTangency {
  double z = 0;       ///< the start phase
  double flight = 0;  ///< \f$s = -(a/b)\cos z\f$
  long long k = 0;    ///< \f$h(z) = (2k+1)\pi\f$
};
std::vector<SymmetricTangency> symmetric_tangencies(const Parameters& p, double lo, double hi);
/// The number of odd multiples of \f$\pi\f$ in \f$h([lo, \min(hi, 3\pi/2)])\f$, in closed form: the
/// size of symmetric_tangencies(p, lo, hi) (or a little more), known before any of them is found.
/// It grows like \f$(a/b)/(2\pi)\f$ on \f$[t_2, 3\pi/2]\f$.
long long symmetric_tangency_count(const Parameters& p, double lo, double hi);

}  // namespace dfchaos
