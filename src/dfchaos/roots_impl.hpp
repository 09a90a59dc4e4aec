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
double solve_increasing(GD&& gd, double lo, double hi, double scale, long double g_lo, long double g_hi) {
  const double tol = 4 * DBL_EPSILON * (std::fabs(scale) + std::fabs(hi) + 1.0);
  // Start from the secant of the end values (inside the bracket), then Newton's method, with a
  // bisection whenever a Newton step would leave the bracket or fails to halve the previous step.
  double x = 0.5 * (lo + hi);
  if (g_lo < 0 && g_hi > 0) {
    const double sec = static_cast<double>(lo - g_lo * (hi - lo) / (g_hi - g_lo));
    if (sec > lo && sec < hi) x = sec;
  }
  double dx_old = hi - lo, dx = dx_old;
  for (int it = 0; it < 400; ++it) {
    const auto r = gd(x);  // value and derivative (and second derivative) from one evaluation
    const long double g = std::get<0>(r), d = std::get<1>(r);
    if (g == 0) return x;
    if (g < 0) lo = x; else hi = x;
    if (hi - lo <= tol) return hi;
    bool newton_ok;
    double newton;
    if constexpr (std::tuple_size_v<std::decay_t<decltype(r)>> == 3) {
      // Halley's correction, in double (its relative error 1e-16 moves the next iterate by far
      // less than the tolerance): the Newton step divided by 1 - g g''/(2 g'^2) when that ratio is
      // below 1/2. Accepted only if at most half the step before the last one.
      double step = 0;
      if (d > 0) {
        const double gd_ = static_cast<double>(g), dd_ = static_cast<double>(d);
        step = gd_ / dd_;
        const double ratio = step * static_cast<double>(std::get<2>(r)) / (2 * dd_);
        if (std::fabs(ratio) < 0.5) step /= 1 - ratio;
      }
      newton_ok = d > 0 && std::fabs(2 * step) <= std::fabs(dx_old);
      // Converged: the correction is below the tolerance (see below).
      if (newton_ok && std::fabs(step) <= 0.5 * tol) return x;
      newton = newton_ok ? x - step : 0.0;
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
