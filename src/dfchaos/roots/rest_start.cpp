// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/roots/rest_start.hpp"

#include <algorithm>
#include <cmath>

#include "dfchaos/phase.hpp"

namespace dfchaos::roots_detail {

RestStart rest_start(const QuadraticPlusHarmonic& f, long double R, long double limit) {
  // f(origin) = 0 exactly, and near the origin f = c1 u + c2 u^2/2 + c3 u^3/6 + ... lies below the
  // rounding noise (~1e-16 R) of a direct evaluation. Taylor coefficients at the origin, with
  // P = A sin(phi) + B cos(phi), Q = A cos(phi) - B sin(phi) in long double:
  // c1 = beta + Q (exactly 0 for a flight from rest), c2 = 2 alpha - P (F at the origin for a
  // flight), c3 = -Q.
  const double phi = f.origin.phase;
  const long double tiny1 = 64 * 2.2e-16L * (R + 2 * std::fabs(f.alpha) + std::fabs(f.beta));
  const long double tiny2 = 64 * 1.1e-19L * (R + 2 * std::fabs(f.alpha));
  long double P = 0, Q = 0, c1 = 0, c2 = 0, c3 = 0;
  auto taylor = [&](long double sn, long double cs) {
    P = f.A * sn + f.B * cs;
    Q = f.A * cs - f.B * sn;
    c1 = (f.beta + f.beta_tail) + Q;
    if (std::fabs(c1) <= tiny1) c1 = 0;  // e.g. a progression from rest at the rounded t0
    c2 = f.origin_at_inflection ? 0.0L : 2 * f.alpha - P;
    if (std::fabs(c2) <= tiny2) c2 = 0;
    c3 = -Q;
  };
  // Double trigonometry resolves c2 unless it is small (the origin near an inflection, e.g. a
  // flight from near t2 or t3); then long double, whose error 1e-19 R fixes the sign of c2 for
  // every double phase in [t2, t3) (there |F| >= a cos(t3) ulp/2).
  double sd = f.origin_sin, cd = f.origin_cos;
  if (!f.origin_trig) ::sincos(phi, &sd, &cd);  // (glibc; std::sin and std::cos here would be two calls)
  {
    // Fast path, in double, for the common Case A below (f'' < 0 well beyond rounding on the
    // whole rest region, f' not rising): the decision is the same as in long double.
    const double Rd = static_cast<double>(R), al = static_cast<double>(f.alpha);
    const double Pd = f.A * sd + f.B * cd, Qd = f.A * cd - f.B * sd;
    const double c1d = static_cast<double>(f.beta + f.beta_tail) + Qd, c2d = 2 * al - Pd;
    const double scale = Rd + 2 * al;
    if (!f.origin_at_inflection && c1d <= static_cast<double>(tiny1) && -c2d > std::fabs(Qd) * 1e-3 + 0.5e-6 * Rd + 1e-12 * scale && limit >= 1e-3L)
      return {RestStart::Resume, {}, -1.0L, true};
  }
  taylor(sd, cd);
  if (std::fabs(c2) < 1e-9L * (R + 2 * std::fabs(f.alpha))) taylor(std::sin(static_cast<long double>(phi)), std::cos(static_cast<long double>(phi)));
  if (c1 > 0 || (c1 == 0 && (c2 > 0 || (c2 == 0 && c3 > 0)))) {
    // f rises at once: the root is the origin itself (the motion never leaves the contact, e.g.
    // a start at rest at or beyond t3, where F >= 0).
    UpCrossing r;
    r.t = f.origin;
    r.s = 0;
    r.slope = 0;
    r.pieces = 0;
    return {RestStart::Root, r, 0};
  }
  // f falls at once (c1 < 0, or c1 = 0 > c2, or c1 = c2 = 0 > c3). Search the rest region (0, U].
  // |f''''| <= R, so |f''(u) - c2| <= |c3| u + R u^2/2 and |f'''(u) - c3| <= R u there.
  // With no root in (0, U] the scan goes on from 1e-7 (where it always started: the common
  // cases keep bit-identical results), f being known negative there.
  constexpr long double kRestRegion = 1e-3L;
  const long double U = std::min(kRestRegion, limit);
  if (c2 < 0 && -c2 > std::fabs(c3) * U + 0.5L * R * U * U) {
    // Case A (by far the most common): f'' < 0 on [0, U], so f' < c1 <= 0 and f < 0 on (0, U];
    // the first piece of the scan is concave and falling, and is skipped whatever f is there.
    if (limit < kRestOffset) return {RestStart::NoRoot, {}, 0};
    return {RestStart::Resume, {}, -1.0L, true};
  } else {
    // Cases B, C: the cancellation-free form, accurate to a few ulp relative to its terms.
    auto half_minus_h1 = [](long double u) {  // 1/2 - (1 - cos u)/u^2
      const long double u2 = u * u;
      return u2 * (1.0L / 24 - u2 * (1.0L / 720 - u2 / 40320));
    };
    auto h2 = [](long double u) {  // (u - sin u)/u^3
      const long double u2 = u * u;
      return 1.0L / 6 - u2 * (1.0L / 120 - u2 * (1.0L / 5040 - u2 / 362880));
    };
    auto m = [&](long double u) { return 0.5L * c2 + P * half_minus_h1(u) - Q * u * h2(u); };  // (f - c1 u)/u^2
    auto fr = [&](long double u) { return c1 * u + u * u * m(u); };
    auto dr = [&](long double u) { return c1 + c2 * u + P * u * u * u * h2(u) - Q * u * u * (0.5L - half_minus_h1(u)); };
    auto cr = [&](long double u) { return c2 + P * u * u * (0.5L - half_minus_h1(u)) - Q * (u - u * u * u * h2(u)); };
    // g keeps the sign of f on (0, U] and stays away from 0 near u = 0: g = f/u^2 when c1 = 0
    // (g(0) = c2/2 < 0), else g = f/u (g(0) = c1 < 0).
    auto g = [&](long double u) { return c1 == 0 ? m(u) : c1 + u * m(u); };
    auto root_at = [&](long double u) {
      UpCrossing r;
      r.t = advance(f.origin, u);
      r.s = elapsed(f.origin, r.t);
      r.slope = static_cast<double>(std::max(dr(r.s), 0.0L));
      r.pieces = 1;
      return r;
    };
    // The single sign change of g on (0, hi] (g(hi) >= 0), by Illinois regula falsi to relative
    // long-double precision; returns the end where g >= 0. Bounded: 300 iterations.
    auto solve_sign_change = [&](long double hi) {
      long double lo = 0, glo = c1 == 0 ? 0.5L * c2 : c1, ghi = g(hi);
      int side = 0;
      for (int it = 0; it < 300 && hi - lo > 4 * 1.1e-19L * hi; ++it) {
        long double x = hi - ghi * (hi - lo) / (ghi - glo);
        if (!(x > lo && x < hi)) x = 0.5L * (lo + hi);
        const long double gx = g(x);
        if (gx < 0) {
          lo = x, glo = gx;
          if (side == -1) ghi *= 0.5L;
          side = -1;
        } else {
          hi = x, ghi = gx;
          if (side == 1) glo *= 0.5L;
          side = 1;
        }
      }
      return hi;
    };
    // Bisection for the sign change of a function h that goes from > 0 to <= 0 on [lo, hi].
    auto last_positive = [](auto&& h, long double lo, long double hi) {
      for (int it = 0; it < 200 && hi - lo > 4 * 1.1e-19L * hi; ++it) {
        const long double x = 0.5L * (lo + hi);
        (h(x) > 0 ? lo : hi) = x;
      }
      return lo;
    };
    if (std::fabs(c3) > R * U) {  // f''' keeps the sign of c3 on [0, U]: f'' is monotone
      if (c3 > 0) {
        // Case B: f'' increasing, f' convex with f'(0) = c1 <= 0: f falls, then may rise once.
        // (A flight from rest just below t3: c2 = F(theta) < 0 tiny, root near 3 (t3 - theta).)
        if (g(U) >= 0) return {RestStart::Root, root_at(solve_sign_change(U)), 0};
      } else if (c2 > 0) {
        // Case C: f'' decreasing from c2 > 0 (so c1 < 0): f' rises while f'' > 0, then falls;
        // f increases between the up- and down-crossings of f', and is largest at the latter.
        const long double ui = cr(U) < 0 ? last_positive(cr, 0, U) : U;
        if (dr(ui) > 0) {
          const long double ub = dr(U) < 0 ? last_positive(dr, ui, U) : U;
          if (g(ub) >= 0) return {RestStart::Root, root_at(solve_sign_change(ub)), 0};
        }
      }
      // Otherwise f'' < 0 on (0, U] (c3 < 0, c2 <= 0) and f < 0 there.
    }
    // (Neither bound applies only when f'' and f''' nearly vanish together at the origin,
    // 2 alpha = +-R to about 1e-6: b/a within 5e-7 of 1/2. f < 0 on (0, U] is then assumed.)
    if (limit < kRestOffset) return {RestStart::NoRoot, {}, 0};
    return {RestStart::Resume, {}, std::min(fr(elapsed(f.origin, advance(f.origin, kRestOffset))), -0.0L)};
  }
}

}  // namespace dfchaos::roots_detail
