// SPDX-License-Identifier: GPL-3.0-or-later
/// @file candidates.hpp
/// @brief The floating-point search of candidate covering segments for Lemma 4's proofs
/// (covering.hpp): where to look, never part of a proof.
///
/// Like oracle.hpp, this is the floating layer used as an oracle. Candidates come from the floating
/// search of covering segments (dfchaos::covering_segments); their ends are moved inside their
/// continuity label to where the proofs have margin (T about \f$3\pi/2 + 0.3\f$ at the top end; at
/// the other end, the middle of the plateau where \f$T = t_2\f$, between the phase where
/// \f$\theta_2\f$ crosses \f$t_2\f$ and the end of the branch of \f$T_1\f$). Every candidate is
/// then proved or refused by the certified layer.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace dfchaos::certified {

/// Options of the candidate search.
struct CandidateOptions {
  double margin_top = 0.3;  ///< target T at the top end: \f$3\pi/2 + \f$ this
  int candidates = 6;       ///< floating-point candidates examined (at most)
  /// Branches of \f$T_1\f$ in the first window [lo, w] of the candidate search (covering_candidates).
  long long first_branches = 1LL << 14;
  /// The candidate search stops at a window of this many branches, with the candidates it found.
  long long max_branches = 1LL << 16;
  double lo = 0.0 / 0.0;  ///< search window for candidates (NaN: \f$t_2\f$)
  double hi = 0.0 / 0.0;  ///< (NaN: \f$3\pi/2\f$)
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
std::vector<Candidate> covering_candidates(double a, double b, double q, const CandidateOptions& opt = {});

/// The candidates at (a, b, q), as covering_candidates() finds them, handed one by one to `take`
/// until it returns true (enough) or the search ends. The search looks near lo first: a window
/// [lo, w] holding opt.first_branches branches of T1 (closed form), grown fourfold until it yields
/// opt.candidates segments, becomes [lo, hi], or holds opt.max_branches. The cost follows the
/// branches visited, not the (a/b)/(2 pi) branches of [t2, 3 pi/2]. Segments are re-checked on 32
/// points only: the proof decides, not the search. Returns how far the search looked when it
/// stopped short of hi (empty when it searched [lo, hi]). The floating layer's exceptions end the
/// search (no more candidates); those of `take` pass.
std::string for_each_candidate(double a, double b, double q, const CandidateOptions& opt, const std::function<bool(const Candidate&)>& take);

/// The candidates `old` (of nearby parameters) moved to (a, b, q) by local floating searches: the t2
/// end to the middle of its plateau, the top end re-aimed if T there lost its margin. Candidates
/// that cannot be followed are dropped; empty when fewer than two remain (then search afresh with
/// covering_candidates()).
std::vector<Candidate> track_candidates(double a, double b, double q, const std::vector<Candidate>& old, const CandidateOptions& opt = {});

}  // namespace dfchaos::certified
