// SPDX-License-Identifier: GPL-3.0-or-later
/// @file covering.hpp
/// @brief Certified covering segments: Lemma 4 (Eq. 18) and the covering part of Theorem 1, at a
/// parameter point or for every parameter of a box.
///
/// A closed segment \f$J = [lo, hi] \subset [t_2, 3\pi/2]\f$ is a **certified covering segment** when
///  - T is continuous on J: J is covered by finitely many closed balls on each of which
///    certify_T() proves continuity (return_map.hpp), so T is continuous on J (pasting lemma);
///  - at one end, \f$T = t_2\f$ exactly (the chain proved to stop before \f$t_2\f$);
///  - at the other end, the enclosure of T is \f$\ge 3\pi/2\f$.
/// Then \f$T(J) \supseteq [t_2, 3\pi/2]\f$ by the intermediate value theorem. Two such segments that are
/// disjoint (compared as doubles) prove Lemma 4 at the parameters, or, over a box, for every
/// parameter in it (the same J for all of them).
///
/// Candidates come from the floating-point search (candidates.hpp), only to know where to look.
/// Nothing of the floating search enters the proof.
#pragma once

#include <string>
#include <vector>

#include "dfchaos/certified/candidates.hpp"
#include "dfchaos/certified/parameters.hpp"
#include "dfchaos/certified/return_map.hpp"

namespace dfchaos::certified {

/// Options of the covering proofs (and of the search of their candidates, candidates.hpp).
struct CoveringOptions : CandidateOptions {
  int max_balls = 20000;       ///< closed balls per segment
  int max_depth = 30;          ///< bisection depth of a segment (theta, b and q splits together)
  int end_depth = 6;           ///< bisection depth (b and q) of the checks at the two ends
  long max_tests = 4'000'000;  ///< interval tests per segment
  /// Keep every ball's proof (SegmentProof::top_balls, t2_balls, cover_balls) and Lemma 1 over the
  /// box when a ball used it (CoveringProof::lemma1): the witnesses of a certificate.
  bool record = false;
};

/// The proof of one covering segment.
struct SegmentProof {
  Outcome verdict;           ///< proved: T continuous on J, T = t2 at theta_t2, T >= 3pi/2 at theta_top
  double lo = 0;             ///< left end of J
  double hi = 0;             ///< right end of J
  double theta_top = 0;      ///< the end with \f$T \ge 3\pi/2\f$
  double theta_t2 = 0;       ///< the end with \f$T = t_2\f$
  Ball T_top;                ///< enclosure of T at theta_top (over the box)
  Ball theta2_t2end;         ///< enclosure of the phase of \f$\theta_2\f$ at theta_t2
  int balls = 0;             ///< closed balls of the cover of J
  int depth = 0;             ///< deepest bisection
  double min_width = 0;      ///< narrowest ball
  long tests = 0;            ///< interval tests
  bool used_lemma1 = false;  ///< some ball needed Lemma 1 (T = t2 through scenario C)
  // Kept when CoveringOptions::record:
  std::vector<BallProof> top_balls;    ///< the balls at theta_top (T >= 3pi/2 on each)
  std::vector<BallProof> t2_balls;     ///< the balls at theta_t2 (T = t2 on each)
  std::vector<BallProof> cover_balls;  ///< the balls covering J (T continuous on each)
};

/// Proves that `c` is a covering segment for every parameter of the model's box.
SegmentProof prove_segment(const ParameterBalls& m, const Candidate& c, const CoveringOptions& opt = {});

/// Lemma 4 at a point or over a box: two disjoint certified covering segments.
struct CoveringProof {
  Outcome verdict;           ///< proved: J0, J1 disjoint, both certified covering segments
  ParameterBox box;          ///< the parameters
  SegmentProof J0;           ///< the left segment
  SegmentProof J1;           ///< the right segment (J0.hi < J1.lo)
  int candidates_tried = 0;  ///< candidates examined
  double seconds = 0;        ///< wall time of the whole proof
  /// (CoveringOptions::record, proved, and some ball needed Lemma 1) Lemma 1 over the whole box, for
  /// the certificate; not proved otherwise.
  Lemma1Proof lemma1;
};

/// Lemma 4 over `box`, with candidates from the floating layer at the box's centre.
CoveringProof prove_covering(const ParameterBox& box, const CoveringOptions& opt = {});

/// Lemma 4 over `box` with given candidates (tried in order until two disjoint ones are proved).
CoveringProof prove_covering(const ParameterBox& box, const std::vector<Candidate>& candidates, const CoveringOptions& opt = {});

}  // namespace dfchaos::certified
