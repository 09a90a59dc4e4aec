// SPDX-License-Identifier: GPL-3.0-or-later
/// @file map_derivative.hpp
/// @brief The derivative \f$T'(\theta)\f$ of the return map by the implicit function theorem on
/// Eqs. (11) and (17), and the Lyapunov exponent of an orbit, \f$\lambda = \frac1N\sum\ln|T'(\theta_n)|\f$.
///
/// In scenario A, \f$\theta_1 = T_1(\theta)\f$ solves \f$G_1(\theta, \theta_1) = 0\f$ and \f$\theta_2\f$
/// solves \f$G_2(\theta, \theta_1, \theta_2) = 0\f$, so
/// \f[ \frac{d\theta_1}{d\theta} = -\frac{\partial_\theta G_1}{\partial_t G_1}
///     = \frac{(2b + a\sin\theta)(\theta_1 - \theta)}{v_1}, \qquad
///     T'(\theta) = \frac{d\theta_2}{d\theta} = \frac{2b + a\sin\theta - q\,\theta_1'}{2c + a\sin\theta_2}, \f]
/// with \f$v_1 = \partial_t G_1(\theta, \theta_1)\f$ the impact velocity, \f$\partial_\theta G_2 = -2b - a\sin\theta\f$,
/// \f$\partial_{\theta_1} G_2 = 2b - 2c = q\f$ and \f$\partial_{\theta_2} G_2 = 2c + a\sin\theta_2\f$.
/// In every scenario with a stop (B, C, C′, D, D′) the next free flight starts at an instant that
/// does not depend on \f$\theta\f$ (at \f$t_2\f$, or at the end of a progression from rest at \f$t_0\f$),
/// so \f$T' = 0\f$: those steps are superstable.
#pragma once

#include <limits>
#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

/// \f$T'\f$ at one phase.
struct MapDerivative {
  double dT = 0;                        ///< \f$T'(\theta)\f$ (0 on flat steps; NaN at a grazing, where T is not differentiable)
  double dtheta1 = 0;                   ///< \f$T_1'(\theta)\f$
  bool flat = false;                    ///< the step contains a stop: \f$T' = 0\f$ exactly
  Scenario scenario = Scenario::Other;  ///< the scenario of the step
};

/// \f$T'(\theta)\f$ from an already computed step (see the file comment for the formulas).
MapDerivative map_derivative(const Parameters& p, const MapStep& step);

/// \f$T'(\theta)\f$. @throws as return_map_step.
MapDerivative map_derivative(const Parameters& p, double theta);

/// Statistics of an orbit of \f$T\f$ after a transient.
struct OrbitStatistics {
  long long steps = 0;          ///< steps averaged over (after the transient)
  double lyapunov = 0;          ///< \f$\frac1N\sum\ln|T'|\f$ over steps without a stop; -inf if any step is flat
  long long flat_steps = 0;     ///< steps with \f$T' = 0\f$ (a stop)
  double elapsed = 0;           ///< total time of the averaged steps
  double penetration = 0;       ///< total advance of the delimiter over them
  double penetration_rate = 0;  ///< penetration / elapsed: mean drilling speed (units of a per unit time)
  /// If the computed orbit reaches t2 and returns to it: the return time, else 0. A cycle of the
  /// computed orbit; whether it is a superstable cycle of T: superstable.hpp, t2_cycle.
  long long period_of_t2 = 0;
  /// T of the last averaged step with a stop (the fixed phase it sends its arc to: t2 in scenarios
  /// B and C), NaN if none: the orbit goes on as the orbit of this phase.
  double last_stop_image = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> tail;  ///< the last phases of the orbit (as many as asked)
};

/// Iterates \f$T\f$ from \f$\theta_0\f$: `transient` steps discarded, then `steps` steps averaged;
/// keeps the last `keep` phases. Bounded: exactly transient + steps evaluations of T.
/// @throws InvalidParameter for a bad start or counts, GaveUp as return_map_step.
OrbitStatistics orbit_statistics(const Parameters& p, double theta0, long long transient, long long steps, int keep = 0);

}  // namespace dfchaos
