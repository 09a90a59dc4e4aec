// SPDX-License-Identifier: GPL-3.0-or-later
#include "steps.hpp"

#include <algorithm>
#include <cstdio>

#include "paper.hpp"

namespace recheck {

// ---- checking --------------------------------------------------------------------------------------

/// Whether the closed intervals cover [lo, hi] (lo == hi: contain the point).
bool covers(std::vector<std::pair<double, double>> v, double lo, double hi) {
  std::sort(v.begin(), v.end());
  double reach = lo;
  bool started = false;
  for (const auto& [l, h] : v) {
    if (l > reach) break;  // (reach, l) is covered by nothing
    if (h >= reach) {
      reach = h;
      started = true;
    }
  }
  return started && reach >= hi;
}

std::string describe(const Box& s) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "b in [%a, %a], q in [%a, %a]", s.b_lo, s.b_hi, s.q_lo, s.q_hi);
  return buf;
}

/// The sorted distinct values of `ends` clipped to [lo, hi], with lo and hi.
std::vector<double> edges(double lo, double hi, std::vector<double> ends) {
  for (double& e : ends) e = std::clamp(e, lo, hi);
  ends.insert(ends.end(), {lo, hi});
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  return ends;
}

/// Requires that the closed balls cover [th_lo, th_hi] x box, exactly in double comparisons: for each
/// open cell between consecutive theta edges (the point when th_lo == th_hi) and consecutive b edges
/// (likewise), the q ranges of the balls whose closed theta and b ranges contain the cell cover
/// [q_lo, q_hi]. Closed balls then cover the cells' edges too.
void require_cover(Steps& st, const std::vector<Ball>& balls, double th_lo, double th_hi, const Box& box, const std::string& step) {
  std::vector<double> th_ends, b_ends;
  for (const Ball& s : balls) th_ends.insert(th_ends.end(), {s.th_lo, s.th_hi}), b_ends.insert(b_ends.end(), {s.box.b_lo, s.box.b_hi});
  const std::vector<double> th = edges(th_lo, th_hi, th_ends), b = edges(box.b_lo, box.b_hi, b_ends);
  if (static_cast<double>(th.size()) * static_cast<double>(b.size()) * static_cast<double>(balls.size()) > 2e8)
    throw Failed(step + ": the cover is too large to check (" + std::to_string(th.size()) + " theta edges, " + std::to_string(b.size()) +
                 " b edges, " + std::to_string(balls.size()) + " balls)");
  const auto cells = [](const std::vector<double>& e) {
    std::vector<std::pair<double, double>> c;
    for (std::size_t i = 0; i + 1 < e.size(); ++i) c.emplace_back(e[i], e[i + 1]);
    if (e.size() == 1) c.emplace_back(e[0], e[0]);
    return c;
  };
  const auto covered = [&] {
    for (const auto& [x, y] : cells(th)) {
      std::vector<const Ball*> in;
      for (const Ball& s : balls)
        if (s.th_lo <= x && s.th_hi >= y) in.push_back(&s);
      for (const auto& [u, v] : cells(b)) {
        std::vector<std::pair<double, double>> q;
        for (const Ball* s : in)
          if (s->box.b_lo <= u && s->box.b_hi >= v) q.emplace_back(s->box.q_lo, s->box.q_hi);
        if (!covers(q, box.q_lo, box.q_hi)) return false;
      }
    }
    return true;
  };
  st.require(covered(), step);
}

/// Eq. (1): f(lo) < 0 < f(hi) with 0 < lo < hi < pi/2 (f' > 0 on (0, pi/2): analytic, README.md);
/// then the correctly rounded doubles of vartheta0 and sin vartheta0, when given.
void vartheta0_steps(Steps& st, const Num& lo, const Num& hi) {
  const Iv L(lo), H(hi);
  st.require(L.positive() && (H - L).positive() && (0.5 * pi() - H).positive(), "0 < lo < hi < pi/2");
  st.require(f_eq1(L).negative(), "Eq. (1): f(lo) < 0");
  st.require(f_eq1(H).positive(), "Eq. (1): f(hi) > 0");
  st.require(f_eq1_slope(Iv(lo, hi)).positive(), "Eq. (1): f' > 0 on [lo, hi]");
}

/// The standing conditions of Section 2 on {a} x B x Q: 2b < a, q > 2b, q - 2b < a, and b > 0
/// unless B starts at 0 (b0's [0, b_low], whose statement is about (0, b_low]).
void standing(Steps& st, const Iv& A, const Iv& B, const Iv& Q, bool b_positive) {
  st.require(A.positive(), "a > 0");
  if (b_positive) st.require(B.positive(), "b > 0 on the box");
  st.require((A - 2.0 * B).positive(), "2b < a on the box");
  st.require((Q - 2.0 * B).positive(), "q > 2b on the box");
  st.require((A - (Q - 2.0 * B)).positive(), "q - 2b < a on the box");
}

/// The parameters {a} x [b_lo, b_hi] x [q_lo, q_hi] of a certificate.
std::pair<double, Box> read_box(const json& c) {
  const json& p = field(c, "parameters", "");
  const json &b = field(p, "b", "parameters."), &q = field(p, "q", "parameters.");
  return {parameter(p, "a", "parameters."),
          {parameter(b, "lo", "parameters.b."), parameter(b, "hi", "parameters.b."), parameter(q, "lo", "parameters.q."),
           parameter(q, "hi", "parameters.q.")}};
}

/// The box is not empty and the standing conditions hold on it; returns {a}.
Iv standing_box(Steps& st, double a, const Box& box) {
  st.require(box.b_lo <= box.b_hi && box.q_lo <= box.q_hi, "the box is not empty");
  const Iv A(a);
  standing(st, A, Iv(box.b_lo, box.b_hi), Iv(box.q_lo, box.q_hi), true);
  return A;
}

/// Lemma 1's witness {"sub_boxes": [[b_lo, b_hi, q_lo, q_hi], ...]}.
std::vector<Ball> read_sub_boxes(const json& w, const std::string& where) {
  const json& list = field(w, "sub_boxes", where);
  if (!list.is_array()) throw Malformed("'" + where + "sub_boxes' is not an array");
  std::vector<Ball> subs;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::vector<double> v = doubles(list[i], 4, where + "sub_boxes[" + std::to_string(i) + "]");
    subs.push_back({0, 0, {v[0], v[1], v[2], v[3]}});
  }
  return subs;
}

/// Lemma 1 over the box (its standing conditions already required): the sub-boxes inside the box
/// and covering it, Eq. (8) u(t2) < 0 on each.
void lemma1(Steps& st, const Iv& A, const Box& box, const std::vector<Ball>& subs) {
  for (std::size_t i = 0; i < subs.size(); ++i) {
    const Box& s = subs[i].box;
    st.require(s.b_lo <= s.b_hi && s.q_lo <= s.q_hi && box.b_lo <= s.b_lo && s.b_hi <= box.b_hi && box.q_lo <= s.q_lo && s.q_hi <= box.q_hi,
               "Lemma 1: sub-box " + std::to_string(i) + " (" + describe(s) + ") lies inside the box");
  }
  require_cover(st, subs, 0, 0, box, "Lemma 1: the sub-boxes cover the box (no gap)");
  for (std::size_t i = 0; i < subs.size(); ++i) {
    const Box& s = subs[i].box;
    st.require(u_at_t2(A, Iv(s.b_lo, s.b_hi), Iv(s.q_lo, s.q_hi)).negative(),
               "Lemma 1: Eq. (8): u(t2) < 0 on sub-box " + std::to_string(i) + " (" + describe(s) + ")");
  }
}

std::string box_text(double a, const Box& s) {
  const auto part = [](const char* name, double lo, double hi) {
    return std::string(name) + (lo == hi ? " = " + dec(lo) : " in " + range_text(lo, hi));
  };
  return "a = " + dec(a) + ", " + part("b", s.b_lo, s.b_hi) + ", " + part("q", s.q_lo, s.q_hi);
}

}  // namespace recheck
