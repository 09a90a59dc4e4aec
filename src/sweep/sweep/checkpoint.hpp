// SPDX-License-Identifier: GPL-3.0-or-later
/// @file checkpoint.hpp
/// @brief The side directory `FILE.chunks/` of `--resume FILE`: the chunks of cells computed so far,
/// each written atomically, from which an interrupted run continues.
///
/// Layout: `header` (the output header of the run: spec, build and shard), `lock` (held with
/// flock while a run uses the directory: two runs never share it), and one
/// `chunk-BEGIN-END.tsv` per chunk of positions [BEGIN, END) of the shard, holding the run's
/// header, their rows and a seal line (seal.hpp: the row count and the SHA-256 of the header and
/// rows, so that a chunk is tied to its run). Every chunk is checked when
/// the directory is opened and again when the output is assembled: an incomplete or damaged chunk
/// is refused, never merged.
/// A chunk file appears only complete (written to a unique temporary, then renamed): a run killed
/// at any instant leaves complete chunks and at most stale temporaries, which the next run removes.
/// When every position is done, the output is assembled into FILE (atomically) and the directory
/// removed.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "sweep/shard.hpp"

namespace dfchaos::sweep {

/// Positions [begin, end) of a shard.
struct Interval {
  long long begin = 0;                            ///< first position
  long long end = 0;                              ///< one past the last
  long long size() const { return end - begin; }  ///< number of positions
};

/// The checkpoint directory of one resumable run.
class Checkpoint {
 public:
  /// The directory of `file`: FILE.chunks.
  static std::filesystem::path directory(const std::filesystem::path& file);

  /// Opens (or creates) the directory of `file` for a run with output header `header` over the
  /// `positions` positions of `shard`, rows with these `columns`. Reads and checks every chunk.
  /// @throws InvalidParameter naming "resume" when the directory holds another run (another spec,
  ///         build or shard), is in use by another run, or holds a damaged or overlapping chunk;
  ///         kit::OutputError when it cannot be created.
  Checkpoint(const std::filesystem::path& file, std::string header, const Shard& shard, long long positions, std::vector<std::string> columns);
  Checkpoint(const Checkpoint&) = delete;
  Checkpoint& operator=(const Checkpoint&) = delete;

  /// The chunks done, sorted and disjoint.
  const std::vector<Interval>& done() const { return done_; }
  /// Number of positions done.
  long long done_positions() const;
  /// Saves the rows of a chunk (atomically). @throws kit::OutputError
  void save(const Interval& chunk, std::string_view rows);
  /// Whether every position is done.
  bool complete() const { return done_positions() == positions_; }
  /// Writes FILE (header and every chunk in order, atomically) and removes the directory.
  /// @throws std::logic_error unless complete(); kit::OutputError when writing fails.
  void assemble();

 private:
  std::filesystem::path file_, dir_;
  std::string header_;
  long long positions_;
  Shard shard_;
  std::vector<std::string> columns_;
  std::vector<Interval> done_;
  /// An open file descriptor holding the directory's flock, closed (the lock released) on
  /// destruction, also when the constructor of Checkpoint throws after taking it.
  struct Lock {
    int fd = -1;
    Lock() = default;
    Lock(const Lock&) = delete;
    Lock& operator=(const Lock&) = delete;
    ~Lock();
    void release();
  } lock_;
  void insert(const Interval& chunk);
  /// The rows of chunk file `path` of positions `c`, without its seal.
  /// @throws InvalidParameter naming "resume" unless it is sealed and every row is well-formed.
  std::string read_chunk(const std::filesystem::path& path, const Interval& c) const;
};

}  // namespace dfchaos::sweep
