// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "../ball.hpp"
#include "../interval.hpp"
#include "../paper.hpp"
#include "../reading.hpp"
#include "../statements.hpp"
#include "../steps.hpp"

namespace recheck {

/// (I1)-(I7) of docs/certified.md for every eps in [0, eps*] (a = 1, theta = pi + w, w in [pi/100,
/// pi/50], s0 = cos(w)/eps), re-derived here: G1(theta, theta + s) = s^2 [eps - sin(w)/2 + s g],
/// g = sin(w) s E(s) + cos(w) K(s); G1 <= eps - cos w - sin w + 1 on [1, s0 - 1]; at a symmetric
/// tangency z (2z - cos(z)/eps = (2k+1) pi), G1(z, t* + u) = u^2 [eps - sin w (1/2 - u^2 E(u)) -
/// cos(w) u K(u)]; the closed-form count h(101pi/100) - h(51pi/50) >= 6 pi; s0 - 1 > 2 cot(pi/200)
/// (no tangency of the other family can be a first contact); (q/a - 2 eps)(s0 - 1) > 2 (theta2
/// decreases along a branch); and (I8), the arc L1, as the embedded arc-l1 certificate for the same
/// q/a with a bound >= eps*. The argument from these to Lemma 4 is trusted (README.md).
long check_lemma4_uniform(const json& c, std::string& what) {
  Steps st;
  const json& p = field(c, "parameters", "");
  const json& k = field(p, "q_over_a", "parameters.");
  const double k_lo = parameter(k, "lo", "parameters.q_over_a."), k_hi = parameter(k, "hi", "parameters.q_over_a.");
  const double eps_star = parameter(p, "b_over_a_max", "parameters.");
  const json& w = field(c, "witnesses", "");
  const json& np = field(w, "pieces", "witnesses.");
  if (!np.is_number_integer() || np.get<long long>() < 1 || np.get<long long>() > 4096)
    throw Malformed("'witnesses.pieces' is not an integer in 1..4096");
  const int n = static_cast<int>(np.get<long long>());
  const json& arc = field(w, "arc_l1", "witnesses.");
  const double a = require_amplitude(c);
  require_embedded(arc, "arc-l1", "witnesses.arc_l1");
  st.n += embedded("witnesses.arc_l1", [&] {
    std::string ignored;
    return check_arc_l1(arc, ignored);
  });
  const json& ap = field(arc, "parameters", "witnesses.arc_l1.");
  const json& ak = field(ap, "q_over_a", "witnesses.arc_l1.parameters.");
  const double w_lo = parameter(p, "w_lo", "parameters."), w_hi = parameter(p, "w_hi", "parameters.");
  st.require(parameter(ak, "lo", "witnesses.arc_l1.parameters.q_over_a.") <= k_lo &&
                 parameter(ak, "hi", "witnesses.arc_l1.parameters.q_over_a.") >= k_hi &&
                 parameter(ap, "b_over_a_max", "witnesses.arc_l1.parameters.") >= eps_star &&
                 parameter(ap, "delta_max", "witnesses.arc_l1.parameters.") >= w_hi,
             "(I8) the arc [2pi - w_hi, t3) is proved for these q/a and every b/a <= b_over_a_max");
  st.require(0 < k_lo && k_lo <= k_hi && k_hi <= 1 && eps_star > 0, "0 < q/a lo <= q/a hi <= 1, b_over_a_max > 0");
  st.require(0 < w_lo && w_lo < w_hi && w_hi <= 0.5, "0 < w_lo < w_hi <= 1/2: the segment [pi + w_lo, pi + w_hi]");
  const Iv PI = pi(), w1(w_lo), w2(w_hi), E(eps_star), eps(0.0, eps_star);
  st.require(le(6.0 * PI, (cos(w1) - cos(w2)) / E - 2.0 * (w2 - w1)),
             "(I5) h(pi + w_lo) - h(pi + w_hi) >= 6 pi at b_over_a_max (so for every smaller b/a)");
  st.require(lt(2.0 * E, sin(w1)), "(I1) 2 b_over_a_max < sin(w_lo)");
  const double a0 = w_lo, b0 = w_hi;
  for (int i = 0; i < n; ++i) {
    const double a = a0 + (b0 - a0) * i / n, b = i + 1 == n ? b0 : a0 + (b0 - a0) * (i + 1) / n;
    const Iv W(a, b), sw = sin(W), cw = cos(W);
    const std::string cell = "w in [" + std::to_string(a) + ", " + std::to_string(b) + "]";
    st.require((eps - 0.5 * sw).negative(), "(I2) b/a - sin(w)/2 < 0 on " + cell);
    // 1 - cos w - sin w decreases on [0, pi/4] (derivative sin w - cos w < 0): its largest value is at w = a.
    st.require(b <= 0.75 && (eps + Iv(1.0) - cos(Iv(a)) - sin(Iv(a))).negative(), "(I3) b/a + 1 - cos w - sin w < 0 on " + cell);
    st.require(le(2.0 * E, cw), "(I3) s0 = cos(w)/(b/a) >= 2 on " + cell);
    for (int j = 0; j < n; ++j) {
      const double s1 = static_cast<double>(j) / n, s2 = j + 1 == n ? 1.0 : static_cast<double>(j + 1) / n;
      const Iv s(s1, s2), h(s2), h2 = sqr(h);
      const Iv Es = hull(Iv(1.0) / Iv(24.0) - h2 / Iv(720.0), Iv(1.0) / Iv(24.0));
      const Iv Ks = hull(Iv(-1.0) / Iv(6.0), Iv(-1.0) / Iv(6.0) + h2 / Iv(120.0));
      st.require((sw * s * Es + cw * Ks).negative(), "(I2) g < 0 on " + cell + ", s in [" + std::to_string(s1) + ", " + std::to_string(s2) + "]");
      const Iv u = -s;  // E and K are even
      st.require((eps - sw * (Iv(0.5) - sqr(u) * Es) - cw * u * Ks).negative(),
                 "(I4) the end-window bracket < 0 on " + cell + ", u in [" + std::to_string(-s2) + ", " + std::to_string(-s1) + "]");
    }
  }
  const Iv s_min = cos(w2) / E - Iv(1.0);
  st.require(lt(2.0 * cot(0.5 * w1), s_min), "(I6) s0 - 1 > 2 cot(w_lo/2)");
  // (I9) Lemma 1 on [0, b_over_a_max] x [q/a lo, q/a hi]: cells inside, covering, u(t2) < 0 on each; q > 2b.
  st.require(2.0 * eps_star < k_lo, "(I9) q/a > 2 b/a on the box");
  lemma1(st, Iv(1.0), Box{0.0, eps_star, k_lo, k_hi}, read_sub_boxes(field(w, "lemma1", "witnesses."), "witnesses.lemma1."));
  st.require(lt(Iv(2.0), (Iv(k_lo) - 2.0 * E) * s_min), "(I7) (q/a - 2 b/a)(s0 - 1) > 2");
  what = "(I1)-(I9), the inequalities of Lemma 4's argument, at a = " + exact_text(a) + ", for every b/a <= " + exact_text(eps_star) +
         " and q/a in " + range_text(k_lo, k_hi) + " on the segment [pi + " + dec(w_lo) + ", pi + " + dec(w_hi) + "]";
  return st.n;
}

}  // namespace recheck
