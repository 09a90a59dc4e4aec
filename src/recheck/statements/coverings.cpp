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

/// Lemma 4 over a set of boxes (a column of the certified region): each element of witnesses.boxes is
/// a `covering` certificate, checked as one, whose box lies in the certificate's {a} x B x Q.
long check_coverings(const json& c, std::string& what) {
  Steps st;
  const auto [a, box] = read_box(c);
  const json& boxes = field(field(c, "witnesses", ""), "boxes", "witnesses.");
  if (!boxes.is_array() || boxes.empty()) throw Malformed("'witnesses.boxes' is not a non-empty array");
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string who = "witnesses.boxes[" + std::to_string(i) + "]";
    require_embedded(boxes[i], "covering", who);
    const auto [ai, x] = read_box(boxes[i]);
    st.require(ai == a && box.b_lo <= x.b_lo && x.b_hi <= box.b_hi && box.q_lo <= x.q_lo && x.q_hi <= box.q_hi,
               who + ": its box lies in the parameters");
    try {
      std::string ignored;
      st.n += check_covering(boxes[i], ignored);
    } catch (const Failed& e) {
      throw Failed(who + " (" + describe(x) + "): " + e.what());
    } catch (const Malformed& e) {
      throw Malformed(who + ": " + e.what());
    }
  }
  what = "Lemma 4 for every point of each of " + std::to_string(boxes.size()) + " boxes inside " + box_text(a, box) +
         " (their union, not necessarily all of it)";
  return st.n;
}

}  // namespace recheck
