// SPDX-License-Identifier: GPL-3.0-or-later
/// @file ode_map.hpp
/// @brief The return map computed by numerical integration (GSL odeiv2, rk8pd), independently of
/// the closed forms: a cross-check for \f$T\f$, the baseline a user without dfchaos would write,
/// and the integrator for the perturbed system of Section 10 (\f$\ddot x = F + G\f$).
///
/// Regimes are integrated as ODEs; contacts (\f$x = y\f$ from below) and progression ends
/// (\f$\dot x = 0\f$ from above) are located by bisection in time, re-integrating from the last
/// accepted step, to event_tol. The step size is capped by max_step so that no event between
/// steps is missed when the event function oscillates with the forcing. Stop phases end where the
/// contact force leaves \f$[0, q]\f$, located by the same scan and bisection.
#pragma once

#include <functional>
#include <string>
#include <utility>

#include "dfchaos/parameters.hpp"

namespace dfchaos {

/// Options of the integrated map.
struct OdeMapOptions {
  double max_step = 0.05;        ///< largest integration step (time units)
  double eps_abs = 1e-13;        ///< absolute error target per step
  double eps_rel = 1e-13;        ///< relative error target per step
  double event_tol = 1e-12;      ///< width in time of the final event bracket
  long max_steps = 100'000'000;  ///< give up after this many accepted steps
  /// Additional force \f$G(t, x, \dot x)\f$ of Section 10 (free and progression regimes); none if empty.
  std::function<double(double, double, double)> perturbation;
};

/// One step of the integrated map.
struct OdeMapStep {
  double T1 = 0;             ///< the first contact instant
  double hit_velocity = 0;   ///< impact velocity at T1
  double T = 0;              ///< phase of the next switch to free flight
  double elapsed = 0;        ///< its instant minus theta
  double penetration = 0;    ///< advance of the delimiter
  std::string chain;         ///< regimes visited, as in MapStep::chain
  long steps = 0;            ///< accepted integration steps
  long rhs_evaluations = 0;  ///< evaluations of the right-hand side
};

/// Position and velocity at \f$t_1\f$ of \f$\ddot x = a\sin t + C\f$ from \f$x(t_0) = x_0\f$,
/// \f$\dot x(t_0) = v_0\f$, by GSL odeiv2 rk8pd with per-step error targets `eps`: the free regime
/// of Eq. (3) is \f$C = 2b\f$, the progression of Eq. (4) \f$C = 2c = 2b - q\f$. No events: an
/// independent check of the closed forms of Eqs. (3)–(7).
/// @throws InvalidParameter for non-finite input or \f$t_1 < t_0\f$; GaveUp if GSL fails.
std::pair<double, double> integrate_forced_motion(double a, double C, double t0, double x0, double v0, double t1, double eps = 1e-13);

/// One step of the return map by numerical integration, from rest at the delimiter at phase theta.
/// @throws InvalidParameter for bad options, GaveUp when max_steps or 8 regime changes are exceeded.
OdeMapStep ode_return_map_step(const Parameters& p, double theta, const OdeMapOptions& options = {});

}  // namespace dfchaos
