// SPDX-License-Identifier: GPL-3.0-or-later
/// @file cell.hpp
/// @brief One cell of a sweep: its observables, computed and formatted as one row of the output.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "dfchaos/certified/rectangle.hpp"
#include "dfchaos/covering.hpp"
#include "dfchaos/parameters.hpp"
#include "sweep/spec.hpp"

namespace dfchaos::sweep {

/// The chaos witness of Theorem 1 at one point of the plane: the covering of Lemma 4, searched
/// branch by branch (CoveringSearch::branchwise) within a budget of `max_branches` branches of
/// \f$T_1\f$. The rule of the `covering` column of a sweep and of experiments/thm1_parameter_plane.
/// @throws as lemma4_covering (InvalidParameter, GaveUp when the budget is exceeded).
Lemma4Covering plane_covering(const Parameters& p, long long max_branches = kDefaultMaxCoveringBranches, CoveringSearchStats* stats = nullptr);

/// Theorem 2 at one point of the plane: \f$t_2\f$ is superstable when \f$T(t_2) = t_2\f$ and
/// \f$T = t_2\f$ on an arc \f$[t_2, t_2 + \varepsilon)\f$ with \f$\varepsilon > 0\f$ (superstable_check
/// with a scan of `scan` steps).
struct PlaneSuperstable {
  bool superstable = false;  ///< \f$T(t_2) = t_2\f$ and \f$\varepsilon > 0\f$
  double epsilon = 0;        ///< superstable_check's \f$\varepsilon\f$ (0 unless \f$T(t_2) = t_2\f$)
};
/// The rule of the `superstable` and `epsilon` columns of a sweep and of
/// experiments/thm1_parameter_plane. @throws as superstable_check.
PlaneSuperstable plane_superstable(const Parameters& p, int scan = 400);

/// The step of certified::prove_covering that was not proved, as the code written in the
/// `certified_step` column (0 when the covering is proved). The codes follow the order of the
/// proof: admissibility of the parameters, the floating-point candidates, then, for a candidate
/// segment J, its place, its two ends and the continuity of T on it. When several candidates fail,
/// it is the step of the last one tried (prove_covering's verdict). "Not proved" is never "false".
enum class CertifiedStep {
  Proved = 0,         ///< nothing failed: two disjoint covering segments proved
  Admissibility = 1,  ///< "admissibility": 2b < a, q > 2b or q - 2b < a not proved in ball arithmetic
  Candidates = 2,     ///< "covering: candidates": fewer than two disjoint candidate segments to prove
  Inside = 3,         ///< "covering: J inside [t2, 3pi/2]": a candidate not proved inside the arc
  TopEnd = 4,         ///< "covering: T >= 3pi/2 at the top end"
  T2End = 5,          ///< "covering: T = t2 at the t2 end"
  Continuity = 6      ///< "covering: continuity on J"
};

/// Every CertifiedStep, in code order.
inline constexpr CertifiedStep kAllCertifiedSteps[] = {CertifiedStep::Proved,    CertifiedStep::Admissibility, CertifiedStep::Candidates,
                                                       CertifiedStep::Inside,    CertifiedStep::TopEnd,        CertifiedStep::T2End,
                                                       CertifiedStep::Continuity};

/// The step's name exactly as prove_covering's Outcome::step spells it ("proved" for Proved).
const char* certified_step_name(CertifiedStep s);

/// The code of the step named `step` by prove_covering's verdict; none for a name without a code.
std::optional<CertifiedStep> certified_step_of(const std::string& step);

/// The legend of the codes, "0 proved | 1 admissibility | 2 covering: candidates | ...", as written in
/// the header and the help.
std::string certified_step_legend();

/// Lemma 4 proved at one point of the plane (the `certified` and `certified_step` columns).
struct PlaneCertified {
  bool proved = false;                         ///< prove_covering's verdict
  CertifiedStep step = CertifiedStep::Proved;  ///< the step not proved (Proved when proved)
};

/// The rule of the `certified` and `certified_step` columns: certified::prove_covering at the point
/// (a, b, q) of `p`, with its default options (as `dfchaos certify covering --a A --b B --q Q`)
/// except CoveringOptions::max_branches (of its CandidateOptions) = max_branches / kDenseCostFactor (the budget of the
/// covering column's Dense fallback): its candidates come from a Dense search in a window above
/// \f$t_2\f$ that grows up to that many branches of \f$T_1\f$ (beyond it the cell is not proved, step
/// "covering: candidates"). Its work is bounded by counts only (branches, interval tests, balls,
/// candidates), never by time, so the answer is deterministic.
/// @throws std::logic_error when the verdict names a step without a code (a newer certified layer:
/// the cell is then an error cell, not a wrong code).
PlaneCertified plane_certified(const Parameters& p, long long max_branches = kDefaultMaxCoveringBranches);

/// The legend of the `region_stop` codes (certified::RectangleStop), "0 decided to the top | 1 ... | 2 ...",
/// as written in the header.
std::string region_stop_legend();
/// Theorem 1 over the rectangle of a cell (the `region` columns).
struct PlaneRegion {
  double proved_fraction = 0;                                         ///< proved part of the rectangle's b-length
  double uniform_bound = 0;                                           ///< b/a bound of the uniform proof for its q/a range, 0 when none
  long boxes = 0;                                                     ///< box proofs attempted above that bound
  certified::RectangleStop stop = certified::RectangleStop::Decided;  ///< why it was not decided to its top
};
/// The rule of the `region` columns: certified::prove_rectangle over the cell's rectangle of ratios
/// (Range::extent of its q/a and b/a, at a = 1: only the ratios matter, and they are then exact), with the uniform proof of
/// certified::best_lemma4_uniform for its q/a range (computed once per q/a range and process: a
/// pure function of the range) and at most `max_boxes` box proofs.
/// @throws std::invalid_argument for a rectangle of zero width in b (Spec::validate refuses those axes).
PlaneRegion plane_region(const Spec& spec, long long index, long max_boxes);
/// The entropy of T bounded from both sides at one point (the `entropy` columns).
struct PlaneEntropy {
  double lower = 0;    ///< the proved lower bound of h_top(T) (0 when none above ln 1)
  double upper = NAN;  ///< the proved upper bound (NaN when the laps were not proved)
  double laps = 0;     ///< the laps of T (0 when not proved)
};
/// The rule of the `entropy` columns: certified::prove_entropy_bracket(1, b/a, q/a) with its default
/// options (at a = 1: only the ratios matter). Bounded by counts only, never by time: deterministic.
PlaneEntropy plane_entropy(double q_over_a, double b_over_a);
/// The orbit observables at one parameter set: `lyapunov`, `rate` and `period` of a sweep's cell,
/// from the phase theta0 (a sweep's cell starts at orbit_start(p, OrbitSettings::theta0_fraction)).
struct PlaneOrbit {
  double lyapunov = NAN;    ///< orbit_statistics' Lyapunov exponent (-inf when a step stops); NaN unless asked
  double rate = NAN;        ///< orbit_statistics' penetration rate; NaN unless asked
  double period = NAN;      ///< the period of the cycle at the orbit's end (Spec), 0 if none; NaN unless asked
  double stop_image = NAN;  ///< orbit_statistics' last_stop_image when the statistics were computed
};

/// The phase \f$\theta_0 = t_2 + f\,(t_3 - t_2)\f$ at which a sweep's orbit starts.
/// @throws InvalidParameter unless \f$t_2, t_3\f$ exist (b < a/2).
double orbit_start(const Parameters& p, double fraction);

/// The rule of the `lyapunov`, `rate` and `period` columns of a sweep, at one parameter set and from
/// the phase `theta0`: `orbit.transient` steps of T discarded, `orbit.steps` averaged
/// (orbit_statistics, when `statistics`); with `period`, the smallest k <= period.max with
/// \f$|T^k(e) - e| \le\f$ period.tol on the circle, \f$e = T^{\,transient + steps}(\theta_0)\f$, 0 if
/// none. `orbit.theta0_fraction` is not read. The settings are not checked here (Spec::validate,
/// OrbitSettings::validate and PeriodSettings::validate check them).
/// @throws as orbit_statistics and T_power (InvalidParameter, GaveUp).
PlaneOrbit plane_orbit(const Parameters& p, double theta0, const OrbitSettings& orbit, const PeriodSettings& period, bool statistics,
                       bool with_period);

/// The status of a cell.
enum class CellStatus {
  Ok,            ///< every observable computed
  Inadmissible,  ///< q/a <= 2 b/a: the return map is not defined (Parameters::require_return_map)
  Error          ///< an observable threw (e.g. GaveUp: the orbit met eternal stick-slip)
};

/// The observables of one cell (NaN where not computed).
struct CellValues {
  long long index = 0;                 ///< the cell
  double q_over_a = 0;                 ///< its q/a
  double b_over_a = 0;                 ///< its b/a
  CellStatus status = CellStatus::Ok;  ///< ok, inadmissible or error
  double covering = NAN;               ///< plane_covering(p).holds as 0/1
  double superstable = NAN;            ///< plane_superstable(p, scan).superstable as 0/1
  double epsilon = NAN;                ///< plane_superstable(p, scan).epsilon
  double lyapunov = NAN;               ///< orbit_statistics: Lyapunov exponent (-inf when a step stops)
  double rate = NAN;                   ///< orbit_statistics: penetration rate
  double period = NAN;                 ///< the period of the cycle at the orbit's end, 0 if none (see Spec)
  double certified = NAN;              ///< plane_certified(p).proved as 0/1
  double certified_step = NAN;         ///< plane_certified(p).step as its code (0 when proved)
  double region = NAN;                 ///< plane_region(spec, index).proved_fraction
  double region_uniform = NAN;         ///< plane_region(spec, index).uniform_bound
  double region_boxes = NAN;           ///< plane_region(spec, index).boxes
  double region_stop = NAN;            ///< plane_region(spec, index).stop as its code
  double entropy_lower = NAN;          ///< plane_entropy(p).lower
  double entropy_upper = NAN;          ///< plane_entropy(p).upper
  double entropy_laps = NAN;           ///< plane_entropy(p).laps
  /// With lyapunov or rate: the image of the orbit's last step with a stop (orbit_statistics'
  /// last_stop_image), NaN if none. Not a column of the output.
  double stop_image = NAN;
  std::string error;  ///< "observable: message" of each observable that threw, joined by "; "
};

/// Computes the observables of cell `index` of `spec`. Never throws for a failure of the cell:
/// each group (covering; superstable; the orbit behind lyapunov, rate and period; certified; region; entropy) that throws is
/// recorded in `error` and its values stay NaN; the others are kept. Running out of memory is not
/// a failure of the cell (another run, with more memory, would answer): std::bad_alloc passes.
CellValues evaluate_cell(const Spec& spec, long long index);

/// The text of the `error` column of a cell: its error with tabs and line breaks made spaces, "-"
/// when it has none.
std::string error_field(const CellValues& v);

/// The values of the columns of a cell between status and error, in the order of Spec::columns():
/// the observables' (rate times omega with --physical), then with --physical friction_N and static_N.
/// What a row holds and the Python module returns.
std::vector<double> observable_values(const Spec& spec, const CellValues& v);
/// The row of a cell: the spec's columns, tab-separated, numbers in %.17g, ending in '\n'.
std::string format_row(const Spec& spec, const CellValues& v);

/// The name of a status as written in the status column.
const char* status_name(CellStatus s);

}  // namespace dfchaos::sweep
