// SPDX-License-Identifier: GPL-3.0-or-later
/// @file spec.hpp
/// @brief What one sweep computes: the plane's axes, the observables and their settings. Everything
/// that determines the output's bytes is here, and nothing else is (no shard, thread or rank count).
///
/// **Cells.** Cell `index` = i·n_b + j (i over q/a, slowest; j over b/a), 0 <= index < n_q·n_b. Its
/// parameters are a = A, q = (q/a)_i·A, b = (b/a)_j·A.
///
/// **The orbit** (for lyapunov, rate and period): from \f$\theta_0 = t_2 + f\,(t_3 - t_2)\f$, `transient`
/// steps of T are discarded, then `steps` steps are averaged (orbit_statistics).
///
/// **The period** of the attracting cycle: with \f$\theta_e = T^{\,transient + steps}(\theta_0)\f$ (the
/// end of that orbit), the smallest \f$k \le\f$ period_max with \f$|T^k(\theta_e) - \theta_e| \le\f$
/// period_tol on the circle; 0 when there is none (no cycle of period \f$\le\f$ period_max found: a
/// chaotic orbit, a longer cycle, or a slower approach). This is a cycle of the *computed* orbit. A
/// cycle through a stop closes exactly in floating point (a stop sends a whole arc to one phase)
/// even where double precision cannot follow the orbit from that phase back to the stop arc: then
/// it is a cycle of the rounding, not of T. superstable.hpp's stop_cycle tells the two apart for a
/// cycle through a stop; the sweep does not (the report's plane_lyapunov does, per cell).
#pragma once

#include <string>
#include <vector>

#include "dfchaos/covering.hpp"
#include "dfchaos/limits.hpp"
#include "dfchaos/parameters.hpp"
#include "sweep/observables.hpp"
#include "sweep/range.hpp"

namespace dfchaos::sweep {

inline constexpr long long kMaxCells = 100'000'000;               ///< most cells in one sweep
inline constexpr long long kMaxTransient = kMaxOrbitSteps;        ///< most transient steps per cell (as `dfchaos orbit --steps`)
inline constexpr long long kMaxSteps = kMaxOrbitSteps;            ///< most averaged steps per cell (as `dfchaos orbit --steps`)
inline constexpr long long kMaxPeriod = 10'000;                   ///< largest period searched for
inline constexpr long long kMinSuperstableScan = 2;               ///< superstable_check's least scan
inline constexpr long long kMaxSuperstableScan = 1'000'000;       ///< most scan points of superstable_check
inline constexpr long long kMaxCoveringBranches = 1'000'000'000;  ///< largest covering work budget per cell
inline constexpr long long kMaxRegionBoxes = 100'000'000;         ///< largest box budget per cell of `region`
inline constexpr long long kDefaultRegionBoxes = 4000;            ///< default box budget per cell of `region`
/// Default and largest caps on the proofs a whole sweep may attempt, cells·(proofs per cell), where
/// a cell of `certified` is one proof and a cell of `region` up to region_max_boxes box proofs (at
/// some 10 to 50 ms each on one core, 2·10^7 proofs are some 2 to 12 core-days).
inline constexpr long long kDefaultMaxProofs = 20'000'000;
inline constexpr long long kMaxMaxProofs = 1'000'000'000'000;  ///< see kDefaultMaxProofs
inline constexpr int kRegionFailedRun = 16;                    ///< `region` gives up a cell after this many unproved boxes in a row
/// Most evaluations of T by the orbits of a whole sweep, cells·(transient + steps + period_max):
/// 10^12, some 25 core-days at 2 µs per evaluation.
inline constexpr double kMaxOrbitEvaluations = 1e12;
inline constexpr double kMinA = kMinParameter;  ///< smallest forcing amplitude: the model's range
inline constexpr double kMaxA = kMaxParameter;  ///< largest forcing amplitude: the model's range
inline constexpr double kMinPeriodTol = 1e-15;  ///< smallest period tolerance (about the rounding of T)
inline constexpr double kMaxPeriodTol = 1e-3;   ///< largest period tolerance

/// The orbit of T followed at each cell (lyapunov, rate, period).
struct OrbitSettings {
  double theta0_fraction = 0.5;  ///< f in [0, 1): \f$\theta_0 = t_2 + f(t_3 - t_2)\f$
  long long transient = 1000;    ///< steps discarded, 0..kMaxTransient
  long long steps = 1000;        ///< steps averaged, 1..kMaxSteps
  /// Checks theta0_fraction, transient and steps against their bounds. @throws InvalidParameter
  /// naming the option (theta0, transient, steps) as on the command line.
  void validate() const;
};

/// The search for the period of the attracting cycle.
struct PeriodSettings {
  long long max = 64;  ///< largest k tried, 1..kMaxPeriod
  double tol = 1e-9;   ///< the closing tolerance on the circle
  /// Checks max and tol against their bounds. @throws InvalidParameter naming the option
  /// (period-max, period-tol) as on the command line.
  void validate() const;
};

/// A sweep of a drilling model in physical units (`--physical MASS OMEGA AMPLITUDE`, docs/units.md):
/// the length a = AMPLITUDE/(MASS OMEGA^2) (units.hpp's length_scale), the axes unchanged but read as
/// q/a = FRICTION/AMPLITUDE and b/a = STATIC/(2 AMPLITUDE), the rate in m/s, the two forces added to
/// each row in newtons. Not given (all 0): the paper's units.
struct PhysicalScale {
  double mass = 0;                                                                 ///< m (kg)
  double omega = 0;                                                                ///< the forcing's angular frequency (rad/s)
  double amplitude = 0;                                                            ///< F0, the harmonic force's amplitude (N)
  bool given() const { return amplitude > 0; }                                     ///< whether the sweep is in physical units
  double metres_per_second(double rate) const { return omega * rate; }             ///< a rate (length per unit of t) in m/s
  double friction(double q_over_a) const { return q_over_a * amplitude; }          ///< Q = (q/a) F0 (N)
  double static_force(double b_over_a) const { return 2 * b_over_a * amplitude; }  ///< P = 2 (b/a) F0 (N)
};

/// A sweep of the (q/a, b/a) plane.
struct Spec {
  double a = 1;                      ///< the forcing amplitude (the dynamics depend only on q/a and b/a)
  PhysicalScale physical;            ///< --physical: a from it, the rate in m/s and the forces added
  Range q_over_a;                    ///< first axis (slowest)
  Range b_over_a;                    ///< second axis
  ObservableSet observables;         ///< what each cell computes
  long long superstable_scan = 400;  ///< scan of superstable_check (as in thm1_parameter_plane)
  /// The covering search's work budget per cell (CoveringSearch::max_branches, 1..kMaxCoveringBranches):
  /// a cell with more branches of T1 in [t2, 3pi/2] is an error cell naming the budget.
  long long covering_max_branches = kDefaultMaxCoveringBranches;
  /// Box proofs attempted per cell by `region` (1..kMaxRegionBoxes) above the uniform bound.
  long long region_max_boxes = kDefaultRegionBoxes;
  /// Most proofs the whole sweep may attempt (1..kMaxMaxProofs): cells·(1 for certified +
  /// region_max_boxes for region) above it is refused by validate(). Bounds the work only: not in the
  /// header, no row depends on it.
  long long max_proofs = kDefaultMaxProofs;
  OrbitSettings orbit;    ///< the orbit (lyapunov, rate, period)
  PeriodSettings period;  ///< the period search

  /// Checks every bound and admissibility condition before any work: a in [kMinA, kMaxA], and
  /// a·(q/a), a·(b/a) normal numbers for every cell; every q/a in
  /// (0, inf) and every b/a in [kMinMapRatio, 1/2) (the joint condition q/a > 2 b/a is checked per cell, whose
  /// status is then `inadmissible`); the cell count, the orbit counts and the total orbit work
  /// bounded (the k* constants); with `region`, a b/a axis whose cells have a width (two points or
  /// more, or `mid`). @throws InvalidParameter naming the option (as on the command line).
  void validate() const;

  long long cells() const { return q_over_a.size() * b_over_a.size(); }             ///< n_q·n_b
  double q_at(long long index) const { return q_over_a[index / b_over_a.size()]; }  ///< (q/a) of a cell
  double b_at(long long index) const { return b_over_a[index % b_over_a.size()]; }  ///< (b/a) of a cell

  /// The header lines `key = value` (without the leading "# ") that describe the spec; identical
  /// for every run of the same spec, canonical whatever the spelling on the command line.
  std::vector<std::string> header_lines() const;
  /// The column names of a row: index, q_over_a, b_over_a, status, the observables' columns, error.
  std::vector<std::string> columns() const;
};

/// The report's plane at n x n cells (thm1_parameter_plane's axes): q/a the cell centres of
/// \f$(\sin\vartheta_0, 1)\f$, b/a log-spaced in [1e-4, 0.1], a = 1, with `observables`
/// (ObservableSet::parse), validated. Used by the experiments plane_lyapunov and plane_certified.
Spec report_plane(long long n, const std::string& observables);

}  // namespace dfchaos::sweep
