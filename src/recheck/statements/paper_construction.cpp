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

/// The paper's construction in the proof of Lemma 4 at the point (a, b, q): a `covering` certificate
/// there and a `discontinuities` certificate on L2, each checked as such; at least three
/// discontinuities z_1 < ... < z_n of T1 on L2 (all of them, by the latter), and each segment J of
/// the covering inside a branch: z_i < J < z_(i+1) for consecutive i. The paper's remark that
/// T1(z_i) mod 2 pi = pi - z_i mod 2 pi lies in L1 = [197 pi/100, t3] holds as z_i is in L2 and
/// 199 pi/100 < t3 (checked).
long check_paper_construction(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  const json& w = field(c, "witnesses", "");
  const json &cov = field(w, "covering", "witnesses."), &dis = field(w, "discontinuities", "witnesses.");
  require_embedded(cov, "covering", "witnesses.covering");
  require_embedded(dis, "discontinuities", "witnesses.discontinuities");
  const auto [ac, box] = read_box(cov);
  const json& dp = field(dis, "parameters", "witnesses.discontinuities.");
  st.require(ac == a && box.b_lo == b && box.b_hi == b && box.q_lo == q && box.q_hi == q, "the covering is at the point (a, b, q)");
  st.require(parameter(dp, "a", "witnesses.discontinuities.parameters.") == a && parameter(dp, "b", "witnesses.discontinuities.parameters.") == b &&
                 field(dp, "segment", "witnesses.discontinuities.parameters.") == "L2",
             "the discontinuities are at (a, b), on L2");
  st.n += embedded("witnesses.covering", [&] {
    std::string ignored;
    return check_covering(cov, ignored);
  });
  std::string discontinuities;
  st.n += embedded("witnesses.discontinuities", [&] { return check_discontinuities(dis, discontinuities); });
  const json& ts = field(field(dis, "witnesses", ""), "tangencies", "witnesses.discontinuities.witnesses.");
  st.require(ts.size() >= 3, "at least three discontinuities on L2");
  std::vector<Num> zl, zh;
  for (const json& t : ts) zl.push_back(exact(t["z"][0], "z")), zh.push_back(exact(t["z"][1], "z"));
  for (std::size_t s = 0; s < 2; ++s) {
    const json& seg = cov["witnesses"]["segments"][s];
    const double lo = exact_double(seg["lo"], "lo"), hi = exact_double(seg["hi"], "hi");
    bool inside = false;
    for (std::size_t i = 0; i + 1 < zl.size(); ++i) inside = inside || (mpfr_cmp_d(zh[i].x, lo) < 0 && mpfr_cmp_d(zl[i + 1].x, hi) > 0);
    st.require(inside, std::string(s == 0 ? "J0" : "J1") + " lies strictly between two consecutive discontinuities");
  }
  st.require(lt(Iv(199.0) / Iv(100.0) * pi(), t3(Iv(a), Iv(b))), "199 pi/100 < t3 (T1(z_i) mod 2 pi in L1)");
  const json& segs = cov["witnesses"]["segments"];
  what = "the paper's construction of Lemma 4 at " + box_text(a, {b, b, q, q}) +
         ": J0 = " + range_text(exact_double(segs[0]["lo"], "lo"), exact_double(segs[0]["hi"], "hi")) +
         " and J1 = " + range_text(exact_double(segs[1]["lo"], "lo"), exact_double(segs[1]["hi"], "hi")) + " each between consecutive ones of the " +
         std::to_string(ts.size()) + " discontinuities of T1 on L2";
  return st.n;
}

}  // namespace recheck
