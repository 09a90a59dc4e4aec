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

/// Lemma 2 at (a, b) on L = L0 or L2 (docs/certificates.md): the k listed are exactly those with
/// (2k+1) pi in h(L), k >= 2; each z_k is bracketed, its tangency t* = (2k+1) pi - z_k lies in a
/// window W where F < 0; left of z_k a T1 ball whose no-contact proof skips W, right of z_k no
/// contact up to W (then the concavity of G1 on W); T1 balls cover the rest of [lo, hi], which
/// contains L. So T1 is discontinuous exactly at the z_k on L.
long check_discontinuities(const json& c, std::string& what) {
  Steps st;
  const json& p = field(c, "parameters", "");
  const double a = parameter(p, "a", "parameters."), b = parameter(p, "b", "parameters.");
  const json& segment = field(p, "segment", "parameters.");
  if (segment != "L0" && segment != "L2") throw Malformed("'parameters.segment' is not \"L0\" or \"L2\"");
  const json& w = field(c, "witnesses", "");
  const double lo = exact_double(field(w, "lo", "witnesses."), "witnesses.lo"), hi = exact_double(field(w, "hi", "witnesses."), "witnesses.hi");
  struct Tangency {
    long long k;
    Num zl, zh, wl, wh;
    BallWitness left, right;
  };
  std::vector<Tangency> ts;
  std::vector<BallWitness> cover;
  const json &jt = field(w, "tangencies", "witnesses."), &jc = field(w, "cover", "witnesses.");
  if (!jt.is_array() || !jc.is_array()) throw Malformed("'witnesses.tangencies' or 'witnesses.cover' is not an array");
  for (std::size_t i = 0; i < jt.size(); ++i) {
    const std::string wi = "witnesses.tangencies[" + std::to_string(i) + "].";
    Tangency t;
    t.k = turn(field(jt[i], "k", wi), wi + "k");
    std::tie(t.zl, t.zh) = exact_pair(field(jt[i], "z", wi), wi + "z");
    std::tie(t.wl, t.wh) = exact_pair(field(jt[i], "window", wi), wi + "window");
    t.left = read_t1_ball(field(jt[i], "left", wi), wi + "left.", b);
    t.right = read_t1_ball(field(jt[i], "right", wi), wi + "right.", b, true);
    ts.push_back(std::move(t));
  }
  for (std::size_t i = 0; i < jc.size(); ++i) cover.push_back(read_t1_ball(jc[i], "witnesses.cover[" + std::to_string(i) + "].", b));
  // Everything is read: the checks. L and h' = 2 + (a/b) sin z < 0 on (t2, t3) (sin z < -2b/a there).
  const Iv A(a), B(b);
  st.require(A.positive() && B.positive() && lt(2.0 * B, A), "a > 0 and 0 < 2b < a");
  const Iv Llo = Iv(101.0) * pi() / Iv(100.0), Lhi = segment == "L0" ? 1.5 * pi() : Iv(51.0) * pi() / Iv(50.0);
  st.require(le(Iv(lo), Llo) && le(Lhi, Iv(hi)), "[lo, hi] contains L = " + segment.get<std::string>());
  st.require(lt(t2(A, B), Iv(lo)) && lt(Iv(hi), t3(A, B)), "t2 < lo and hi < t3 (h decreases on [lo, hi])");
  // (i) The count: the k listed are consecutive, descending as z ascends, and exactly those k >= 2
  // with h(L.hi) < (2k+1) pi < h(L.lo).
  const Iv Hlo = h_tangency(A, B, Lhi), Hhi = h_tangency(A, B, Llo);
  for (std::size_t i = 0; i < ts.size(); ++i)
    st.require(ts[i].k == ts[0].k - static_cast<long long>(i), "tangency " + std::to_string(i) + ": k = k_0 - " + std::to_string(i));
  if (ts.empty()) {  // h(L) lies between (2K-1) pi (or K = 2) and (2K+1) pi
    const long long K = turn(field(w, "k_above", "witnesses."), "witnesses.k_above");
    st.require(K >= 2 && lt(Hhi, odd_pi(K)) && (K == 2 || lt(odd_pi(K - 1), Hlo)),
               "count: none listed, and (2K-1) pi < h(L.hi) (or K = 2), h(L.lo) < (2K+1) pi for K = k_above");
  } else {
    const long long kmax = ts.front().k, kmin = ts.back().k;
    st.require(kmin >= 2 && lt(Hlo, odd_pi(kmin)) && (kmin == 2 || lt(odd_pi(kmin - 1), Hlo)),
               "count: the least k listed is the least k >= 2 with (2k+1) pi > h(L.hi)");
    st.require(lt(odd_pi(kmax), Hhi) && lt(Hhi, odd_pi(kmax + 1)), "count: the greatest k listed is the greatest with (2k+1) pi < h(L.lo)");
  }
  std::vector<std::pair<Num, Num>> pieces_of_L;  // the closed sets on which T1 is continuous (one-sided at z_k)
  Num reach;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Tangency& t = ts[i];
    const std::string who = "tangency " + std::to_string(i) + " (k = " + std::to_string(t.k) + ")";
    // (ii) z_k in (z_lo, z_hi) inside L; t* = z + s = (2k+1) pi - z with the flight s = -(a/b) cos z > 0
    // is a double root of G1(z_k, .) (analytic); F < 0 on W makes G1(z_k, .) <= 0 on W.
    const Iv Zl(t.zl), Zh(t.zh), Z(t.zl, t.zh), Wl(t.wl), Wh(t.wh), Tstar = odd_pi(t.k) - Z;
    st.require(lt(Llo, Zl) && lt(Zl, Zh) && lt(Zh, Lhi), who + ": L.lo < z_lo < z_hi < L.hi");
    st.require((h_tangency(A, B, Zl) - odd_pi(t.k)).positive() && (h_tangency(A, B, Zh) - odd_pi(t.k)).negative(),
               who + ": z bracket: h(z_lo) > (2k+1) pi > h(z_hi)");
    st.require(cos(Z).negative(), who + ": the flight -(a/b) cos z > 0");
    st.require(lt(Wl, Tstar) && lt(Tstar, Wh), who + ": window: wl < t* = (2k+1) pi - z < wh");
    st.require(F(A, B, Iv(t.wl, t.wh)).negative(), who + ": window: F < 0 on W (G1 concave in t there)");
    // (iii) Left: T1 on [theta_lo, z_k) (theta_hi >= z_hi), W skipped: for theta < z_k, G1(theta, .) <
    // G1(z_k, .) <= 0 on W; the bracket after W.
    st.require(mpfr_cmp(t.left.th_lo.x, t.zl.x) <= 0 && mpfr_cmp(t.left.th_hi.x, t.zh.x) >= 0,
               who + ": left ball: theta_lo <= z_lo, theta_hi >= z_hi");
    const Window W{Wl, Wh};
    check_T1(st, A, t.left, who + " left ball", &W);
    st.require(lt(Wh, Iv(t.left.t_lo)), who + ": left ball: wh < t_lo (T1(z_k - 0) > T1(z_k) = t*)");
    // (iv) Right: G1 < 0 on (theta, wl] on [theta_lo, theta_hi], which contains [z_k, z_hi], theta_hi < wl; for
    // theta >= z_k, G1(theta, t*) >= 0 and G1 concave on W: T1 is the one crossing in (wl, t*].
    st.require(mpfr_cmp(t.right.th_lo.x, t.zl.x) <= 0 && mpfr_cmp(t.right.th_hi.x, t.zh.x) >= 0 && lt(Iv(t.right.th_hi), Wl),
               who + ": right piece: theta_lo <= z_lo, z_hi <= theta_hi < wl");
    const Corners cr = corners(A, t.right);
    start_set_step(st, A, t.right, cr, who + " right piece");
    no_contact_steps(st, A, t.right, cr, Wl, "wl", nullptr, who + " right piece");
    st.require(i == 0 || mpfr_cmp(ts[i - 1].zh.x, t.zl.x) < 0, who + ": z ascending");
    pieces_of_L.emplace_back(t.left.th_lo, t.right.th_hi);
  }
  // (v) T1 balls cover the rest: with the tangencies' [left theta_lo, right theta_hi], [lo, hi].
  for (std::size_t i = 0; i < cover.size(); ++i) {
    check_T1(st, A, cover[i], "cover ball " + std::to_string(i));
    pieces_of_L.emplace_back(cover[i].th_lo, cover[i].th_hi);
  }
  std::sort(pieces_of_L.begin(), pieces_of_L.end(), [](const auto& x, const auto& y) { return mpfr_cmp(x.first.x, y.first.x) < 0; });
  mpfr_set_d(reach.x, lo, MPFR_RNDN);
  bool started = false;
  for (const auto& [x, y] : pieces_of_L) {
    if (mpfr_cmp(x.x, reach.x) > 0) break;  // (reach, x) is covered by nothing
    if (mpfr_cmp(y.x, reach.x) >= 0) reach = y, started = true;
  }
  st.require(started && mpfr_cmp_d(reach.x, hi) >= 0, "the tangencies' pieces and the cover balls cover [lo, hi] (no gap)");
  what = "at a = " + dec(a) + ", b = " + dec(b) + ": T1 has exactly " + std::to_string(ts.size()) + " discontinuities on " +
         segment.get<std::string>() + " (inside " + range_text(lo, hi) + ", which the witnesses cover), the tangencies z_k listed (k = " +
         (ts.empty() ? std::string("none")
                     : std::to_string(std::min(ts.front().k, ts.back().k)) + ".." + std::to_string(std::max(ts.front().k, ts.back().k))) +
         ")";
  return st.n;
}

}  // namespace recheck
