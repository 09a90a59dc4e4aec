// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/lemma4_construction.hpp"

#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/next_hit.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

Lemma4Construction lemma4_construction(const Parameters& p, int l1_points) {
  p.require_return_map();
  if (l1_points < 1) throw InvalidParameter("l1_points", "l1_points >= 1", l1_points);
  Lemma4Construction r;
  const double t2 = *p.t2(), t3 = *p.t3(), L1lo = 1.97 * pi, L2lo = 1.01 * pi, L2hi = 1.02 * pi;
  r.arcs_defined = L1lo < t3 && L2lo > t2;
  if (!r.arcs_defined) return r;
  r.L1_to_t2 = true;
  for (int i = 0; i < l1_points; ++i) {  // L1 = [197pi/100, t3): every phase is sent to t2
    const double th = L1lo + (t3 - L1lo) * i / l1_points;
    if (T(p, th) != t2) {
      r.L1_to_t2 = false;
      break;
    }
  }
  const auto z = symmetric_tangencies(p, L2lo, L2hi);
  r.discontinuities = static_cast<long long>(z.size());
  r.three_discontinuities = z.size() >= 3;
  if (!r.three_discontinuities) return r;
  r.images_in_L1 = r.branches_cover = r.left_of_z_to_t2 = true;
  // Step (iv) on a branch [z_i, z_(i+1)) of T1 uses its structure in closed form (the Branchwise
  // search, covering.hpp): theta2 is continuous and monotone there, so the covering segment is
  // located by bisection on theta2 from the branch's ends. A sampled scan of the branch (200 points,
  // as this check did before) misses the arc where T = t2 when it is narrower than the spacing: near
  // z_(i+1) it can be a fraction of a percent of the branch, and the construction was then reported
  // to fail inside the region that lemma4-uniform proves. A branch that does not show the
  // monotone structure sends the search back to the dense scan (200 points per branch, as before),
  // which remains sampled.
  CoveringSearch s = CoveringSearch::branchwise();
  s.scan = 200;
  s.uniform = 0;
  s.recheck = 100;
  s.max_segments = 1;
  // z_i as listed by symmetric_tangencies are in descending order of k, i.e. ascending in z.
  for (std::size_t i = 0; i < z.size(); ++i) {
    // T(z_i) is the grazing value T1(z_i) mod 2pi, which is exactly pi - z_i (mod 2pi) for these
    // tangencies (next_hit.hpp). Just right of z_i, T moves away from it like a square root, so the
    // numerical check is only that T(z_i + 1e-12 z_i) lies in L1 as well.
    const double tangency = wrap_phase(pi - z[i].z);
    const double right_of_z = T(p, z[i].z * (1 + 1e-12));
    if (!(tangency >= L1lo && tangency < t3 && right_of_z >= L1lo && right_of_z < t3)) r.images_in_L1 = false;
    if (i + 1 < z.size() && i >= 1) {  // interior i: T([z_i, z_{i+1})) covers [t2, 3pi/2]
      // The search starts just inside the branch: at z_i itself T1 is the tangency, which belongs to
      // the branch on its left, and the Branchwise search would fall back to the dense scan.
      const double left = z[i].z + 1e-9 * (z[i + 1].z - z[i].z), right = z[i + 1].z;
      if (covering_segments(p, left, right - 1e-12 * right, 1.5 * pi, s).empty()) r.branches_cover = false;
      if (T(p, right - 1e-9) != t2) r.left_of_z_to_t2 = false;
    }
  }
  return r;
}

}  // namespace dfchaos
