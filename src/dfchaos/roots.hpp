// SPDX-License-Identifier: GPL-3.0-or-later
/// @file roots.hpp
/// @brief First-root isolation that cannot skip a root, for functions
/// \f$f(t) = \alpha s^2 + \beta s + \gamma + A\sin t + B\cos t\f$, \f$s = t - t_{\mathrm{origin}}\f$.
///
/// Both event functions of the model have this form:
///  - the free-flight gap \f$x(t) - y\f$ (Eq. 3, and \f$G_1\f$ of Eq. 11): \f$\alpha = b\f$,
///    \f$A = -a\f$, \f$B = 0\f$, with \f$f'' = a\sin t + 2b = F(t)\f$;
///  - minus the progression velocity \f$-\dot x(t)\f$ (Eqs. 7 and 17): \f$\alpha = 0\f$,
///    \f$\beta = q - 2b\f$, \f$A = 0\f$, \f$B = a\f$, with \f$f'' = -a\cos t\f$.
///
/// **Why no root is missed.** \f$f'' = 2\alpha - A\sin t - B\cos t\f$ vanishes at no more than two
/// phases per period, known in closed form (inflection_phases_into() in roots/piecewise.cpp). Between consecutive inflection
/// instants \f$f'\f$ is monotone, so it has at most one zero there, which splits the piece into at
/// most two sub-pieces on which \f$f\f$ itself is monotone. On a monotone sub-piece \f$f\f$ has a
/// zero iff its end values differ in sign, and the zero is unique: a bracketing solver finds it.
/// Scanning the sub-pieces in order therefore finds the *first* root, with no step size to guess.
///
/// **Why the cost does not grow as \f$b/a \to 0\f$.** With \f$R = \sqrt{A^2+B^2}\f$,
/// \f$f \le U(s) = \alpha s^2 + \beta s + \gamma + R\f$: on the interval where \f$U < 0\f$ there is no
/// root, and it is skipped in one step. Likewise \f$f \ge \alpha s^2 + \beta s + \gamma - R\f$ bounds
/// where the root must already have occurred. For a free flight of length \f$\sim (a/b)|\cos\theta|\f$
/// only \f$O(1)\f$ periods at each end are scanned.
///
/// **Where each step is.** first_upcrossing() (roots.cpp) is the driver, in the order above: the
/// envelope and the pieces come from roots/piecewise.hpp (with f's exact evaluation on a piece),
/// an origin at rest from roots/rest_start.hpp, and the search of one monotone piece from
/// roots/piece_solver.hpp, which ends in solve_increasing() (roots_impl.hpp).
#pragma once

#include <limits>
#include <optional>

#include "dfchaos/phase.hpp"

namespace dfchaos {

/// \f$f(t) = \alpha s^2 + \beta s + \gamma + A\sin t + B\cos t\f$ with \f$s = t - \mathrm{origin}\f$,
/// \f$\alpha \ge 0\f$. The polynomial part is kept in long double: for small \f$b/a\f$ its terms
/// reach \f$10^7 a\f$ and cancel to \f$O(a)\f$ at the root.
///
/// **Evaluation far from the origin.** At \f$s \sim 10^7\f$ a long double \f$s\f$ is resolved only to
/// \f$10^{-12}\f$, and \f$\alpha s^2 + \beta s\f$ loses \f$10^{-12} a\f$ to rounding. The root search
/// therefore re-centres the polynomial at the start \f$s_0\f$ of every piece:
/// \f$\alpha(s_0+u)^2 + \beta(s_0+u) + \gamma = P_0 + P_1 u + \alpha u^2\f$ with
/// \f$P_1 = 2\alpha s_0 + \beta\f$, \f$P_0 = s_0(\alpha s_0 + \beta) + \gamma\f$, where \f$s_0\f$ (exactly
/// \f$2\pi\f$ times whole turns plus a difference of two phases) and \f$P_0, P_1\f$ are formed in
/// double-double arithmetic (error-free TwoSum/TwoProd, \f$2\pi\f$ to 107 bits). Near a root
/// \f$P_0, P_1 = O(a)\f$, so rounding them to long double costs only \f$10^{-19}a\f$. What remains is
/// the error of \f$\beta\f$ itself, multiplied by \f$s_0\f$: callers form it in long double, and may
/// add a further correction in beta_tail.
struct QuadraticPlusHarmonic {
  Instant origin;             ///< \f$s = 0\f$
  long double alpha = 0;      ///< \f$\alpha\f$, coefficient of \f$s^2\f$ (a double value)
  long double beta = 0;       ///< \f$\beta\f$, coefficient of \f$s\f$
  long double beta_tail = 0;  ///< optional low-order part: the coefficient of \f$s\f$ is beta + beta_tail
  long double gamma = 0;      ///< \f$\gamma\f$, constant term
  double A = 0;               ///< \f$A\f$, coefficient of \f$\sin t\f$
  double B = 0;               ///< \f$B\f$, coefficient of \f$\cos t\f$
  /// True when \f$f(\mathrm{origin}) = 0\f$ holds exactly by construction (a motion starting at rest
  /// at the contact). Near such an origin \f$f = c_1u + c_2u^2/2 + c_3u^3/6 + \dots\f$ lies far below
  /// the rounding noise of a direct evaluation. The search then decides the direction of departure
  /// from the Taylor coefficients at the origin (\f$c_1\f$ below \f$64\epsilon\f$ of its terms counts
  /// as 0; \f$c_2\f$ from long-double trigonometry), and searches \f$(0, 10^{-3}]\f$ with the
  /// cancellation-free form \f$f(u) = c_1u + u^2\bigl[c_2/2 + P(\tfrac12 - h_1(u)) - Q\,u\,h_2(u)\bigr]\f$,
  /// \f$P = A\sin\varphi + B\cos\varphi\f$, \f$Q = A\cos\varphi - B\sin\varphi\f$ at the origin's phase
  /// \f$\varphi\f$, \f$h_1 = (1-\cos u)/u^2\f$, \f$h_2 = (u-\sin u)/u^3\f$ (short series). A root there,
  /// such as the return after \f$3(t_3-\theta)\f$ of a flight from rest just below \f$t_3\f$, is found to
  /// full relative precision, with its tiny positive slope.
  bool starts_at_rest = false;
  /// With starts_at_rest: \f$f''(\mathrm{origin}) = 0\f$ by definition (a flight from rest at the phase
  /// \f$t_2\f$, where \f$F = 0\f$, although the rounded \f$t_2\f$ may give \f$F\f$ either sign in the
  /// last bit). The direction of departure is then that of \f$f'''\f$.
  bool origin_at_inflection = false;
  /// Whether origin_sin and origin_cos hold \f$\sin\f$ and \f$\cos\f$ of the origin's phase, as
  /// glibc's sincos gives them (the callers compute them anyway to form beta and gamma). The search
  /// then uses them instead of calling sincos again (the values are those sincos gives there).
  bool origin_trig = false;
  double origin_sin = 0;  ///< \f$\sin\f$ of the origin's phase (with origin_trig)
  double origin_cos = 0;  ///< \f$\cos\f$ of the origin's phase (with origin_trig)

  /// \f$f\f$ at elapsed time \f$s\f$ whose phase is \f$\varphi\f$ (direct long-double evaluation).
  long double value_at(long double s, double phi) const;
  /// \f$f' = 2\alpha s + \beta + A\cos\varphi - B\sin\varphi\f$ (direct long-double evaluation).
  long double slope_at(long double s, double phi) const;
  /// \f$f\f$ at an instant, with the polynomial re-centred there in double-double (see above).
  long double value(const Instant& t) const;
  /// \f$f'\f$ at an instant, re-centred as value().
  long double slope(const Instant& t) const;
};

/// The first instant after the origin at which \f$f\f$ reaches 0 from below.
struct UpCrossing {
  Instant t;          ///< the root
  long double s = 0;  ///< elapsed time from the origin
  double slope = 0;   ///< \f$f'\f$ at the root (\f$\ge 0\f$ up to rounding; 0 at a tangency)
  long pieces = 0;    ///< monotone pieces examined (work done; independent of \f$b/a\f$)
};

/// Bounds of a search. Every search is bounded: it ends at the horizon or after max_pieces
/// pieces, whichever comes first; reaching max_pieces throws GaveUp.
struct SearchLimits {
  long double horizon = std::numeric_limits<long double>::infinity();  ///< max elapsed time
  long max_pieces = 20'000'000;                                        ///< max monotone pieces examined
};

/// The first root \f$t > \mathrm{origin}\f$ of \f$f\f$ reached from below, assuming
/// \f$f < 0\f$ just after the origin (or starts_at_rest). With starts_at_rest and \f$f\f$ rising at
/// once (\f$c_1 > 0\f$, or \f$c_1 = 0 < c_2\f$, or \f$c_1 = c_2 = 0 < c_3\f$) the root is the origin
/// itself (s = 0, slope 0): the motion never leaves the contact.
/// @return nothing when \f$f < 0\f$ on the whole horizon.
/// @throws GaveUp when max_pieces is reached, or when neither the horizon nor a root bound
///         limits the search.
std::optional<UpCrossing> first_upcrossing(const QuadraticPlusHarmonic& f, const SearchLimits& limits = {});

/// Safeguarded Newton iteration for an increasing function on \f$[lo, hi]\f$ with
/// \f$g(lo) < 0 \le g(hi)\f$ (end values g_lo, g_hi, used for a secant start); `gd(x)` returns the
/// pair \f$(g(x), g'(x))\f$. Newton steps inside the bracket, bisection when a step would leave it
/// or fails to halve the previous one (as in Numerical Recipes' rtsafe). When `gd(x)` returns a
/// triple \f$(g, g', g'')\f$ the correction is Halley's (cubic convergence), computed in double. Stops when the Newton
/// correction or the bracket falls below the tolerance \f$4\epsilon(|x_0| + |hi| + 1)\f$, where
/// \f$x_0\f$ is the offset scale. A `start` strictly inside \f$(lo, hi)\f$ replaces the secant start
/// (e.g. a root of an interpolant of the end data); any other value (NaN) keeps the secant.
/// With Halley's correction and a `jerk_bound` \f$J \ge |g'''|\f$ (near the root), an iterate
/// whose predicted error after the step, \f$2\bigl((g''/2g')^2 + J/(6g')\bigr)|\text{step}|^3\f$,
/// is below tol/16 is corrected and returned without a further evaluation (NaN: always evaluate).
/// @throws std::logic_error if 400 iterations do not suffice.
template <class GD>
double solve_increasing(GD&& gd, double lo, double hi, double scale, long double g_lo, long double g_hi,
                        double start = std::numeric_limits<double>::quiet_NaN(), double jerk_bound = std::numeric_limits<double>::quiet_NaN());

}  // namespace dfchaos

#include "dfchaos/roots_impl.hpp"
