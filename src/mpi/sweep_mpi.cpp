/// @file sweep_mpi.cpp
/// @brief `dfchaos-sweep-mpi`: the sweep of `dfchaos sweep` distributed over MPI ranks, with the
/// same options and byte for byte the same output.
///
///     mpirun -np R dfchaos-sweep-mpi --q-range LO:HI:N[:KIND] --b-range LO:HI:N[:KIND] [options]
///
/// Rank 0 checks the request, owns the output (stdout, --out FILE or the checkpoint of --resume
/// FILE) and plans the chunks; it broadcasts the plan. Chunk by chunk, every rank (rank 0 too)
/// computes the cells at positions ≡ rank (mod R) of the chunk with its OpenMP threads, and rank 0
/// gathers the rows (MPI_Gatherv) and writes them in cell order. The cyclic split gives each rank
/// the same mix of cheap and costly cells (neighbouring cells cost about the same). Bad input: one
/// line from rank 0, every rank exits with status 2. With --progress, rank 0 ends with one line on
/// stderr: the wall time and each rank's CPU seconds spent on cells, whose ratio mean/max is the
/// balance of the split (1 when every rank worked as long as the busiest).
#include <mpi.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "dfchaos/errors.hpp"
#include "kit/format.hpp"
#include "kit/output.hpp"
#include "kit/provenance.hpp"
#include "sweep/engine.hpp"
#include "sweep/options.hpp"
#include "sweep/run.hpp"

namespace {

using namespace dfchaos;

constexpr int kRoot = 0;
constexpr int kExitBadInput = 2;
constexpr int kExitFailed = 1;

/// What rank 0 tells the others after checking the request.
struct Verdict {
  long long status = 0;  ///< 0: go on; otherwise every rank exits with this status
  long long chunks = 0;  ///< the number of chunks planned
};

/// CPU seconds used by this process so far (all its threads).
double cpu_seconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The rows of one chunk computed by this rank: positions begin + rank, begin + rank + R, ...
std::string my_rows(const sweep::Spec& spec, const sweep::Shard& shard, const sweep::Interval& chunk, int rank, int ranks) {
  std::vector<long long> cells;
  for (long long p = chunk.begin + rank; p < chunk.end; p += ranks) cells.push_back(shard.cell(p));
  std::string text;
  for (const auto& row : sweep::compute_rows(spec, cells, nullptr)) text += row;
  return text;
}

/// Rank 0: the rows of every rank, interleaved back into position order (row k from rank k mod R).
std::string interleave(const std::vector<std::string>& per_rank, long long rows) {
  std::vector<std::size_t> at(per_rank.size(), 0);
  std::string out;
  std::size_t total = 0;
  for (const auto& s : per_rank) total += s.size();
  out.reserve(total);
  for (long long k = 0; k < rows; ++k) {
    const std::size_t r = static_cast<std::size_t>(k) % per_rank.size();
    const std::size_t nl = per_rank[r].find('\n', at[r]);
    out.append(per_rank[r], at[r], nl + 1 - at[r]);
    at[r] = nl + 1;
  }
  return out;
}

/// Gathers each rank's text to rank 0 (whose result is the texts by rank; empty elsewhere).
std::vector<std::string> gather_text(const std::string& mine, int rank, int ranks) {
  if (mine.size() > static_cast<std::size_t>(INT_MAX)) throw std::length_error("a chunk's rows exceed 2 GB on one rank: use a smaller --chunk");
  int size = static_cast<int>(mine.size());
  std::vector<int> sizes(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks));
  MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, kRoot, MPI_COMM_WORLD);
  std::string all;
  if (rank == kRoot) {
    long long total = 0;
    for (int r = 0; r < ranks; ++r) {
      offsets[static_cast<std::size_t>(r)] = static_cast<int>(total);
      total += sizes[static_cast<std::size_t>(r)];
    }
    if (total > INT_MAX) throw std::length_error("a chunk's rows exceed 2 GB: use a smaller --chunk");
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), size, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR, kRoot, MPI_COMM_WORLD);
  std::vector<std::string> parts;
  if (rank == kRoot)
    for (int r = 0; r < ranks; ++r) parts.push_back(all.substr(static_cast<std::size_t>(offsets[static_cast<std::size_t>(r)]),
                                                                static_cast<std::size_t>(sizes[static_cast<std::size_t>(r)])));
  return parts;
}

int run(int argc, char** argv, int rank, int ranks) {
  CLI::App app{"dfchaos-sweep-mpi: dfchaos sweep distributed over MPI ranks (same options, same output)"};
  app.set_version_flag("--version", std::string(kit::version()) + " (" + kit::git_hash() + ")");
  sweep::SweepArguments args;
  args.add_to(&app);
  // Every rank parses the same arguments; only rank 0 speaks.
  Verdict verdict;
  std::unique_ptr<sweep::Run> job;
  sweep::RunOptions options;
  try {
    app.parse(argc, argv);
    options = args.resolve();
    // A round gathers one chunk: kDefaultChunk cells per rank by default, so that each rank has
    // enough cells per round for the cyclic split to balance (the round ends at its slowest rank).
    if (!options.chunk_given) options.chunk = std::min(sweep::kMaxChunk, sweep::kDefaultChunk * ranks);
    if (rank == kRoot) {
      job = std::make_unique<sweep::Run>(options);
      verdict.chunks = static_cast<long long>(job->chunks().size());
    }
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {  // --help, --version
      if (rank == kRoot) app.exit(e);
      return 0;
    }
    if (rank == kRoot) {
      std::string msg = e.what();
      for (auto& ch : msg)
        if (ch == '\n') ch = ' ';
      std::fprintf(stderr, "dfchaos-sweep-mpi: error: %s\n", msg.c_str());
    }
    verdict.status = kExitBadInput;
  } catch (const InvalidParameter& e) {
    if (rank == kRoot) std::fprintf(stderr, "dfchaos-sweep-mpi: error: %s\n", e.what());
    verdict.status = kExitBadInput;
  } catch (const kit::OutputError& e) {
    if (rank == kRoot) std::fprintf(stderr, "dfchaos-sweep-mpi: error: %s\n", e.what());
    verdict.status = e.bad_path() ? kExitBadInput : kExitFailed;
  }
  // Every rank met the same parse errors; rank 0 alone met the output's. Its word decides.
  MPI_Bcast(&verdict, 2, MPI_LONG_LONG, kRoot, MPI_COMM_WORLD);
  if (verdict.status != 0) return static_cast<int>(verdict.status);
  std::vector<long long> plan(static_cast<std::size_t>(2 * verdict.chunks));
  if (rank == kRoot)
    for (std::size_t k = 0; k < job->chunks().size(); ++k) {
      plan[2 * k] = job->chunks()[k].begin;
      plan[2 * k + 1] = job->chunks()[k].end;
    }
  if (!plan.empty()) MPI_Bcast(plan.data(), static_cast<int>(plan.size()), MPI_LONG_LONG, kRoot, MPI_COMM_WORLD);
  const sweep::Shard shard = options.shard.value_or(sweep::Shard{});
  const auto wall_start = std::chrono::steady_clock::now();
  double busy = 0;  // CPU seconds on this rank's cells
  long long cells = 0;
  for (long long k = 0; k < verdict.chunks; ++k) {
    const sweep::Interval chunk{plan[static_cast<std::size_t>(2 * k)], plan[static_cast<std::size_t>(2 * k + 1)]};
    const double cpu0 = cpu_seconds();
    const std::string mine = my_rows(options.spec, shard, chunk, rank, ranks);
    busy += cpu_seconds() - cpu0;
    cells += chunk.size();
    const auto parts = gather_text(mine, rank, ranks);
    if (rank == kRoot) {
      job->deliver(static_cast<std::size_t>(k), interleave(parts, chunk.size()));
      job->progress().step(chunk.size());
    }
  }
  std::vector<double> busy_by_rank(static_cast<std::size_t>(ranks));
  MPI_Gather(&busy, 1, MPI_DOUBLE, busy_by_rank.data(), 1, MPI_DOUBLE, kRoot, MPI_COMM_WORLD);
  long long status = rank == kRoot ? job->finish() : 0;
  if (rank == kRoot && options.progress) {
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    double sum = 0, most = 0;
    std::string list;
    for (double b : busy_by_rank) {
      sum += b;
      most = std::max(most, b);
      list += (list.empty() ? "" : " ") + kit::format_significant(b, 4);
    }
    std::fprintf(stderr, "dfchaos-sweep-mpi: %lld cells on %d ranks in %.3f s; cpu seconds per rank: %s; balance %.4f\n", cells, ranks,
                 wall, list.c_str(), most > 0 ? sum / (ranks * most) : 1.0);
  }
  MPI_Bcast(&status, 1, MPI_LONG_LONG, kRoot, MPI_COMM_WORLD);
  return static_cast<int>(status);
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);  // only the main thread calls MPI
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int status = 0;
  try {
    status = run(argc, argv, rank, ranks);
  } catch (const std::exception& e) {
    // A failure after the plan (a write to the output failed): the other ranks may wait in a
    // collective, so the whole job is aborted.
    std::fprintf(stderr, "dfchaos-sweep-mpi: error (rank %d): %s\n", rank, e.what());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, kExitFailed);
  }
  MPI_Finalize();
  return status;
}
