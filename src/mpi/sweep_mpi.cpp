// SPDX-License-Identifier: GPL-3.0-or-later
/// @file sweep_mpi.cpp
/// @brief `dfchaos-sweep-mpi`: the sweep of `dfchaos sweep` distributed over MPI ranks, with the
/// same options and byte for byte the same output.
///
///     mpirun -np R dfchaos-sweep-mpi --q-range LO:HI:N[:KIND] --b-range LO:HI:N[:KIND] [options]
///
/// Rank 0 checks the request, owns the output (stdout, --out FILE or the checkpoint of --resume
/// FILE) and plans the chunks, and broadcasts the plan; then the cells are shared out dynamically
/// (dispatch.hpp): every rank, rank 0 included, computes batches of cells with its OpenMP threads,
/// and rank 0 writes the rows in cell order as chunks complete. Bad input: one line from rank 0,
/// every rank exits with status 2. With --progress, rank 0 ends with one line on stderr: the wall
/// time, each rank's CPU seconds and wall seconds spent on cells, and the utilization (the mean
/// share of the wall time the ranks spent on cells: 1 when no rank ever waited).
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "dfchaos/errors.hpp"
#include "dispatch.hpp"
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
  std::vector<sweep::Interval> chunks;
  for (long long k = 0; k < verdict.chunks; ++k)
    chunks.push_back(sweep::Interval{plan[static_cast<std::size_t>(2 * k)], plan[static_cast<std::size_t>(2 * k + 1)]});
  const sweep::mpi::Queue queue(options.shard.value_or(sweep::Shard{}), std::move(chunks));
  const auto wall_start = std::chrono::steady_clock::now();
  const sweep::mpi::Busy busy = rank == kRoot ? sweep::mpi::serve(*job, queue, ranks) : sweep::mpi::work(options.spec, queue);
  const double mine[2] = {busy.cpu, busy.wall};
  std::vector<double> by_rank(static_cast<std::size_t>(2 * ranks));
  MPI_Gather(mine, 2, MPI_DOUBLE, by_rank.data(), 2, MPI_DOUBLE, kRoot, MPI_COMM_WORLD);
  long long status = rank == kRoot ? job->finish() : 0;
  if (rank == kRoot && options.progress && queue.size() > 0) {
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    std::string cpu, busy_wall;
    double sum = 0;
    for (int r = 0; r < ranks; ++r) {
      cpu += (r ? " " : "") + kit::format_significant(by_rank[2 * static_cast<std::size_t>(r)], 4);
      busy_wall += (r ? " " : "") + kit::format_significant(by_rank[2 * static_cast<std::size_t>(r) + 1], 4);
      sum += by_rank[2 * static_cast<std::size_t>(r) + 1];
    }
    std::fprintf(stderr,
                 "dfchaos-sweep-mpi: %lld cells on %d ranks in %.3f s; cpu seconds per rank: %s; busy seconds per rank: %s; utilization %.4f\n",
                 queue.size(), ranks, wall, cpu.c_str(), busy_wall.c_str(), wall > 0 ? sum / (ranks * wall) : 1.0);
  }
  MPI_Bcast(&status, 1, MPI_LONG_LONG, kRoot, MPI_COMM_WORLD);
  return static_cast<int>(status);
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);  // only the main thread calls MPI
  dfchaos::kit::remove_temporaries_on_signals();                  // rank 0's output temporary goes with a SIGINT/SIGTERM/SIGHUP
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
