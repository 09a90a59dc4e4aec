// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bench_plane.cpp
/// @brief The cost of the report's parameter plane, run by `make bench` (bench_return_map): the
/// region of experiments/thm1_parameter_plane at 100 x 100 (q/a: cell centres of (sin vartheta0, 1);
/// b/a: log-spaced in [1e-4, 0.1]; covering and superstable at each cell) computed by the sweep
/// engine with all OpenMP threads, with every evaluation of T counted (t_evaluations.hpp).
///
///     bench_plane [--nq N] [--nb N]      (1 <= N <= 2000; default 100 x 100)
///
/// Prints `key value` lines: cells, T_evaluations, seconds (wall), cpu_seconds (all threads),
/// threads, errors. It is a separate
/// executable because counting wraps every call of T in the process, which must not touch the
/// timings of bench_return_map.
#include <omp.h>
#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "kit/options.hpp"
#include "sweep/engine.hpp"
#include "t_evaluations.hpp"

namespace {
constexpr long long kDefaultN = 100;  ///< 100 x 100: the report's plane, at which docs/performance.md gives the per-cell cost
constexpr long long kMaxN = 2000;     ///< as thm1_parameter_plane's bounds

/// CPU seconds of this process so far (all threads).
double cpu_seconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
}  // namespace

int main(int argc, char** argv) {
  using namespace dfchaos;
  long long nq = kDefaultN, nb = kDefaultN;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if ((a == "--nq" || a == "--nb") && i + 1 < argc) {
        const double v = kit::parse_number(a.substr(2), argv[++i], true);
        if (v < 1 || v > kMaxN) throw InvalidParameter(a.substr(2), "1 <= N <= 2000", v);
        (a == "--nq" ? nq : nb) = static_cast<long long>(v);
      } else {
        throw InvalidParameter("arguments", "usage: bench_plane [--nq N] [--nb N] (got '" + a + "')");
      }
    }
  } catch (const InvalidParameter& e) {
    std::fprintf(stderr, "bench_plane: error: %s\n", e.what());
    return 2;
  }
  sweep::Spec spec;
  spec.q_over_a = sweep::Range::parse("q-range", format_double(std::sin(vartheta0())) + ":1:" + std::to_string(nq) + ":mid");
  spec.b_over_a = sweep::Range::parse("b-range", "1e-4:0.1:" + std::to_string(nb) + ":log");
  spec.observables = sweep::ObservableSet::parse("observables", "covering,superstable");
  spec.validate();
  std::vector<long long> cells;
  for (long long k = 0; k < spec.cells(); ++k) cells.push_back(k);
  const long long before = T_evaluations();
  const double cpu_start = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  const auto rows = sweep::compute_rows(spec, cells, nullptr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpu_seconds() - cpu_start;
  const long long evaluations = T_evaluations() - before;
  long long errors = 0;
  for (const auto& r : rows) errors += r.find("\terror\t") != std::string::npos;
  std::printf("cells %lld\nT_evaluations %lld\nseconds %.6f\ncpu_seconds %.6f\nthreads %d\nerrors %lld\n", spec.cells(), evaluations, seconds, cpu,
              omp_get_max_threads(), errors);
  return 0;
}
