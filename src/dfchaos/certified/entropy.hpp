// SPDX-License-Identifier: GPL-3.0-or-later
/// @file entropy.hpp
/// @brief A certified lower bound of the topological entropy of T from a covering graph (Section 7
/// beyond two symbols).
///
/// Section 7 codes the orbits that stay in \f$J_0 \cup J_1\f$ by the full 2-shift, so
/// \f$h_{top}(T) \ge \ln 2\f$. The same argument works for any finite family of pairwise disjoint
/// closed segments \f$I_1 < \dots < I_n\f$ of \f$[t_2, t_3)\f$ on each of which T is continuous:
/// write \f$j \to k\f$ when \f$T(I_j) \supseteq I_k\f$ (proved by the intermediate value theorem:
/// \f$I_k\f$ lies strictly between the enclosures of T at the two ends of \f$I_j\f$). Every path of
/// the graph is followed by an orbit (nested compact preimages), the points whose orbits stay in
/// \f$\bigcup I_j\f$ form a compact invariant set on which T is continuous, and the itinerary map
/// is a continuous semi-conjugacy onto the subshift of finite type of the graph. So
/// \f$h_{top}(T) \ge \ln \rho(A)\f$, A the 0-1 matrix of the graph, and for any vector
/// \f$v > 0\f$ (Collatz–Wielandt) \f$\rho(A) \ge \min_j (Av)_j / v_j\f$ — a bound computed here
/// exactly from double v.
///
/// The segments come from a floating-point grid (where T is continuous between samples of one
/// continuity label, the segment between the samples where T is least and largest, both above
/// \f$t_2\f$); the edges and the strongly connected part with the largest Perron root are chosen
/// in floating point, v is its Perron vector. Only the certified steps enter the bound: a segment
/// whose continuity or end values are not proved is dropped with its edges, an edge that is not
/// proved is dropped, and the bound is taken over what remains (any subgraph gives a valid bound).
#pragma once

#include <vector>

#include "dfchaos/certified/parameters.hpp"
#include "dfchaos/certified/return_map.hpp"

namespace dfchaos::certified {

/// Options of the entropy bound.
struct EntropyOptions {
  int grid = 4000;         ///< floating-point samples of T on [t2, t3)
  int max_segments = 400;  ///< segments of the graph's strongly connected part that are proved (at most)
  int max_balls = 2000;    ///< closed balls per segment (continuity cover)
  bool record = false;     ///< keep every ball's proof (the witnesses of a certificate)
};

/// One vertex of the graph: a closed segment on which T is proved continuous.
struct GraphSegment {
  double lo = 0;                ///< left end (a double)
  double hi = 0;                ///< right end
  Ball T_lo;                    ///< enclosure of T at lo
  Ball T_hi;                    ///< enclosure of T at hi
  std::vector<int> successors;  ///< indices k (in EntropyProof::segments) with T(this) containing I_k, proved
  double weight = 0;            ///< the component of the positive vector v
  // Kept when EntropyOptions::record:
  std::vector<BallProof> cover;  ///< the balls covering [lo, hi] (T continuous on each)
  BallProof at_lo;               ///< the ball {lo}: T there (scenario A/B with theta2 above t2)
  BallProof at_hi;               ///< the ball {hi}
};

/// The bound at a parameter point.
struct EntropyProof {
  Outcome verdict;                     ///< proved: rho_lower > 1 is a lower bound of rho(A)
  double a = 1;                        ///< the parameter point: a
  double b = 0;                        ///< b
  double q = 0;                        ///< q
  std::vector<GraphSegment> segments;  ///< ascending, disjoint, each with its proved successors
  double rho_lower = 0;                ///< a double r with sum_{k in succ(j)} v_k >= r v_j for every j, proved exactly
  Ball log_rho_lower;                  ///< enclosure of ln(rho_lower): h_top(T) is at least its lower end
  double rho_float = 0;                ///< floating Perron root of the chosen part (before the proofs)
  int candidates = 0;                  ///< segments proposed by the grid
  bool used_lemma1 = false;            ///< some ball needed Lemma 1 (then `lemma1` is proved)
  Lemma1Proof lemma1;                  ///< Lemma 1 at the point, when some ball needed it and record
};

/// The entropy bound of the file comment at the point (a, b, q).
EntropyProof prove_entropy_bound(double a, double b, double q, const EntropyOptions& opt = {});

}  // namespace dfchaos::certified
