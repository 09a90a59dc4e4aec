// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/arc_l1.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dfchaos/certified/next_hit.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

namespace {

/// \f$E'(s) = \sum_{k \ge 1} (-1)^k 2k\, s^{2k-1}/(2k+4)!\f$ over \f$s \in [s_1, s_2] \subset [0, 1]\f$:
/// an alternating series with decreasing terms, so \f$E' \in [-s/360, -s/360 + s^3/10080]\f$.
Ball dE(const Ball& s, const Ball& s2) { return -(s / 360.0) + Ball::hull(Ball(0.0), sqr(s2) * s2 / 10080.0); }

/// \f$K'(s) = \sum_{k \ge 2} (-1)^k (2k-2)\, s^{2k-3}/(2k+1)!\f$: \f$K' \in [s/60 - s^3/1260, s/60]\f$.
Ball dK(const Ball& s, const Ball& s2) { return s / 60.0 - Ball::hull(Ball(0.0), sqr(s2) * s2 / 1260.0); }

std::string num(const Ball& x) { return x.str(6); }

}  // namespace

ArcL1Proof prove_arc_l1(double kappa_lo, double kappa_hi, const ArcL1Options& opt) {
  ArcL1Proof r;
  r.kappa_lo = kappa_lo;
  r.kappa_hi = kappa_hi;
  r.S = opt.S;
  r.stop_arc = opt.stop_arc;
  const auto fail = [&r](const std::string& step, const std::string& detail) {
    r.verdict = Outcome::fail("arc L1: " + step, detail);
    return r;
  };
  const int delta_pieces = opt.delta_pieces, s_pieces = opt.s_pieces;
  if (!(kappa_lo > 0 && kappa_lo <= kappa_hi && kappa_hi <= 1)) return fail("parameters", "needs 0 < q/a lo <= hi <= 1");
  if (delta_pieces < 1 || s_pieces < 1 || delta_pieces > 4096 || s_pieces > 4096) return fail("parameters", "pieces in 1..4096");
  if (!(opt.S > 0 && opt.S <= 1)) return fail("parameters", "0 < S <= 1");
  const bool paper_arc = std::isnan(opt.delta_max);
  if (!paper_arc && !(opt.delta_max > 0 && opt.delta_max <= 0.5)) return fail("parameters", "0 < Delta <= 0.5");
  const Ball Delta = paper_arc ? Ball::pi() * 3.0 / 100.0 : Ball(opt.delta_max);
  const Ball sinD = sin(Delta);
  r.delta_max = paper_arc ? Delta.upper() : opt.delta_max;
  r.paper_arc = paper_arc;
  r.eps_max = std::isnan(opt.eps_max) ? (sinD / 2.0).lower() : opt.eps_max;  // default: 2 eps_max <= sin(Delta)
  if (!(r.eps_max > 0 && r.eps_max < 0.25)) return fail("parameters", "0 < b/a max < 1/4");
  const double delta_end = r.delta_max, S = r.S;

  // g and H' = g + s dg/ds on the pieces of [0, Delta] x [0, S].
  Ball g_all, dH_all;
  bool first = true;
  for (int i = 0; i < delta_pieces; ++i) {
    poll_stop();  // stop.hpp: a caller may end the proof here
    const double d1 = delta_end * i / delta_pieces, d2 = i + 1 == delta_pieces ? delta_end : delta_end * (i + 1) / delta_pieces;
    Ball sd, cd;
    sin_cos(Ball::interval(d1, d2), sd, cd);
    for (int j = 0; j < s_pieces; ++j) {
      const double s1 = S * j / s_pieces, s2 = j + 1 == s_pieces ? S : S * (j + 1) / s_pieces;
      const Ball s = Ball::interval(s1, s2), sh(s2);
      const Ball E = departure_E(sh), K = departure_K(sh);
      const Ball g = sd * s * E - cd * K;
      const Ball dg = sd * (E + s * dE(s, sh)) - cd * dK(s, sh);
      const Ball dH = g + s * dg;
      r.pieces.push_back(ArcL1Piece{d1, d2, s1, s2, g, dH});
      g_all = first ? g : Ball::hull(g_all, g);
      dH_all = first ? dH : Ball::hull(dH_all, dH);
      first = false;
    }
  }
  r.g_lo = g_all.lower();
  r.g_hi = g_all.upper();
  r.h_lo = dH_all.lower();
  r.h_hi = dH_all.upper();
  if (!(r.g_lo > 0)) return fail("g > 0", "g in " + num(g_all));
  if (!(r.h_lo > 0)) return fail("H' > 0", "H' in " + num(dH_all));

  // 1. The first contact lies in s <= A_max / g_lo <= S, inside the pieces.
  const Ball A_max = sinD / 2.0;
  const Ball s_star_max = A_max / Ball(r.g_lo);
  if (!le(s_star_max, Ball(S))) return fail("contact within S", "A_max/g_lo = " + num(s_star_max));
  // 2. The contact is past t3: cos(Delta) > 2 g_hi.
  if (!lt(Ball(2.0 * r.g_hi), cos(Delta))) return fail("contact past t3", "2 g_hi = " + num(Ball(2.0 * r.g_hi)) + " vs cos(Delta)");
  r.x1_max = sqr(s_star_max) * Ball(r.h_hi);  // the impact velocity x1 = s*^2 H'(s*)
  const Ball k_lo(kappa_lo);
  const Ball room = k_lo - 2.0 * Ball(r.eps_max);  // q/a - 2 b/a >= this
  if (opt.stop_arc) {
    // 3'. Per row [d1, d2] of the grid: s* <= sin(d2)/(2 g_lo), the landing l = theta1 - 2pi lies in
    // [A_min/g_hi - d2, s* - d1] and x1 <= s*^2 h_hi. A time 2pi + tau (l < tau < pi) with progression velocity
    // u = x1 + (2 eps - q/a)(tau - l) - cos(tau) + cos(l) < 0 puts the first stop in (theta1, 2pi + tau),
    // inside the stop arc (t3, t2 + 2pi). tau is searched on a grid of (l_hi, pi) (bounded).
    for (int i = 0; i < delta_pieces; ++i) {
      poll_stop();  // stop.hpp: a caller may end the proof here
      const ArcL1Piece& row = r.pieces[static_cast<std::size_t>(i) * static_cast<std::size_t>(s_pieces)];
      const Ball s_row = sin(Ball(row.delta_hi)) / 2.0 / Ball(r.g_lo);
      // s* >= A/g_hi with A = (sin(delta) - 2 b/a)/2 >= (sin(d1) - 2 eps_max)/2 (when positive)
      const Ball a_min = max(Ball(0.0), (sin(Ball(row.delta_lo)) - 2.0 * Ball(r.eps_max)) / 2.0);
      const Ball l = Ball::hull(a_min / Ball(r.g_hi) - Ball(row.delta_hi), s_row - Ball(row.delta_lo));
      const Ball x1 = sqr(s_row) * Ball(r.h_hi);
      const double l_hi = l.upper();
      double tau = 0.0 / 0.0;
      Ball u;
      for (int m = 1; m <= 256 && std::isnan(tau); ++m) {
        const double t = l_hi + (3.1415926 - l_hi) * m / 256;  // 3.1415926 < pi
        u = x1 - room * (Ball(t) - l) - cos(Ball(t)) + cos(l);
        if (u.is_negative()) tau = t;
      }
      if (std::isnan(tau))
        return fail("stop before t2 + 2pi",
                    "no time in (l, pi) with u < 0 on the row delta in [" + std::to_string(row.delta_lo) + ", " + std::to_string(row.delta_hi) + "]");
      r.tau.push_back(tau);
    }
    r.verdict = Outcome::ok();
    return r;
  }
  // 3. The progression stops within W: gamma W > x1_max, gamma = kappa_lo - 2 eps_max - sin(S + W) > 0.
  // W from gamma(W) W = x1_max, by a few fixed-point steps from W = 0 (W grows monotonically; bounded).
  double W = 0;
  for (int it = 0; it < 50; ++it) {
    const Ball g = room - sin(Ball(S) + Ball(W));
    if (!g.is_positive() || !lt(Ball(S) + Ball(W), Ball(1.5))) break;
    const double next = (r.x1_max / g).upper() * 1.001;
    if (next <= W) break;
    W = next;
  }
  r.W = W;
  const Ball SW = Ball(S) + Ball(r.W);
  r.gamma = room - sin(SW);
  if (!lt(SW, Ball::pi() / 2.0) || !r.gamma.is_positive() || !lt(r.x1_max, r.gamma * Ball(r.W)))
    return fail("progression stops within W", "gamma = " + num(r.gamma) + ", W = " + num(Ball(r.W)));
  // 4. ... before t0 + 2 pi: S + W <= asin(kappa_lo - 2 eps_max) <= t0.
  if (!lt(room, Ball(1.0))) return fail("t0 exists", "q/a lo - 2 b/a max >= 1");
  r.t0_min = asin(room);
  if (!lt(SW, r.t0_min)) return fail("stop before t0", "S + W = " + num(SW) + ", t0 >= " + num(r.t0_min));
  r.verdict = Outcome::ok();
  return r;
}

}  // namespace dfchaos::certified
