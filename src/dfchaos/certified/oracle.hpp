// SPDX-License-Identifier: GPL-3.0-or-later
/// @file oracle.hpp
/// @brief The floating-point layer as an oracle of *where to look*: guesses of \f$T_1\f$, \f$\theta_2\f$
/// and T at double parameters. Nothing certified rests on these numbers: every guess is verified
/// (or the proof fails).
#pragma once

#include <optional>

#include "dfchaos/return_map.hpp"

namespace dfchaos::certified::oracle {

/// \f$T_1(\theta)\f$ at (a, b) as a real number; NaN if the floating layer refuses or gives up.
/// \f$\theta\f$ is clamped into \f$[t_2, t_3)\f$ of the double parameters.
double T1(double a, double b, double theta);

/// One step of T at (a, b, q, theta) (theta clamped as in T1()); nothing on failure.
std::optional<MapStep> step(double a, double b, double q, double theta);

/// \f$\theta_2\f$ as a real number (instant) of step(); NaN on failure.
double theta2(double a, double b, double q, double theta);

}  // namespace dfchaos::certified::oracle
