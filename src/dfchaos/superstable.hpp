// SPDX-License-Identifier: GPL-3.0-or-later
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

#include <cstddef>

#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

/// The conditions of Theorem 2 at one parameter set, and the measured superstable width.
struct SuperstableCheck {
  MapStep step;                ///< the step of T from t2
  double theta2_phase = 0;     ///< \f$\theta_2(t_2) \bmod 2\pi\f$
  bool eq21 = false;           ///< \f$\theta_2 \bmod 2\pi \in (t_1, t_2)\f$
  bool eq22 = false;           ///< \f$\theta_2 \bmod 2\pi \in (t_3, 2\pi) \cup [0, t_0)\f$
  double impact_velocity = 0;  ///< \f$\partial_t G_1(t_2, T_1(t_2))\f$
  double dG2 = 0;              ///< \f$F(\theta_2) - q\f$
  bool nondegenerate = false;  ///< both of the above non-zero (beyond 1e-9)
  bool hypotheses = false;     ///< Theorem 2: ((2) and (22)) or ((21) and (23))
  bool fixed = false;          ///< \f$T(t_2) = t_2\f$
  double epsilon = 0;          ///< largest e with \f$T = t_2\f$ on a grid of \f$[t_2, t_2 + e)\f$, refined by bisection
};

/// Evaluates Theorem 2 at `p`; epsilon is measured with a scan of `scan` steps over \f$[t_2, t_3)\f$.
/// @throws InvalidParameter unless the map is defined.
SuperstableCheck superstable_check(const Parameters& p, int scan = 20000);

/// The cycle that a computed orbit falls onto after a stop, judged against the precision of \f$T\f$
/// (beyond the paper; Lemma 3, Section 8; Theorem 2 is the case of the fixed point \f$t_2\f$).
///
/// A step with a stop sends a whole arc of phases to one phase, its *image*: \f$t_2\f$ in scenarios B
/// and C (the flight starts at \f$t_2\f$), another fixed phase in D and D′ (the phase where the
/// progression from \f$t_0\f$ ends). An orbit that meets such an arc goes on as the orbit of the
/// image, and \f$T\f$ is a function: once the *computed* orbit of an image meets a stop arc with an
/// image it has visited, it repeats for ever. That is a superstable cycle of the exact map only if
/// every step on the way was taken far enough from where \f$T\f$ changes:
///  - the error is propagated as \f$e_{i+1} = |T'(\theta_i)|\,e_i + \delta\f$ (\f$\delta\f$: the error
///    allowed to one evaluation of \f$T\f$; \f$e = \delta\f$ at the start and after every stop, whose
///    image is a fixed phase);
///  - a step with a stop must lie in its stop arc by at least kStopCycleSafety times \f$e\f$: the arc is
///    probed at \f$\theta_i \pm r\f$, \f$r = 10^{-14}, 10^{-13}, \dots, 10^{-2}\f$, where the step must
///    stop with the same image (probes outside \f$[t_2, t_3)\f$ are skipped; a probe that throws ends
///    the arc);
///  - a step without a stop must carry \f$e < 10^{-3}\f$ and keep its continuity label (covering.hpp) and
///    scenario at \f$\theta_i \pm\f$ kStopCycleSafety \f$e\f$, so that \f$T\f$ is smooth between; an error
///    that reaches \f$10^{-3}\f$ counts as infinite until the next stop, as does a grazing (where
///    \f$T'\f$ is undefined).
/// All three are sampled, not proved. Where \f$T'\f$ grows fast (a chaotic orbit) the error exceeds
/// every arc after a few dozen steps, and a return seen afterwards rests on the last bits of the
/// computation: a cycle of the rounding, about which double precision cannot decide.
struct StopCycle {
  double image = 0;      ///< the phase the cycle passes through: the first stop image it repeats
  long long entry = 0;   ///< steps from the start before the cycle's first visit of `image`
  long long period = 0;  ///< steps of the cycle (0: no stop image repeated within the bound)
  long long stops = 0;   ///< steps with a stop followed (each one resets the error)
  /// The smallest ratio, over the steps with a stop, of the stop arc's sampled radius to the
  /// propagated error; 0 when the error reached \f$10^{-3}\f$ (or overflowed) before a stop, a step
  /// grazed, or a step without a stop changed branch within kStopCycleSafety times its error.
  double margin = 0;
  bool resolved = false;  ///< period > 0 and margin >= kStopCycleSafety: a superstable cycle (sampled)
  /// The error reached \f$10^{-3}\f$ before a stop (or overflowed, or a step grazed), or a step without
  /// a stop changed branch within its reach: margin 0 for that reason, not for a narrow arc. Also set
  /// when no stop image repeated (period 0) and the error at the last step was beyond \f$10^{-3}\f$.
  bool lost = false;
};

/// Margin (distance over propagated error) that stop_cycle() requires of every step it follows.
inline constexpr double kStopCycleSafety = 10;

/// The propagated error at which stop_cycle() counts the orbit's precision as lost (StopCycle::lost).
inline constexpr double kStopCycleLostAt = 1e-3;

/// The default \f$\delta\f$ of stop_cycle(): the accuracy docs/accuracy.md promises for \f$T\f$ near a
/// discontinuity of \f$T_1\f$, the loosest of its bounds.
inline constexpr double kStopCycleStepError = 1e-9;

/// Follows the computed orbit of `image` (a phase in \f$[t_2, t_3)\f$, normally the image of a stop)
/// for at most `max_steps` steps (see StopCycle); `step_error` is \f$\delta\f$.
/// @throws InvalidParameter unless the map is defined, image \f$\in [t_2, t_3)\f$,
///         \f$1 \le\f$ max_steps \f$\le 10^7\f$ and \f$0 < \f$ step_error \f$< 10^{-3}\f$; GaveUp as
///         return_map_step on the orbit itself.
StopCycle stop_cycle(const Parameters& p, double image, long long max_steps, double step_error = kStopCycleStepError);

/// stop_cycle() from \f$t_2\f$: the cycle that an orbit falls onto after a stop of scenario B or C.
StopCycle t2_cycle(const Parameters& p, long long max_steps, double step_error = kStopCycleStepError);

/// The least \f$n \in [1, \mathrm{max\_steps}]\f$ with \f$T^n(\theta) = \mathrm{target}\f$ exactly as
/// computed, 0 if none (\f$\theta = \mathrm{target} = t_2\f$: the return time of \f$t_2\f$).
/// @throws InvalidParameter unless \f$\theta \in [t_2, t_3)\f$ and \f$1 \le\f$ max_steps \f$\le 10^7\f$.
long long first_visit(const Parameters& p, double theta, double target, long long max_steps);

/// A second check of stop_cycle()'s verdict, independent of its error model: whether the cycle `c`
/// (period > 0) is closed at the same step when the orbit is moved by `h` where it first can be.
/// That is after the first step from the image: \f$T'(t_2) = 0\f$ (the flight from rest at \f$t_2\f$
/// starts with \f$F = 0\f$, Eq. 11), so a shift of \f$t_2\f$ itself would be lost at once. For period 1
/// the shifted point is image \f$+\,h\f$ (is it in the stop arc?); otherwise \f$T(\mathrm{image}) + h\f$
/// must reach the image first after period \f$-\,1\f$ steps (\f$-h\f$ where \f$+h\f$ would leave
/// \f$[t_2, t_3)\f$). A resolved cycle passes; a cycle whose return depends on the digits below
/// \f$h\f$ does not.
/// @throws InvalidParameter unless c.period \f$\in [1, 10^7]\f$ and \f$0 < h < 10^{-3}\f$.
bool stop_cycle_survives_shift(const Parameters& p, const StopCycle& c, double h);

/// A maximal interval of \f$b\f$ (at fixed \f$a, q\f$) on which (21) or (22) holds.
struct SuperstableWindow {
  double b_lo = 0;    ///< left end of the window
  double b_hi = 0;    ///< right end of the window
  int condition = 0;  ///< 21 or 22
};

/// All windows of \f$b \in [b_{lo}, b_{hi}]\f$ where (21) or (22) holds. The end \f$\theta_2(t_2)\f$ of the
/// first progression, as an unwrapped instant \f$w(r)\f$ of \f$r = a/b\f$, is followed on a grid of
/// `samples` points uniform in \f$r\f$; each crossing of \f$w\f$ with a boundary \f$t_1, t_2, t_3\f$ or
/// \f$t_0 + 2\pi\f$ (mod \f$2\pi\f$, all moving with \f$b\f$) between two samples is located by bisection;
/// where \f$T_1(t_2)\f$ jumps or \f$w\f$ moves by more than 1 between samples, the interval is
/// bisected down to \f$10^{-12}\f$ relative width and the jump is an event too. Windows are the
/// intervals between events where the condition holds at the midpoint.
std::vector<SuperstableWindow> superstable_windows(double a, double q, double b_lo, double b_hi, int samples);

/// A maximal interval of \f$b\f$ on which \f$T(t_2) = t_2\f$: consecutive windows of
/// superstable_windows() that share an end, joined (a (21) window followed by a (22) one meet where
/// \f$\theta_2(t_2)\f$ jumps from one stop arc to the other, and T(t2) = t2 on both sides).
struct SuperstableInterval {
  double b_lo = 0;        ///< left end
  double b_hi = 0;        ///< right end
  std::size_t first = 0;  ///< index of its first window in the list it was joined from
  std::size_t last = 0;   ///< one past the index of its last window
  bool has21 = false;     ///< a window of condition (21) is part of it
  bool has22 = false;     ///< a window of condition (22) is part of it
};

/// The windows (sorted, as superstable_windows() returns them) joined into maximal intervals.
std::vector<SuperstableInterval> join_windows(const std::vector<SuperstableWindow>& windows);

/// The end of a superstable interval near `edge` (its lower end if `lower`), sharpened: bisection on
/// whether the computed \f$T(t_2) = t_2\f$ at \f$(a, b, q)\f$, from a bracket of relative width
/// \f$2\cdot10^{-10}\f$ around `edge` down to adjacent doubles (at most 64 halvings). Returns the last
/// b where \f$T(t_2) = t_2\f$, or `edge` itself when the bracket's ends do not straddle an edge.
/// superstable_windows() places its ends on the conditions (21), (22) to \f$10^{-12}\f$ relative;
/// this is what a certified bracket of that width needs (thm2_windows).
double sharpen_interval_end(double a, double q, double edge, bool lower);

}  // namespace dfchaos
