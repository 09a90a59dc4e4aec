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

/// Lemma 1 over {a} x [b_lo, b_hi] x [q_lo, q_hi]: the standing conditions on the box, the
/// sub-boxes inside it and covering it, Eq. (8) u(t2) < 0 on each.
long check_lemma1(const json& c, std::string& what) {
  Steps st;
  const auto [a, box] = read_box(c);
  const std::vector<Ball> subs = read_sub_boxes(field(c, "witnesses", ""), "witnesses.");
  lemma1(st, standing_box(st, a, box), box, subs);
  what = "Lemma 1 (Eq. 8: u(t2) < 0) for every point of " + box_text(a, box);
  return st.n;
}

/// A lower bound b_low of b0(q): the standing conditions on {a} x [0, b_low] x {q}, the
/// b-intervals inside [0, b_low] and covering it, Eq. (8) u(t2) < 0 on each.
long check_b0(const json& c, std::string& what) {
  Steps st;
  const auto [a, q] = read_a_q(c);
  const json& w = field(c, "witnesses", "");
  const double b_low = parameter(w, "b_low", "witnesses.");
  const Iv A(a), Q(q);
  st.require(b_low > 0, "b_low > 0");
  standing(st, A, Iv(0.0, b_low), Q, false);
  const json& list = field(w, "b_pieces", "witnesses.");
  if (!list.is_array()) throw Malformed("'witnesses.b_pieces' is not an array");
  std::vector<std::pair<double, double>> pieces;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::vector<double> v = doubles(list[i], 2, "witnesses.b_pieces[" + std::to_string(i) + "]");
    pieces.emplace_back(v[0], v[1]);
    st.require(0 <= v[0] && v[0] <= v[1] && v[1] <= b_low,
               "b piece " + std::to_string(i) + " [" + describe({v[0], v[1], q, q}) + "] lies inside [0, b_low]");
  }
  st.require(covers(pieces, 0, b_low), "the b pieces cover [0, b_low] (no gap)");
  for (std::size_t i = 0; i < pieces.size(); ++i)
    st.require(u_at_t2(A, Iv(pieces[i].first, pieces[i].second), Q).negative(),
               "Eq. (8): u(t2) < 0 on b piece " + std::to_string(i) + " (" + describe({pieces[i].first, pieces[i].second, q, q}) + ")");
  what = "b0(q) >= b_low = " + exact_text(b_low) + ": Lemma 1 (u(t2) < 0) for every b in (0, b_low] at a = " + dec(a) + ", q = " + dec(q);
  return st.n;
}

}  // namespace recheck
