// SPDX-License-Identifier: GPL-3.0-or-later
/// @file oracle.hpp
/// @brief The floating-point layer as an oracle of *where to look*: guesses of \f$T_1\f$, \f$\theta_2\f$
/// and T at double parameters. Nothing certified rests on these numbers: every guess is verified
/// (or the proof fails).
#pragma once

#include <exception>
#include <new>
#include <optional>
#include <utility>

#include "dfchaos/return_map.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified::oracle {

/// Runs `f`, a call of the floating layer, and says whether it returned: false when the floating
/// layer refused its input or gave up (any std::exception), which only means "no guess here". A stop
/// request (Stopped, stop.hpp) and exhausted memory (std::bad_alloc) are not answers of the floating
/// layer: they pass through.
template <class F>
bool attempt(F&& f) {
  try {
    std::forward<F>(f)();
    return true;
  } catch (const Stopped&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    return false;
  }
}

/// \f$T_1(\theta)\f$ at (a, b) as a real number; NaN if the floating layer refuses or gives up.
/// \f$\theta\f$ is clamped into \f$[t_2, t_3)\f$ of the double parameters.
double T1(double a, double b, double theta);

/// One step of T at (a, b, q, theta) (theta clamped as in T1()); nothing on failure.
std::optional<MapStep> step(double a, double b, double q, double theta);

/// \f$\theta_2\f$ as a real number (instant) of step(); NaN on failure.
double theta2(double a, double b, double q, double theta);

}  // namespace dfchaos::certified::oracle
