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
/// Candidates come from the floating-point search (dfchaos::covering_segments), only to know where
/// to look; their ends are moved inside their continuity label to where the proofs have margin
/// (T about \f$3\pi/2 + 0.3\f$ at the top end; at the other end, the middle of the plateau where
/// \f$T = t_2\f$, between the phase where \f$\theta_2\f$ crosses \f$t_2\f$ and the end of the branch of
/// \f$T_1\f$). Nothing of the floating search enters the proof.
#pragma once

#include <string>
#include <vector>

#include "dfchaos/certified/parameters.hpp"
#include "dfchaos/certified/return_map.hpp"

namespace dfchaos::certified {

/// Options of the covering proofs.
struct CoveringOptions {
  double margin_top = 0.3;     ///< target T at the top end: \f$3\pi/2 + \f$ this
  int max_balls = 20000;       ///< closed balls per segment
  int max_depth = 30;          ///< bisection depth of a segment (theta, b and q splits together)
  int end_depth = 6;           ///< bisection depth (b and q) of the checks at the two ends
  long max_tests = 4'000'000;  ///< interval tests per segment
  int candidates = 6;          ///< floating-point candidates examined (at most)
  /// Branches of \f$T_1\f$ in the first window [lo, w] of the candidate search (covering_candidates).
  long long first_branches = 1LL << 14;
  /// The candidate search stops at a window of this many branches, with the candidates it found.
  long long max_branches = 1LL << 16;
  double lo = 0.0 / 0.0;  ///< search window for candidates (NaN: \f$t_2\f$)
  double hi = 0.0 / 0.0;  ///< (NaN: \f$3\pi/2\f$)
  /// Keep every ball's proof (SegmentProof::top_balls, t2_balls, cover_balls) and Lemma 1 over the
  /// box when a ball used it (CoveringProof::lemma1): the witnesses of a certificate.
  bool record = false;
};

/// A candidate segment from the floating layer.
struct Candidate {
  double theta_top = 0;  ///< end where T should be at least \f$3\pi/2\f$
  double theta_t2 = 0;   ///< end where T should be \f$t_2\f$
  double plateau = 0;    ///< width of the plateau T = t2 around theta_t2 when it was centred (0: unknown)
  double lo() const { return theta_top < theta_t2 ? theta_top : theta_t2; }  ///< left end
  double hi() const { return theta_top < theta_t2 ? theta_t2 : theta_top; }  ///< right end
};

/// Floating-point candidates at (a, b, q), ends moved as in the file comment, ascending, disjoint.
std::vector<Candidate> covering_candidates(double a, double b, double q, const CoveringOptions& opt = {});

/// The candidates `old` (of nearby parameters) moved to (a, b, q) by local floating searches: the t2
/// end to the middle of its plateau, the top end re-aimed if T there lost its margin. Candidates
/// that cannot be followed are dropped; empty when fewer than two remain (then search afresh with
/// covering_candidates()).
std::vector<Candidate> track_candidates(double a, double b, double q, const std::vector<Candidate>& old, const CoveringOptions& opt = {});

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
