// SPDX-License-Identifier: GPL-3.0-or-later
/// @file lemma4_uniform.hpp
/// @brief Lemma 4 for every b/a below an explicit bound at once: the paper's construction on
/// \f$L_2 = [101\pi/100, 51\pi/50]\f$, its "b/a sufficiently small" replaced by inequalities proved in
/// ball arithmetic for all \f$\varepsilon = b/a \in (0, \varepsilon_*]\f$.
///
/// Take a = 1, \f$\theta = \pi + w \in L_2\f$ (\f$w \in [\pi/100, \pi/50]\f$), s = t − θ, and
/// \f$s_0 = \cos w/\varepsilon\f$, so that \f$G_1(\theta, \theta + s) = \varepsilon s(s - s_0) + \sin\theta - \sin(\theta + s)\f$
/// (Eq. 11). The inequalities, each over all w and all \f$\varepsilon \le \varepsilon_*\f$:
///  - **(I1)** \f$2\varepsilon_* < \sin(\pi/100)\f$: \f$L_2 \subset (t_2, t_3)\f$, \f$t_3 > 199\pi/100\f$, and
///    \f$h(z) = 2z - \cos z/\varepsilon\f$ decreases on \f$L_2\f$ (\f$h' = 2 + \sin z/\varepsilon < 0\f$);
///  - **(I2)** departure: \f$\varepsilon - \tfrac12\sin w < 0\f$ and \f$g = \sin w\, sE(s) + \cos w\, K(s) < 0\f$ on
///    \f$s \in [0, 1]\f$ (next_hit.hpp's factorisation), so \f$G_1 < 0\f$ for \f$s \in (0, 1]\f$;
///  - **(I3)** middle: \f$\varepsilon + 1 - \cos w - \sin w < 0\f$ and \f$s_0 \ge 2\f$; on \f$[1, s_0 - 1]\f$,
///    \f$\varepsilon s(s - s_0) \le \varepsilon - \cos w\f$, so \f$G_1 \le \varepsilon - \cos w - \sin w + 1 < 0\f$:
///    every first contact from \f$L_2\f$ has \f$s > s_0 - 1\f$;
///  - **(I4)** end window at a symmetric tangency \f$z\f$ (\f$h(z) = (2k+1)\pi\f$, \f$t^* = (2k+1)\pi - z\f$):
///    \f$G_1(z, t^* + u) = u^2[\varepsilon - \sin w(\tfrac12 - u^2E(u)) - \cos w\, uK(u)]\f$ exactly, and the bracket
///    is < 0 on \f$u \in [-1, 0]\f$: z is a first-contact tangency, \f$T_1(z) = t^*\f$;
///  - **(I5)** count: \f$h(101\pi/100) - h(51\pi/50) \ge 6\pi\f$, so \f$L_2\f$ holds at least three such z;
///  - **(I6)** no other first-contact tangency on \f$L_2\f$: eliminating \f$t\f$ from \f$G_1 = \partial_tG_1 = 0\f$
///    leaves \f$\sigma = \varepsilon s - \cos w = 0\f$ (the symmetric family) or
///    \f$\sigma = (2s\sin w - 4\cos w)/(4 + s^2)\f$, where \f$\sin t < 0\f$ (needed for a local maximum 0 of
///    \f$G_1\f$: \f$\partial_{tt}G_1 = 2\varepsilon + \sin t \le 0\f$) forces \f$s < 2\cot(w/2)\f$; (I6) is
///    \f$s_0 - 1 \ge 2\cot(\pi/200)\f$;
///  - **(I7)** \f$\theta_2\f$ decreases along a branch: \f$(q/a - 2\varepsilon)(s_0 - 1) > 2\f$, so
///    \f$q\,|T_1'| = q|F(\theta)|s/v > |F(\theta)|\f$ (impact velocity \f$v \le 2\varepsilon s + 2\f$) and
///    \f$d\theta_2/d\theta = (q T_1' - F(\theta))/(q - F(\theta_2)) < 0\f$ wherever \f$\theta_2 \bmod 2\pi \in (t_2, t_3)\f$;
///  - **(I9)** Lemma 1 for every b/a in [0, eps*] and q/a in the box: Eq. (8) u(t2) < 0 on sub-boxes
///    covering them. Along a branch the first zero theta2 of the progression's velocity can jump
///    only where a local minimum of the velocity touches 0, at phase t0 (where F = q); after such a
///    touch the motion is the progression from rest at t0, which by Lemma 1 stops in (t1, t2). So,
///    with (I9), theta2 cannot leave (t2, t3) by a jump: it crosses t2 first (found by a referee's
///    review: without Lemma 1, at q/a below sin(vartheta0), T stops at t4 in (t2, t3) instead);
///  - **(I8)** the arc \f$L_1\f$ (arc_l1.hpp) for q/a in the box and every \f$\varepsilon \le \varepsilon_*\f$.
/// The argument that turns them into Lemma 4 (two segments \f$[z_i, \theta_c]\f$, i = 1, 2, on which T
/// decreases continuously from \f$T(z_i) = t^*_i \bmod 2\pi \ge 99\pi/50\f$ to \f$t_2\f$) is written out in
/// docs/certified.md; it is the paper's proof with the steps it leaves to "b/a small" made explicit,
/// and it is an argument, not a computation. Lemma 1 is needed, as (I9).
#pragma once

#include <vector>

#include "dfchaos/certified/arc_l1.hpp"
#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/outcome.hpp"
#include "dfchaos/certified/progression.hpp"

namespace dfchaos::certified {

/// Options of prove_lemma4_uniform(). The argument works on any segment \f$L = [\pi + w_a, \pi + w_b]\f$
/// whose landing points \f$2\pi - w\f$ lie in the arc of (I8): wider segments hold more tangencies, so
/// (I5) holds up to larger b/a.
struct Lemma4UniformOptions {
  double w_a = 0.0 / 0.0;  ///< NaN (with w_b): the paper's \f$L_2\f$, \f$w \in [\pi/100, \pi/50]\f$; else a double
  double w_b = 0.0 / 0.0;  ///< the upper end (a double, 0 < w_a < w_b <= 0.5)
  /// The bound of b/a. NaN: the largest double with (I5) on the segment.
  double eps_max = 0.0 / 0.0;
  int pieces = 16;  ///< pieces in w and in u (and s)
};

/// The inequalities (I1)-(I9) of the file comment for every b/a in (0, eps_star] and q/a in [kappa_lo, kappa_hi].
struct Lemma4UniformProof {
  Outcome verdict;             ///< proved: every inequality, for every b/a in (0, eps_star]
  double kappa_lo = 0;         ///< the box of q/a: lower end
  double kappa_hi = 0;         ///< upper end
  double w_a = 0;              ///< the segment is [pi + w_a, pi + w_b] (the doubles that end its grid)
  double w_b = 0;              ///< its upper end
  bool paper_L2 = false;       ///< the segment is the paper's L2 (Lemma4UniformOptions::w_a, w_b NaN), its ends enclosed
  double eps_star = 0;         ///< the bound: the largest double with (I5), \f$(\cos(\pi/100) - \cos(\pi/50))/(6\pi + \pi/50)\f$ rounded down
  int w_pieces = 0;            ///< pieces of \f$[\pi/100, \pi/50]\f$ in (I2)-(I4)
  int u_pieces = 0;            ///< pieces of \f$[-1, 0]\f$ in (I4) (and of \f$[0, 1]\f$ in (I2))
  double departure_g_max = 0;  ///< (I2): a double above every enclosure of g (negative when proved)
  double middle_max = 0;       ///< (I3): a double above every enclosure of \f$\varepsilon + 1 - \cos w - \sin w\f$
  double end_bracket_max = 0;  ///< (I4): a double above every enclosure of the bracket
  Ball count_length;           ///< (I5): \f$h(101\pi/100) - h(51\pi/50)\f$ at \f$\varepsilon_*\f$ (it grows as \f$\varepsilon\f$ shrinks)
  Ball s_min;                  ///< \f$s_0 - 1\f$ at its least, \f$\cos(\pi/50)/\varepsilon_* - 1\f$
  ArcL1Proof arc_l1;           ///< (I8)
  std::vector<Lemma1SubBox> lemma1_cells;  ///< (I9): (b/a, q/a) cells covering [0, eps*] x [kappa_lo, kappa_hi], u(t2) < 0 on each
};

/// Proves (I1)-(I9) for q/a in [kappa_lo, kappa_hi] on the segment of `opt`.
Lemma4UniformProof prove_lemma4_uniform(double kappa_lo, double kappa_hi, const Lemma4UniformOptions& opt = {});

/// The largest bound of b/a found for q/a in [kappa_lo, kappa_hi]: for each w_b on a grid of
/// [0.05, 0.33] (step 0.02), a bisection in log(b/a) over [1e-5, 4e-3] with w_a just above the
/// smallest (I6) and (I1) allow; the best proved one is returned (any proved one is a valid proof, the
/// search only chooses). Not proved when none is. Bounded: at most 15 x 12 proofs.
Lemma4UniformProof best_lemma4_uniform(double kappa_lo, double kappa_hi);

}  // namespace dfchaos::certified
