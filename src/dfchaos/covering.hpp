// SPDX-License-Identifier: GPL-3.0-or-later
/// @file covering.hpp
/// @brief Continuity branches of \f$T\f$ and covering segments: Lemma 4 (Eq. 18).
///
/// **Where T can jump.** On a continuity branch of \f$T_1\f$ (between consecutive grazing points),
/// the end \f$\theta_2\f$ of the first progression moves continuously, except where the
/// progression velocity touches 0 at phase \f$t_0\f$ — and there \f$T = t_2\f$ on both sides while
/// Lemma 1 holds. \f$T = \theta_2 \bmod 2\pi\f$ while that phase is in \f$[t_2, t_3)\f$ (scenario A)
/// and \f$T = t_2\f$ in scenarios B and C, which join continuously at \f$\theta_2 \equiv t_2\f$. So
/// \f$T\f$ jumps only (i) at a discontinuity of \f$T_1\f$, (ii) where \f$\theta_2\f$'s phase crosses
/// \f$t_3\f$ (A against a stop), and (iii) between scenario D, where \f$T\f$ is the constant end phase
/// of the progression from \f$t_0\f$, and the rest. The ContinuityLabel changes at each of these:
/// it is (\f$T_1\f$ branch, number of phases \f$t_3\f$ passed before \f$\theta_2\f$, D or not).
///
/// **Covering segments.** A closed segment \f$J\f$ on which \f$T\f$ is continuous and which holds a
/// point with \f$T = t_2\f$ and a point with \f$T \ge 3\pi/2\f$ satisfies \f$T(J) \supseteq [t_2, 3\pi/2]\f$
/// (intermediate values; \f$T \ge t_2\f$ everywhere). They are searched for among grid points of
/// one label run — a fixed number of points in each continuity branch of \f$T_1\f$, whose ends are
/// known in closed form — and each one found is re-checked on a finer grid inside it. Arcs where
/// \f$T = t_2\f$ can be much narrower than the grid step, and \f$T\f$ often plunges onto one just
/// before its label changes; a run that reaches \f$3\pi/2\f$ without a sample at \f$t_2\f$ therefore
/// has the gaps at its two ends searched by a golden-section descent of \f$T\f$.
#pragma once

#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

/// Label of the continuity branch of \f$T\f$ containing \f$\theta\f$ (see the file comment).
struct ContinuityLabel {
  long long t1_branch = 0;  ///< NextHit::maxima_before
  long long t3_passed = 0;  ///< \f$\lfloor(\theta_2 - t_3)/2\pi\rfloor\f$, turns counted from \f$\theta\f$
  bool scenario_d = false;  ///< scenario D or D' (T is the constant end of the progression from t0)
  /// Two phases lie on the same continuity branch of \f$T\f$ only if their labels are equal.
  friend bool operator==(const ContinuityLabel&, const ContinuityLabel&) = default;
};

/// The label together with the map step it was computed from.
struct LabelledStep {
  MapStep step;           ///< one step of \f$T\f$ from \f$\theta\f$
  ContinuityLabel label;  ///< the continuity label of that step
};

/// The continuity label at \f$\theta\f$.
LabelledStep continuity_label(const Parameters& p, double theta);

/// A closed segment on which \f$T\f$ is continuous and whose image contains \f$[t_2, \text{top}]\f$.
struct CoveringSegment {
  double lo = 0;            ///< left end of the segment
  double hi = 0;            ///< right end of the segment
  double theta_at_t2 = 0;   ///< an end where \f$T = t_2\f$
  double theta_at_top = 0;  ///< an end where \f$T \ge\f$ top
  double T_at_top = 0;      ///< \f$T\f$ at theta_at_top (at least top)
  ContinuityLabel label;    ///< the continuity label shared by the whole segment
  bool rechecked = false;   ///< labels constant, and no T-jump on the fine grid inside
};

/// How covering_segments looks for covering segments.
enum class CoveringMethod {
  /// Samples every continuity branch of \f$T_1\f$ densely (at least CoveringSearch::scan points,
  /// and the density of CoveringSearch::uniform), with local refinement and descents: thousands
  /// of evaluations of \f$T\f$. The reference search; its segments feed Sections 6, 7, 10 and the
  /// certified layer.
  Dense,
  /// Uses what is known about each branch instead of sampling it. After the first progression
  /// stops at \f$\theta_2\f$ (Eq. 17) the motion depends only on the phase of \f$\theta_2\f$, so
  /// \f$T(\theta) = g(\theta_2(\theta) \bmod 2\pi)\f$ for one function \f$g\f$ of the circle:
  /// \f$g = t_2\f$ on the stop window just below \f$t_2\f$ (scenario B, the plateaus), the identity on
  /// \f$[t_2, t_3)\f$ (scenario A), and \f$g\f$ is continuous across \f$t_2\f$. On a branch of \f$T_1\f$
  /// (ends in closed form, next_hit.hpp) \f$\theta_2\f$ is continuous and monotone (the terms of
  /// \f$d\theta_2/d\theta\f$ from Eq. 17 and Lemma 2 have one sign), so the range of
  /// \f$\psi = \theta_2 - t_2\f$ over the branch follows from its two ends, and each multiple
  /// \f$2\pi m\f$ with \f$\psi_{min} < 2\pi m\f$ and \f$\psi_{max} \ge 2\pi m + (top - t_2)\f$ marks
  /// a covering segment. Its ends are found by bisection on \f$\psi\f$ (a phase with
  /// \f$T = t_2\f$ just below \f$2\pi m\f$, one with \f$T \ge top\f$ above \f$2\pi m + top - t_2\f$)
  /// and the segment is re-checked on CoveringSearch::recheck points (one label, \f$\psi\f$ monotone,
  /// no jump of \f$T\f$). Monotonicity is checked on every branch at its ends and two inner
  /// points; a branch where it fails, or a cut that is not a discontinuity of \f$T_1\f$, sends the
  /// whole search back to Dense (counted in CoveringSearchStats::dense_fallbacks). About 100
  /// evaluations of \f$T\f$ per parameter set. Sampled evidence, like Dense.
  Branchwise
};

/// The default CoveringSearch::max_branches: 1e6 branches, reached near b/a = 1.6e-7. A branchwise
/// search that must visit every branch costs about 20 us per branch (measured: 10 s and 37 MB at
/// b/a = 3e-7, q/a = 0.3; docs/reliability.md), so at most about 20 s and 40 MB.
inline constexpr long long kDefaultMaxCoveringBranches = 1'000'000;
/// A Dense search evaluates T about this many times as often per branch as a Branchwise one
/// (CoveringSearch::scan = 48 points against 4): the Dense fallback of a Branchwise search takes
/// on at most max_branches / this.
inline constexpr long long kDenseCostFactor = 12;

/// Options of the covering search.
struct CoveringSearch {
  int scan = 48;                                  ///< at least this many grid points per continuity branch of T1
  int uniform = 8000;                             ///< and at least the density of this many points spread over [lo, hi]
  int recheck = 400;                              ///< fine-grid points inside each segment found (both methods)
  int refine = 32;                                ///< local points on each side where T comes within 5% of t2 (narrow B arcs)
  bool descend = true;                            ///< descend T into the end gaps of runs that reach the top without t2
  int max_segments = 0;                           ///< stop after this many rechecked segments (0: find all; both methods)
  CoveringMethod method = CoveringMethod::Dense;  ///< how to search (the fields above are for Dense unless noted)
  /// The work budget: most continuity branches of \f$T_1\f$ in [lo, hi] (symmetric_tangency_count
  /// + 1) that the search takes on (the Dense fallback of a Branchwise search: max_branches /
  /// kDenseCostFactor). Their number grows like \f$(a/b)/(2\pi)\f$ (about 1.6e5 at b/a = 1e-6), and
  /// so do the time and memory of the search. Beyond it covering_segments gives up (GaveUp) before
  /// any work.
  long long max_branches = kDefaultMaxCoveringBranches;
  /// The branchwise search with its re-check on 64 points (about 100 evaluations of T in all).
  static CoveringSearch branchwise() { return {.recheck = 64, .method = CoveringMethod::Branchwise}; }
};

/// Whether a Branchwise search fell back to the dense one (for measurements and tests).
struct CoveringSearchStats {
  long long dense_fallbacks = 0;  ///< searches that went back to Dense (see CoveringMethod::Branchwise)
};

/// Disjoint covering segments of \f$[t_2, \text{top}]\f$ inside \f$[lo, hi]\f$, in ascending order.
/// @throws InvalidParameter unless the map is defined and \f$t_2 \le lo < hi < t_3\f$.
/// When `stats` is given, a fallback of the Branchwise method to Dense is counted in it.
std::vector<CoveringSegment> covering_segments(const Parameters& p, double lo, double hi, double top, const CoveringSearch& search = {},
                                               CoveringSearchStats* stats = nullptr);

/// Lemma 4's conclusion at one parameter set: two disjoint closed segments of \f$[t_2, 3\pi/2]\f$,
/// each with \f$T\f$ continuous and \f$T(J_i) \supseteq [t_2, 3\pi/2]\f$.
struct Lemma4Covering {
  bool holds = false;      ///< whether two disjoint rechecked covering segments were found
  CoveringSegment J0;      ///< the leftmost rechecked segment (when holds)
  CoveringSegment J1;      ///< the next rechecked segment, disjoint from J0 (when holds)
  int segments_found = 0;  ///< rechecked segments found (at most search.max_segments if set)
};
Lemma4Covering lemma4_covering(const Parameters& p, const CoveringSearch& search = {}, CoveringSearchStats* stats = nullptr);

/// Lemma 4's covering where an experiment needs it to exist: demands assumption (2) and the
/// return map (Parameters::require_eq2, require_return_map), then searches as lemma4_covering.
/// @throws InvalidParameter naming `b` or `q` for broken assumptions, and `b` when no covering is
/// found at these parameters.
Lemma4Covering require_lemma4_covering(const Parameters& p);

}  // namespace dfchaos
