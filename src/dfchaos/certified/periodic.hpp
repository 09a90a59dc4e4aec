// SPDX-License-Identifier: GPL-3.0-or-later
/// @file periodic.hpp
/// @brief Sections 6 and 7 from a certified covering: periodic points of every minimal period, an
/// explicit enclosure of one orbit per period by the Krawczyk operator, and the entropy bound.
///
/// **Existence (Section 6).** Let \f$J_0, J_1 \subset [t_2, 3\pi/2]\f$ be disjoint closed segments with T
/// continuous on each and \f$T(J_i) \supseteq [t_2, 3\pi/2] \supseteq J_0 \cup J_1\f$ — exactly what
/// prove_covering() certifies. For the word \f$w = 0^{m-1}1\f$ the nested segments
/// \f$J_{w_0} \supset J_{w_0w_1} \supset \dots\f$ give a closed \f$I \subset J_0\f$ (or \f$J_1\f$ if m = 1) with
/// \f$T^m\f$ continuous on I and \f$T^m(I) \supseteq I\f$, hence a fixed point of \f$T^m\f$ in I whose orbit
/// follows \f$(0^{m-1}1)^\infty\f$; J0 and J1 being disjoint, its minimal period is m. The same
/// hypotheses give a compact invariant \f$\Lambda \subset J_0 \cup J_1\f$ with a continuous
/// surjection \f$H: \Lambda \to \Sigma_2\f$, \f$H \circ T = S \circ H\f$ (Section 7), so
/// \f$h_{top}(T|_\Lambda) \ge h_{top}(S) = \ln 2\f$. These are theorems applied to certified
/// hypotheses; no further computation is involved.
///
/// **Enclosure.** For \f$F_j(x) = T(x_j) - x_{j+1 \bmod m}\f$ on boxes \f$X_j \ni \hat x_j\f$ where T is
/// proved smooth (scenario A, certify_T) with \f$T'\f$ enclosed (derivative_T), the Krawczyk operator
/// \f$K = \hat x - C F(\hat x) + (I - C\,DF(X))(X - \hat x)\f$, \f$C \approx DF(\hat x)^{-1}\f$, inside the
/// interior of X proves a unique zero of F in X. With \f$X_j \subset J_{w_j}\f$ this is the periodic
/// orbit of itinerary \f$w^\infty\f$, enclosed to about \f$10^{-20}\f$.
///
/// **The certificate's form** (PeriodicOptions::record). A checker without matrices can verify the
/// same enclosure by covering relations: T continuous on each \f$X_j = [l_j, h_j]\f$ with \f$T(l_j)\f$
/// and \f$T(h_j)\f$ on opposite sides outside \f$X_{j+1}\f$ gives \f$T(X_j) \supseteq X_{j+1}\f$, and a
/// cycle of such relations holds a point with \f$T^j x \in X_j\f$, \f$T^m x = x\f$ (intermediate values,
/// going back along the cycle). As \f$|T'| \gg 1\f$ on these orbits, the Krawczyk boxes satisfy it; the
/// prover checks the relations on the recorded brackets before recording.
#pragma once

#include <string>
#include <vector>

#include "dfchaos/certified/covering.hpp"
#include "dfchaos/certified/return_map.hpp"
#include "dfchaos/continuation.hpp"

namespace dfchaos::certified {

/// Options of prove_periodic().
struct PeriodicOptions {
  double radius = 1e-22;  ///< half-width of the Krawczyk boxes \f$X_j\f$ (relative to 1)
  int newton_steps = 6;   ///< Newton refinements of the orbit before the Krawczyk test
  bool record = false;    ///< keep the witnesses of the covering relations (for a certificate)
};

/// The witnesses of one box \f$X_j = [lo, hi]\f$ of an orbit (PeriodicOptions::record): T on the box and
/// at its two ends, each in scenario A with a \f$\theta_2\f$ bracket, the ends mapped to opposite sides
/// outside \f$X_{j+1}\f$ (checked on those brackets).
struct OrbitBoxProof {
  Ball lo;          ///< the lower end of \f$X_j\f$ (exact)
  Ball hi;          ///< the upper end of \f$X_j\f$ (exact)
  BallProof on;     ///< T on \f$[lo, hi]\f$ (continuous)
  BallProof at_lo;  ///< T at lo
  BallProof at_hi;  ///< T at hi
};

/// A periodic orbit of T with itinerary \f$(\text{word})^\infty\f$ (\f$0^{m-1}1\f$ unless another word is given).
struct PeriodicProof {
  Outcome verdict;                   ///< proved: Krawczyk encloses a unique orbit in the boxes, each inside its J
  bool existence = false;            ///< the Section 6 argument applies (the covering is certified)
  int period = 0;                    ///< m
  std::string word;                  ///< one period of the itinerary, e.g. "0001"
  std::vector<Ball> orbit;           ///< the boxes \f$X_0, \dots, X_{m-1}\f$ (each with the unique orbit point)
  Ball log_multiplier;               ///< \f$\ln|(T^m)'| = \sum_j \ln|T'(x_j)|\f$ over the boxes
  std::vector<OrbitBoxProof> boxes;  ///< with PeriodicOptions::record: the covering relations, one per box
  std::string unrecorded;            ///< why `boxes` is empty although recorded (a relation not shown)
  double seconds = 0;                ///< wall time
};

/// Periodic orbit of minimal period m = `period` (1 <= m <= 64), itinerary \f$(0^{m-1}1)^\infty\f$, from
/// the proved covering `cov`.
PeriodicProof prove_periodic(const CoveringProof& cov, int period, const PeriodicOptions& opt = {});

/// The periodic orbit with itinerary \f$(\text{word})^\infty\f$ for any primitive word over {0, 1} of
/// 1 to 64 letters (symbolic.hpp, is_primitive_word): the same existence argument (nested segments
/// of J0, J1 along the word) and the same enclosure; its least period is the word's length, since J0
/// and J1 are disjoint and the word is no power of a shorter one. Another word fails the proof, naming it.
PeriodicProof prove_periodic(const CoveringProof& cov, const std::string& word, const PeriodicOptions& opt = {});

/// A cycle of T for every b of an interval (a, q fixed): the cycle that continuation.hpp follows in
/// floating point, proved to exist over one of its steps.
struct CycleIntervalProof {
  Outcome verdict;                   ///< proved: for every b in [b_lo, b_hi], a point x with \f$T^j x \in X_j\f$, \f$T^m x = x\f$
  std::vector<Ball> X;               ///< the boxes \f$X_0, \dots, X_{m-1}\f$ (the same for every b of the interval)
  double radius = 0;                 ///< how far each \f$X_j\f$ reaches beyond the two floating points
  std::vector<OrbitBoxProof> boxes;  ///< the covering relations over the parameter box (witnesses)
  int pieces = 0;                    ///< the pieces of b proved (X, radius, boxes: those of the first piece)
};

/// prove_cycle_on_interval() halves an interval of b at most this many times (up to 32 pieces).
inline constexpr int kCyclePieceDepth = 5;

/// Proves a cycle for every b in [b_lo, b_hi] by the covering relations of the file comment over the
/// parameter box \f$\{a\} \times [b_{lo}, b_{hi}] \times \{q\}\f$: T continuous (scenario A) on each
/// \f$X_j\f$ and its ends mapped to opposite sides outside \f$X_{j+1}\f$, for every b at once. \f$X_j\f$ is
/// the hull of x_lo[j] and x_hi[j] (the floating cycles at the two ends) widened by a radius r, from
/// \f$r = 0.01\max_j|x^{hi}_j - x^{lo}_j| + 10^{-13}\f$, grown x4 up to 5 times until the relations hold
/// (where \f$|T'| \gg 1\f$ a small r suffices, and a large one would reach the next break of T). Where
/// that fails the interval is halved (at most kCyclePieceDepth times), the cycle at a cut taken halfway
/// between the two given ones: each piece is proved on its own, the radius covering how far the true
/// cycle is from that guess (a guess only chooses the boxes; the proof does not rest on it).
CycleIntervalProof prove_cycle_on_interval(double a, double q, double b_lo, double b_hi, const std::vector<double>& x_lo,
                                           const std::vector<double>& x_hi);

/// prove_cycle_on_interval() over every step of a followed orbit (continuation.hpp): entry k is 1 if
/// the cycle exists for every b between points k - 1 and k of `branch`, 0 if that is not proved, -1
/// for k = 0 (no interval).
std::vector<int> prove_branch_steps(double a, double q, const OrbitBranch& branch);

}  // namespace dfchaos::certified
