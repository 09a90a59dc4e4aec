// SPDX-License-Identifier: GPL-3.0-or-later
/// @file orbit_diagram.hpp
/// @brief The orbit diagram over a grid of cells (q/a, b/a): one column of dfchaos/orbit_diagram.hpp
/// per cell, computed in parallel and handed over in the order of the cells, for the
/// `dfchaos orbit-diagram` command and the Python module's `orbit_diagram`.
#pragma once

#include <functional>
#include <vector>

#include "dfchaos/orbit_diagram.hpp"

namespace dfchaos::sweep {

/// Most rows (cells times keep) and most evaluations of \f$T\f$ (cells times transient + steps)
/// of one diagram (1e9 evaluations: about half an hour on two cores, at some 3 us each).
inline constexpr long long kMaxOrbitDiagramRows = 100'000'000;
inline constexpr long long kMaxOrbitDiagramWork = 1'000'000'000;

/// Refuses a diagram of nq x nb cells beyond the bounds above, before anything is allocated.
/// @throws InvalidParameter naming keep (rows) or steps (evaluations).
void check_orbit_diagram_size(double nq, double nb, const OrbitDiagramSettings& settings);

/// The orbit diagram over the cells (q/a, b/a) of two axes, q/a outer and b/a inner (cell
/// \f$i\f$ is q_over_a[i / nb], b_over_a[i % nb]), at amplitude a: every cell checked first (T
/// defined), then computed in parallel (OpenMP; the result does not depend on the threads) and
/// handed to `sink` in the order of the cells, so that a caller can stream them.
/// @throws InvalidParameter naming q-range or b-range (a cell where T is not defined), a setting,
/// or the bounds above, before any cell is computed; GaveUp from the first cell that gives up,
/// after the cells before it were handed over.
void orbit_diagram(double a, const std::vector<double>& q_over_a, const std::vector<double>& b_over_a, const OrbitDiagramSettings& settings,
                   const std::function<void(long long cell, const OrbitDiagramColumn& column)>& sink);

}  // namespace dfchaos::sweep
