// SPDX-License-Identifier: GPL-3.0-or-later
/// @file engine.hpp
/// @brief Computing rows of a sweep in parallel on one machine (OpenMP threads), and the whole
/// serial run of `dfchaos sweep`.
#pragma once

#include <string>
#include <vector>

#include "kit/grid.hpp"
#include "sweep/cell.hpp"
#include "sweep/run.hpp"
#include "sweep/spec.hpp"

namespace dfchaos::sweep {

/// The observables of the given cells, in the given order, computed by OpenMP threads (dynamic
/// schedule: the cost of a cell varies a lot); one step of `progress` (if any) per cell.
/// Deterministic: the values do not depend on the thread count. @throws std::bad_alloc when memory
/// ran out in a cell (after the other threads stopped taking cells; nothing is returned).
std::vector<CellValues> compute_cells(const Spec& spec, const std::vector<long long>& cells, kit::Progress* progress);

/// The rows of the given cells, in the given order, computed by OpenMP threads (dynamic schedule:
/// the cost of a cell varies a lot); one step of `progress` (if any) per cell. Deterministic: the
/// rows do not depend on the thread count. @throws std::bad_alloc when memory ran out in a cell
/// (after the other threads stopped taking cells; no row of the chunk is returned).
std::vector<std::string> compute_rows(const Spec& spec, const std::vector<long long>& cells, kit::Progress* progress);

/// A whole run on this machine: every chunk of `run` computed by compute_rows and delivered.
/// @return Run::finish()'s status.
int run_on_threads(Run& run);

}  // namespace dfchaos::sweep
