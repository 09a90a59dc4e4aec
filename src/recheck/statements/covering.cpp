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

/// Lemma 4 (Theorem 1): two disjoint segments J0 < J1 in [t2, 3 pi/2], each covered by balls on
/// which T is continuous, with T(theta_top) >= 3 pi/2 and T(theta_t2) = t2: T(J) contains [t2, 3 pi/2].
long check_covering(const json& c, std::string& what) {
  Steps st;
  const auto [a, box] = read_box(c);
  const json& w = field(c, "witnesses", "");
  const bool has_lemma1 = w.contains("lemma1");
  const std::vector<Ball> subs = has_lemma1 ? read_sub_boxes(w["lemma1"], "witnesses.lemma1.") : std::vector<Ball>{};
  const json& segs = field(w, "segments", "witnesses.");
  if (!segs.is_array() || segs.size() != 2) throw Malformed("'witnesses.segments' is not an array of two segments");
  const char* const lists[3] = {"top", "t2_end", "cover"};
  struct Segment {
    double lo, hi, top, bot;
    std::vector<BallWitness> balls[3];
  } J[2];
  for (std::size_t s = 0; s < 2; ++s) {
    const std::string ws(s == 0 ? "witnesses.segments[0]." : "witnesses.segments[1].");
    J[s].lo = exact_double(field(segs[s], "lo", ws), ws + "lo"), J[s].hi = exact_double(field(segs[s], "hi", ws), ws + "hi");
    J[s].top = exact_double(field(segs[s], "theta_top", ws), ws + "theta_top");
    J[s].bot = exact_double(field(segs[s], "theta_t2", ws), ws + "theta_t2");
    for (std::size_t l = 0; l < 3; ++l) {
      const json& jl = field(segs[s], lists[l], ws);
      if (!jl.is_array()) throw Malformed("'" + ws + lists[l] + "' is not an array");
      for (std::size_t i = 0; i < jl.size(); ++i) J[s].balls[l].push_back(read_ball(jl[i], ws + lists[l] + "[" + std::to_string(i) + "]."));
    }
  }
  // Everything is read: the checks.
  const Iv A = standing_box(st, a, box);
  if (has_lemma1) lemma1(st, A, box, subs);
  std::string needs_lemma1;  // the first ball that needs Lemma 1
  for (std::size_t s = 0; s < 2; ++s) {
    const std::string name(s == 0 ? "J0" : "J1");
    const Segment& seg = J[s];
    st.require(seg.lo == std::min(seg.top, seg.bot) && seg.hi == std::max(seg.top, seg.bot),
               name + ": lo = min(theta_top, theta_t2), hi = max(theta_top, theta_t2)");
    st.require(le(t2(A, Iv(box.b_hi)), Iv(seg.lo)) && le(Iv(seg.hi), 1.5 * pi()), name + ": t2(b_hi) <= lo and hi <= 3 pi/2");
    for (std::size_t l = 0; l < 3; ++l) {
      const double th_lo = l == 0 ? seg.top : l == 1 ? seg.bot : seg.lo, th_hi = l == 0 ? seg.top : l == 1 ? seg.bot : seg.hi;
      std::vector<Ball> balls;
      for (std::size_t i = 0; i < seg.balls[l].size(); ++i) {
        const BallWitness& bw = seg.balls[l][i];
        const Box& x = bw.ball.box;
        const std::string who = name + " " + lists[l] + " ball " + std::to_string(i);
        balls.push_back(bw.ball);
        st.require(x.b_lo <= x.b_hi && x.q_lo <= x.q_hi && box.b_lo <= x.b_lo && x.b_hi <= box.b_hi && box.q_lo <= x.q_lo && x.q_hi <= box.q_hi,
                   who + ": lies inside the parameter box (" + describe(x) + ")");
        st.require(th_lo <= bw.ball.th_lo && bw.ball.th_lo <= bw.ball.th_hi && bw.ball.th_hi <= th_hi,
                   who + ": theta range inside the list's theta range");
        const Outcome o = check_ball(st, A, bw, who);
        if (o.needs_lemma1 && needs_lemma1.empty()) needs_lemma1 = who;
        if (l == 0) st.require(o.ab && o.theta2 && le(1.5 * pi(), o.u_lo - o.two_pi_k), who + ": T >= 3 pi/2 (case AB, u_lo - 2 pi k >= 3 pi/2)");
        if (l == 1)
          st.require(!o.ab || lt(o.u_hi - o.two_pi_k, t2(A, Iv(x.b_lo, x.b_hi))), who + ": T = t2 (case BC, or AB with u_hi - 2 pi k < t2)");
      }
      require_cover(st, balls, th_lo, th_hi, box, name + " " + lists[l] + ": the balls cover the theta range x the parameter box (no gap)");
    }
  }
  st.require(needs_lemma1.empty() || has_lemma1, "Lemma 1 is needed (first by " + needs_lemma1 + ") and witnesses.lemma1 is given");
  st.require(J[0].hi < J[1].lo, "Lemma 4: J0.hi < J1.lo (disjoint segments)");
  what = "Lemma 4 (T(J0) and T(J1) contain [t2, 3pi/2], J0 = " + range_text(J[0].lo, J[0].hi) + " < J1 = " + range_text(J[1].lo, J[1].hi) +
         ") for every point of " + box_text(a, box);
  return st.n;
}

}  // namespace recheck
