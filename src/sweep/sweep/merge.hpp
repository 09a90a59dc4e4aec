// SPDX-License-Identifier: GPL-3.0-or-later
/// @file merge.hpp
/// @brief `dfchaos sweep-merge`: the shard files of one sweep, given in any order, joined into the
/// output the unsharded run prints, byte for byte.
///
/// Checked before anything is written: every file is a shard of the same sweep (identical headers
/// but for the shard line: same spec, same build), the shards are 0/N ... N-1/N each exactly once,
/// and each file is whole and undamaged: its seal matches its bytes (seal.hpp) and it holds exactly
/// its cells (index ≡ i mod N, increasing), every field of every row well-formed (row_problem).
/// The shard files must be regular files (each is read twice); the output carries a seal of its own.
#pragma once

#include <string>
#include <vector>

#include "sweep/shard.hpp"
#include "sweep/stream.hpp"

namespace dfchaos::sweep {

/// Most shard files merged at once (each is open during the merge).
inline constexpr long long kMaxMergeFiles = kMaxShards;

/// Merges the shard files into `out` (not committed). @throws InvalidParameter naming
/// "sweep-merge" and the file for a missing, duplicate, foreign or damaged shard;
/// kit::OutputError when writing fails.
void merge_shards(const std::vector<std::string>& files, Stream& out);

}  // namespace dfchaos::sweep
