// SPDX-License-Identifier: GPL-3.0-or-later
/// @file discontinuities.hpp
/// @brief Lemma 2 certified: the discontinuities of \f$T_1\f$ on a segment \f$L \subset (t_2, t_3)\f$ (the paper's
/// \f$L_0 = [101\pi/100, 3\pi/2]\f$ or \f$L_2 = [101\pi/100, 51\pi/50]\f$), counted exactly and enclosed,
/// with \f$T_1\f$ continuous and decreasing between them.
///
/// **Where they are.** Eliminating b between \f$G_1 = 0\f$ and \f$\partial_t G_1 = 0\f$ (Eq. 14) gives
/// \f$\cos\frac{\theta_1+\theta}{2}(s\cos\frac s2 - 2\sin\frac s2) = 0\f$; the symmetric family
/// \f$\theta_1 + \theta \equiv \pi\f$ has flight \f$s = -(a/b)\cos z\f$ and
/// \f$h(z) = 2z - (a/b)\cos z = (2k+1)\pi\f$. \f$h' = 2 + (a/b)\sin z < 0\f$ on \f$(t_2, t_3)\f$, so each odd
/// multiple of \f$\pi\f$ in \f$h(L)\f$ (with \f$k \ge 2\f$: \f$\cos z < 0\f$, a positive flight) gives exactly one
/// \f$z_k\f$, enclosed by bisection on certified signs.
///
/// **Each is a jump** (with \f$t^* = z + s\f$, a window \f$W = [t^* - \delta, t^* + \delta]\f$ on which
/// \f$F < 0\f$ is proved): \f$G_1(z, t) = \tfrac12 F(\xi)(t - t^*)^2 \le 0\f$ on W (a double root at a
/// maximum). Left of z, \f$G_1(\theta, t) < G_1(z, t) \le 0\f$ on W (\f$G_1\f$ increases with \f$\theta\f$), so
/// certify_T1 with W skipped proves \f$T_1\f$ continuous on \f$[z - \eta', z)\f$ with values after W; the
/// same corner proof gives \f$G_1(z, \cdot) < 0\f$ on \f$(z, t^*)\f$: \f$T_1(z) = t^*\f$, a first contact.
/// Right of z, \f$G_1(\theta, t^*) \ge 0\f$ and \f$G_1\f$ is concave on W, negative at \f$t^* - \delta\f$ with no
/// contact before: on \f$[z, z + \eta]\f$ the first root is the unique crossing in \f$[t^* - \delta, t^*]\f$,
/// continuous (transversal for \f$\theta > z\f$, tending to \f$t^*\f$ at z). So \f$T_1\f$ jumps at z by more
/// than \f$t_{lo} - t^* > \delta\f$.
///
/// **Nowhere else**: between these pieces, closed balls on which certify_T1 proves a simple first
/// root cover the rest of L. \f$T_1\f$ decreases (the proof of Lemma 2; also \f$T_1' < 0\f$ on each ball).
/// If another kind of discontinuity existed (e.g. the second factor \f$\tan(s/2) = s/2\f$), the
/// cover would fail there and the answer would be "not proved".
#pragma once

#include <vector>

#include "dfchaos/certified/next_hit.hpp"

namespace dfchaos::certified {

/// A proof of \f$T_1\f$ over the start interval [lo, hi] (exact ends), kept for a certificate.
struct T1Piece {
  Ball lo;              ///< least start phase (exact)
  Ball hi;              ///< greatest start phase (exact)
  FirstHitProof proof;  ///< certify_T1 with FirstHitOptions::record
};

/// A certified discontinuity of \f$T_1\f$.
struct Tangency {
  Outcome verdict;  ///< proved: first-contact tangency, T1 continuous on both one-sided neighbourhoods, jump
  long long k = 0;  ///< \f$h(z) = (2k+1)\pi\f$
  Ball z;           ///< the discontinuity
  Ball flight;      ///< \f$s = -(a/b)\cos z\f$
  Ball t_star;      ///< \f$T_1(z) = z + s\f$ (the tangency, \f$T_1(z+0)\f$)
  Ball left_limit;  ///< enclosure of \f$T_1(z - 0)\f$
  Ball jump;        ///< lower bound of \f$T_1(z-0) - T_1(z)\f$
  Ball window_lo;   ///< W = [window_lo, window_hi] around t* on which F < 0 (exact ends)
  Ball window_hi;   ///< (see window_lo)
  // The witnesses, kept when prove_discontinuities records (docs/certificates.md, discontinuities):
  T1Piece left;                       ///< T1 on [z - eta', z.hi] with W skipped in the no-contact proof
  Ball right_lo;                      ///< the right piece's start phases [right_lo, right_hi] (exact ends)
  Ball right_hi;                      ///< (see right_lo)
  Ball right_s0;                      ///< its departure length
  NegativityRecord right_no_contact;  ///< G1(right_hi, right_hi + s; b) < 0 on these s-pieces, up to window_lo
};

/// Lemma 2 on a segment.
struct DiscontinuityProof {
  Outcome verdict;             ///< proved: exactly the z below, T1 continuous and decreasing elsewhere on [lo, hi]
  double lo = 0;               ///< left end of the segment covered (contains the requested one)
  double hi = 0;               ///< right end of the segment covered
  std::vector<Tangency> z;     ///< ascending
  long long k_above = 0;       ///< the least k >= 2 with (2k+1) pi > h(hi) proved (= the last k of z when there is one)
  int balls = 0;               ///< certify_T1 calls that succeeded (pieces of the cover)
  std::vector<T1Piece> cover;  ///< when recording: the T1 balls between the tangencies' pieces
  double seconds = 0;          ///< wall time
};

/// Lemma 2 at (a, b) on the segment [lo, hi] (balls, e.g. 101 pi/100 and 3 pi/2): covers
/// [lower(lo), upper(hi)]. At most `max_tangencies` discontinuities are handled (else not proved).
/// With `record`, every witness a certificate needs is kept (Tangency::left, right_*, cover); without,
/// the proof does no more work than before.
DiscontinuityProof prove_discontinuities(double a, double b, const Ball& lo, const Ball& hi, int max_tangencies = 4000, bool record = false);

/// \f$L_0 = [101\pi/100, 3\pi/2]\f$ and \f$L_2 = [101\pi/100, 51\pi/50]\f$ of Lemma 2 and Lemma 4, as balls.
Ball L_101pi_100();
Ball L_51pi_50();  ///< \f$51\pi/50\f$
Ball L_3pi_2();    ///< \f$3\pi/2\f$

}  // namespace dfchaos::certified
