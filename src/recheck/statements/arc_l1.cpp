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

/// With a = 1, theta = 2pi - delta, s = t - theta: G1(theta, theta + s) = s^2 (-A + s g(delta, s)),
/// A = (sin delta - 2b)/2, g = sin(delta) s E(s) - cos(delta) K(s), E = (1/2 - (1 - cos s)/s^2)/s^2,
/// K = (sin s - s)/s^3 (Taylor's formula of sin and cos at theta). For 0 <= s <= 1 the series of E,
/// K and of their derivatives alternate with decreasing terms, so on a cell s in [s1, s2]:
/// E in [1/24 - s2^2/720, 1/24], K in [-1/6, -1/6 + s2^2/120], E' in [-s/360, -s/360 + s2^3/10080],
/// K' in [s/60 - s2^3/1260, s/60]. H = -A + s g has H' = g + s g', g' = sin(delta)(E + s E') - cos(delta) K'.
/// The checker encloses g and H' on every cell of the grid and checks the stated bounds; then the
/// scalar inequalities of the argument (README.md): contact within S and after t3, the progression's
/// deceleration gamma, its stop within W, before t0 + 2pi.
long check_arc_l1(const json& c, std::string& what) {
  Steps st;
  const double a = require_amplitude(c);
  const json& p = field(c, "parameters", "");
  const json& k = field(p, "q_over_a", "parameters.");
  const double k_lo = parameter(k, "lo", "parameters.q_over_a."), k_hi = parameter(k, "hi", "parameters.q_over_a.");
  const double eps_max = parameter(p, "b_over_a_max", "parameters."), delta_max = parameter(p, "delta_max", "parameters.");
  const json& w = field(c, "witnesses", "");
  const json& concl = field(w, "conclusion", "witnesses.");
  if (!concl.is_string() || (concl.get<std::string>() != "stop_arc" && concl.get<std::string>() != "before_t0"))
    throw Malformed("'witnesses.conclusion' is neither \"stop_arc\" nor \"before_t0\"");
  const bool stop_arc = concl.get<std::string>() == "stop_arc";
  const double S = parameter(w, "S", "witnesses."), W = parameter(w, "W", "witnesses.");
  const double g_lo = parameter(w, "g_lo", "witnesses."), g_hi = parameter(w, "g_hi", "witnesses.");
  const double h_lo = parameter(w, "dH_lo", "witnesses."), h_hi = parameter(w, "dH_hi", "witnesses.");
  const std::vector<double> dc = cuts(field(w, "delta_cuts", "witnesses."), "witnesses.delta_cuts");
  const std::vector<double> sc = cuts(field(w, "s_cuts", "witnesses."), "witnesses.s_cuts");
  const Iv Delta(delta_max), sinD = sin(Delta), cosD = cos(Delta);
  st.require(0 < k_lo && k_lo <= k_hi && k_hi <= 1, "0 < q/a lo <= q/a hi <= 1");
  st.require(eps_max > 0 && eps_max < 0.25 && delta_max > 0 && delta_max <= 0.5, "0 < b_over_a_max < 1/4 and 0 < delta_max <= 1/2");
  st.require(S > 0 && S <= 1 && (stop_arc || W > 0), "0 < S <= 1, W > 0");
  bool grid = dc.front() == 0 && sc.front() == 0 && sc.back() == S && dc.back() == delta_max;
  for (std::size_t i = 1; i < dc.size(); ++i) grid = grid && dc[i] > dc[i - 1];
  for (std::size_t i = 1; i < sc.size(); ++i) grid = grid && sc[i] > sc[i - 1];
  st.require(grid, "the grid covers [0, delta_max] x [0, S] (cuts increasing from 0)");
  for (std::size_t i = 0; i + 1 < dc.size(); ++i) {
    const Iv d(dc[i], dc[i + 1]), sd = sin(d), cd = cos(d);
    for (std::size_t j = 0; j + 1 < sc.size(); ++j) {
      const Iv s(sc[j], sc[j + 1]), s2(sc[j + 1]), s2sq = sqr(s2), s2cu = s2sq * s2;
      const Iv E = hull(Iv(1.0) / Iv(24.0) - s2sq / Iv(720.0), Iv(1.0) / Iv(24.0));
      const Iv K = hull(Iv(-1.0) / Iv(6.0), Iv(-1.0) / Iv(6.0) + s2sq / Iv(120.0));
      const Iv dE = hull(-(s / Iv(360.0)), -(s / Iv(360.0)) + s2cu / Iv(10080.0));
      const Iv dK = hull(s / Iv(60.0) - s2cu / Iv(1260.0), s / Iv(60.0));
      const Iv g = sd * s * E - cd * K;
      const Iv dH = g + s * (sd * (E + s * dE) - cd * dK);
      const std::string cell = "cell delta in [" + std::to_string(dc[i]) + ", " + std::to_string(dc[i + 1]) + "], s in [" + std::to_string(sc[j]) +
                               ", " + std::to_string(sc[j + 1]) + "]";
      st.require(le(Iv(g_lo), g) && le(g, Iv(g_hi)), "g in [g_lo, g_hi] on " + cell);
      st.require(le(Iv(h_lo), dH) && le(dH, Iv(h_hi)), "H' in [dH_lo, dH_hi] on " + cell);
    }
  }
  st.require(g_lo > 0 && h_lo > 0, "g_lo > 0 and dH_lo > 0 (H increasing: one simple contact)");
  const Iv s_star = sinD / (2.0 * Iv(g_lo));
  st.require(le(s_star, Iv(S)), "the contact lies within S: sin(delta_max) / (2 g_lo) <= S");
  st.require(lt(2.0 * Iv(g_hi), cosD), "the contact is past t3: 2 g_hi < cos(delta_max)");
  const Iv room = Iv(k_lo) - 2.0 * Iv(eps_max);
  const std::string arc_text = "at a = " + exact_text(a) + ", for every b/a <= " + exact_text(eps_max) + " and q/a in " + range_text(k_lo, k_hi) +
                               ", from rest on [2pi - " + dec(delta_max) + ", t3) the first contact is simple and after t3,";
  if (stop_arc) {  // per row: at 2pi + tau, l_hi < tau < pi, u = x1 + (2 b/a - q/a)(tau - l) - cos(tau) + cos(l) < 0, l = theta1 - 2pi
    const std::vector<double> tau = cuts(field(w, "tau", "witnesses."), "witnesses.tau", false);
    st.require(tau.size() + 1 == dc.size(), "one tau per row of the grid");
    for (std::size_t i = 0; i + 1 < dc.size(); ++i) {
      const Iv s_row = sin(Iv(dc[i + 1])) / (2.0 * Iv(g_lo));
      // s* >= A/g_hi, A = (sin(delta) - 2 b/a)/2 >= max(0, (sin(d1) - 2 b_over_a_max)/2)
      Iv a_min = 0.5 * (sin(Iv(dc[i])) - 2.0 * Iv(eps_max));
      if (!a_min.positive()) a_min = Iv(0.0);
      const Iv l = hull(a_min / Iv(g_hi) - Iv(dc[i + 1]), s_row - Iv(dc[i]));
      const Iv T(tau[i]);
      const Iv u = sqr(s_row) * Iv(h_hi) - room * (T - l) - cos(T) + cos(l);
      const std::string row = "the row delta in [" + std::to_string(dc[i]) + ", " + std::to_string(dc[i + 1]) + "]";
      st.require(lt(l, T) && lt(T, pi()), "the landing precedes 2pi + tau < 3pi on " + row);
      st.require(u.negative(), "the progression stops before 2pi + tau (u < 0) on " + row);
    }
    what = arc_text + " and the progression stops in (t3, 2pi + tau), tau < pi per row of the grid: inside the stop arc";
    return st.n;
  }
  const Iv x1 = sqr(s_star) * Iv(h_hi), SW = Iv(S) + Iv(W), gamma = room - sin(SW);
  st.require(lt(SW, 0.5 * pi()), "S + W < pi/2");
  st.require(gamma.positive() && lt(x1, gamma * Iv(W)), "the progression stops within W: gamma W > x1_max, gamma > 0");
  st.require(room.positive() && lt(room, Iv(1.0)) && lt(SW, asin(room)), "the stop precedes t0 + 2pi: S + W < asin(q/a lo - 2 b_over_a_max)");
  what = arc_text + " and the progression stops in (t3, t0 + 2pi)";
  return st.n;
}

}  // namespace recheck
