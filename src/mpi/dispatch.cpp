// SPDX-License-Identifier: GPL-3.0-or-later
#include "dispatch.hpp"

#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_map>
#include <utility>

#include "sweep/engine.hpp"

namespace dfchaos::sweep::mpi {

namespace {

constexpr int kRoot = 0;
constexpr int kTagRequest = 1;
constexpr int kTagAssign = 2;
constexpr int kTagRows = 3;
constexpr std::size_t kRowsHeader = 2 * sizeof(std::int64_t);  // first item, count

/// CPU seconds used by this process so far (all its threads).
double cpu_seconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The rows of queue items [first, first + count), concatenated; the time taken added to `busy`.
std::string rows_of(const Spec& spec, const Queue& queue, long long first, long long count, Busy& busy) {
  const double cpu0 = cpu_seconds();
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<long long> cells;
  for (long long item = first; item < first + count; ++item) cells.push_back(queue.cell(item));
  std::string text;
  for (const auto& row : compute_rows(spec, cells, nullptr)) text += row;
  busy.cpu += cpu_seconds() - cpu0;
  busy.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return text;
}

/// Splits concatenated rows (each ending in '\n') into `count` rows.
std::vector<std::string> split_rows(const char* text, std::size_t size, long long count) {
  std::vector<std::string> rows;
  std::size_t at = 0;
  for (long long k = 0; k < count; ++k) {
    const void* nl = std::memchr(text + at, '\n', size - at);
    if (!nl) throw std::runtime_error("dfchaos-sweep-mpi: a batch of rows arrived incomplete");
    const std::size_t end = static_cast<std::size_t>(static_cast<const char*>(nl) - text) + 1;
    rows.emplace_back(text + at, end - at);
    at = end;
  }
  return rows;
}

/// Rank 0's bookkeeping: rows received or computed, waiting for their chunk to be complete.
class Collector {
 public:
  Collector(Run& run, const Queue& queue) : run_(run), queue_(queue), done_(queue.chunks(), 0) {}
  /// Stores the rows of items first.., delivers every chunk that is now complete, in order.
  void store(long long first, std::vector<std::string> rows) {
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const long long item = first + static_cast<long long>(k);
      ++done_[queue_.chunk_of(item)];
      rows_.emplace(item, std::move(rows[k]));
    }
    run_.progress().step(static_cast<long long>(rows.size()));
    while (next_ < queue_.chunks() && done_[next_] == queue_.chunk_begin(next_ + 1) - queue_.chunk_begin(next_)) {
      std::string text;
      for (long long item = queue_.chunk_begin(next_); item < queue_.chunk_begin(next_ + 1); ++item) {
        auto it = rows_.find(item);
        text += it->second;
        rows_.erase(it);
      }
      run_.deliver(next_, text);
      ++next_;
    }
  }
  bool complete() const { return next_ == queue_.chunks(); }  ///< every chunk delivered

 private:
  Run& run_;
  const Queue& queue_;
  std::vector<long long> done_;                      // cells in by chunk
  std::unordered_map<long long, std::string> rows_;  // rows not yet delivered, by queue item
  std::size_t next_ = 0;                             // the next chunk to deliver
};

}  // namespace

Queue::Queue(const Shard& shard, std::vector<Interval> chunks) : shard_(shard), chunks_(std::move(chunks)) {
  starts_.reserve(chunks_.size() + 1);
  long long total = 0;
  for (const auto& c : chunks_) {
    starts_.push_back(total);
    total += c.size();
  }
  starts_.push_back(total);
}

std::size_t Queue::chunk_of(long long item) const {
  return static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), item) - starts_.begin() - 1);
}

long long Queue::cell(long long item) const {
  const std::size_t k = chunk_of(item);
  return shard_.cell(chunks_[k].begin + (item - starts_[k]));
}

Busy serve(Run& run, const Queue& queue, int ranks) {
  Collector collector(run, queue);
  const long long threads = omp_get_max_threads();
  const long long batch = kBatchPerThread * threads;  // the workers' threads, taken to be as many as ours
  // The queue, shared by this thread (handing out batches) and the computing thread.
  std::mutex queue_mutex;
  long long next = 0;
  auto take = [&](long long n) {
    std::lock_guard<std::mutex> lock(queue_mutex);
    const std::int64_t first = next, count = std::min(n, queue.size() - next);
    next += count;
    return std::pair<std::int64_t, std::int64_t>{first, count};
  };
  // Rows computed here, passed to this thread (only it calls MPI and writes the output).
  struct Done {
    long long first, count;
    std::string text;
  };
  std::mutex inbox_mutex;
  std::vector<Done> inbox;
  std::exception_ptr failure;
  Busy busy;
  std::thread computing([&] {
    try {
      for (;;) {  // ends when the queue is empty: each pass takes at least one cell
        const auto [first, count] = take(kRootCellsPerThread * threads);
        if (count == 0) break;
        std::string text = rows_of(run.spec(), queue, first, count, busy);
        std::lock_guard<std::mutex> lock(inbox_mutex);
        inbox.push_back(Done{first, count, std::move(text)});
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(inbox_mutex);
      failure = std::current_exception();
    }
  });
  int stopped = 0;  // ranks told to stop
  std::vector<char> buffer;
  try {
    // Serves until every chunk is delivered and every other rank was told to stop; sleeps briefly
    // when there is nothing to do (a blocking MPI_Probe would spin and take a core from the cells).
    while (!collector.complete() || stopped < ranks - 1) {
      bool idle = true;
      int flag = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
      if (flag) {
        idle = false;
        if (st.MPI_TAG == kTagRequest) {
          MPI_Recv(nullptr, 0, MPI_CHAR, st.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          const auto [first, count] = take(batch);
          const std::int64_t assign[2] = {first, count};
          stopped += count == 0;
          MPI_Send(assign, 2, MPI_INT64_T, st.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD);
        } else if (st.MPI_TAG == kTagRows) {
          int size = 0;
          MPI_Get_count(&st, MPI_CHAR, &size);
          buffer.resize(static_cast<std::size_t>(size));
          MPI_Recv(buffer.data(), size, MPI_CHAR, st.MPI_SOURCE, kTagRows, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          std::int64_t head[2];
          std::memcpy(head, buffer.data(), kRowsHeader);
          collector.store(head[0], split_rows(buffer.data() + kRowsHeader, buffer.size() - kRowsHeader, head[1]));
        } else {
          throw std::runtime_error("dfchaos-sweep-mpi: unexpected message tag " + std::to_string(st.MPI_TAG));
        }
      }
      std::vector<Done> mine;
      {
        std::lock_guard<std::mutex> lock(inbox_mutex);
        if (failure) std::rethrow_exception(failure);
        mine.swap(inbox);
      }
      for (auto& d : mine) {
        idle = false;
        collector.store(d.first, split_rows(d.text.data(), d.text.size(), d.count));
      }
      if (idle) std::this_thread::sleep_for(kIdlePoll);
    }
  } catch (...) {
    computing.join();
    throw;
  }
  computing.join();
  return busy;
}

Busy work(const Spec& spec, const Queue& queue) {
  Busy busy;
  std::int64_t assign[2] = {0, 0};
  MPI_Send(nullptr, 0, MPI_CHAR, kRoot, kTagRequest, MPI_COMM_WORLD);
  MPI_Recv(assign, 2, MPI_INT64_T, kRoot, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::string message;  // the rows in flight (kept alive until their send completes)
  MPI_Request in_flight = MPI_REQUEST_NULL;
  // Each pass computes one batch; the queue is finite and every batch is non-empty.
  while (assign[1] > 0) {
    MPI_Send(nullptr, 0, MPI_CHAR, kRoot, kTagRequest, MPI_COMM_WORLD);  // the next batch, asked for now
    const std::string text = rows_of(spec, queue, assign[0], assign[1], busy);
    MPI_Wait(&in_flight, MPI_STATUS_IGNORE);
    message.assign(kRowsHeader, '\0');
    std::memcpy(message.data(), assign, kRowsHeader);
    message += text;
    if (message.size() > static_cast<std::size_t>(INT_MAX)) throw std::length_error("a batch of rows exceeds 2 GB");
    MPI_Isend(message.data(), static_cast<int>(message.size()), MPI_CHAR, kRoot, kTagRows, MPI_COMM_WORLD, &in_flight);
    MPI_Recv(assign, 2, MPI_INT64_T, kRoot, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
  MPI_Wait(&in_flight, MPI_STATUS_IGNORE);
  return busy;
}

}  // namespace dfchaos::sweep::mpi
