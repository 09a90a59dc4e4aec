// SPDX-License-Identifier: GPL-3.0-or-later
/// @file roots_impl.hpp
/// @brief Template definition of solve_increasing (included by roots.hpp).
#pragma once

#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <type_traits>

namespace dfchaos {

template <class GD>
double solve_increasing(GD&& gd, double lo, double hi, double scale, long double g_lo, long double g_hi, double start, double jerk_bound) {
  const double tol = 4 * DBL_EPSILON * (std::fabs(scale) + std::fabs(hi) + 1.0);
  // Start from the given start if it lies inside the bracket, else from the secant of the end
  // values, then Newton's method, with a bisection whenever a Newton step would leave the bracket
  // or fails to halve the previous step.
  double x = 0.5 * (lo + hi);
  if (start > lo && start < hi) {
    x = start;
  } else if (g_lo < 0 && g_hi > 0) {
    const double sec = static_cast<double>(lo - g_lo * (hi - lo) / (g_hi - g_lo));
    if (sec > lo && sec < hi) x = sec;
  }
  double dx_old = hi - lo, dx = dx_old;
  for (int it = 0; it < 400; ++it) {
    const auto r = gd(x);  // value and derivative (and second derivative) from one evaluation
    const long double g = std::get<0>(r), d = std::get<1>(r);
    if (g == 0) return x;
    if (g < 0)
      lo = x;
    else
      hi = x;
    if (hi - lo <= tol) return hi;
    bool newton_ok;
    double newton;
    if constexpr (std::tuple_size_v<std::decay_t<decltype(r)>> == 3) {
      // Halley's correction, in double (its relative error 1e-16 moves the next iterate by far
      // less than the tolerance): the Newton step divided by 1 - g g''/(2 g'^2) when that ratio is
      // below 1/2. Accepted only if at most half the step before the last one.
      double step = 0, ratio = 0;
      if (d > 0) {
        const double gd_ = static_cast<double>(g), dd_ = static_cast<double>(d);
        step = gd_ / dd_;
        ratio = step * static_cast<double>(std::get<2>(r)) / (2 * dd_);
        if (std::fabs(ratio) < 0.5) step /= 1 - ratio;
      }
      newton_ok = d > 0 && std::fabs(2 * step) <= std::fabs(dx_old);
      // Converged: the correction is below the tolerance (see below). It is applied: after it the
      // error is at the level of the rounding of g, whatever the path to x was.
      if (newton_ok && std::fabs(step) <= 0.5 * tol) return x - step;
      newton = newton_ok ? x - step : 0.0;
      // Converged after this step, without evaluating g there: Halley's error after a step of
      // size e is about C e^3 with C = (g''/(2g'))^2 - g'''/(6g'); with |g'''| <= jerk_bound near
      // the root and a safety factor 2 on C, when that bound on the error is below tol/16 the
      // iterate x - step is returned at once. The iteration would otherwise evaluate g there and
      // find a correction below tol/2 (so the evaluation is saved). Only for small steps
      // (|g g''/(2 g'^2)| < 0.01) that stay inside the bracket.
      if (newton_ok && newton > lo && newton < hi && jerk_bound >= 0 && std::fabs(ratio) < 0.01) {
        const double dd_ = static_cast<double>(d), k = static_cast<double>(std::get<2>(r)) / (2 * dd_);
        const double C = 2 * (k * k + jerk_bound / (6 * dd_));
        if (C * std::fabs(step) * step * step <= tol / 16) return newton;
      }
    } else {
      newton_ok = d > 0 && std::fabs(2 * g) <= std::fabs(dx_old * d);
      // Converged: the Newton correction is below the tolerance. (Tested before the bracket test:
      // a correction of a few ulp lands on the bracket end just set to x, and rejecting it would
      // fall back to bisection for ~50 more evaluations.)
      if (newton_ok && std::fabs(g / d) <= 0.5L * tol) return x;
      newton = newton_ok ? static_cast<double>(x - g / d) : 0.0;
    }
    dx_old = dx;
    if (newton_ok && newton > lo && newton < hi) {
      dx = x - newton;
      x = newton;
      if (std::fabs(dx) <= 0.5 * tol) return x;
    } else {
      dx = 0.5 * (hi - lo);
      x = lo + dx;
    }
  }
  throw std::logic_error("solve_increasing: no convergence in 400 iterations");
}

}  // namespace dfchaos
