// SPDX-License-Identifier: GPL-3.0-or-later
/// @file superstable.hpp
/// @brief Theorem 2 (Section 8) certified: \f$t_2\f$ is a superstable fixed point of T — a whole
/// \f$[t_2, t_2 + \varepsilon]\f$ is sent to \f$t_2\f$ — with a certified \f$\varepsilon > 0\f$; conditions
/// (21) and (22) with certified margins; and certified enclosures of the edges of superstability
/// windows in \f$b\f$.
///
/// **At a parameter point.** certify_T() over \f$[t_2, t_2 + \varepsilon]\f$ (split into closed balls, the
/// first one starting exactly at \f$t_2\f$, where \f$b + \tfrac a2 \sin t_2 = 0\f$ and the departure of the
/// flight is proved from the cubic term) proves on each ball that \f$T_1\f$ and \f$\theta_2\f$ are simple
/// roots and that T is identically \f$t_2\f$ (the progression stops in an arc where the mass waits
/// for \f$t_2\f$, with Lemma 1 when it waits for \f$t_0\f$). Condition (21) is \f$\theta_2(t_2) \bmod 2\pi \in
/// (t_1, t_2)\f$ and (22) is \f$\in (t_3, 2\pi) \cup [0, t_0)\f$, each decided on the certified enclosure.
///
/// **Window edges.** Over a box \f$[b_{lo}, b_{hi}]\f$ of b (q fixed), the starts \f$\theta = t_2(b)\f$ give
/// \f$\theta_2(t_2(b))\f$ as a continuous function of b (certify_T1/theta2 over the family, implicit
/// function theorem). Let \f$\varphi(b) = \theta_2(t_2(b)) - B(b) - 2\pi k\f$ for the boundary B
/// (\f$t_1, t_2, t_3\f$ or \f$t_0\f$) that the phase crosses. A certified sign change of \f$\varphi\f$ between
/// the ends and \f$\varphi' \ne 0\f$ on the box (enclosed by the implicit function theorem:
/// \f$dT_1/db = -(T_1 - t_2)^2/\partial_t G_1\f$ since \f$F(t_2) = 0\f$, and
/// \f$d\theta_2/db = -(2(\theta_2 - t_2) + q\,dT_1/db)/(F(\theta_2) - q)\f$) give exactly one crossing in the
/// box: the window edge, with the condition proved at the inner end and disproved at the outer.
#pragma once

#include <string>

#include <vector>

#include "dfchaos/certified/return_map.hpp"

namespace dfchaos::certified {

/// Theorem 2 at a parameter point.
struct SuperstableProof {
  Outcome verdict;           ///< proved: T = t2 on [t2, t2 + eps] (and (21) or (22) holds)
  int condition = 0;         ///< 21 or 22 when certified; 0 when neither holds (certified); -1 undecided
  Ball T1;                   ///< \f$T_1(t_2)\f$
  Ball theta2;               ///< \f$\theta_2(t_2)\f$ (instant)
  Ball theta2_phase;         ///< its phase (in \f$[t_1, t_1 + 2\pi)\f$)
  double eps = 0;            ///< certified: \f$T \equiv t_2\f$ on \f$[t_2, t_2 + \varepsilon]\f$
  int balls = 0;             ///< closed balls of the cover of that interval
  bool used_lemma1 = false;  ///< the chain waited for \f$t_0\f$ (scenario C): Lemma 1 was proved
  bool eq2 = false;          ///< assumptions (2) certified (with the certified \f$\vartheta_0\f$)
  bool eq23 = false;         ///< assumptions (23) certified
  double seconds = 0;        ///< wall time
  // The witnesses, kept when asked (docs/certificates.md, statement superstable):
  std::vector<BallProof> at;     ///< T at \f$[t_2, t_2^{\uparrow}]\f$ (\f$t_2^{\uparrow}\f$ the double above \f$t_2\f$): one ball
  std::vector<BallProof> cover;  ///< the balls on which T = t2, covering \f$[t_2, t_2^{\uparrow} + \varepsilon]\f$
  long long phase_turn = 0;      ///< the phase of \f$\theta_2(t_2)\f$ is \f$\theta_2 - 2\pi\f$ phase_turn
  Lemma1Proof lemma1;            ///< when used_lemma1: Lemma 1 at the point (the certificate's witness)
};

/// Proves Theorem 2's conclusion at (a, b, q). `eps_try`: the width to try first (NaN: from the
/// floating layer's measured width, halved until proved, at most 12 times). With `record`, the
/// witnesses are kept.
SuperstableProof prove_superstable(double a, double b, double q, double eps_try = 0.0 / 0.0, bool record = false);

/// The condition (21)/(22) of a certified T at \f$t_2\f$: 21, 22, 0 (certainly neither), -1 (undecided).
int superstable_condition(const ParameterBalls& m, const MapStepProof& t);

/// A superstability window in b (q fixed): the maximal interval W of b containing the middle of
/// the floating estimate on which \f$T(t_2) = t_2\f$.
///
/// Proof: b-boxes covering \f$[b^L_{in}, b^R_{in}]\f$, on each of which \f$T \equiv t_2\f$ on
/// \f$[t_2(b), t_2(b_{hi}) + e]\f$ for every b of the box (certify_T over that start set, e > 0 halved
/// until proved: t2 is superstable at each b, with \f$\varepsilon_b \ge e\f$), and \f$T(t_2) \ne t_2\f$ (certified, scenario A) at the outer
/// points \f$b^L_{out} < b^L_{in}\f$ and \f$b^R_{out} > b^R_{in}\f$. Hence the edges of W lie in
/// \f$[b^L_{out}, b^L_{in}]\f$ and \f$[b^R_{in}, b^R_{out}]\f$, whatever happens at them (a crossing of
/// \f$t_2\f$ by \f$\theta_2(t_2)\f$, or the flight from \f$t_2\f$ grazing the delimiter at \f$t_3\f$).
struct WindowProof {
  Outcome verdict;          ///< all parts proved
  double b_lo_float = 0;    ///< the floating estimate of the window: left end
  double b_hi_float = 0;    ///< the floating estimate of the window: right end
  SuperstableProof inside;  ///< at the middle: Theorem 2 with a certified epsilon
  double left_out = 0;      ///< the left edge lies in [left_out, left_in]
  double left_in = 0;       ///< (see left_out)
  double right_in = 0;      ///< the right edge lies in [right_in, right_out]
  double right_out = 0;     ///< (see right_in)
  Ball T_left_out;          ///< T(t2) at left_out (certainly not t2)
  Ball T_right_out;         ///< T(t2) at right_out (certainly not t2)
  int boxes = 0;            ///< b-boxes of the cover of [left_in, right_in]
  double min_eps = 0;       ///< on each box, T = t2 on [t2(b), t2(b) + eps_b] with eps_b at least this
  double seconds = 0;       ///< wall time
  // The witnesses, kept when asked (docs/certificates.md, statement window):
  std::vector<BallProof> outer;       ///< T at t2 at b = left_out and right_out (T != t2)
  std::vector<BallProof> box_proofs;  ///< T(t2(b)) = t2 on each b-box, covering [left_in, right_in]
  Lemma1Proof lemma1;                 ///< when a box used Lemma 1: Lemma 1 over [left_in, right_in] x {q}
};

/// Certifies the window estimated by the floating layer as \f$[b_{lo}, b_{hi}]\f$; the edge brackets have
/// relative half-width `rel` (grown x10, at most 4 times, until proved). With `record`, the witnesses
/// are kept (of the middle's proof too).
WindowProof prove_window(double a, double q, double b_lo, double b_hi, double rel = 1e-9, bool record = false);

/// Theorem 2 as stated, tested where Lemma 1 fails: hypotheses (2) and (22) certified, and yet
/// \f$T(t_2) \ne t_2\f$, because the progression that starts from rest at \f$t_0\f$ does not stop before
/// \f$t_2\f$ (b above \f$b_0(q)\f$): with \f$u(t) = -a(\cos t - \cos t_0) + 2c(t - t_0)\f$ (Eq. 7), u > 0 on
/// \f$(t_0, t_1]\f$, u decreasing on \f$[t_1, t_3]\f$, \f$u(t_2) > 0 > u(t_3)\f$: it stops once, at
/// \f$t_4 \in (t_2, t_3)\f$, where the mass flies (scenario D): \f$T(t_2) = t_4 \ne t_2\f$.
struct Theorem2Counterexample {
  Outcome verdict;    ///< proved: (2) and (22) hold, and T(t2) = t4 in (t2, t3)
  Ball theta2_phase;  ///< \f$\theta_2(t_2) \bmod 2\pi\f$ (in \f$(t_3, 2\pi) \cup [0, t_0)\f$)
  Ball u_at_t2;       ///< Eq. (8): positive
  Ball u_at_t3;       ///< negative
  Ball T;             ///< \f$T(t_2) = t_4\f$
  /// The witnesses (docs/certificates.md, statement theorem2_counterexample): T1 and theta2 from
  /// \f$[t_2, t_2^{\uparrow}]\f$ (case and turn of the phase of \f$\theta_2\f$ set as for a ball).
  std::vector<BallProof> at;
};
/// Proves the counterexample at (a, b, q); with `record`, the witnesses are kept.
Theorem2Counterexample prove_theorem2_counterexample(double a, double b, double q, bool record = false);

}  // namespace dfchaos::certified
