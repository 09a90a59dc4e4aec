// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/arc_l1.hpp"

#include <algorithm>
#include <string>

#include "dfchaos/certified/next_hit.hpp"

namespace dfchaos::certified {

namespace {

/// \f$E'(s) = \sum_{k \ge 1} (-1)^k 2k\, s^{2k-1}/(2k+4)!\f$ over \f$s \in [s_1, s_2] \subset [0, 1]\f$:
/// an alternating series with decreasing terms, so \f$E' \in [-s/360, -s/360 + s^3/10080]\f$.
Ball dE(const Ball& s, const Ball& s2) { return -(s / 360.0) + Ball::hull(Ball(0.0), sqr(s2) * s2 / 10080.0); }

/// \f$K'(s) = \sum_{k \ge 2} (-1)^k (2k-2)\, s^{2k-3}/(2k+1)!\f$: \f$K' \in [s/60 - s^3/1260, s/60]\f$.
Ball dK(const Ball& s, const Ball& s2) { return s / 60.0 - Ball::hull(Ball(0.0), sqr(s2) * s2 / 1260.0); }

std::string num(const Ball& x) { return x.str(6); }

}  // namespace

ArcL1Proof prove_arc_l1(double kappa_lo, double kappa_hi, int delta_pieces, int s_pieces) {
  ArcL1Proof r;
  r.kappa_lo = kappa_lo;
  r.kappa_hi = kappa_hi;
  const auto fail = [&r](const std::string& step, const std::string& detail) {
    r.verdict = Outcome::fail("arc L1: " + step, detail);
    return r;
  };
  if (!(kappa_lo > 0 && kappa_lo <= kappa_hi && kappa_hi <= 1)) return fail("parameters", "needs 0 < q/a lo <= hi <= 1");
  if (delta_pieces < 1 || s_pieces < 1 || delta_pieces > 4096 || s_pieces > 4096) return fail("parameters", "pieces in 1..4096");
  const Ball Delta = Ball::pi() * 3.0 / 100.0;
  const Ball sinD = sin(Delta);
  r.eps_max = (sinD / 2.0).lower();  // 2 eps_max <= sin(Delta): t3 >= 197 pi / 100 (L1 not empty)
  const double delta_end = Delta.upper(), S = r.S;

  // g and H' = g + s dg/ds on the pieces of [0, Delta] x [0, S].
  Ball g_all, dH_all;
  bool first = true;
  for (int i = 0; i < delta_pieces; ++i) {
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
  if (!lt(Ball(2.0 * r.g_hi), cos(Delta))) return fail("contact past t3", "2 g_hi = " + num(Ball(2.0 * r.g_hi)) + " vs cos(3 pi/100)");
  // 3. The progression stops within W: gamma W > x1_max, gamma = kappa_lo - sin(Delta) - sin(S + W) > 0.
  r.x1_max = sqr(s_star_max) * Ball(r.h_hi);
  const Ball k_lo(kappa_lo);
  const Ball room = k_lo - sinD;  // kappa - 2 eps >= this
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
  // 4. ... before t0 + 2 pi: S + W <= asin(kappa_lo - sin(Delta)) <= t0.
  if (!lt(room, Ball(1.0))) return fail("t0 exists", "q/a lo - sin(3 pi/100) >= 1");
  r.t0_min = asin(room);
  if (!lt(SW, r.t0_min)) return fail("stop before t0", "S + W = " + num(SW) + ", t0 >= " + num(r.t0_min));
  r.verdict = Outcome::ok();
  return r;
}

}  // namespace dfchaos::certified
