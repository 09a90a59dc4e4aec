// SPDX-License-Identifier: GPL-3.0-or-later
/// @file progression.hpp
/// @brief Certified progressions: the stop \f$\theta_2\f$ of the first progression (Eq. 17) over a
/// start set and a parameter box, and Lemma 1 (the progression from rest at \f$t_0\f$ stops in
/// \f$(t_1, t_2)\f$), at a box and as a certified lower bound of \f$b_0(q)\f$.
///
/// **θ2.** After the impact at \f$\theta_1 = T_1(\theta)\f$ the velocity of mass and delimiter is
/// \f$G_2(\theta, \theta_1, t) = 2b(\theta_1-\theta) + a\cos\theta + 2c(t-\theta_1) - a\cos t\f$ (Eq. 17),
/// \f$2c = 2b - q\f$; \f$\theta_2\f$ is its first zero after \f$\theta_1\f$. For \f$t \ge \theta_1\f$:
/// \f$\partial_{\theta_1} G_2 = q > 0\f$, \f$\partial_\theta G_2 = -F(\theta) \ge 0\f$, \f$\partial_b G_2 = 2(t-\theta) > 0\f$
/// (also along \f$\theta = t_2(b)\f$) and \f$\partial_q G_2 = -(t-\theta_1) \le 0\f$. With the certified
/// \f$T_1 \in [t_{lo}, t_{hi}]\f$, \f$G_2\f$ lies between the corner functions
/// \f$G_2^{\min}(t) = G_2(\theta_{\min}, t_{lo}, t; b_{lo}, q_{hi})\f$ and
/// \f$G_2^{\max}(t) = G_2(\theta_{\max}, t_{hi}, t; b_{hi}, q_{lo})\f$. certify_theta2() proves
/// \f$G_2^{\min} > 0\f$ on \f$[t_{lo}, u_{lo}]\f$, \f$G_2^{\max}(u_{hi}) < 0\f$ and
/// \f$\partial_t G_2 = a\sin t + 2b - q \le a \sin t + 2b_{hi} - q_{lo} < 0\f$ on \f$[u_{lo}, u_{hi}]\f$: then
/// \f$\theta_2\f$ is, for every point, the unique and simple zero in \f$[u_{lo}, u_{hi}]\f$ and the first
/// after \f$\theta_1\f$, continuous in \f$\theta\f$ (implicit function theorem).
///
/// **Lemma 1.** From rest at \f$t_0\f$, \f$u(t) = -a(\cos t - \cos t_0) + 2c(t - t_0)\f$ (Eq. 7) has
/// \f$u' = F - q\f$, positive on \f$(t_0, t_1)\f$ and negative on \f$(t_1, t_0 + 2\pi)\f$; so \f$u > 0\f$ on
/// \f$(t_0, t_1]\f$ and \f$u(t_2) < 0\f$ (Eq. 8) gives exactly one stop \f$t_4 \in (t_1, t_2)\f$, where
/// \f$0 < F < q\f$: the mass stays until \f$t_2\f$ and flies. Only \f$u(t_2) < 0\f$ needs computing.
#pragma once

#include <vector>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/next_hit.hpp"
#include "dfchaos/certified/outcome.hpp"
#include "dfchaos/certified/parameters.hpp"

namespace dfchaos::certified {

/// \f$G_2(\theta, \theta_1, t; b, q)\f$ of Eq. (17): model::G2 in ball arithmetic.
Ball G2(const ParameterBalls& m, const Ball& theta, const Ball& theta1, const Ball& t, const Ball& b, const Ball& q);

/// The certified end of the first progression.
struct Theta2Proof {
  Outcome verdict;        ///< proved: for every point, \f$\theta_2\f$ is the first zero after \f$\theta_1\f$, simple, in [u_lo, u_hi]
  Ball u_lo;              ///< left end of the bracket (exact)
  Ball u_hi;              ///< right end of the bracket (exact)
  Ball enclosure;         ///< \f$[u_{lo}, u_{hi}]\f$
  NegativityStats stats;  ///< work
  // The witnesses, kept when asked (docs/certificates.md, statement covering):
  NegativityRecord no_earlier_stop;  ///< \f$G_2^{\min} > 0\f$ on these pieces of \f$[t_{lo}, u_{lo}]\f$
  NegativityRecord simple_zero;      ///< \f$a\sin t + 2b_{hi} - q_{lo} < 0\f$ on these pieces of \f$[u_{lo}, u_{hi}]\f$
};

/// \f$\theta_2\f$ over `set` given the certified \f$T_1\f$ (which must be proved); with `record`, the
/// witnesses are kept. The zeros are first sought near the floating layer's \f$\theta_2\f$; with
/// `retry`, a failed proof is tried once more from the first zeros after this proof's \f$T_1\f$
/// (the floating layer may follow the other branch of \f$T_1\f$ next to a discontinuity).
Theta2Proof certify_theta2(const ParameterBalls& m, const StartSet& set, const FirstHitProof& t1, Budget& budget, bool record = false,
                           bool retry = false);

/// The weaker statement that suffices where T is constant: the first zero of \f$G_2\f$ after
/// \f$\theta_1\f$ lies in the stop arc \f$R_k = [t_3 + 2\pi k, t_2 + 2\pi(k+1))\f$, for every point of the set.
/// Proved by \f$G_2^{\min} > 0\f$ on \f$[t_{lo}, t_3 + 2\pi k]\f$ (or \f$\theta_1 \ge t_3 + 2\pi k\f$ already) and
/// \f$G_2^{\max}(\tau) < 0\f$ at some \f$\tau \in (t_{hi}, t_2 + 2\pi(k+1))\f$. No simplicity is needed:
/// wherever in \f$R_k\f$ the progression stops (at most tangentially at \f$t_0\f$), the mass waits for
/// \f$t_2\f$, or for \f$t_0\f$ and then (Lemma 1) for \f$t_2\f$: T = t2.
struct StopArcProof {
  Outcome verdict;           ///< proved: the first stop lies in [from, tau] inside R_k
  long long k = 0;           ///< the arc
  Ball from;                 ///< the first stop lies after this
  Ball tau;                  ///< and before this
  bool needs_lemma1 = true;  ///< the range meets [t3, t0] + 2 pi k (the mass may wait for t0)
  NegativityStats stats;     ///< work
  // The witnesses, kept when asked (docs/certificates.md, statement covering):
  bool from_impact = false;            ///< the impact is already past \f$t_3 + 2\pi k\f$ (from = t_lo); else from = \f$t_3 + 2\pi k\f$
  Ball from_end;                       ///< (not from_impact) the exact upper end of \f$t_3 + 2\pi k\f$ up to which \f$G_2^{\min} > 0\f$ was proved
  NegativityRecord no_stop_before_t3;  ///< (not from_impact) \f$G_2^{\min} > 0\f$ on these pieces of \f$[t_{lo}, \f$ from_end\f$]\f$
};

/// Proves that the first progression ends in a stop arc (see StopArcProof); with `record`, the
/// witnesses are kept.
StopArcProof certify_stop_arc(const ParameterBalls& m, const StartSet& set, const FirstHitProof& t1, Budget& budget, bool record = false);

/// \f$u(t_2) = -a(\cos t_2 - \cos t_0) + (2b - q)(t_2 - t_0)\f$ (Eq. 8) over balls of b and q
/// (b = 0 allowed; needs \f$|q - 2b| < a\f$, \f$2b < a\f$).
Ball lemma1_velocity_at_t2(const Ball& a, const Ball& b, const Ball& q);

/// One sub-box \f$[b_{lo}, b_{hi}] \times [q_{lo}, q_{hi}]\f$ (exact double ends) on which a proof showed
/// Eq. (8) \f$u(t_2) < 0\f$: a witness of Lemma 1, written into certificates.
struct Lemma1SubBox {
  double b_lo = 0;  ///< lower end of b
  double b_hi = 0;  ///< upper end of b
  double q_lo = 0;  ///< lower end of q
  double q_hi = 0;  ///< upper end of q
};

/// Lemma 1 over a parameter box.
struct Lemma1Proof {
  Outcome verdict;                      ///< proved: for every parameter of the box the progression from rest at t0 stops at t4 in (t1, t2)
  Ball u_at_t2;                         ///< enclosure of Eq. (8) over the box (hull of the pieces)
  Ball t4;                              ///< enclosure of the stop (point boxes only; else the whole of [t1, t2])
  int pieces = 0;                       ///< sub-boxes used
  std::vector<Lemma1SubBox> sub_boxes;  ///< (when proved) the leaves of the split, covering the box: u(t2) < 0 on each
};

/// Proves Lemma 1's conclusion over the box (sub-boxes split in b and q, at most `max_pieces`).
Lemma1Proof certify_lemma1(const ParameterBalls& m, int max_pieces = 4096);

/// A certified lower bound of \f$b_0(q)\f$: Lemma 1 holds for every \f$b \in (0, b_{low}]\f$ at (a, q).
struct Lemma1Bound {
  Outcome verdict;                     ///< proved for the whole interval (0, b_low]
  double b_low = 0;                    ///< the bound (a double)
  double b_float = 0;                  ///< floating-point estimate of the first b with u(t2) = 0 (not certified)
  int pieces = 0;                      ///< b-balls used in the proof
  std::vector<Lemma1SubBox> b_pieces;  ///< (when proved) the leaves [x, y] (as b ranges, q = q_lo = q_hi) covering [0, b_low]
};

/// Searches the largest \f$b_{low} = b_{\mathrm{float}}(1 - \text{resolution})\f$ (shrinking by 10% on
/// failure, at most 20 times) such that \f$u(t_2) < 0\f$ is proved for all \f$b \in [0, b_{low}]\f$ by an
/// adaptive cover with b-balls.
Lemma1Bound lemma1_b0_lower_bound(double a, double q, double resolution = 1e-3, int max_pieces = 20000);

}  // namespace dfchaos::certified
