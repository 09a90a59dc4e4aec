/// @file cell.hpp
/// @brief One cell of a sweep: its observables, computed and formatted as one row of the output.
#pragma once

#include <cmath>
#include <string>

#include "dfchaos/covering.hpp"
#include "dfchaos/parameters.hpp"
#include "sweep/spec.hpp"

namespace dfchaos::sweep {

/// The chaos witness of Theorem 1 at one point of the plane: the covering of Lemma 4, searched
/// branch by branch (CoveringSearch::branchwise) within a budget of `max_branches` branches of
/// \f$T_1\f$. The rule of the `covering` column of a sweep and of experiments/thm1_parameter_plane.
/// @throws as lemma4_covering (InvalidParameter, GaveUp when the budget is exceeded).
Lemma4Covering plane_covering(const Parameters& p, long long max_branches = kDefaultMaxCoveringBranches,
                              CoveringSearchStats* stats = nullptr);

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

/// The status of a cell.
enum class CellStatus {
  Ok,            ///< every observable computed
  Inadmissible,  ///< q/a <= 2 b/a: the return map is not defined (Parameters::require_return_map)
  Error          ///< an observable threw (e.g. GaveUp: the orbit met eternal stick-slip)
};

/// The observables of one cell (NaN where not computed).
struct CellValues {
  long long index = 0;      ///< the cell
  double q_over_a = 0;      ///< its q/a
  double b_over_a = 0;      ///< its b/a
  CellStatus status = CellStatus::Ok;  ///< ok, inadmissible or error
  double covering = NAN;    ///< plane_covering(p).holds as 0/1
  double superstable = NAN; ///< plane_superstable(p, scan).superstable as 0/1
  double epsilon = NAN;     ///< plane_superstable(p, scan).epsilon
  double lyapunov = NAN;    ///< orbit_statistics: Lyapunov exponent (-inf when a step stops)
  double rate = NAN;        ///< orbit_statistics: penetration rate
  double period = NAN;      ///< the period of the cycle at the orbit's end, 0 if none (see Spec)
  /// With lyapunov or rate: the image of the orbit's last step with a stop (orbit_statistics'
  /// last_stop_image), NaN if none. Not a column of the output.
  double stop_image = NAN;
  std::string error;        ///< "observable: message" of each observable that threw, joined by "; "
};

/// Computes the observables of cell `index` of `spec`. Never throws for a failure of the cell:
/// each group (covering; superstable; the orbit behind lyapunov, rate and period) that throws is
/// recorded in `error` and its values stay NaN; the others are kept. Running out of memory is not
/// a failure of the cell (another run, with more memory, would answer): std::bad_alloc passes.
CellValues evaluate_cell(const Spec& spec, long long index);

/// The row of a cell: the spec's columns, tab-separated, numbers in %.17g, ending in '\n'.
std::string format_row(const Spec& spec, const CellValues& v);

/// The name of a status as written in the status column.
const char* status_name(CellStatus s);

}  // namespace dfchaos::sweep
