// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/lemma4_uniform.hpp"

#include <algorithm>
#include <string>

#include "dfchaos/certified/next_hit.hpp"

namespace dfchaos::certified {

Lemma4UniformProof prove_lemma4_uniform(double kappa_lo, double kappa_hi, int pieces) {
  Lemma4UniformProof r;
  r.kappa_lo = kappa_lo;
  r.kappa_hi = kappa_hi;
  r.w_pieces = r.u_pieces = pieces;
  const auto fail = [&r](const std::string& step, const std::string& detail) {
    r.verdict = Outcome::fail("Lemma 4 for small b/a: " + step, detail);
    return r;
  };
  if (!(kappa_lo > 0 && kappa_lo <= kappa_hi && kappa_hi <= 1)) return fail("parameters", "needs 0 < q/a lo <= hi <= 1");
  if (pieces < 1 || pieces > 4096) return fail("parameters", "pieces in 1..4096");
  const Ball pi = Ball::pi(), w1 = pi / 100.0, w2 = pi / 50.0;
  // (I5) fixes the bound: h(101pi/100) - h(51pi/50) = (cos(pi/100) - cos(pi/50))/eps - pi/50 >= 6 pi.
  const Ball dcos = cos(w1) - cos(w2);
  r.eps_star = (dcos / (6.0 * pi + w2)).lower();
  const Ball E(r.eps_star), eps = Ball::interval(0, r.eps_star);
  r.count_length = dcos / E - w2;
  if (!le(6.0 * pi, r.count_length)) return fail("(I5) count", "h(101pi/100) - h(51pi/50) = " + r.count_length.str(6));
  // (I1)
  if (!lt(2.0 * E, sin(w1))) return fail("(I1) L2 inside (t2, t3)", "2 eps* >= sin(pi/100)");
  // (I2), (I3), (I4) on pieces of w.
  const double wa = w1.lower(), wb = w2.upper();
  bool first = true;
  for (int i = 0; i < pieces; ++i) {
    const double a = wa + (wb - wa) * i / pieces, b = i + 1 == pieces ? wb : wa + (wb - wa) * (i + 1) / pieces;
    Ball sw, cw;
    sin_cos(Ball::interval(a, b), sw, cw);
    if (!(eps - sw / 2.0).is_negative())
      return fail("(I2) departure", "eps - sin(w)/2 not < 0 for w in [" + std::to_string(a) + ", " + std::to_string(b) + "]");
    const Ball mid = eps + 1.0 - cw - sw;
    r.middle_max = first ? mid.upper() : std::max(r.middle_max, mid.upper());
    if (!mid.is_negative()) return fail("(I3) middle of the flight", "eps + 1 - cos w - sin w = " + mid.str(6));
    if (!le(Ball(2.0) * E, cw)) return fail("(I3) middle of the flight", "s0 = cos(w)/eps < 2");
    for (int j = 0; j < pieces; ++j) {
      const double s1 = static_cast<double>(j) / pieces, s2 = j + 1 == pieces ? 1.0 : static_cast<double>(j + 1) / pieces;
      const Ball s = Ball::interval(s1, s2), sh(s2);
      // (I2): g(theta, s) with sin(theta) = -sin w, cos(theta) = -cos w.
      const Ball g = sw * s * departure_E(sh) + cw * departure_K(sh);
      r.departure_g_max = first ? g.upper() : std::max(r.departure_g_max, g.upper());
      if (!g.is_negative()) return fail("(I2) departure", "g = " + g.str(6));
      // (I4): u = -s in [-1, 0]; E and K are even, so their bounds at |u| <= s2 hold.
      const Ball u = -s;
      const Ball bracket = eps - sw * (Ball(0.5) - sqr(u) * departure_E(sh)) - cw * u * departure_K(sh);
      r.end_bracket_max = first ? bracket.upper() : std::max(r.end_bracket_max, bracket.upper());
      if (!bracket.is_negative()) return fail("(I4) end window", "bracket = " + bracket.str(6));
      first = false;
    }
  }
  // (I6), (I7)
  r.s_min = cos(w2) / E - 1.0;
  if (!lt(2.0 * cot(pi / 200.0), r.s_min)) return fail("(I6) no other tangency", "s0 - 1 = " + r.s_min.str(6) + " <= 2 cot(pi/200)");
  if (!lt(Ball(2.0), (Ball(kappa_lo) - 2.0 * E) * r.s_min)) return fail("(I7) theta2 decreases", "(q/a - 2 eps)(s0 - 1) <= 2");
  // (I8)
  r.arc_l1 = prove_arc_l1(kappa_lo, kappa_hi);
  if (!r.arc_l1.verdict.proved) return fail("(I8) arc L1", r.arc_l1.verdict.describe());
  if (!(r.eps_star <= r.arc_l1.eps_max)) return fail("(I8) arc L1", "its bound is below eps*");
  r.verdict = Outcome::ok();
  return r;
}

}  // namespace dfchaos::certified
