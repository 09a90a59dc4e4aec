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
