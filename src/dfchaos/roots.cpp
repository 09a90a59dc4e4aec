#include "dfchaos/roots.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "dfchaos/double_double.hpp"
#include "dfchaos/errors.hpp"

namespace dfchaos {

long double QuadraticPlusHarmonic::value_at(long double s, double phi) const {
  return (alpha * s + (beta + beta_tail)) * s + gamma + static_cast<long double>(A * std::sin(phi) + B * std::cos(phi));
}
long double QuadraticPlusHarmonic::slope_at(long double s, double phi) const {
  return 2 * alpha * s + (beta + beta_tail) + static_cast<long double>(A * std::cos(phi) - B * std::sin(phi));
}

namespace {

using dd::DD;

/// Pieces that start this far (in time) from the origin are evaluated re-centred. Below it the direct
/// long-double evaluation loses at most ~2e-19 s a < 4e-15 a (s itself resolved to 2e-15), results
/// stay bit-identical to the direct evaluation, and no per-piece double-double work is spent.
constexpr long double kRecentreFrom = 16384;
/// Re-centred pieces between two exact (double-double) re-centrings.
constexpr int kRecentreEvery = 16;

/// The polynomial part p(s) = alpha s^2 + beta s + gamma and its slope at the instant `at`, with
/// s = elapsed(origin, at) formed exactly as 2 pi * turns + (phase difference) in double-double.
std::pair<long double, long double> recentred(const QuadraticPlusHarmonic& f, const Instant& at) {
  const double k = static_cast<double>(at.turn - f.origin.turn);  // |k| < 2^53
  const DD S = dd::add(dd::add(dd::two_prod(k, dd::kTwoPi.hi), DD{k * dd::kTwoPi.lo, 0.0}), dd::two_sum(at.phase, -f.origin.phase));
  const DD aS = dd::mul(dd::of(f.alpha), S);
  const DD W = dd::add(aS, dd::add(dd::of(f.beta), dd::of(f.beta_tail)));  // alpha s + beta
  const DD P0 = dd::add(dd::mul(S, W), dd::of(f.gamma));                    // s (alpha s + beta) + gamma
  const DD P1 = dd::add(W, aS);                                             // 2 alpha s + beta
  return {dd::to_long_double(P0), dd::to_long_double(P1)};
}

}  // namespace

long double QuadraticPlusHarmonic::value(const Instant& t) const {
  const long double s = elapsed(origin, t);
  if (!(s >= kRecentreFrom)) return value_at(s, t.phase);
  return recentred(*this, t).first + static_cast<long double>(A * std::sin(t.phase) + B * std::cos(t.phase));
}
long double QuadraticPlusHarmonic::slope(const Instant& t) const {
  const long double s = elapsed(origin, t);
  if (!(s >= kRecentreFrom)) return slope_at(s, t.phase);
  return recentred(*this, t).second + static_cast<long double>(A * std::cos(t.phase) - B * std::sin(t.phase));
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

/// What a start at rest (f(origin) = 0 exactly) leads to near the origin.
struct RestStart {
  enum Kind { Root, NoRoot, Resume } kind;  ///< a root found; no root within the limit; scan on from kRestOffset
  UpCrossing root;                          ///< (Root) the root, possibly the origin itself
  long double left_value;                   ///< (Resume) f at kRestOffset, or -1 for "negative"
  /// (Resume) Case A below: f'' < 0 at the origin beyond rounding and f' <= 0 there. Since f'' keeps
  /// its sign on a piece, f' < 0 and f falls on the whole first piece of the scan, which therefore
  /// holds no up-crossing and needs no evaluation.
  bool falling = false;
};

/// Distance from the origin at which the scan of a start at rest resumes (where it always started).
constexpr long double kRestOffset = 1e-7L;

/// The start-at-rest analysis of first_upcrossing (see QuadraticPlusHarmonic::starts_at_rest), out of
/// line: it runs once per search, and keeps the piece loop small.
[[gnu::noinline]] RestStart rest_start(const QuadraticPlusHarmonic& f, long double R, long double limit) {
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
    if (!f.origin_at_inflection && c1d <= static_cast<double>(tiny1) &&
        -c2d > std::fabs(Qd) * 1e-3 + 0.5e-6 * Rd + 1e-12 * scale && limit >= 1e-3L)
      return {RestStart::Resume, {}, -1.0L, true};
  }
  taylor(sd, cd);
  if (std::fabs(c2) < 1e-9L * (R + 2 * std::fabs(f.alpha)))
    taylor(std::sin(static_cast<long double>(phi)), std::cos(static_cast<long double>(phi)));
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

/// \f$R = \sqrt{A^2 + B^2}\f$: hypot, exact and cheaper when one of the two is 0, as in both event
/// functions of the model.
long double amplitude(double A, double B) {
  if (B == 0) return std::fabs(A);
  if (A == 0) return std::fabs(B);
  return std::hypot(A, B);
}

/// The inflection phases of a coefficient set and \f$\sin, \cos\f$ there (one sincos call each).
struct Inflections {
  int n = 0;                        ///< how many (0 or 2)
  double at[2] = {0, 0};            ///< the phases, ascending
  double sn[2] = {0, 0}, cs[2] = {0, 0};  ///< sine and cosine at them
};

/// inflection_phases_into and the sine and cosine there, remembered per thread for the last two
/// coefficient sets \f$(A, B, \alpha)\f$: an evaluation of T searches two kinds of function (the
/// gap, the progression velocity), whose coefficients repeat from one search to the next. A pure
/// function of its key, so the results do not depend on what was computed before.
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
    if (e.valid && e.A == f.A && e.B == f.B && e.alpha == f.alpha && std::signbit(e.A) == std::signbit(f.A) &&
        std::signbit(e.B) == std::signbit(f.B))
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

/// Where the search looks, from the quadratic envelope \f$\alpha s^2 + \beta s + \gamma \pm R\f$ of f
/// (\f$R = \sqrt{A^2 + B^2}\f$).
struct SearchBounds {
  /// Skip window (ws, we): there \f$U(s) = \alpha s^2 + \beta s + \gamma + R < 0\f$ and \f$f \le U\f$,
  /// so f has no root (no window when ws = we = 0).
  long double ws = 0, we = 0;
  /// End of the search: the horizon, or a root bound beyond which
  /// \f$f \ge \alpha s^2 + \beta s + \gamma - R \ge 0\f$.
  long double limit = 0;
  bool limit_is_bound = false;  ///< limit is a root bound: a root must be found before it
  bool no_root = false;         ///< U is negative from the start on and never rises: no root at all

  /// Whether the elapsed time s lies in the skip window.
  bool in_window(long double s) const { return we > 0 && s >= ws && s < we; }
};

/// The skip window and the limit of a search (SearchBounds), searching up to `horizon`.
SearchBounds search_bounds(const QuadraticPlusHarmonic& f, long double R, long double horizon) {
  SearchBounds b;
  b.limit = horizon;
  auto shrink = [](long double lo, long double hi, long double& a, long double& e) {
    const long double margin = 1e-9L * (1 + std::fabs(hi));
    a = lo + margin;
    e = hi - margin;
    if (!(a < e)) a = e = 0;
  };
  if (f.alpha > 0) {
    long double r1, r2;
    if (quadratic_roots(f.alpha, f.beta, f.gamma + R, r1, r2) && r2 > 0) shrink(std::max(r1, 0.0L), r2, b.ws, b.we);
    if (quadratic_roots(f.alpha, f.beta, f.gamma - R, r1, r2)) {
      const long double bound = std::max(r2, 0.0L) * (1 + 1e-9L) + 1e-6L;
      if (bound < b.limit) { b.limit = bound; b.limit_is_bound = true; }
    } else {
      b.limit = std::min(b.limit, 1e-6L);  // lower bound positive everywhere: f >= 0 at once
      b.limit_is_bound = true;
    }
  } else if (f.beta > 0) {
    const long double s_neg = -(f.gamma + R) / f.beta;
    if (s_neg > 0) shrink(0, s_neg, b.ws, b.we);
    const long double bound = std::max((R - f.gamma) / f.beta, 0.0L) * (1 + 1e-9L) + 1e-6L;
    if (bound < b.limit) { b.limit = bound; b.limit_is_bound = true; }
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

/// The phases in [0, 2 pi) where pieces end: the inflections of f (zeros of f''), ascending and
/// distinct, or the phase 0 alone when f'' has no sign change (then a piece is one whole period).
/// Between two consecutive breaks f' is monotone; a piece may run across the phase 0 (turn
/// boundary). With each break, the sine and cosine of its phase when known (the harmonic part at a
/// piece end is then formed from them, without a sincos call). (A fixed array: this is built once
/// per search, and a heap allocation here cost more than the arithmetic.)
struct PieceBreaks {
  /// One break: its phase, and the sine and cosine there when known.
  struct Break {
    double at = 0;      ///< the phase
    double sn = 0;      ///< sine at it (when trig)
    double cs = 0;      ///< cosine at it (when trig)
    bool trig = false;  ///< whether sn, cs hold
  };
  std::array<Break, 2> br{};  ///< the breaks, ascending by phase
  int n = 0;                  ///< how many (1 or 2)

  /// The end of the piece that starts at `cursor`: the first break after its phase in the same
  /// turn, else the first break of the next turn; `index` receives which break it is.
  Instant next_after(const Instant& cursor, int& index) const {
    for (int i = 0; i < n; ++i)
      if (br[i].at > cursor.phase) {
        index = i;
        return Instant{cursor.turn, br[i].at};
      }
    index = 0;
    return Instant{cursor.turn + 1, br[0].at};
  }
};

/// The piece breaks of f. An inflection computed a few ulp away from the origin's phase (the origin
/// *is* an inflection, e.g. a start at rest at t2) would leave a sliver piece whose rounded slope
/// has no meaning: such a break is snapped onto the origin (within 1e-12 on the circle).
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

/// The polynomial part carried from piece to piece far from the origin (see roots.hpp): at the
/// instant `at`, \f$\alpha(s_0+u)^2 + \beta(s_0+u) + \gamma = P_0 + P_1 u + \alpha u^2\f$.
struct Recentring {
  bool valid = false;  ///< P0, P1 hold for the instant `at`
  Instant at;          ///< where they hold
  long double P0 = 0;  ///< the polynomial at `at`
  long double P1 = 0;  ///< its slope at `at`
  int steps = 0;       ///< carried steps since the last exact re-centring

  /// The coefficients (base, c1, c0) of the polynomial part on the piece starting at `cursor`
  /// (elapsed time s0), written as \f$(\alpha s + c_1) s + c_0\f$ with \f$s = \mathrm{base} + u\f$:
  /// directly (base = s0, c1 = beta, c0 = gamma) below kRecentreFrom; beyond, re-centred (base = 0,
  /// c1 = P1, c0 = P0), exactly (double-double) at the first far piece and every kRecentreEvery
  /// pieces, in between carried over from the previous piece (carry()).
  void coefficients(const QuadraticPlusHarmonic& f, const Instant& cursor, long double s0, long double& base, long double& c1,
                    long double& c0) {
    base = s0;
    c1 = f.beta + f.beta_tail;
    c0 = f.gamma;
    if (s0 >= kRecentreFrom) {
      base = 0;
      if (valid && at == cursor && steps < kRecentreEvery) {
        c0 = P0;
        c1 = P1;
        ++steps;
      } else {
        std::tie(c0, c1) = recentred(f, cursor);
        steps = 0;
      }
    }
  }
  /// Carries re-centred coefficients (c0, c1) at `from` over a piece to `to` in long double:
  /// \f$P_0 \mathrel{+}= (P_1 + \alpha L) L\f$, \f$P_1 \mathrel{+}= 2\alpha L\f$ (each step adds ~1e-19 a:
  /// the pieces there have \f$P_0, P_1 = O(a)\f$).
  void carry(const QuadraticPlusHarmonic& f, const Instant& from, const Instant& to, long double c0, long double c1) {
    const long double Lp = elapsed(from, to);
    P0 = c0 + (c1 + f.alpha * Lp) * Lp;
    P1 = c1 + 2 * f.alpha * Lp;
    at = to;
    valid = true;
  }
};

/// Steps up to this size (in phase) are taken from a known sine-cosine pair by the addition
/// theorem with the short series of small_sincos(), not by a call of sincos (see PieceFunction).
constexpr double kRotate = 0.25;

/// \f$\sin h\f$ and \f$\cos h - 1\f$ for \f$|h| \le\f$ kRotate, by their Taylor series (to
/// \f$h^{15}\f$ and \f$h^{16}\f$: the first omitted term is below \f$10^{-24}\f$ of the result).
inline void small_sincos(double h, double& sn, double& cm1) {
  const double h2 = h * h;
  sn = h + h * h2 *
               (-1.0 / 6 + h2 * (1.0 / 120 + h2 * (-1.0 / 5040 + h2 * (1.0 / 362880 + h2 * (-1.0 / 39916800 +
                h2 * (1.0 / 6227020800 + h2 * (-1.0 / 1307674368000)))))));
  cm1 = h2 * (-0.5 + h2 * (1.0 / 24 + h2 * (-1.0 / 720 + h2 * (1.0 / 40320 + h2 * (-1.0 / 3628800 +
              h2 * (1.0 / 479001600 + h2 * (-1.0 / 87178291200 + h2 * (1.0 / 20922789888000))))))));
}

/// The harmonic part \f$H = A\sin\varphi + B\cos\varphi\f$ and its derivative
/// \f$D = A\cos\varphi - B\sin\varphi\f$ at the piece time u.
struct HarmonicAt {
  double u = 0;
  double H = 0;
  double D = 0;
};

/// f on one piece, as a function of the time u elapsed since the piece's start (phase phi0): the
/// polynomial part \f$(\alpha s + c_1) s + c_0\f$, \f$s = \mathrm{base} + u\f$ (Recentring::coefficients),
/// plus the harmonic part.
///
/// **The harmonic part without a sincos call per evaluation.** It is computed exactly at a few
/// anchors: the piece's end, its start (or, when the scan goes on from the previous piece, that
/// piece's end), and the points where an evaluation is more than kRotate from every anchor; on a
/// piece shorter than kRotate, an end that is not known is rotated from the other. An anchor at
/// a break (an inflection phase, PieceBreaks) or at the origin takes the sine and cosine known
/// there; any other costs one sincos call. Elsewhere, at \f$u = u_a + h\f$ with \f$|h| \le\f$ kRotate, it follows
/// from the anchor's \f$(H, D)\f$ by the addition theorem,
/// \f$H(u) = H + (H(\cos h - 1) + D\sin h)\f$, \f$D(u) = D + (D(\cos h - 1) - H\sin h)\f$, with the
/// series of small_sincos(): a few multiplications instead of a sincos call, with an error of
/// about one ulp of \f$R = \sqrt{A^2+B^2}\f$, as that of the direct evaluation. (The Newton steps of
/// a root search are small: most of its evaluations rotate.)
class PieceFunction {
 public:
  PieceFunction(const QuadraticPlusHarmonic& f, double phi0) : f_(f), phi0_(phi0) {}

  const QuadraticPlusHarmonic& f_;
  double phi0_;           ///< phase of the piece's start
  long double base = 0;   ///< s at the piece's start, or 0 when re-centred
  long double c1 = 0;     ///< linear coefficient (beta, or P1)
  long double c0 = 0;     ///< constant (gamma, or P0)

  long double poly(double u) const {
    const long double s = base + u;
    return (f_.alpha * s + c1) * s + c0;
  }
  long double dpoly(double u) const { return 2 * f_.alpha * (base + u) + c1; }
  /// The harmonic part and its derivative at u (exact at an anchor, else rotated from the nearest).
  HarmonicAt harmonic(double u) {
    const HarmonicAt* best = nullptr;
    double best_d = kRotate;
    for (int i = 0; i < n_anchors_; ++i) {
      const double d = std::fabs(u - anchors_[i].u);
      if (d <= best_d) {
        best_d = d;
        best = &anchors_[i];
      }
    }
    if (best == nullptr) return exact(u);
    if (best->u == u) return *best;
    double sh, cm1;
    small_sincos(u - best->u, sh, cm1);
    return {u, best->H + (best->H * cm1 + best->D * sh), best->D + (best->D * cm1 - best->H * sh)};
  }
  /// \f$f(u)\f$.
  long double value(double u) { return poly(u) + static_cast<long double>(harmonic(u).H); }
  /// \f$f'(u)\f$.
  long double slope(double u) { return dpoly(u) + static_cast<long double>(harmonic(u).D); }
  /// \f$(f, f')\f$.
  std::pair<long double, long double> value_slope(double u) {
    const HarmonicAt h = harmonic(u);
    return {poly(u) + static_cast<long double>(h.H), dpoly(u) + static_cast<long double>(h.D)};
  }
  /// \f$(f, f', f'')\f$.
  std::tuple<long double, long double, long double> value_slope_curvature(double u) {
    const HarmonicAt h = harmonic(u);
    return {poly(u) + static_cast<long double>(h.H), dpoly(u) + static_cast<long double>(h.D), 2 * f_.alpha - static_cast<long double>(h.H)};
  }
  /// \f$(f', f'', f''')\f$.
  std::tuple<long double, long double, long double> slope_curvature_jerk(double u) {
    const HarmonicAt h = harmonic(u);
    return {dpoly(u) + static_cast<long double>(h.D), 2 * f_.alpha - static_cast<long double>(h.H), -static_cast<long double>(h.D)};
  }

  /// Makes a known harmonic part an anchor: the end of the previous piece (at u = 0), or a value
  /// formed from a known sine and cosine (from_trig) at a break end (u = L) or a known start. At
  /// most two are added before the first exact() call, so both ends keep their slots.
  void add_anchor(const HarmonicAt& h) { anchors_[n_anchors_ < 3 ? n_anchors_++ : 2] = h; }
  /// The harmonic part at u from the sine and cosine of its phase.
  HarmonicAt from_trig(double u, double sn, double cs) const { return {u, f_.A * sn + f_.B * cs, f_.A * cs - f_.B * sn}; }

 private:
  /// One sincos call at u; the result becomes an anchor (the first two anchors, the ends, stay; a
  /// third slot is reused).
  HarmonicAt exact(double u) {
    double sn, cs;
    ::sincos(phi0_ + u, &sn, &cs);  // (glibc: one call for both)
    const HarmonicAt h = from_trig(u, sn, cs);
    add_anchor(h);
    return h;
  }
  HarmonicAt anchors_[3];
  int n_anchors_ = 0;
};

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

/// f, f' and the harmonic part at the end of a piece: the start of the next one.
struct PieceEnd {
  bool valid = false;
  long double value = 0;
  long double slope = 0;
  double H = 0;
  double D = 0;
};

/// The first up-crossing of f on one piece [0, L] (f' monotone there), or nothing. `left_value`,
/// when not null, is f at u = 0 as the rest region left it (known better than by a direct
/// evaluation, or -1 for "negative"); else f(0) is evaluated. `pieces` is the work count to report
/// with a crossing.
std::optional<UpCrossing> search_piece(const QuadraticPlusHarmonic& f, PieceFunction& pf, const Instant& cursor, long double s0,
                                       double L, const long double* left_value, long double R, long pieces,
                                       const PieceEnd& start, PieceEnd& end) {
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
    const double guess =
        after_rest ? std::numeric_limits<double>::quiet_NaN()
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

}  // namespace

std::optional<UpCrossing> first_upcrossing(const QuadraticPlusHarmonic& f, const SearchLimits& limits) {
  if (f.alpha < 0) throw std::logic_error("first_upcrossing: alpha must be >= 0");
  const long double R = amplitude(f.A, f.B);
  const SearchBounds bounds = search_bounds(f, R, limits.horizon);
  if (bounds.no_root) return std::nullopt;
  if (!std::isfinite(static_cast<double>(bounds.limit)))
    throw GaveUp("first_upcrossing: no horizon and no root bound; the search would not end");
  const long double limit = bounds.limit;
  const PieceBreaks breaks = piece_breaks(f);

  Instant cursor = f.origin;
  long double s_cursor = 0;
  // f at the cursor when it is known better than a direct evaluation there would give it (after
  // the rest region below); -1 stands for "known negative, value not needed" (Case A).
  bool has_left_value = false;
  long double left_value = 0;
  long pieces = 0;
  Recentring recentring;
  PieceEnd carried;  // f at the cursor from the end of the previous piece, when the scan goes on from there
  bool falling_first_piece = false;  // the first piece falls (RestStart::falling): skipped unevaluated
  // Sine and cosine of the cursor's phase, when known: at the origin (origin_trig), at a break.
  bool cursor_trig = f.origin_trig;
  double cursor_sn = f.origin_sin, cursor_cs = f.origin_cos;
  if (f.starts_at_rest) {
    const RestStart rs = rest_start(f, R, limit);
    if (rs.kind == RestStart::Root) return rs.root;
    if (rs.kind == RestStart::NoRoot) return std::nullopt;
    cursor = advance(f.origin, kRestOffset);
    s_cursor = elapsed(f.origin, cursor);
    left_value = rs.left_value;
    has_left_value = true;
    falling_first_piece = rs.falling;
    cursor_trig = false;
  }
  while (true) {
    if (bounds.in_window(s_cursor)) {
      cursor = advance(f.origin, std::min(bounds.we, limit));  // (a window may reach far beyond a horizon)
      s_cursor = elapsed(f.origin, cursor);
      has_left_value = false;
      carried = PieceEnd{};
      falling_first_piece = false;  // (the piece after the window is not the one next to the origin)
      cursor_trig = false;
    }
    if (s_cursor >= limit) break;
    if (++pieces > limits.max_pieces)
      throw GaveUp("first_upcrossing: gave up after " + std::to_string(limits.max_pieces) + " monotone pieces");

    // The piece [cursor, end]: up to the next break (inflection), the limit, or the window.
    int end_break = 0;
    Instant end = breaks.next_after(cursor, end_break);
    long double s_end = elapsed(f.origin, end);
    long double cut = limit;
    if (bounds.we > 0 && bounds.ws > s_cursor) cut = std::min(cut, bounds.ws);
    bool end_trig = breaks.br[end_break].trig;
    if (s_end > cut) {
      end = advance(f.origin, cut);
      s_end = cut;
      end_trig = false;
    }
    const double L = static_cast<double>(elapsed(cursor, end));
    PieceFunction pf(f, cursor.phase);
    // The harmonic part at a break end, and at an uncarried start whose phase has a known sine and
    // cosine, without a sincos call (at the end from the break's own phase, where cursor.phase + L
    // would carry the rounding of L).
    // (At most these two anchors come before search_piece's: the carried start is added there
    // only when no trig start was added here.)
    if (end_trig) pf.add_anchor(pf.from_trig(L, breaks.br[end_break].sn, breaks.br[end_break].cs));
    if (cursor_trig && !carried.valid) pf.add_anchor(pf.from_trig(0, cursor_sn, cursor_cs));
    recentring.coefficients(f, cursor, s_cursor, pf.base, pf.c1, pf.c0);
    PieceEnd piece_end;
    if (falling_first_piece) falling_first_piece = false;
    else if (L > 0)
      if (auto root = search_piece(f, pf, cursor, s_cursor, L, has_left_value ? &left_value : nullptr, R, pieces, carried, piece_end)) return root;
    carried = piece_end;
    if (pf.base == 0) recentring.carry(f, cursor, end, pf.c0, pf.c1);  // re-centred: carry P0, P1 over
    cursor = end;
    s_cursor = s_end;
    has_left_value = false;
    cursor_trig = end_trig;
    if (end_trig) {
      cursor_sn = breaks.br[end_break].sn;
      cursor_cs = breaks.br[end_break].cs;
    }
  }
  if (bounds.limit_is_bound && limit < limits.horizon)
    throw std::logic_error("first_upcrossing: no root found before the guaranteed bound (a bug)");
  return std::nullopt;
}

}  // namespace dfchaos
