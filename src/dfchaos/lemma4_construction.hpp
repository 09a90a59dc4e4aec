// SPDX-License-Identifier: GPL-3.0-or-later
/// @file lemma4_construction.hpp
/// @brief The proof of Lemma 4 as the paper writes it, step by step, at concrete parameters.
///
/// The proof takes the arcs \f$L_1 = [197\pi/100, t_3)\f$ and \f$L_2 = [101\pi/100, 51\pi/50]\f$ and
/// argues: (i) every start in \f$L_1\f$ is sent to \f$t_2\f$ (a stop after the progression);
/// (ii) \f$T_1\f$ has at least three discontinuities \f$z_1 < z_2 < \dots\f$ inside \f$L_2\f$;
/// (iii) the tangential hits \f$T_1(z_i)\f$ land in \f$L_1\f$; (iv) on each interior branch
/// \f$[z_i, z_{i+1})\f$ the image of \f$T\f$ covers \f$[t_2, 3\pi/2]\f$, because (v) just left of
/// \f$z_{i+1}\f$ the map sends everything to \f$t_2\f$. Each step is checked here in floating point
/// (steps (i) and (v) by sampling, (iv) from the branch structure), so a "yes" is a sampled verdict,
/// not a proof (see the certified layer for proofs).
#pragma once

#include "dfchaos/parameters.hpp"

namespace dfchaos {

/// The outcome of each step of the paper's construction at one parameter set.
struct Lemma4Construction {
  bool arcs_defined = false;           ///< \f$197\pi/100 < t_3\f$ and \f$t_2 < 101\pi/100\f$: \f$L_1, L_2\f$ make sense
  bool L1_to_t2 = false;               ///< step (i), on `l1_points` phases of \f$L_1\f$
  long long discontinuities = 0;       ///< number of discontinuities of \f$T_1\f$ in \f$L_2\f$ (closed form, next_hit.hpp)
  bool three_discontinuities = false;  ///< step (ii): at least three
  bool images_in_L1 = false;           ///< step (iii): \f$T(z_i)\f$ and \f$T\f$ just right of \f$z_i\f$ lie in \f$L_1\f$
  /// Step (iv): a covering segment on every interior branch \f$[z_i, z_{i+1})\f$, located from
  /// \f$\theta_2\f$ at the branch's ends (CoveringMethod::Branchwise), not by a scan of the branch.
  bool branches_cover = false;
  bool left_of_z_to_t2 = false;  ///< step (v): \f$T = t_2\f$ just left of every interior \f$z_{i+1}\f$
  /// Every step went through.
  bool all() const { return arcs_defined && L1_to_t2 && three_discontinuities && images_in_L1 && branches_cover && left_of_z_to_t2; }
};

/// Checks the paper's construction of Lemma 4 at `p`, with `l1_points` sample phases on \f$L_1\f$.
/// Steps after the first failing one are reported as not done (false).
/// @throws InvalidParameter unless the return map is defined (b < a/2, q > 2b) and l1_points >= 1.
Lemma4Construction lemma4_construction(const Parameters& p, int l1_points = 200);

}  // namespace dfchaos
