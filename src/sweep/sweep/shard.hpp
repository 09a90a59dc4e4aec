// SPDX-License-Identifier: GPL-3.0-or-later
/// @file shard.hpp
/// @brief A share of a sweep's cells: shard i of N takes the cells with index ≡ i (mod N).
///
/// The distribution is cyclic because the cost of a cell varies a lot across the plane but slowly
/// from one cell to the next: neighbouring cells go to different shards, so every shard gets about
/// the same mix of cheap and costly cells. The cells of a shard are numbered by their *position*
/// p = 0, 1, ...: position p is cell i + p·N.
#pragma once

#include <string>

namespace dfchaos::sweep {

/// Most shards of one sweep (sweep-merge holds every shard file open at once).
inline constexpr long long kMaxShards = 10'000;

/// Shard `index` of `count` (the whole sweep is shard 0/1).
struct Shard {
  long long index = 0;  ///< i, 0 <= i < N
  long long count = 1;  ///< N >= 1

  /// Parses "i/N" with 0 <= i < N, 1 <= N <= min(kMaxShards, cells): every shard has a cell.
  /// @throws InvalidParameter naming `option`.
  static Shard parse(const std::string& option, const std::string& text, long long cells);

  /// Number of cells of the shard in a sweep of `cells` cells.
  long long size(long long cells) const { return cells > index ? (cells - index + count - 1) / count : 0; }
  /// The cell index at position p.
  long long cell(long long position) const { return index + position * count; }
  /// Whether this is the whole sweep (0/1).
  bool whole() const { return count == 1; }
  /// "i/N".
  std::string canonical() const { return std::to_string(index) + "/" + std::to_string(count); }
};

}  // namespace dfchaos::sweep
