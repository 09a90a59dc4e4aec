// SPDX-License-Identifier: GPL-3.0-or-later
/// @file run.hpp
/// @brief One run of a sweep, whatever computes its cells (OpenMP threads, MPI ranks): checks the
/// whole request before any work, plans the chunks still to compute, and puts their rows where
/// they belong — streamed to stdout or into `--out FILE` (atomically), or saved chunk by chunk
/// into the checkpoint of `--resume FILE` and assembled at the end. Every output ends in its seal
/// (seal.hpp); `--resume` of a finished file accepts it only when its seal and rows check.
///
/// Use: construct (throws on bad input), compute the rows of chunks()[k] for k = 0, 1, ... in order
/// and deliver() each, then finish(). The output does not depend on how the rows were computed.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kit/grid.hpp"
#include "sweep/checkpoint.hpp"
#include "sweep/seal.hpp"
#include "sweep/shard.hpp"
#include "sweep/spec.hpp"
#include "sweep/stream.hpp"

namespace dfchaos::sweep {

/// Exit status of a run stopped by --max-chunks before it was complete (rerun to continue).
inline constexpr int kExitIncomplete = 3;
/// Default cells per chunk (the unit of checkpoints, and of delivery by the MPI driver).
inline constexpr long long kDefaultChunk = 256;
/// Most cells per chunk.
inline constexpr long long kMaxChunk = 1'000'000;
/// Most chunks in one run.
inline constexpr long long kMaxChunks = 1'000'000;

/// Everything a run is asked to do.
struct RunOptions {
  Spec spec;                        ///< what to compute
  std::optional<Shard> shard;       ///< only this share of the cells (a shard file, with a shard line)
  std::string out;                  ///< the output file ("" and no resume: stdout)
  std::string resume;               ///< the output file of a resumable run (checkpoints in FILE.chunks/)
  long long chunk = kDefaultChunk;  ///< cells per chunk, 1..kMaxChunk (it never changes the output)
  long long max_chunks = 0;         ///< with resume: stop after this many new chunks (0: no limit)
  bool progress = false;            ///< progress on stderr even when it is not a terminal
};

/// One run. Not copyable.
class Run {
 public:
  /// Checks the options (Spec::validate, chunk bounds, option combinations), opens the checkpoint
  /// or the output and writes the header (stdout or file), and plans the chunks.
  /// @throws InvalidParameter naming the option; kit::OutputError for an unusable output path.
  explicit Run(RunOptions options);
  ~Run();
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;

  const Spec& spec() const { return o_.spec; }   ///< the spec
  const Shard& shard() const { return shard_; }  ///< the shard (0/1 for the whole sweep)
  /// The chunks to compute in this run, in order (positions of the shard; cell = shard().cell(p)).
  const std::vector<Interval>& chunks() const { return chunks_; }
  /// The cell indices of a chunk.
  std::vector<long long> cells_of(const Interval& chunk) const;
  /// The rows of chunks()[k] (k = 0, 1, ... in order), concatenated. @throws kit::OutputError
  void deliver(std::size_t k, const std::string& rows);
  /// Completes the output. @return 0 when the sweep (or shard) is complete, kExitIncomplete when
  /// --max-chunks stopped it first. @throws kit::OutputError
  int finish();
  /// Progress of this run on stderr (cells of chunks(), with an estimate of the time left).
  kit::Progress& progress() { return *progress_; }

 private:
  RunOptions o_;
  Shard shard_;
  long long positions_ = 0;
  std::vector<Interval> chunks_;
  std::unique_ptr<Checkpoint> checkpoint_;
  std::unique_ptr<Stream> stream_;
  Sealer sealer_;  ///< the seal of what went to stream_
  std::unique_ptr<kit::Progress> progress_;
  bool already_complete_ = false;
  std::size_t delivered_ = 0;
};

/// The chunks still to compute: [0, positions) minus `done` (sorted, disjoint), cut into pieces of
/// at most `chunk` positions, in increasing order.
std::vector<Interval> plan_chunks(long long positions, const std::vector<Interval>& done, long long chunk);

}  // namespace dfchaos::sweep
