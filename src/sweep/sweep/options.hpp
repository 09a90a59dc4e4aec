// SPDX-License-Identifier: GPL-3.0-or-later
/// @file options.hpp
/// @brief The command-line options of a sweep, shared by `dfchaos sweep` and `dfchaos-sweep-mpi`
/// so that both accept exactly the same spelling, bounds and help.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "sweep/run.hpp"

namespace dfchaos::sweep {

/// The options as typed (parsed by resolve()).
struct SweepArguments {
  std::string a = "1", q_range, b_range, observables = kDefaultObservables;
  std::string max_branches = std::to_string(kDefaultMaxCoveringBranches);
  std::string superstable_scan = "400", theta0 = "0.5", transient = "1000", steps = "1000";
  std::vector<std::string> physical;  ///< --physical MASS OMEGA AMPLITUDE, as typed (empty: not given)
  std::string old_theta0;             ///< --theta0, refused (the start is --theta0-fraction)
  std::string period_max = "64", period_tol = "1e-9";
  std::string region_max_boxes = std::to_string(kDefaultRegionBoxes);
  std::string max_proofs = std::to_string(kDefaultMaxProofs);
  std::string shard, out, resume, chunk = std::to_string(kDefaultChunk), max_chunks = "0";
  bool progress = false;

  /// Registers the options on `app`, with the output columns in its footer.
  void add_to(CLI::App* app);
  /// The run they ask for. @throws InvalidParameter naming the first bad option (one line).
  RunOptions resolve() const;
};

}  // namespace dfchaos::sweep
