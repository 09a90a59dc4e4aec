// SPDX-License-Identifier: GPL-3.0-or-later
/// @file orbit_diagram.hpp
/// @brief One column of an orbit diagram of \f$T\f$ (Lemma 3): the phases an orbit visits after a
/// transient at one parameter set, with the marks that say what the column shows: whether the
/// orbit met a stop arc (a step with \f$T' = 0\f$, so that it goes on as the orbit of the stop's
/// image), whether that is the orbit of \f$t_2\f$ returning to \f$t_2\f$, and whether double
/// precision resolves that return as a superstable cycle (Theorem 2; superstable.hpp, t2_cycle).
/// The experiment bifurcation_diagram computes its columns here; sweep/orbit_diagram.hpp runs them
/// over a grid of cells for the `dfchaos orbit-diagram` command and the Python module.
#pragma once

#include <vector>

#include "dfchaos/map_derivative.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/superstable.hpp"

namespace dfchaos {

/// A column of the orbit diagram at one parameter set.
struct OrbitDiagramColumn {
  /// The orbit after the transient: its statistics over the averaged steps (Lyapunov exponent,
  /// -inf when a step stops; the return time of \f$t_2\f$, 0 if none seen) and its last phases.
  OrbitStatistics orbit;
  /// When the orbit returned to \f$t_2\f$: that cycle followed again from \f$t_2\f$ with its
  /// propagated error; `cycle.resolved` marks a superstable cycle that double precision resolves.
  /// Empty (period 0) when there was no return, or when following it gave up.
  StopCycle cycle;
};

/// Iterates \f$T\f$ from \f$\theta_0\f$: `transient` steps discarded, `steps` averaged, the last
/// `keep` phases kept (orbit_statistics), then, if the orbit returned to \f$t_2\f$, t2_cycle for
/// that period. Bounded: transient + steps evaluations of \f$T\f$, and at most as many again for the
/// cycle. @throws InvalidParameter for a bad start or counts, GaveUp as return_map_step.
OrbitDiagramColumn orbit_diagram_column(const Parameters& p, double theta0, long long transient, long long steps, int keep);

/// What a diagram over many cells computes per cell, with its bounds.
struct OrbitDiagramSettings {
  double theta0_fraction = 0.377;  ///< the start: \f$t_2 + f\,(t_3 - t_2)\f$, \f$0 \le f < 1\f$ (orbit_diagram_start's)
  long long transient = 500;       ///< steps discarded, \f$0 \le N \le 10^8\f$
  long long steps = 256;           ///< steps averaged, \f$1 \le N \le 10^8\f$
  long long keep = 64;             ///< last phases kept, \f$1 \le K \le\f$ min(steps, 1e5)
  /// @throws InvalidParameter naming theta0-fraction, transient, steps or keep.
  void validate() const;
};

/// The start of an orbit diagram's orbits, \f$t_2 + f\,(t_3 - t_2)\f$; the report's f = 0.377
/// (OrbitDiagramSettings) is a phase in no particular relation to the arcs of the map.
/// @throws InvalidParameter where \f$T\f$ is not defined.
double orbit_diagram_start(const Parameters& p, double theta0_fraction = OrbitDiagramSettings{}.theta0_fraction);

}  // namespace dfchaos
