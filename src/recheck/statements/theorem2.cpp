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

/// Theorem 2's conclusion at (a, b, q) from the witnesses `w` (statement superstable, or a window's
/// middle): the condition (21) or (22) named, T = t2 on [t2, theta_end] with theta_end > t2, and the
/// hypotheses listed. Returns a description of what holds.
std::string superstable_at(Steps& st, double a, double b, double q, const json& w, const std::string& where) {
  const Box point{b, b, q, q};
  const Iv A = standing_box(st, a, point), B(b), Q(q);
  const bool has_lemma1 = w.contains("lemma1");
  if (has_lemma1) lemma1(st, A, point, read_sub_boxes(w["lemma1"], where + "lemma1."));
  bool needs_lemma1 = false;
  // The condition, from theta2(t2) (Section 8): (21) t1 < P < t2, (22) t3 < P < t0 + 2 pi.
  const Outcome at = check_at_t2(st, A, field(w, "at_t2", where), b, q, where + "at_t2");
  needs_lemma1 = at.needs_lemma1;
  const Iv P = phase(st, at, w, where);
  const json& jc = field(w, "condition", where);
  if (jc != 21 && jc != 22) throw Malformed("'" + where + "condition' is not 21 or 22");
  const int condition = jc.get<int>();
  if (condition == 21)
    st.require(lt(t1(A, B, Q), P) && lt(P, t2(A, B)), where + "(21): t1 < theta2(t2) - 2 pi k' < t2");
  else
    st.require(lt(t3(A, B), P) && lt(P, t0(A, B, Q) + 2.0 * pi()), where + "(22): t3 < theta2(t2) - 2 pi k' < t0 + 2 pi");
  // T = t2 on [t2, theta_end]: balls from t2 or inside (t2, theta_end], each T = t2, covering it.
  const double end = exact_double(field(w, "theta_end", where), where + "theta_end");
  st.require(lt(t2(A, B), Iv(end)), where + "theta_end > t2");
  const json& cover = field(w, "cover", where);
  if (!cover.is_array()) throw Malformed("'" + where + "cover' is not an array");
  Num t2_lo;  // a double <= t2: the lower end of balls from t2, in the exact cover comparison
  mpfi_get_left(t2_lo.x, t2(A, B).x);
  const double t2_down = mpfr_get_d(t2_lo.x, MPFR_RNDD);
  std::vector<Ball> balls;
  for (std::size_t i = 0; i < cover.size(); ++i) {
    const std::string who = where + "cover[" + std::to_string(i) + "]";
    BallWitness bw = read_ball(cover[i], who + ".");
    st.require(bw.ball.box.b_lo == b && bw.ball.box.b_hi == b && bw.ball.box.q_lo == q && bw.ball.box.q_hi == q,
               who + ": phases at the parameter point");
    const Outcome o = check_ball(st, A, bw, who);
    st.require(proves_T_is_t2(A, o, point), who + ": T = t2 (case BC, or AB with u_hi - 2 pi k < t2)");
    needs_lemma1 = needs_lemma1 || o.needs_lemma1;
    if (bw.ball.start == Start::FromT2) bw.ball.th_lo = t2_down;
    st.require(bw.ball.th_hi <= end, who + ": inside [t2, theta_end]");
    balls.push_back(bw.ball);
  }
  require_cover(st, balls, t2_down, end, point, where + "cover: the balls cover [t2, theta_end] (no gap)");
  st.require(!needs_lemma1 || has_lemma1, where + "Lemma 1 is needed and lemma1 is given");
  // The hypotheses the certificate lists: (2) 2b < a, a sin(vartheta0) < q < a; (23) q < a.
  const json& hyp = field(w, "hypotheses", where);
  if (!hyp.is_array()) throw Malformed("'" + where + "hypotheses' is not an array");
  bool h2 = false, h23 = false;
  for (const json& h : hyp) {
    if (h == "(2)") {
      const Iv v0 = vartheta0_bracket(st, w, where);
      st.require(lt(2.0 * B, A) && lt(A * sin(v0), Q) && lt(Q, A), where + "(2): 2b < a, a sin(vartheta0) < q < a");
      h2 = true;
    } else if (h == "(23)") {
      st.require(lt(Q, A), where + "(23): q < a");
      h23 = true;
    } else {
      throw Malformed("'" + where + "hypotheses' holds " + h.dump() + " (not \"(2)\" or \"(23)\")");
    }
  }
  const bool theorem2 = (h2 && condition == 22) || (h23 && condition == 21);
  return std::string("T = t2 on [t2, t2 + eps], (") + std::to_string(condition) + ")" + (theorem2 ? ", Theorem 2's hypotheses hold" : "");
}

long check_superstable(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  what = "at " + box_text(a, {b, b, q, q}) + ": " + superstable_at(st, a, b, q, field(c, "witnesses", ""), "witnesses.");
  return st.n;
}

/// T(t2) > t2 at (a, b, q): t2 is not a fixed point of T.
long check_not_superstable(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  const Box point{b, b, q, q};
  const Iv A = standing_box(st, a, point);
  const Outcome o = check_at_t2(st, A, field(field(c, "witnesses", ""), "at_t2", "witnesses."), b, q, "witnesses.at_t2");
  st.require(proves_T_above_t2(A, o, point), "T(t2) > t2 (case AB, u_lo - 2 pi k > t2)");
  what = "T(t2) > t2 at " + box_text(a, point) + ": t2 is not a fixed point of T";
  return st.n;
}

/// A superstability window in b at (a, q): on b-boxes covering [left_in, right_in], T = t2 on
/// [t2(b), h] with h > t2(b_hi) (t2 superstable at every such b); T(t2) > t2 at left_out and
/// right_out; Theorem 2's conclusion at the middle.
long check_window(const json& c, std::string& what) {
  Steps st;
  const auto [a, q] = read_a_q(c);
  const json& w = field(c, "witnesses", "");
  double e[4];
  const char* names[4] = {"left_out", "left_in", "right_in", "right_out"};
  for (int i = 0; i < 4; ++i) e[i] = exact_double(field(w, names[i], "witnesses."), std::string("witnesses.") + names[i]);
  st.require(0 < e[0] && e[0] < e[1] && e[1] < e[2] && e[2] < e[3], "0 < left_out < left_in < right_in < right_out");
  const Box range{e[0], e[3], q, q}, inner{e[1], e[2], q, q};
  const Iv A = standing_box(st, a, range);
  const json& outer = field(w, "outer", "witnesses.");
  if (!outer.is_array() || outer.size() != 2) throw Malformed("'witnesses.outer' is not an array of two balls");
  for (int side = 0; side < 2; ++side) {
    const double b = side == 0 ? e[0] : e[3];
    const std::string who = side == 0 ? "witnesses.outer[0] (left_out)" : "witnesses.outer[1] (right_out)";
    const Outcome o = check_at_t2(st, A, outer[side], b, q, who);
    st.require(proves_T_above_t2(A, o, {b, b, q, q}), who + ": T(t2) > t2");
  }
  const bool has_lemma1 = w.contains("lemma1");
  if (has_lemma1) lemma1(st, A, inner, read_sub_boxes(w["lemma1"], "witnesses.lemma1."));
  const json& boxes = field(w, "boxes", "witnesses.");
  if (!boxes.is_array()) throw Malformed("'witnesses.boxes' is not an array");
  std::vector<Ball> balls;
  bool needs_lemma1 = false;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string who = "witnesses.boxes[" + std::to_string(i) + "]";
    const BallWitness bw = read_ball(boxes[i], who + ".");
    const Box& x = bw.ball.box;
    st.require(bw.ball.start == Start::FromT2 && e[1] <= x.b_lo && x.b_lo <= x.b_hi && x.b_hi <= e[2] && x.q_lo == q && x.q_hi == q,
               who + ": phases [t2(b), h], b inside [left_in, right_in]");
    st.require(lt(t2(A, Iv(x.b_hi)), Iv(bw.ball.th_hi)), who + ": h > t2(b_hi) (so eps_b = h - t2(b) > 0 for every b)");
    const Outcome o = check_ball(st, A, bw, who);
    st.require(proves_T_is_t2(A, o, x), who + ": T = t2 on [t2(b), h], every b (case BC, or AB with u_hi - 2 pi k < t2)");
    needs_lemma1 = needs_lemma1 || o.needs_lemma1;
    balls.push_back(bw.ball);
  }
  require_cover(st, balls, 0, 0, inner, "the b-boxes cover [left_in, right_in] (no gap)");
  st.require(!needs_lemma1 || has_lemma1, "Lemma 1 is needed by a box and witnesses.lemma1 is given");
  const json& inside = field(w, "inside", "witnesses.");
  const double b_mid = exact_double(field(inside, "b", "witnesses.inside."), "witnesses.inside.b");
  st.require(e[1] <= b_mid && b_mid <= e[2], "inside.b lies in [left_in, right_in]");
  const std::string middle = superstable_at(st, a, b_mid, q, inside, "witnesses.inside.");
  what = "at a = " + dec(a) + ", q = " + dec(q) + ": T = t2 near t2 (t2 superstable) for every b in " + range_text(e[1], e[2]) +
         ", T(t2) > t2 at b = " + dec(e[0]) + " and " + dec(e[3]) + "; at b = " + dec(b_mid) + ": " + middle;
  return st.n;
}

/// The erratum to Theorem 2: (2) and (22) hold at (a, b, q), yet u(t2) > 0 > u(t3) (Eq. 7), so the
/// progression from rest at t0 stops at t4 in (t2, t3), where the mass flies: T(t2) = t4 != t2.
long check_theorem2_counterexample(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  const json& w = field(c, "witnesses", "");
  const Iv A = standing_box(st, a, {b, b, q, q}), B(b), Q(q);
  const Iv v0 = vartheta0_bracket(st, w, "witnesses.");
  st.require(lt(2.0 * B, A) && lt(A * sin(v0), Q) && lt(Q, A), "(2): 2b < a, a sin(vartheta0) < q < a");
  const Outcome at = check_at_t2(st, A, field(w, "at_t2", "witnesses."), b, q, "witnesses.at_t2", true);
  const Iv P = phase(st, at, w, "witnesses.");
  st.require(lt(t3(A, B), P) && lt(P, t0(A, B, Q) + 2.0 * pi()), "(22): t3 < theta2(t2) - 2 pi k' < t0 + 2 pi");
  st.require(u_from_t0(A, B, Q, t2(A, B)).positive(), "Eq. (7): u(t2) > 0");
  st.require(u_from_t0(A, B, Q, t3(A, B)).negative(), "Eq. (7): u(t3) < 0");
  what = "at " + box_text(a, {b, b, q, q}) + ": (2) and (22) hold, u(t2) > 0 > u(t3), so T(t2) != t2 (the erratum to Theorem 2)";
  return st.n;
}

}  // namespace recheck
