/// @file roots_impl.hpp
/// @brief Template definition of solve_increasing (included by roots.hpp).
#pragma once

#include <cfloat>
#include <cmath>
#include <stdexcept>

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
    const auto [g, d] = gd(x);  // value and derivative from one evaluation
    if (g == 0) return x;
    if (g < 0) lo = x; else hi = x;
    if (hi - lo <= tol) return hi;
    const bool newton_ok = d > 0 && std::fabs(2 * g) <= std::fabs(dx_old * d);
    // Converged: the Newton correction is below the tolerance. (Tested before the bracket test:
    // a correction of a few ulp lands on the bracket end just set to x, and rejecting it would
    // fall back to bisection for ~50 more evaluations.)
    if (newton_ok && std::fabs(g / d) <= 0.5L * tol) return x;
    const double newton = newton_ok ? static_cast<double>(x - g / d) : 0.0;
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
