// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/roots/piecewise.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "dfchaos/double_double.hpp"

namespace dfchaos {

long double QuadraticPlusHarmonic::value_at(long double s, double phi) const {
  return (alpha * s + (beta + beta_tail)) * s + gamma + static_cast<long double>(A * std::sin(phi) + B * std::cos(phi));
}
long double QuadraticPlusHarmonic::slope_at(long double s, double phi) const {
  return 2 * alpha * s + (beta + beta_tail) + static_cast<long double>(A * std::cos(phi) - B * std::sin(phi));
}

long double QuadraticPlusHarmonic::value(const Instant& t) const {
  const long double s = elapsed(origin, t);
  if (!(s >= roots_detail::kRecentreFrom)) return value_at(s, t.phase);
  return roots_detail::recentred(*this, t).first + static_cast<long double>(A * std::sin(t.phase) + B * std::cos(t.phase));
}
long double QuadraticPlusHarmonic::slope(const Instant& t) const {
  const long double s = elapsed(origin, t);
  if (!(s >= roots_detail::kRecentreFrom)) return slope_at(s, t.phase);
  return roots_detail::recentred(*this, t).second + static_cast<long double>(A * std::cos(t.phase) - B * std::sin(t.phase));
}

namespace roots_detail {

using dd::DD;

std::pair<long double, long double> recentred(const QuadraticPlusHarmonic& f, const Instant& at) {
  const double k = static_cast<double>(at.turn - f.origin.turn);  // |k| < 2^53
  const DD S = dd::add(dd::add(dd::two_prod(k, dd::kTwoPi.hi), DD{k * dd::kTwoPi.lo, 0.0}), dd::two_sum(at.phase, -f.origin.phase));
  const DD aS = dd::mul(dd::of(f.alpha), S);
  const DD W = dd::add(aS, dd::add(dd::of(f.beta), dd::of(f.beta_tail)));  // alpha s + beta
  const DD P0 = dd::add(dd::mul(S, W), dd::of(f.gamma));                   // s (alpha s + beta) + gamma
  const DD P1 = dd::add(W, aS);                                            // 2 alpha s + beta
  return {dd::to_long_double(P0), dd::to_long_double(P1)};
}

namespace {

/// The zeros of \f$f''\f$ on one period, ascending, into out[0..1]; returns how many (0 or 2).
/// A sin t + B cos t = R sin(t + delta), delta = atan2(B, A); zeros of f'' solve sin(t+delta) = 2 alpha / R.
int inflection_phases_into(const QuadraticPlusHarmonic& f, double out[2]) {
  const double R = std::hypot(f.A, f.B);
  if (R == 0) return 0;
  const double w = static_cast<double>(2 * f.alpha) / R;
  if (!(std::fabs(w) < 1)) return 0;  // f'' keeps one sign (tangency at most): f' monotone
  const double delta = std::atan2(f.B, f.A), s = std::asin(w);
  out[0] = wrap_phase(s - delta);
  out[1] = wrap_phase(pi - s - delta);
  if (out[1] < out[0]) std::swap(out[0], out[1]);
  return 2;
}

}  // namespace

const Inflections& inflections_cached(const QuadraticPlusHarmonic& f) {
  struct Entry {
    bool valid = false;
    double A = 0, B = 0;
    long double alpha = 0;
    Inflections value;
  };
  thread_local Entry cache[2];
  thread_local int next = 0;
  for (const Entry& e : cache)
    // (signbit too: atan2 tells -0 from +0, so the inflections of B = -0 and B = +0 may differ)
    if (e.valid && e.A == f.A && e.B == f.B && e.alpha == f.alpha && std::signbit(e.A) == std::signbit(f.A) && std::signbit(e.B) == std::signbit(f.B))
      return e.value;
  Entry& e = cache[next];
  next ^= 1;
  e.value.n = inflection_phases_into(f, e.value.at);
  for (int i = 0; i < e.value.n; ++i) ::sincos(e.value.at[i], &e.value.sn[i], &e.value.cs[i]);  // (glibc: one call)
  e.A = f.A;
  e.B = f.B;
  e.alpha = f.alpha;
  e.valid = true;
  return e.value;
}

bool quadratic_roots(long double alpha, long double beta, long double k, long double& r1, long double& r2) {
  const long double disc = beta * beta - 4 * alpha * k;
  if (disc < 0) return false;
  const long double sq = std::sqrt(disc);
  const long double qq = -0.5L * (beta + (beta >= 0 ? sq : -sq));
  if (qq == 0) {
    r1 = r2 = 0;
    return true;
  }
  r1 = qq / alpha;
  r2 = k / qq;
  if (r1 > r2) std::swap(r1, r2);
  return true;
}

SearchBounds search_bounds(const QuadraticPlusHarmonic& f, long double R, long double horizon) {
  SearchBounds b;
  b.limit = horizon;
  auto shrink = [](long double lo, long double hi, long double& a, long double& e) {
    // Well separated roots are accurate to a few long-double ulps (relative 1e-18): the margin covers
    // them a billionfold, but is capped at 10 (3 pieces of the harmonic part), reached only by flights
    // beyond 1e10 (b/a below 1e-10), whose relative 1e-9 would leave hundreds of pieces of the middle
    // of a flight to scan (a 1e12 flight: a margin of 1000, 320 pieces). Nearly double roots are
    // ill-conditioned (error about eps r^2 / w for a window of half-width w), but for G1 such a
    // window needs alpha r^2 of order gamma + R <= 2a, so r <= sqrt(2a/b), where the cap is not reached.
    const long double margin = std::min(1e-9L * (1 + std::fabs(hi)), 10.0L);
    a = lo + margin;
    e = hi - margin;
    if (!(a < e)) a = e = 0;
  };
  if (f.alpha > 0) {
    long double r1, r2;
    if (quadratic_roots(f.alpha, f.beta, f.gamma + R, r1, r2) && r2 > 0) shrink(std::max(r1, 0.0L), r2, b.ws, b.we);
    if (quadratic_roots(f.alpha, f.beta, f.gamma - R, r1, r2)) {
      const long double bound = std::max(r2, 0.0L) * (1 + 1e-9L) + 1e-6L;
      if (bound < b.limit) {
        b.limit = bound;
        b.limit_is_bound = true;
      }
    } else {
      b.limit = std::min(b.limit, 1e-6L);  // lower bound positive everywhere: f >= 0 at once
      b.limit_is_bound = true;
    }
  } else if (f.beta > 0) {
    const long double s_neg = -(f.gamma + R) / f.beta;
    if (s_neg > 0) shrink(0, s_neg, b.ws, b.we);
    const long double bound = std::max((R - f.gamma) / f.beta, 0.0L) * (1 + 1e-9L) + 1e-6L;
    if (bound < b.limit) {
      b.limit = bound;
      b.limit_is_bound = true;
    }
  } else if (f.beta < 0 || f.gamma + R < 0) {
    // U decreases (or is a negative constant): beyond its root there is no root of f.
    const long double s_neg = f.beta < 0 ? -(f.gamma + R) / f.beta : 0;
    if (s_neg <= 0) {
      b.no_root = true;
      return b;
    }
    b.limit = std::min(b.limit, s_neg * (1 + 1e-9L) + 1e-6L);
  }
  return b;
}

PieceBreaks piece_breaks(const QuadraticPlusHarmonic& f) {
  PieceBreaks b;
  const Inflections& inf = inflections_cached(f);
  if (inf.n == 0) {
    b.n = 1;
    b.br[0] = {0.0, 0.0, 1.0, true};
    return b;
  }
  for (int i = 0; i < inf.n; ++i) {
    b.br[i] = {inf.at[i], inf.sn[i], inf.cs[i], true};
    const double d = std::fabs(inf.at[i] - f.origin.phase);
    if (std::min(d, two_pi - d) < 1e-12) b.br[i] = {f.origin.phase, f.origin_sin, f.origin_cos, f.origin_trig};
  }
  // Ascending (the snap may have swapped two inflections that were within 1e-12 of each other),
  // distinct.
  if (b.br[1].at < b.br[0].at) std::swap(b.br[0], b.br[1]);
  b.n = b.br[1].at == b.br[0].at ? 1 : 2;
  return b;
}

}  // namespace roots_detail
}  // namespace dfchaos
