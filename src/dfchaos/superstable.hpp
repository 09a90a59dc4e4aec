/// @file superstable.hpp
/// @brief Section 8 and Theorem 2: conditions (21), (22) under which \f$t_2\f$ is a superstable
/// fixed point of \f$T\f$ (a whole neighbourhood \f$[t_2, t_2+\varepsilon)\f$ is sent to \f$t_2\f$).
///
/// From \f$\theta = t_2\f$: \f$T_1(t_2)\f$ is the first zero of \f$G_1(t_2, \cdot)\f$ (Eq. 11) and
/// \f$\theta_2(t_2)\f$ the first zero of \f$G_2(t_2, T_1(t_2), \cdot)\f$ (Eq. 17). Condition (21):
/// \f$\theta_2 \bmod 2\pi \in (t_1, t_2)\f$; condition (22): \f$\theta_2 \bmod 2\pi \in (t_3, 2\pi)\cup[0, t_0)\f$.
/// Robustness needs both roots simple: \f$\partial_t G_1 \ne 0\f$ at \f$T_1(t_2)\f$ (a non-zero impact
/// velocity) and \f$\partial G_2/\partial\theta_2 = F(\theta_2) - q \ne 0\f$ at \f$\theta_2(t_2)\f$. (The
/// paper writes both as derivatives in \f$\theta\f$ of \f$G_1\f$; the second is of \f$G_2\f$.)
#pragma once

#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

/// The conditions of Theorem 2 at one parameter set, and the measured superstable width.
struct SuperstableCheck {
  MapStep step;                 ///< the step of T from t2
  double theta2_phase = 0;      ///< \f$\theta_2(t_2) \bmod 2\pi\f$
  bool eq21 = false;            ///< \f$\theta_2 \bmod 2\pi \in (t_1, t_2)\f$
  bool eq22 = false;            ///< \f$\theta_2 \bmod 2\pi \in (t_3, 2\pi) \cup [0, t_0)\f$
  double impact_velocity = 0;   ///< \f$\partial_t G_1(t_2, T_1(t_2))\f$
  double dG2 = 0;               ///< \f$F(\theta_2) - q\f$
  bool nondegenerate = false;   ///< both of the above non-zero (beyond 1e-9)
  bool hypotheses = false;      ///< Theorem 2: ((2) and (22)) or ((21) and (23))
  bool fixed = false;           ///< \f$T(t_2) = t_2\f$
  double epsilon = 0;           ///< largest e with \f$T = t_2\f$ on a grid of \f$[t_2, t_2 + e)\f$, refined by bisection
};

/// Evaluates Theorem 2 at `p`; epsilon is measured with a scan of `scan` steps over \f$[t_2, t_3)\f$.
/// @throws InvalidParameter unless the map is defined.
SuperstableCheck superstable_check(const Parameters& p, int scan = 20000);

/// The cycle through \f$t_2\f$ that the computed orbit of \f$t_2\f$ closes, judged against the
/// precision of \f$T\f$ (beyond the paper; Lemma 3, Theorem 2).
///
/// An orbit that meets an arc where the motion stops until \f$t_2\f$ continues as the orbit of
/// \f$t_2\f$, and \f$T\f$ is a function: once the *computed* orbit of \f$t_2\f$ returns to
/// \f$t_2\f$, it repeats for ever. That return is a superstable cycle of the exact map only if every
/// step with a stop on the way was taken from a phase that lies inside its stop arc by more than
/// the error accumulated up to there. The error is propagated along the orbit as
/// \f$e_{i+1} = |T'(\theta_i)|\,e_i + \delta\f$ (\f$\delta\f$: the error allowed to one evaluation of
/// \f$T\f$; \f$e = \delta\f$ at \f$t_2\f$ and after every stop, whose image is a fixed phase), and the
/// stop arc around \f$\theta_i\f$ is probed at \f$\theta_i \pm r\f$ for
/// \f$r = 10^{-14}, 10^{-13}, \dots, 10^{-2}\f$ (sampled: two phases per radius). Where \f$T'\f$ grows
/// fast (a chaotic orbit of \f$t_2\f$) the error exceeds every arc after a few dozen steps, and a
/// return seen afterwards is a cycle of the rounding, not of \f$T\f$: double precision cannot decide.
struct T2Cycle {
  long long period = 0;       ///< least k with \f$T^k(t_2) = t_2\f$ as computed (0: none within the bound)
  long long stops = 0;        ///< steps with a stop on the way (each one resets the error)
  /// \f$\min_i r_i/e_i\f$ over the steps with a stop: how far inside its stop arc, in units of the
  /// propagated error, the worst of them was taken (0 when the error overflowed or a step grazed).
  double margin = 0;
  bool resolved = false;      ///< period > 0 and margin >= kT2CycleSafety: a superstable cycle (sampled)
};

/// Margin (arc radius over propagated error) that t2_cycle() requires of every step with a stop.
inline constexpr double kT2CycleSafety = 10;

/// The default \f$\delta\f$ of t2_cycle(): the accuracy docs/accuracy.md promises for \f$T\f$ near a
/// discontinuity of \f$T_1\f$, the loosest of its bounds.
inline constexpr double kT2CycleStepError = 1e-9;

/// Follows the computed orbit of \f$t_2\f$ for at most `max_period` steps (see T2Cycle); `step_error`
/// is \f$\delta\f$.
/// @throws InvalidParameter unless the map is defined and \f$1 \le\f$ max_period \f$\le 10^7\f$,
///         \f$0 < \f$ step_error \f$< 10^{-3}\f$; GaveUp as return_map_step.
T2Cycle t2_cycle(const Parameters& p, long long max_period, double step_error = kT2CycleStepError);

/// A maximal interval of \f$b\f$ (at fixed \f$a, q\f$) on which (21) or (22) holds.
struct SuperstableWindow {
  double b_lo = 0;         ///< left end of the window
  double b_hi = 0;         ///< right end of the window
  int condition = 0;       ///< 21 or 22
};

/// All windows of \f$b \in [b_{lo}, b_{hi}]\f$ where (21) or (22) holds. The end \f$\theta_2(t_2)\f$ of the
/// first progression, as an unwrapped instant \f$w(r)\f$ of \f$r = a/b\f$, is followed on a grid of
/// `samples` points uniform in \f$r\f$; each crossing of \f$w\f$ with a boundary \f$t_1, t_2, t_3\f$ or
/// \f$t_0 + 2\pi\f$ (mod \f$2\pi\f$, all moving with \f$b\f$) between two samples is located by bisection;
/// where \f$T_1(t_2)\f$ jumps or \f$w\f$ moves by more than 1 between samples, the interval is
/// bisected down to \f$10^{-12}\f$ relative width and the jump is an event too. Windows are the
/// intervals between events where the condition holds at the midpoint.
std::vector<SuperstableWindow> superstable_windows(double a, double q, double b_lo, double b_hi, int samples);

}  // namespace dfchaos
