/// @file roots_impl.hpp
/// @brief Template definition of solve_increasing (included by roots.hpp).
#pragma once

#include <cfloat>
#include <cmath>
#include <stdexcept>

namespace dfchaos {

template <class G, class DG>
double solve_increasing(G&& g, DG&& dg, double lo, double hi, double scale) {
  const double tol = 4 * DBL_EPSILON * (std::fabs(scale) + std::fabs(hi) + 1.0);
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 400; ++it) {
    if (hi - lo <= tol) return hi;
    const long double gx = g(x);
    if (gx == 0) return x;
    if (gx < 0) lo = x; else hi = x;
    const long double d = dg(x);
    double next = 0.5 * (lo + hi);
    if (it % 4 != 3 && d > 0) {
      const double newton = static_cast<double>(x - gx / d);
      if (newton > lo && newton < hi) {
        if (std::fabs(newton - x) <= 0.5 * tol) return newton;
        next = newton;
      }
    }
    x = next;
  }
  throw std::logic_error("solve_increasing: no convergence in 400 iterations");
}

}  // namespace dfchaos
