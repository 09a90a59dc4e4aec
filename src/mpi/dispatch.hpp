// SPDX-License-Identifier: GPL-3.0-or-later
/// @file dispatch.hpp
/// @brief How dfchaos-sweep-mpi shares the cells of a run among MPI ranks: dynamically, in small
/// batches handed out by rank 0, which computes cells too.
///
/// The cells still to compute (the run's chunks, one after the other) form a queue. Each other rank
/// asks rank 0 for a batch, and asks for the next one *before* computing the current one, so that
/// the answer is waiting when it is done; it sends the batch's rows back. On rank 0 a second thread
/// computes cells from the same queue, while the main thread (the only one that calls MPI) answers
/// requests within a few milliseconds, receives rows and, as soon as every cell of the next chunk is in,
/// delivers the chunk (Run::deliver: stdout, the output file, or the checkpoint of --resume). The cost of a cell varies by a factor of ten across
/// the plane, so a static split leaves ranks idle (measured: a cyclic split of 900 cells over 2
/// ranks gave them 7.2 and 7.75 CPU seconds, balance 0.96); handing out batches keeps every rank
/// busy until the queue is empty, whatever the costs. Rows go to the output in cell order, so the
/// output does not depend on which rank computed what.
///
/// Messages (MPI_COMM_WORLD): kTagRequest (empty, rank r -> 0), kTagAssign (two int64: first queue
/// item and count; count 0 means stop; 0 -> r), kTagRows (two int64 then the rows; r -> 0). Every
/// request is answered, and a rank stops after its first empty assignment, so no message is left
/// unmatched at the end.
#pragma once

#include <chrono>
#include <vector>

#include "sweep/checkpoint.hpp"
#include "sweep/run.hpp"
#include "sweep/shard.hpp"
#include "sweep/spec.hpp"

namespace dfchaos::sweep::mpi {

/// Cells per batch of another rank, per OpenMP thread (small batches balance; the prefetched
/// request hides the round trip).
inline constexpr long long kBatchPerThread = 2;
/// Cells rank 0's computing thread takes from the queue at a time, per OpenMP thread.
inline constexpr long long kRootCellsPerThread = 1;
/// How long rank 0's main thread sleeps when no message and no rows are waiting (a worker asks
/// for its next batch a whole batch ahead, so this delay is hidden; each look costs CPU).
inline constexpr std::chrono::microseconds kIdlePoll{2000};

/// The queue of cells: the chunks one after the other.
class Queue {
 public:
  Queue(const Shard& shard, std::vector<Interval> chunks);
  long long size() const { return starts_.back(); }                  ///< number of cells
  long long cell(long long item) const;                              ///< the cell index of a queue item
  std::size_t chunk_of(long long item) const;                        ///< the chunk holding a queue item
  long long chunk_begin(std::size_t k) const { return starts_[k]; }  ///< first queue item of chunk k
  std::size_t chunks() const { return chunks_.size(); }              ///< number of chunks

 private:
  Shard shard_;
  std::vector<Interval> chunks_;
  std::vector<long long> starts_;  // queue item of each chunk's first cell, and the total at the end
};

/// The time a rank spent computing cells.
struct Busy {
  double cpu = 0;   ///< CPU seconds (all its threads)
  double wall = 0;  ///< wall-clock seconds (the rest of the run it waited or exchanged messages)
};

/// Rank 0: hands out batches of `queue` to ranks 1..ranks-1, computes cells itself, and delivers
/// every chunk of `run` in order.
Busy serve(Run& run, const Queue& queue, int ranks);

/// Any other rank: asks for batches until told to stop, computes them, sends their rows.
Busy work(const Spec& spec, const Queue& queue);

}  // namespace dfchaos::sweep::mpi
