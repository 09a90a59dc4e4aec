// SPDX-License-Identifier: GPL-3.0-or-later
/// @file observables.hpp
/// @brief What a sweep computes at each cell of the (q/a, b/a) plane.
///
///  - `covering`: Lemma 4 / Theorem 1 by sampling, lemma4_covering(p, CoveringSearch::branchwise()).holds
///    (0 or 1): the branch-by-branch search, about 100 evaluations of T (covering.hpp);
///  - `superstable`: Theorem 2, superstable_check(p, scan): \f$T(t_2) = t_2\f$ with a measured
///    superstable width \f$\varepsilon > 0\f$ (0 or 1), and that width `epsilon`;
///  - `lyapunov`: \f$\frac1N\sum\ln|T'(\theta_n)|\f$ over the orbit's averaged steps (orbit_statistics;
///    -inf when a step stops; whether the orbit then lies on a superstable cycle is a further question:
///    superstable.hpp, stop_cycle);
///  - `rate`: the mean drilling speed, the delimiter's advance over the elapsed time of those steps;
///  - `period`: the period of the cycle the computed orbit closes at its end (see Spec: through a stop,
///    it may be a cycle of the rounding);
///  - `certified`: Lemma 4 / Theorem 1 *proved* in ball arithmetic (Arb) at the cell's parameters as
///    doubles, certified::prove_covering(ParameterBox::point(a, b, q)) with its default options (0 or
///    1), and `certified_step`, the code of the step that was not proved (CertifiedStep; 0 when
///    proved). Certified evidence at one point of the cell, not a proof over the cell's area. Not in
///    the default set: about 5 to 40 ms per cell.
///  - `region`: Lemma 4 / Theorem 1 proved for *every* parameter of the cell's rectangle (the cell's
///    extents on both axes, Range::extent) by certified::prove_rectangle: `region` is the proved
///    fraction of its b-length (0 to 1), `region_uniform` the b/a bound of the uniform proof for the
///    cell's q/a range (certified::best_lemma4_uniform, 0 when none), `region_boxes` the parameter
///    boxes attempted above that bound, `region_stop` why the rectangle was not decided to its top
///    (RegionStop). Not in the default set: from nothing (below the uniform bound) to some seconds
///    per cell.
///  - `entropy`: the topological entropy of T bounded from both sides, *proved* in ball arithmetic at
///    the cell's ratios (a = 1) by certified::prove_entropy_bracket with its default options
///    (certified/laps.hpp): `entropy_lower` (0 when no bound above ln 1 was proved), `entropy_upper`
///    (NaN when the laps were not proved) and `entropy_laps` (the laps of T, 0 when not proved). At
///    one point of the cell. Not in the default set: about 0.1 s (b/a = 0.01) to 25 s (b/a = 5e-5)
///    per cell, growing like a/b.
/// Their columns always come in this order, whatever the order in which they were asked for.
#pragma once

#include <string>
#include <vector>

namespace dfchaos::sweep {

/// One observable.
enum class Observable { Covering, Superstable, Lyapunov, Rate, Period, Certified, Region, Entropy };

/// All observables, in column order.
inline constexpr Observable kAllObservables[] = {Observable::Covering, Observable::Superstable, Observable::Lyapunov, Observable::Rate,
                                                 Observable::Period,   Observable::Certified,   Observable::Region,   Observable::Entropy};

/// The observables computed when none are named (`--observables` omitted): all but `certified`, `region` and `entropy`.
inline constexpr const char* kDefaultObservables = "covering,superstable,lyapunov,rate,period";

/// The name as written on the command line and in the header ("covering", ...).
const char* observable_name(Observable o);

/// Every observable's name in column order, joined by `separator` (the help and the error messages).
std::string observable_names(const char* separator);

/// A set of observables.
class ObservableSet {
 public:
  /// Parses a comma-separated list of names, e.g. "covering,period". @throws InvalidParameter
  /// naming `option` for an empty list, an empty or unknown name, or a name given twice.
  static ObservableSet parse(const std::string& option, const std::string& text);

  bool has(Observable o) const { return (bits_ >> static_cast<int>(o)) & 1U; }  ///< whether o is in the set
  /// Whether the orbit of T is needed (lyapunov, rate or period).
  bool needs_orbit() const { return has(Observable::Lyapunov) || has(Observable::Rate) || has(Observable::Period); }
  /// The canonical list, in column order, e.g. "covering,superstable".
  std::string canonical() const;
  /// The data columns of these observables, in order (superstable gives two: superstable, epsilon;
  /// certified two: certified, certified_step; region four: region, region_uniform, region_boxes,
  /// region_stop; entropy three: entropy_lower, entropy_upper, entropy_laps).
  std::vector<std::string> columns() const;

 private:
  unsigned bits_ = 0;
};

}  // namespace dfchaos::sweep
