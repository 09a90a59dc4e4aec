// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/roots/piece_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace dfchaos::roots_detail {

namespace {

/// A start for the root search on a piece [0, L] where f(0) < 0 <= f(L): the root of the quintic
/// Hermite interpolant of f, f', f'' at both ends (f0, d0, k0 at 0; f1, d1, k1 at L), found by a
/// bracketed Newton iteration on the interpolant (no evaluation of f). The interpolant differs from
/// f by at most \f$L^6 \max|f^{(6)}| / 46080 \le L^6 R / 46080\f$ (\f$f^{(6)}\f$ is the harmonic
/// part's): about \f$0.02R\f$ on a piece of length \f$\pi\f$, the common case (the pieces between
/// the two inflections of the gap or of the progression velocity). Pieces reach \f$2\pi\f$ when
/// \f$f''\f$ has no sign change, or two nearly coincident ones; the bound is then no better than
/// the secant's. A start only: the root itself is found by solve_increasing on f.
/// Returns NaN when the interpolant gives no start inside (0, L).
double hermite_start(double L, double f0, double d0, double k0, double f1, double d1, double k1) {
  // p(t) = f0 + m0 t + K0 t^2 / 2 + c3 t^3 + c4 t^4 + c5 t^5 on t = u / L in [0, 1].
  const double m0 = d0 * L, m1 = d1 * L, K0 = k0 * L * L, K1 = k1 * L * L, df = f1 - f0;
  const double c3 = 10 * df - 6 * m0 - 4 * m1 - 1.5 * K0 + 0.5 * K1;
  const double c4 = -15 * df + 8 * m0 + 7 * m1 + 1.5 * K0 - K1;
  const double c5 = 6 * df - 3 * (m0 + m1) - 0.5 * (K0 - K1);
  const double c2 = 0.5 * K0;
  double lo = 0, hi = 1, t = f0 / (f0 - f1);  // secant start, then Newton kept inside [lo, hi]
  if (!(t > 0 && t < 1)) t = 0.5;
  for (int it = 0; it < 12; ++it) {
    const double p = f0 + t * (m0 + t * (c2 + t * (c3 + t * (c4 + t * c5))));
    const double dp = m0 + t * (2 * c2 + t * (3 * c3 + t * (4 * c4 + t * 5 * c5)));
    (p < 0 ? lo : hi) = t;
    double next = dp > 0 ? t - p / dp : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::fabs(next - t) <= 1e-6;
    t = next;
    if (done) break;
  }
  const double u = t * L;
  return u > 0 && u < L ? u : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

std::optional<UpCrossing> search_piece(PieceFunction& pf, const Cursor& at, double L, long double R, long pieces, PieceEnd& end) {
  const QuadraticPlusHarmonic& f = pf.f_;
  const Instant& cursor = at.t;
  const long double s0 = at.s;
  const long double* left_value = at.has_left_value ? &at.left_value : nullptr;
  const PieceEnd& start = at.carried;
  auto val_der = [&pf](double u) { return pf.value_slope(u); };
  auto crossing_at = [&](double u) {
    UpCrossing r;
    r.t = advance(cursor, u);
    r.s = s0 + u;
    r.slope = static_cast<double>(pf.slope(u));
    r.pieces = pieces;
    return r;
  };
  const double phi0 = pf.phi0_;
  // Value and slope at both ends (the harmonic part at a break end is known; the start's is the
  // end of the previous piece when the scan continues from there).
  const HarmonicAt h1 = pf.harmonic(L);
  const long double f_end = pf.poly(L) + static_cast<long double>(h1.H), d1 = pf.dpoly(L) + static_cast<long double>(h1.D);
  end = PieceEnd{true, f_end, d1, h1.H, h1.D};
  long double f_start_computed, d0;
  if (start.valid) {
    pf.add_anchor(HarmonicAt{0, start.H, start.D});
    f_start_computed = start.value;
    d0 = start.slope;
  } else {
    std::tie(f_start_computed, d0) = val_der(0);
  }
  const bool after_rest = left_value != nullptr;  // f(0) is the value left by the rest region
  const long double f_start = after_rest ? *left_value : f_start_computed;
  // On a piece f' is monotone, so f is increasing, decreasing, convex with one minimum or
  // concave with one maximum. Two shortcuts avoid the split point m below:
  // (1) f(0) < 0 <= f(L): in every one of these shapes there is exactly one up-crossing in
  //     (0, L], with f < 0 before it and f >= 0 after it, so the sign bracket [0, L] is valid
  //     (the solver bisects where f' < 0).
  auto val_der_curv = [&pf](double u) { return pf.value_slope_curvature(u); };
  if (f_start < 0 && f_end >= 0) {
    // (After a start at rest the value at 0 is a bound, not data for an interpolant: secant start.)
    const double guess = after_rest ? std::numeric_limits<double>::quiet_NaN()
                                    : hermite_start(L, static_cast<double>(f_start), static_cast<double>(d0),
                                                    static_cast<double>(2 * f.alpha) - (start.valid ? start.H : pf.harmonic(0).H),
                                                    static_cast<double>(f_end), static_cast<double>(d1), static_cast<double>(2 * f.alpha) - h1.H);
    // (|f'''| = |A cos t - B sin t| <= R.)
    return crossing_at(solve_increasing(val_der_curv, 0, L, phi0, f_start, f_end, guess, static_cast<double>(R)));
  }
  // (2) f < 0 at both ends: only a concave piece can rise above 0 in between. Its graph lies
  //     below the tangent lines at both ends, so its maximum is at most where the tangents
  //     cross; the piece is skipped when that bound is negative beyond a rounding margin (the
  //     terms of f are up to alpha s^2 in size).
  if (f_start < 0 && f_end < 0) {
    if (!(d0 > 0 && d1 < 0)) return std::nullopt;
    const long double s_far = s0 + L;
    const long double margin = 1e-12L * (R + f.alpha * s_far * s_far + std::fabs(f.beta) * s_far + std::fabs(f.gamma) + 1);
    const long double u_cross = std::clamp((f_end - d1 * L - f_start) / (d0 - d1), 0.0L, static_cast<long double>(L));
    if (std::min(f_start + d0 * u_cross, f_end + d1 * (u_cross - L)) < -margin) return std::nullopt;
  }
  // The general case: split at the zero m of f' and look for a crossing from below in each
  // monotone part.
  double sub[3] = {0, L, L};
  int nsub = 1;
  if ((d0 > 0 && d1 < 0) || (d0 < 0 && d1 > 0)) {
    auto der_curv = [&pf](double u) { return pf.slope_curvature_jerk(u); };
    const double m = d0 > 0 ? solve_increasing(
                                  [&](double u) {
                                    const auto [d, c, j] = der_curv(u);
                                    return std::tuple<long double, long double, long double>{-d, -c, -j};
                                  },
                                  0, L, phi0, -d0, -d1)
                            : solve_increasing(der_curv, 0, L, phi0, d0, d1);
    sub[1] = m;
    nsub = 2;
  }
  for (int i = 0; i < nsub; ++i) {
    const double u0 = sub[i], u1 = sub[i + 1];
    const long double dl = (i == 0) ? d0 : 0.0L, dr = (i + 1 == nsub) ? d1 : 0.0L;
    if (!(dl + dr > 0) || u1 <= u0) continue;  // f decreasing (or constant) here: no crossing from below
    const long double f1 = u1 == L ? f_end : pf.value(u1);
    if (f1 < 0) continue;
    const long double f0 = u0 == 0 ? f_start : pf.value(u0);
    if (f0 >= 0) return crossing_at(u0);  // a start not strictly below zero
    return crossing_at(solve_increasing(val_der_curv, u0, u1, phi0, f0, f1));
  }
  return std::nullopt;
}

}  // namespace dfchaos::roots_detail
