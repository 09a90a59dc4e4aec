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

/// Sections 6-7: for each orbit, boxes X_0..X_(m-1) with X_j inside J_(w_j) (J0 < J1 disjoint, w a
/// word of m letters 0 and 1, checked here to be primitive: no power of a shorter word), T continuous
/// on X_j and T at the ends of X_j on opposite sides outside X_(j+1): then T(X_j) contains X_(j+1)
/// (intermediate values), and going back along the cycle a point x of X_0 has T^j x in X_j and
/// T^m x = x; its itinerary is w^infinity (J0, J1 disjoint), whose least period is m as w is primitive.
/// (The prover's default word is 0^(m-1)1.)
long check_periodic(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  std::string found;  // the orbits verified, for the verdict line
  const json& w = field(c, "witnesses", "");
  const Iv A = standing_box(st, a, {b, b, q, q});
  const std::vector<double> J0 = doubles(field(w, "J0", "witnesses."), 2, "witnesses.J0"),
                            J1 = doubles(field(w, "J1", "witnesses."), 2, "witnesses.J1");
  st.require(J0[0] <= J0[1] && J0[1] < J1[0] && J1[0] <= J1[1], "J0 and J1 are segments, J0 left of J1 (disjoint)");
  const json& orbits = field(w, "orbits", "witnesses.");
  if (!orbits.is_array() || orbits.empty()) throw Malformed("'witnesses.orbits' is not a non-empty array");
  for (std::size_t i = 0; i < orbits.size(); ++i) {
    const std::string wo = "witnesses.orbits[" + std::to_string(i) + "].";
    const json& jm = field(orbits[i], "period", wo);
    if (!jm.is_number_integer() || jm.get<long long>() < 1 || jm.get<long long>() > 64)
      throw Malformed("'" + wo + "period' is not an integer in 1..64");
    const std::size_t m = jm.get<std::size_t>();
    const json &word = field(orbits[i], "word", wo), &boxes = field(orbits[i], "boxes", wo);
    if (!word.is_string() || !boxes.is_array()) throw Malformed("'" + wo + "' has no word string or boxes array");
    const std::string wd = word.get<std::string>();
    // primitive: w occurs in ww only at 0 and m (a power u^k, k >= 2, also occurs at |u|)
    st.require(wd.size() == m && wd.find_first_not_of("01") == std::string::npos && (wd + wd).find(wd, 1) == m,
               wo + "word: m letters 0 and 1 (m = period), primitive, so that the least period is m");
    st.require(boxes.size() == m, wo + "boxes: one per point of the orbit (m of them)");
    std::vector<Num> lo(m), hi(m);
    std::vector<Iv> T_lo(m), T_hi(m);
    for (std::size_t j = 0; j < m; ++j) {
      const std::string wx = wo + "boxes[" + std::to_string(j) + "]";
      const json& X = field(boxes[j], "X", wx + ".");
      if (!X.is_array() || X.size() != 2) throw Malformed("'" + wx + ".X' is not [lo, hi]");
      lo[j] = exact(X[0], wx + ".X[0]"), hi[j] = exact(X[1], wx + ".X[1]");
      const std::vector<double>& Jw = wd[j] == '1' ? J1 : J0;
      st.require(mpfr_cmp(lo[j].x, hi[j].x) < 0 && mpfr_cmp_d(lo[j].x, Jw[0]) >= 0 && mpfr_cmp_d(hi[j].x, Jw[1]) <= 0,
                 wx + ": lo < hi, inside J" + wd[j]);
      T_on(st, A, field(boxes[j], "on", wx + "."), b, q, lo[j], hi[j], wx + ".on");
      T_lo[j] = T_on(st, A, field(boxes[j], "at_lo", wx + "."), b, q, lo[j], lo[j], wx + ".at_lo");
      T_hi[j] = T_on(st, A, field(boxes[j], "at_hi", wx + "."), b, q, hi[j], hi[j], wx + ".at_hi");
    }
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t n = (j + 1) % m;
      const Iv L(lo[n]), H(hi[n]);
      st.require((lt(T_lo[j], L) && lt(H, T_hi[j])) || (lt(H, T_lo[j]) && lt(T_hi[j], L)),
                 wo + "boxes[" + std::to_string(j) + "]: T at its ends lies on opposite sides outside box " + std::to_string(n));
    }
    found += (found.empty() ? "" : ", ") + std::to_string(m) + " (" + wd + ")";
  }
  what = "at " + box_text(a, {b, b, q, q}) + ", with J0 = " + range_text(J0[0], J0[1]) + " and J1 = " + range_text(J1[0], J1[1]) +
         ": an orbit of T of least period m and itinerary (w)^infinity in the orbit's boxes, for (m (w)) = " + found +
         "; not re-verified: that it is the only one there (the prover's Krawczyk test)";
  return st.n;
}

}  // namespace recheck
