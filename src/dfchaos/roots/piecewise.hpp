// SPDX-License-Identifier: GPL-3.0-or-later
/// @file piecewise.hpp
/// @brief Internal to the first-root search (roots.hpp): the function
/// \f$f = \alpha s^2 + \beta s + \gamma + A\sin t + B\cos t\f$ cut into pieces on which \f$f'\f$ is
/// monotone, its exact evaluation on a piece, and its quadratic envelope. Not installed.
///
/// The search (roots.cpp) uses three things from here, in the order of the argument in roots.hpp:
///  - the envelope \f$\alpha s^2 + \beta s + \gamma \pm R\f$ (search_bounds): where f cannot vanish
///    and where its first root must already lie;
///  - the breaks between pieces, the inflections of f (piece_breaks), in closed form;
///  - f on one piece (PieceFunction), with the polynomial part re-centred far from the origin
///    (Recentring) and the harmonic part rotated from exact anchors.
#pragma once

#include <array>
#include <cmath>
#include <tuple>
#include <utility>

#include "dfchaos/phase.hpp"
#include "dfchaos/roots.hpp"

namespace dfchaos::roots_detail {

/// \f$R = \sqrt{A^2 + B^2}\f$: hypot, exact and cheaper when one of the two is 0, as in both event
/// functions of the model.
inline long double amplitude(double A, double B) {
  if (B == 0) return std::fabs(A);
  if (A == 0) return std::fabs(B);
  return std::hypot(A, B);
}

/// Pieces that start this far (in time) from the origin are evaluated re-centred. Below it the direct
/// long-double evaluation loses at most ~2e-19 s a < 4e-15 a (s itself resolved to 2e-15), results
/// stay bit-identical to the direct evaluation, and no per-piece double-double work is spent.
constexpr long double kRecentreFrom = 16384;
/// Re-centred pieces between two exact (double-double) re-centrings.
constexpr int kRecentreEvery = 16;

/// The polynomial part p(s) = alpha s^2 + beta s + gamma and its slope at the instant `at`, with
/// s = elapsed(origin, at) formed exactly as 2 pi * turns + (phase difference) in double-double.
std::pair<long double, long double> recentred(const QuadraticPlusHarmonic& f, const Instant& at);

/// The inflection phases of a coefficient set and \f$\sin, \cos\f$ there (one sincos call each).
struct Inflections {
  int n = 0;                              ///< how many (0 or 2)
  double at[2] = {0, 0};                  ///< the phases, ascending
  double sn[2] = {0, 0}, cs[2] = {0, 0};  ///< sine and cosine at them
};

/// The inflection phases of f and the sine and cosine there, remembered per thread for the last two
/// coefficient sets \f$(A, B, \alpha)\f$: an evaluation of T searches two kinds of function (the
/// gap, the progression velocity), whose coefficients repeat from one search to the next. A pure
/// function of its key, so the results do not depend on what was computed before.
const Inflections& inflections_cached(const QuadraticPlusHarmonic& f);

/// Roots of alpha s^2 + beta s + k = 0 (alpha > 0), ascending; none if the discriminant is negative.
bool quadratic_roots(long double alpha, long double beta, long double k, long double& r1, long double& r2);

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
SearchBounds search_bounds(const QuadraticPlusHarmonic& f, long double R, long double horizon);

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
PieceBreaks piece_breaks(const QuadraticPlusHarmonic& f);

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
  void coefficients(const QuadraticPlusHarmonic& f, const Instant& cursor, long double s0, long double& base, long double& c1, long double& c0) {
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
               (-1.0 / 6 +
                h2 * (1.0 / 120 +
                      h2 * (-1.0 / 5040 + h2 * (1.0 / 362880 + h2 * (-1.0 / 39916800 + h2 * (1.0 / 6227020800 + h2 * (-1.0 / 1307674368000)))))));
  cm1 = h2 *
        (-0.5 +
         h2 * (1.0 / 24 +
               h2 * (-1.0 / 720 +
                     h2 * (1.0 / 40320 + h2 * (-1.0 / 3628800 + h2 * (1.0 / 479001600 + h2 * (-1.0 / 87178291200 + h2 * (1.0 / 20922789888000))))))));
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
  double phi0_;          ///< phase of the piece's start
  long double base = 0;  ///< s at the piece's start, or 0 when re-centred
  long double c1 = 0;    ///< linear coefficient (beta, or P1)
  long double c0 = 0;    ///< constant (gamma, or P0)

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

/// f, f' and the harmonic part at the end of a piece: the start of the next one.
struct PieceEnd {
  bool valid = false;
  long double value = 0;
  long double slope = 0;
  double H = 0;
  double D = 0;
};

/// Where the scan of the pieces stands: the start of the next piece, and what is known of f there
/// besides a direct evaluation.
struct Cursor {
  Instant t;          ///< the instant
  long double s = 0;  ///< elapsed time from the origin
  /// f at the cursor as the rest region left it (RestStart::left_value; -1 for "negative"), known
  /// better than a direct evaluation there would give it.
  bool has_left_value = false;
  long double left_value = 0;        ///< (has_left_value) that value
  PieceEnd carried;                  ///< f there from the end of the previous piece, when the scan goes on from it
  bool falling_first_piece = false;  ///< the piece from here falls (RestStart::falling): skipped unevaluated
  bool trig = false;                 ///< the sine and cosine of the cursor's phase are known:
  double sn = 0, cs = 0;             ///< (trig) they

  /// At the origin, with its sine and cosine when the caller gave them.
  static Cursor at_origin(const QuadraticPlusHarmonic& f) {
    Cursor c;
    c.t = f.origin;
    c.trig = f.origin_trig;
    c.sn = f.origin_sin;
    c.cs = f.origin_cos;
    return c;
  }
  /// At elapsed time `s_at` from the origin, where nothing is known of f.
  static Cursor unknown_at(const QuadraticPlusHarmonic& f, long double s_at) {
    Cursor c;
    c.t = advance(f.origin, s_at);
    c.s = elapsed(f.origin, c.t);
    return c;
  }
};

}  // namespace dfchaos::roots_detail
