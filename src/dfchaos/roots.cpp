#include "dfchaos/roots.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "dfchaos/errors.hpp"

namespace dfchaos {

long double QuadraticPlusHarmonic::value_at(long double s, double phi) const {
  return (alpha * s + beta) * s + gamma + static_cast<long double>(A * std::sin(phi) + B * std::cos(phi));
}
long double QuadraticPlusHarmonic::slope_at(long double s, double phi) const {
  return 2 * alpha * s + beta + static_cast<long double>(A * std::cos(phi) - B * std::sin(phi));
}
long double QuadraticPlusHarmonic::curvature_at(double phi) const {
  return 2 * alpha - static_cast<long double>(A * std::sin(phi) + B * std::cos(phi));
}
long double QuadraticPlusHarmonic::value(const Instant& t) const { return value_at(elapsed(origin, t), t.phase); }
long double QuadraticPlusHarmonic::slope(const Instant& t) const { return slope_at(elapsed(origin, t), t.phase); }

std::vector<double> QuadraticPlusHarmonic::inflection_phases() const {
  // A sin t + B cos t = R sin(t + delta), delta = atan2(B, A); zeros of f'' solve sin(t+delta) = 2 alpha / R.
  const double R = std::hypot(A, B);
  std::vector<double> out;
  if (R == 0) return out;
  const double w = static_cast<double>(2 * alpha) / R;
  if (!(std::fabs(w) < 1)) return out;  // f'' keeps one sign (tangency at most): f' monotone
  const double delta = std::atan2(B, A), s = std::asin(w);
  out = {wrap_phase(s - delta), wrap_phase(pi - s - delta)};
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

/// Roots of alpha s^2 + beta s + k = 0 (alpha > 0), ascending; none if the discriminant is negative.
bool quadratic_roots(long double alpha, long double beta, long double k, long double& r1, long double& r2) {
  const long double disc = beta * beta - 4 * alpha * k;
  if (disc < 0) return false;
  const long double sq = std::sqrt(disc);
  const long double qq = -0.5L * (beta + (beta >= 0 ? sq : -sq));
  if (qq == 0) { r1 = r2 = 0; return true; }
  r1 = qq / alpha;
  r2 = k / qq;
  if (r1 > r2) std::swap(r1, r2);
  return true;
}

}  // namespace

std::optional<UpCrossing> first_upcrossing(const QuadraticPlusHarmonic& f, const SearchLimits& limits) {
  if (f.alpha < 0) throw std::logic_error("first_upcrossing: alpha must be >= 0");
  const long double R = std::hypot(f.A, f.B);

  // Skip window (ws, we): there U(s) = alpha s^2 + beta s + gamma + R < 0 >= f, so no root.
  long double ws = 0, we = 0;
  // Root bound: f(s) >= alpha s^2 + beta s + gamma - R >= 0 for s >= s_bound.
  long double limit = limits.horizon;
  bool limit_is_bound = false;
  auto shrink = [](long double lo, long double hi, long double& a, long double& b) {
    const long double margin = 1e-9L * (1 + std::fabs(hi));
    a = lo + margin;
    b = hi - margin;
    if (!(a < b)) a = b = 0;
  };
  if (f.alpha > 0) {
    long double r1, r2;
    if (quadratic_roots(f.alpha, f.beta, f.gamma + R, r1, r2) && r2 > 0) shrink(std::max(r1, 0.0L), r2, ws, we);
    if (quadratic_roots(f.alpha, f.beta, f.gamma - R, r1, r2)) {
      const long double bound = std::max(r2, 0.0L) * (1 + 1e-9L) + 1e-6L;
      if (bound < limit) { limit = bound; limit_is_bound = true; }
    } else {
      limit = std::min(limit, 1e-6L);  // lower bound positive everywhere: f >= 0 at once
      limit_is_bound = true;
    }
  } else if (f.beta > 0) {
    const long double s_neg = -(f.gamma + R) / f.beta;
    if (s_neg > 0) shrink(0, s_neg, ws, we);
    const long double bound = std::max((R - f.gamma) / f.beta, 0.0L) * (1 + 1e-9L) + 1e-6L;
    if (bound < limit) { limit = bound; limit_is_bound = true; }
  } else if (f.beta < 0 || f.gamma + R < 0) {
    // U decreases (or is negative constant): beyond its root there is no root of f.
    const long double s_neg = f.beta < 0 ? -(f.gamma + R) / f.beta : 0;
    if (s_neg <= 0) return std::nullopt;
    limit = std::min(limit, s_neg * (1 + 1e-9L) + 1e-6L);
  }
  if (!std::isfinite(static_cast<double>(limit)))
    throw GaveUp("first_upcrossing: no horizon and no root bound; the search would not end");

  std::vector<double> breaks = f.inflection_phases();
  // An inflection computed a few ulp away from the origin's phase (the origin *is* an inflection,
  // e.g. a start at rest at t2) would leave a sliver piece whose rounded slope has no meaning:
  // snap such a break onto the origin.
  for (double& b : breaks) {
    const double d = std::fabs(b - f.origin.phase);
    if (std::min(d, two_pi - d) < 1e-12) b = f.origin.phase;
  }
  breaks.push_back(0.0);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  Instant cursor = f.origin;
  long double s_cursor = 0;
  bool left_known_negative = false;
  long pieces = 0;
  if (f.starts_at_rest) {
    // f(origin) = 0 and the slope is O(u) or smaller: evaluations near the origin are below
    // rounding noise. The direction is decided by the first non-negligible Taylor coefficient.
    const double phi = f.origin.phase;
    const long double tiny = 64 * 2.2e-16L * (R + 2 * std::fabs(f.alpha) + std::fabs(f.beta) + 1);
    const long double c1 = f.slope_at(0, phi), c2 = f.curvature_at(phi);
    const long double c3 = static_cast<long double>(-f.A * std::cos(phi) + f.B * std::sin(phi));
    const long double dir = std::fabs(c1) > tiny ? c1 : (std::fabs(c2) > tiny ? c2 : c3);
    if (dir > 0) {  // f rises at once: the root is the origin itself (e.g. contact at rest at t3)
      UpCrossing r;
      r.t = f.origin;
      r.s = 0;
      r.slope = 0;
      r.pieces = 0;
      return r;
    }
    // f < 0 on (0, kRestOffset]: the Taylor terms dominate there by orders of magnitude.
    constexpr long double kRestOffset = 1e-7L;
    if (limit < kRestOffset) return std::nullopt;
    cursor = advance(f.origin, kRestOffset);
    s_cursor = elapsed(f.origin, cursor);
    left_known_negative = true;
  }
  while (true) {
    if (we > 0 && s_cursor >= ws && s_cursor < we) {
      cursor = advance(f.origin, we);
      s_cursor = elapsed(f.origin, cursor);
      left_known_negative = false;
    }
    if (s_cursor >= limit) break;
    if (++pieces > limits.max_pieces)
      throw GaveUp("first_upcrossing: gave up after " + std::to_string(limits.max_pieces) + " monotone pieces");

    // The piece [cursor, end]: up to the next inflection or period boundary, the limit, or the window.
    auto next = std::upper_bound(breaks.begin(), breaks.end(), cursor.phase);
    Instant end = next == breaks.end() ? Instant{cursor.turn + 1, 0.0} : Instant{cursor.turn, *next};
    long double s_end = elapsed(f.origin, end);
    long double cut = limit;
    if (we > 0 && ws > s_cursor) cut = std::min(cut, ws);
    if (s_end > cut) {
      end = advance(f.origin, cut);
      s_end = cut;
    }
    const double L = static_cast<double>(elapsed(cursor, end));
    const double phi0 = cursor.phase;
    const long double s0 = s_cursor;
    auto val = [&](double u) -> long double { return f.value_at(s0 + u, phi0 + u); };
    auto der = [&](double u) -> long double { return f.slope_at(s0 + u, phi0 + u); };
    // Value and slope, or slope and curvature, from one sine-cosine evaluation.
    auto val_der = [&](double u) {
      const double sn = std::sin(phi0 + u), cs = std::cos(phi0 + u);
      const long double s = s0 + u;
      return std::pair<long double, long double>{(f.alpha * s + f.beta) * s + f.gamma + static_cast<long double>(f.A * sn + f.B * cs),
                                                 2 * f.alpha * s + f.beta + static_cast<long double>(f.A * cs - f.B * sn)};
    };
    auto der_curv = [&](double u) {
      const double sn = std::sin(phi0 + u), cs = std::cos(phi0 + u);
      return std::pair<long double, long double>{2 * f.alpha * (s0 + u) + f.beta + static_cast<long double>(f.A * cs - f.B * sn),
                                                 2 * f.alpha - static_cast<long double>(f.A * sn + f.B * cs)};
    };

    if (L > 0) {
      const long double d0 = der(0), d1 = der(L);
      double sub[3] = {0, L, L};
      int nsub = 1;
      if ((d0 > 0 && d1 < 0) || (d0 < 0 && d1 > 0)) {
        // f' is monotone on the piece: its single zero m splits it into two monotone parts.
        const double m = d0 > 0 ? solve_increasing(
                                      [&](double u) {
                                        const auto [d, c] = der_curv(u);
                                        return std::pair<long double, long double>{-d, -c};
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
        if (val(u1) < 0) continue;  // (evaluated twice when it is a root bracket: cheap next to the solve)
        double u;
        const long double f1 = val(u1);
        const long double f0 = (u0 == 0 && left_known_negative) ? -1.0L : val(u0);
        if (f0 >= 0) u = u0;  // a start not strictly below zero
        else u = solve_increasing(val_der, u0, u1, phi0, f0, f1);
        UpCrossing r;
        r.t = advance(cursor, u);
        r.s = s0 + u;
        r.slope = static_cast<double>(der(u));
        r.pieces = pieces;
        return r;
      }
    }
    cursor = end;
    s_cursor = s_end;
    left_known_negative = false;
  }
  if (limit_is_bound && limit < limits.horizon)
    throw std::logic_error("first_upcrossing: no root found before the guaranteed bound (a bug)");
  return std::nullopt;
}

}  // namespace dfchaos
