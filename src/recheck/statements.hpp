// SPDX-License-Identifier: GPL-3.0-or-later
/// @file statements.hpp
/// @brief The statements the checker reads, one file each in statements/, and the table that
/// dispatches a certificate to its check by the name in its "statement" field.
///
/// A check reads the whole certificate, re-verifies every step in interval arithmetic (throwing
/// Failed at the first that does not hold, Malformed for a certificate it cannot read), returns the
/// number of steps and sets `what` to the statement it verified, in the certificate's own numbers, so
/// that the verdict line can be compared with the claim the certificate is for.
#pragma once

#include <string>
#include <vector>

#include "reading.hpp"

namespace recheck {

/// A check of one statement (above).
using Check = long (*)(const json& c, std::string& what);

/// A statement's name (as certificates write it) and its check.
struct Statement {
  const char* name;
  Check check;
};

/// Every statement the checker reads, in the order of docs/certificates.md.
const std::vector<Statement>& statements();

/// The names of statements(), comma-separated (for messages).
std::string statement_names();

long check_vartheta0(const json& c, std::string& what);
/// Lemma 1 over {a} x [b_lo, b_hi] x [q_lo, q_hi]: the standing conditions on the box, the
/// sub-boxes inside it and covering it, Eq. (8) u(t2) < 0 on each.
long check_lemma1(const json& c, std::string& what);
/// A lower bound b_low of b0(q): the standing conditions on {a} x [0, b_low] x {q}, the
/// b-intervals inside [0, b_low] and covering it, Eq. (8) u(t2) < 0 on each.
long check_b0(const json& c, std::string& what);
/// Lemma 4 (Theorem 1): two disjoint segments J0 < J1 in [t2, 3 pi/2], each covered by balls on
/// which T is continuous, with T(theta_top) >= 3 pi/2 and T(theta_t2) = t2: T(J) contains [t2, 3 pi/2].
long check_covering(const json& c, std::string& what);
/// Lemma 2 at (a, b) on L = L0 or L2 (docs/certificates.md): the k listed are exactly those with
/// (2k+1) pi in h(L), k >= 2; each z_k is bracketed, its tangency t* = (2k+1) pi - z_k lies in a
/// window W where F < 0; left of z_k a T1 ball whose no-contact proof skips W, right of z_k no
/// contact up to W (then the concavity of G1 on W); T1 balls cover the rest of [lo, hi], which
/// contains L. So T1 is discontinuous exactly at the z_k on L.
long check_discontinuities(const json& c, std::string& what);
long check_superstable(const json& c, std::string& what);
/// T(t2) > t2 at (a, b, q): t2 is not a fixed point of T.
long check_not_superstable(const json& c, std::string& what);
/// A superstability window in b at (a, q): on b-boxes covering [left_in, right_in], T = t2 on
/// [t2(b), h] with h > t2(b_hi) (t2 superstable at every such b); T(t2) > t2 at left_out and
/// right_out; Theorem 2's conclusion at the middle.
long check_window(const json& c, std::string& what);
/// The erratum to Theorem 2: (2) and (22) hold at (a, b, q), yet u(t2) > 0 > u(t3) (Eq. 7), so the
/// progression from rest at t0 stops at t4 in (t2, t3), where the mass flies: T(t2) = t4 != t2.
long check_theorem2_counterexample(const json& c, std::string& what);
/// Lemma 4 over a set of boxes (a column of the certified region): each element of witnesses.boxes is
/// a `covering` certificate, checked as one, whose box lies in the certificate's {a} x B x Q.
long check_coverings(const json& c, std::string& what);
/// The paper's construction in the proof of Lemma 4 at the point (a, b, q): a `covering` certificate
/// there and a `discontinuities` certificate on L2, each checked as such; at least three
/// discontinuities z_1 < ... < z_n of T1 on L2 (all of them, by the latter), and each segment J of
/// the covering inside a branch: z_i < J < z_(i+1) for consecutive i. The paper's remark that
/// T1(z_i) mod 2 pi = pi - z_i mod 2 pi lies in L1 = [197 pi/100, t3] holds as z_i is in L2 and
/// 199 pi/100 < t3 (checked).
long check_paper_construction(const json& c, std::string& what);
/// Sections 6-7: for each orbit, boxes X_0..X_(m-1) with X_j inside J_(w_j) (J0 < J1 disjoint, w a
/// word of m letters 0 and 1, checked here to be primitive: no power of a shorter word), T continuous
/// on X_j and T at the ends of X_j on opposite sides outside X_(j+1): then T(X_j) contains X_(j+1)
/// (intermediate values), and going back along the cycle a point x of X_0 has T^j x in X_j and
/// T^m x = x; its itinerary is w^infinity (J0, J1 disjoint), whose least period is m as w is primitive.
/// (The prover's default word is 0^(m-1)1.)
long check_periodic(const json& c, std::string& what);
/// With a = 1, theta = 2pi - delta, s = t - theta: G1(theta, theta + s) = s^2 (-A + s g(delta, s)),
/// A = (sin delta - 2b)/2, g = sin(delta) s E(s) - cos(delta) K(s), E = (1/2 - (1 - cos s)/s^2)/s^2,
/// K = (sin s - s)/s^3 (Taylor's formula of sin and cos at theta). For 0 <= s <= 1 the series of E,
/// K and of their derivatives alternate with decreasing terms, so on a cell s in [s1, s2]:
/// E in [1/24 - s2^2/720, 1/24], K in [-1/6, -1/6 + s2^2/120], E' in [-s/360, -s/360 + s2^3/10080],
/// K' in [s/60 - s2^3/1260, s/60]. H = -A + s g has H' = g + s g', g' = sin(delta)(E + s E') - cos(delta) K'.
/// The checker encloses g and H' on every cell of the grid and checks the stated bounds; then the
/// scalar inequalities of the argument (README.md): contact within S and after t3, the progression's
/// deceleration gamma, its stop within W, before t0 + 2pi.
long check_arc_l1(const json& c, std::string& what);
/// (I1)-(I7) of docs/certified.md for every eps in [0, eps*] (a = 1, theta = pi + w, w in [pi/100,
/// pi/50], s0 = cos(w)/eps), re-derived here: G1(theta, theta + s) = s^2 [eps - sin(w)/2 + s g],
/// g = sin(w) s E(s) + cos(w) K(s); G1 <= eps - cos w - sin w + 1 on [1, s0 - 1]; at a symmetric
/// tangency z (2z - cos(z)/eps = (2k+1) pi), G1(z, t* + u) = u^2 [eps - sin w (1/2 - u^2 E(u)) -
/// cos(w) u K(u)]; the closed-form count h(101pi/100) - h(51pi/50) >= 6 pi; s0 - 1 > 2 cot(pi/200)
/// (no tangency of the other family can be a first contact); (q/a - 2 eps)(s0 - 1) > 2 (theta2
/// decreases along a branch); and (I8), the arc L1, as the embedded arc-l1 certificate for the same
/// q/a with a bound >= eps*. The argument from these to Lemma 4 is trusted (README.md).
long check_lemma4_uniform(const json& c, std::string& what);
/// Section 7 beyond two symbols: disjoint segments I_1 < ... < I_n of [t2, t3), each covered by balls
/// on which T is continuous, with T at both ends enclosed (case AB above t2); an edge j -> k only where
/// I_k lies strictly between the enclosures at the ends of I_j (so T(I_j) contains I_k); weights v > 0
/// with sum_{j -> k} v_k >= rho v_j for every j. Then rho(A) >= rho (Collatz-Wielandt) and
/// h_top(T) >= ln rho on the compact invariant set of orbits that stay in the union.
long check_entropy(const json& c, std::string& what);

}  // namespace recheck
