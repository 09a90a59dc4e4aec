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

/// Section 7 beyond two symbols: disjoint segments I_1 < ... < I_n of [t2, t3), each covered by balls
/// on which T is continuous, with T at both ends enclosed (case AB above t2); an edge j -> k only where
/// I_k lies strictly between the enclosures at the ends of I_j (so T(I_j) contains I_k); weights v > 0
/// with sum_{j -> k} v_k >= rho v_j for every j. Then rho(A) >= rho (Collatz-Wielandt) and
/// h_top(T) >= ln rho on the compact invariant set of orbits that stay in the union.
long check_entropy(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  const Box box{b, b, q, q};
  const json& w = field(c, "witnesses", "");
  const bool has_lemma1 = w.contains("lemma1");
  const std::vector<Ball> subs = has_lemma1 ? read_sub_boxes(w["lemma1"], "witnesses.lemma1.") : std::vector<Ball>{};
  const json& segs = field(w, "segments", "witnesses.");
  if (!segs.is_array() || segs.empty()) throw Malformed("'witnesses.segments' is not a non-empty array");
  const double rho = exact_double(field(w, "rho_lower", "witnesses."), "witnesses.rho_lower");
  const std::size_t n = segs.size();
  struct Segment {
    double lo, hi, v;
    Num lo_n, hi_n;
    std::vector<std::size_t> succ;
    std::vector<BallWitness> cover;
  };
  std::vector<Segment> I(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::string ws = "witnesses.segments[" + std::to_string(j) + "].";
    const json& ji = field(segs[j], "I", ws);
    if (!ji.is_array() || ji.size() != 2) throw Malformed("'" + ws + "I' is not [lo, hi]");
    I[j].lo = exact_double(ji[0], ws + "I[0]"), I[j].hi = exact_double(ji[1], ws + "I[1]");
    I[j].lo_n = exact(ji[0], ws + "I[0]"), I[j].hi_n = exact(ji[1], ws + "I[1]");
    I[j].v = exact_double(field(segs[j], "weight", ws), ws + "weight");
    const json& js = field(segs[j], "successors", ws);
    if (!js.is_array()) throw Malformed("'" + ws + "successors' is not an array");
    for (const json& k : js) {
      if (!k.is_number_integer() || k.get<long long>() < 0 || k.get<long long>() >= static_cast<long long>(n))
        throw Malformed("'" + ws + "successors' holds something other than a segment index");
      I[j].succ.push_back(k.get<std::size_t>());
    }
    const json& jc = field(segs[j], "cover", ws);
    if (!jc.is_array() || jc.empty()) throw Malformed("'" + ws + "cover' is not a non-empty array");
    for (std::size_t i = 0; i < jc.size(); ++i) I[j].cover.push_back(read_ball(jc[i], ws + "cover[" + std::to_string(i) + "]."));
  }
  const Iv A = standing_box(st, a, box);
  if (has_lemma1) lemma1(st, A, box, subs);
  std::string needs_lemma1;
  std::vector<Iv> T_lo(n), T_hi(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::string name = "I" + std::to_string(j);
    const Segment& g = I[j];
    st.require(g.lo < g.hi && (j == 0 || I[j - 1].hi < g.lo), name + ": lo < hi, right of the previous segment (disjoint)");
    st.require(le(t2(A, Iv(b)), Iv(g.lo)) && lt(Iv(g.hi), t3(A, Iv(b))), name + ": inside [t2, t3)");
    st.require(g.v > 0, name + ": weight > 0");
    std::vector<Ball> balls;
    for (std::size_t i = 0; i < g.cover.size(); ++i) {
      const BallWitness& bw = g.cover[i];
      const std::string who = name + " cover ball " + std::to_string(i);
      st.require(bw.ball.start == Start::Interval && bw.ball.box.b_lo == b && bw.ball.box.b_hi == b && bw.ball.box.q_lo == q &&
                     bw.ball.box.q_hi == q && g.lo <= bw.ball.th_lo && bw.ball.th_lo <= bw.ball.th_hi && bw.ball.th_hi <= g.hi,
                 who + ": phases inside the segment, at the parameter point");
      const Outcome o = check_ball(st, A, bw, who);
      if (o.needs_lemma1 && needs_lemma1.empty()) needs_lemma1 = who;
      balls.push_back(bw.ball);
    }
    require_cover(st, balls, g.lo, g.hi, box, name + ": the balls cover the segment (no gap)");
    const std::string ws = "witnesses.segments[" + std::to_string(j) + "]";
    T_lo[j] = T_on(st, A, field(segs[j], "at_lo", ws + "."), b, q, g.lo_n, g.lo_n, ws + ".at_lo");
    T_hi[j] = T_on(st, A, field(segs[j], "at_hi", ws + "."), b, q, g.hi_n, g.hi_n, ws + ".at_hi");
  }
  st.require(needs_lemma1.empty() || has_lemma1, "Lemma 1 is needed (first by " + needs_lemma1 + ") and witnesses.lemma1 is given");
  std::size_t edges_n = 0;
  for (std::size_t j = 0; j < n; ++j) {
    Iv sum(0.0);
    std::vector<bool> seen(n, false);
    for (std::size_t k : I[j].succ) {
      const std::string e = "edge I" + std::to_string(j) + " -> I" + std::to_string(k);
      st.require(!seen[k], e + ": listed once");
      seen[k] = true;
      const Iv L(I[k].lo), H(I[k].hi);
      st.require((lt(T_lo[j], L) && lt(H, T_hi[j])) || (lt(T_hi[j], L) && lt(H, T_lo[j])), e + ": I_k lies strictly between T at the ends of I_j");
      sum = sum + Iv(I[k].v);
      ++edges_n;
    }
    st.require(le(Iv(rho) * Iv(I[j].v), sum), "I" + std::to_string(j) + ": sum of the successors' weights >= rho_lower * weight");
  }
  st.require(rho > 1, "rho_lower > 1");
  char buf[160];
  std::snprintf(buf, sizeof buf, "rho(A) >= %.17g, so h_top >= ln of it, from a covering graph of %zu segments and %zu edges", rho, n, edges_n);
  what = "at " + box_text(a, box) + ": " + buf;
  return st.n;
}

}  // namespace recheck
