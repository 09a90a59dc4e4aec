// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/lemma4_uniform.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/next_hit.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

Lemma4UniformProof prove_lemma4_uniform(double kappa_lo, double kappa_hi, const Lemma4UniformOptions& opt) {
  Lemma4UniformProof r;
  r.kappa_lo = kappa_lo;
  r.kappa_hi = kappa_hi;
  const int pieces = opt.pieces;
  r.w_pieces = r.u_pieces = pieces;
  const auto fail = [&r](const std::string& step, const std::string& detail) {
    r.verdict = Outcome::fail("Lemma 4 for small b/a: " + step, detail);
    return r;
  };
  if (!(kappa_lo > 0 && kappa_lo <= kappa_hi && kappa_hi <= 1)) return fail("parameters", "needs 0 < q/a lo <= hi <= 1");
  if (pieces < 1 || pieces > 4096) return fail("parameters", "pieces in 1..4096");
  const bool paper_L2 = std::isnan(opt.w_a) && std::isnan(opt.w_b);
  if (!paper_L2 && !(opt.w_a > 0 && opt.w_a < opt.w_b && opt.w_b <= 0.5)) return fail("parameters", "0 < w_a < w_b <= 0.5");
  const Ball pi = Ball::pi(), w1 = paper_L2 ? pi / 100.0 : Ball(opt.w_a), w2 = paper_L2 ? pi / 50.0 : Ball(opt.w_b);
  r.w_a = w1.lower();
  r.w_b = w2.upper();
  r.paper_L2 = paper_L2;
  // (I5) fixes the default bound: h(pi + w_a) - h(pi + w_b) = (cos w_a - cos w_b)/eps - 2(w_b - w_a) >= 6 pi.
  const Ball dcos = cos(Ball(r.w_a)) - cos(Ball(r.w_b)), two_width = 2.0 * (Ball(r.w_b) - Ball(r.w_a));
  r.eps_star = std::isnan(opt.eps_max) ? (dcos / (6.0 * pi + two_width)).lower() : opt.eps_max;
  if (!(r.eps_star > 0 && r.eps_star < 0.25)) return fail("parameters", "0 < b/a max < 1/4");
  const Ball E(r.eps_star), eps = Ball::interval(0, r.eps_star);
  r.count_length = dcos / E - two_width;
  if (!le(6.0 * pi, r.count_length)) return fail("(I5) count", "h(pi + w_a) - h(pi + w_b) = " + r.count_length.str(6));
  // (I1)
  if (!lt(2.0 * E, sin(Ball(r.w_a)))) return fail("(I1) the segment inside (t2, t3)", "2 eps* >= sin(w_a)");
  // (I2), (I3), (I4) on pieces of w.
  const double wa = r.w_a, wb = r.w_b;
  bool first = true;
  for (int i = 0; i < pieces; ++i) {
    poll_stop();  // stop.hpp: a caller may end the proof here
    const double a = wa + (wb - wa) * i / pieces, b = i + 1 == pieces ? wb : wa + (wb - wa) * (i + 1) / pieces;
    Ball sw, cw;
    sin_cos(Ball::interval(a, b), sw, cw);
    if (!(eps - sw / 2.0).is_negative())
      return fail("(I2) departure", "eps - sin(w)/2 not < 0 for w in [" + std::to_string(a) + ", " + std::to_string(b) + "]");
    // 1 - cos w - sin w decreases on [0, pi/4] (its derivative is sin w - cos w < 0): largest at w = a.
    Ball sa, ca;
    sin_cos(Ball(a), sa, ca);
    const Ball mid = eps + 1.0 - ca - sa;
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
  r.s_min = cos(Ball(r.w_b)) / E - 1.0;
  if (!lt(2.0 * cot(Ball(r.w_a) / 2.0), r.s_min)) return fail("(I6) no other tangency", "s0 - 1 = " + r.s_min.str(6) + " <= 2 cot(w_a/2)");
  if (!lt(Ball(2.0), (Ball(kappa_lo) - 2.0 * E) * r.s_min)) return fail("(I7) theta2 decreases", "(q/a - 2 eps)(s0 - 1) <= 2");
  // (I9): Lemma 1 over [0, eps*] x [kappa_lo, kappa_hi], cells bisected (q and b alternately) until
  // u(t2) < 0 is proved on each; at most 4096 cells.
  {
    auto check = [&](const Lemma1SubBox& c, int) {
      const Ball u = lemma1_velocity_at_t2(Ball(1.0), Ball::interval(c.b_lo, c.b_hi), Ball::interval(c.q_lo, c.q_hi));
      if (u.is_negative()) {
        r.lemma1_cells.push_back(c);
        if (r.lemma1_cells.size() > 4096) return CellVerdict::stop(Outcome::fail("(I9) Lemma 1", "more than 4096 cells"));
        return CellVerdict::proved();
      }
      if (u.is_positive() && c.b_lo == c.b_hi && c.q_lo == c.q_hi)
        return CellVerdict::stop(Outcome::fail("(I9) Lemma 1", "u(t2) > 0 at b/a = " + std::to_string(c.b_lo) + ", q/a = " + std::to_string(c.q_lo)));
      return CellVerdict::split(Outcome::fail(
          "(I9) Lemma 1", "u(t2) < 0 not proved near b/a = " + std::to_string(c.b_hi) + ", q/a = " + std::to_string(c.q_lo) + " (" + u.str(5) + ")"));
    };
    // q/a halved at even depths, b/a at odd ones.
    auto split = [](const Lemma1SubBox& c, int depth) -> std::optional<std::pair<Lemma1SubBox, Lemma1SubBox>> {
      if (depth % 2 == 0) {
        const double m = 0.5 * (c.q_lo + c.q_hi);
        return std::make_pair(Lemma1SubBox{c.b_lo, c.b_hi, c.q_lo, m}, Lemma1SubBox{c.b_lo, c.b_hi, m, c.q_hi});
      }
      const double m = 0.5 * (c.b_lo + c.b_hi);
      return std::make_pair(Lemma1SubBox{c.b_lo, m, c.q_lo, c.q_hi}, Lemma1SubBox{m, c.b_hi, c.q_lo, c.q_hi});
    };
    if (const Outcome v = cover(Lemma1SubBox{0.0, r.eps_star, kappa_lo, kappa_hi}, check, split, 40); !v) return fail(v.step, v.detail);
  }
  // (I8): the paper's arc L1 (3pi/100 >= pi/50) for L2, else the stop-arc form on [2pi - w_b, t3).
  ArcL1Options arc;
  if (!paper_L2) {
    arc.delta_max = r.w_b;
    arc.eps_max = r.eps_star;
    arc.S = 1.0;
    arc.stop_arc = true;
    arc.delta_pieces = 64;
  }
  r.arc_l1 = prove_arc_l1(kappa_lo, kappa_hi, arc);
  if (!r.arc_l1.verdict.proved) return fail("(I8) arc L1", r.arc_l1.verdict.describe());
  if (!(r.eps_star <= r.arc_l1.eps_max && r.w_b <= r.arc_l1.delta_max)) return fail("(I8) arc L1", "its arc or its bound is below the segment's");
  r.verdict = Outcome::ok();
  return r;
}

Lemma4UniformProof best_lemma4_uniform(double kappa_lo, double kappa_hi) {
  Lemma4UniformProof best = prove_lemma4_uniform(kappa_lo, kappa_hi);  // the paper's L2
  for (int j = 0; j <= 14; ++j) {
    const double w_b = 0.05 + 0.02 * j;
    const auto attempt = [&](double eps) {
      Lemma4UniformOptions o;
      o.w_b = w_b;
      o.eps_max = eps;
      // (I6) needs 2 cot(w_a/2) < cos(w_b)/eps - 1, (I1) sin(w_a) > 2 eps: 5% above both.
      o.w_a = 1.05 * std::max(2 * std::atan(2 / (std::cos(w_b) / eps - 1)), std::asin(2 * eps));
      if (!(o.w_a < w_b)) return Lemma4UniformProof{};
      return prove_lemma4_uniform(kappa_lo, kappa_hi, o);
    };
    double lo = std::log(1e-5), hi = std::log(4e-3);
    Lemma4UniformProof found;
    if (Lemma4UniformProof p = attempt(1e-5); p.verdict.proved)
      found = p;
    else
      continue;
    for (int it = 0; it < 12; ++it) {
      const double mid = 0.5 * (lo + hi);
      Lemma4UniformProof p = attempt(std::exp(mid));
      if (p.verdict.proved) {
        lo = mid;
        found = std::move(p);
      } else {
        hi = mid;
      }
    }
    if (!best.verdict.proved || found.eps_star > best.eps_star) best = std::move(found);
  }
  return best;
}

}  // namespace dfchaos::certified
