// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bench_return_map.cpp
/// @brief `make bench`: evaluations of the return map T per second, dfchaos's closed-form root
/// isolation against the way one would do it without dfchaos (integrating the equations of motion
/// with GSL odeiv2 rk8pd, events located by bisection to 1e-12), at b/a = 1e-1 ... 1e-6, q/a = 0.85,
/// theta spread over [t2, t3). Both are measured in the same run. Writes BUILD/bench/bench.json and
/// BUILD/bench/bench.tex (the table of the report; not in the manifest: timings vary), and says which performance targets are met:
///   - ours at least 100 times faster than the baseline at b/a = 1e-2, 10^4 times at b/a = 1e-4;
///   - our cost per evaluation varies by less than a factor 3 over b/a in [1e-6, 1e-1];
///   - the 2-rank sweep runs at least 0.9 times twice as fast as the 1-rank one.
///
/// Also measured in the same run and written to bench.json (after a complete measurement only):
///   - `sincos_seconds` (and `sincos_cpu_seconds`): one sin+cos pair of a phase in [0, 2 pi), so that
///     the cost of T reads as a machine-independent multiple of it (`dfchaos_in_sincos` per row;
///     `cell_in_sincos` for the plane, from CPU times);
///   - `plane`: the report's plane at 100 x 100 (thm1_parameter_plane's region, covering and superstable)
///     by bench_plane: cells, T evaluations per cell, cells per second (all OpenMP threads);
///   - `scaling`: one sweep (kScalingCells cells, every observable) on 1 and on 2 MPI ranks of
///     dfchaos-sweep-mpi (one thread each, `mpiexec --oversubscribe`), or, without MPI, dfchaos sweep
///     on 1 and 2 OpenMP threads (`scaling_mode` says which), with each rank's CPU and busy seconds
///     and the utilization (the share of the wall time the ranks spent on cells), and the machine's
///     load average (other work on the machine lowers the efficiency, not the utilization); each
///     count is run twice, alternately, and the faster run counts.
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "dfchaos/errors.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/return_map.hpp"
#include "kit/format.hpp"
#include "kit/json.hpp"
#include "kit/output.hpp"

namespace {

using namespace dfchaos;
using namespace dfchaos::kit;

constexpr double kQ = 0.85;
const std::vector<double> kRatios = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
constexpr int kPhases = 16;  // phases spread over [t2, t3): the same set for both methods

std::vector<double> phases(const Parameters& p) {
  std::vector<double> th;
  const double t2 = *p.t2(), t3 = *p.t3();
  // An irrational stride spreads the phases without aligning with any structure of T.
  for (int i = 0; i < kPhases; ++i) th.push_back(t2 + (t3 - t2) * std::fmod(0.5 + i * 0.6180339887498949, 1.0));
  return th;
}

void bm_closed_form(benchmark::State& state) {
  const Parameters p(1.0, kRatios[static_cast<std::size_t>(state.range(0))], kQ);
  const auto th = phases(p);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(T(p, th[i]));
    i = (i + 1) % th.size();
  }
  state.SetLabel("b/a=" + format_significant(p.b(), 1));
}

/// What the baseline returned at each phase in its last pass (NaN where it gave up), per b/a index.
std::map<std::size_t, std::vector<double>> g_baseline_T;

/// One iteration evaluates the whole phase set (the flight time, hence the cost, varies with the
/// phase like |cos theta|); the collector divides by kPhases. An evaluation that gives up (its
/// step bound, OdeMapOptions::max_steps, is reached) counts with the time it took before giving up,
/// so the baseline's time is then a lower bound.
void bm_ode_baseline(benchmark::State& state) {
  const auto k = static_cast<std::size_t>(state.range(0));
  const Parameters p(1.0, kRatios[k], kQ);
  const auto th = phases(p);
  std::vector<double> last(th.size(), NAN);
  for (auto _ : state)
    for (std::size_t i = 0; i < th.size(); ++i) {
      try {
        last[i] = ode_return_map_step(p, th[i]).T;
      } catch (const GaveUp&) {
        last[i] = NAN;
      }
      benchmark::DoNotOptimize(last[i]);
    }
  g_baseline_T[k] = last;
  state.SetLabel("b/a=" + format_significant(p.b(), 1) + ", " + std::to_string(kPhases) + " evaluations per iteration");
}

/// One sin+cos pair per iteration, of phases spread over [0, 2 pi) (the compiler turns the pair into
/// one sincos call, as in the library's root search).
void bm_sincos(benchmark::State& state) {
  double x = 0.5, acc = 0;
  for (auto _ : state) {
    acc += std::sin(x) + std::cos(x);
    benchmark::DoNotOptimize(acc);
    x += 0.6180339887498949;
    if (x >= 2 * M_PI) x -= 2 * M_PI;
  }
}

// ---- child processes: the plane and the scaling sweep ----------------------------------------------

/// Cells of the scaling sweep: a 40 x 40 plane (thm1's axes) with every observable, about 25 CPU
/// seconds here, long enough that the start-up of mpiexec (about 0.4 s) hardly counts.
constexpr int kScalingSide = 40;
constexpr long long kScalingCells = static_cast<long long>(kScalingSide) * kScalingSide;
/// A 1-minute load average above this before the scaling runs means other work shared the cores.
constexpr double kBusyLoad = 0.5;
/// Runs of each worker count (alternating), of which the fastest counts.
constexpr int kScalingRepeats = 2;

/// What a child process printed on the stream asked for, and how it ended.
struct ChildResult {
  int status = -1;     ///< exit status (-1: did not exit normally)
  std::string text;    ///< its stdout or stderr, as asked
  double seconds = 0;  ///< wall time from start to end
};

/// Runs argv[0] with `env` added to the environment, capturing its stdout (or stderr); the other
/// stream is inherited. Bounded: waits for the child to end.
ChildResult run_child(const std::vector<std::string>& argv, const std::vector<std::string>& env, bool capture_stderr) {
  ChildResult r;
  int fds[2];
  if (::pipe(fds) != 0) return r;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(fds[1], capture_stderr ? 2 : 1);
    ::close(fds[0]);
    ::close(fds[1]);
    for (const auto& e : env) ::putenv(const_cast<char*>(e.c_str()));
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    std::_Exit(127);
  }
  ::close(fds[1]);
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) r.text.append(buf, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  if (pid > 0 && ::waitpid(pid, &status, 0) == pid && WIFEXITED(status)) r.status = WEXITSTATUS(status);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

/// The value after `key ` on a line of `text` (NaN if absent).
double value_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  return at == std::string::npos ? NAN : std::strtod(text.c_str() + at + key.size(), nullptr);
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// The plane by bench_plane (NaNs in the result if it failed). Its cost per cell in sin+cos pairs
/// compares CPU times (the plane's, and one pair's), which other work on the machine does not inflate.
Json measure_plane(double sincos_cpu_seconds) {
  std::printf("bench: the plane at 100 x 100 (bench_plane) ...\n");
  std::fflush(stdout);
  const ChildResult c = run_child({DFCHAOS_BENCH_PLANE}, {}, false);
  const double cells = value_after(c.text, "cells "), evaluations = value_after(c.text, "T_evaluations "),
               seconds = value_after(c.text, "\nseconds "), threads = value_after(c.text, "threads "), cpu = value_after(c.text, "cpu_seconds ");
  Json j = Json::object();
  j.set("grid", "thm1_parameter_plane: q/a 100 cell centres of (sin vartheta0, 1), b/a 100 log-spaced in [1e-4, 0.1]")
      .set("observables", "covering,superstable")
      .set("cells", cells)
      .set("T_evaluations_per_cell", evaluations / cells)
      .set("cells_per_second", cells / seconds)
      .set("seconds", seconds)
      .set("threads", threads)
      .set("cpu_seconds", cpu)
      .set("cpu_seconds_per_cell", cpu / cells)
      .set("cell_in_sincos", cpu / cells / sincos_cpu_seconds)
      .set("errors", value_after(c.text, "errors "))
      .set("exit_status", c.status);
  std::printf("bench: plane: %.0f cells, %.0f T evaluations per cell, %.1f cells/s on %.0f threads\n", cells, evaluations / cells, cells / seconds,
              threads);
  return j;
}

/// One run of the scaling sweep on `workers` ranks (or threads); its output goes to `file`.
/// One run of the scaling sweep: its record, and (NaN where not measured) its wall seconds, the
/// CPU seconds its ranks spent on cells in total, and its utilization.
struct ScalingRun {
  Json json;
  double seconds = NAN, cpu = NAN, utilization = NAN;
};

ScalingRun scaling_run(int workers, const std::filesystem::path& file, bool mpi) {
  const std::string s0 = format_double(std::sin(vartheta0()));
  const std::vector<std::string> spec = {"--q-range", s0 + ":1:" + std::to_string(kScalingSide) + ":mid",
                                         "--b-range", "1e-4:0.1:" + std::to_string(kScalingSide) + ":log",
                                         "--out",     file.string()};
  std::vector<std::string> argv, env = {"OMP_NUM_THREADS=" + std::string(mpi ? "1" : std::to_string(workers))};
#ifdef DFCHAOS_BENCH_MPI_DRIVER
  if (mpi) {
    // --bind-to none: on a shared machine the ranks must be free to move to whichever core is idle.
    argv = {DFCHAOS_BENCH_MPIEXEC, "--oversubscribe", "--bind-to", "none", "-np", std::to_string(workers), DFCHAOS_BENCH_MPI_DRIVER, "--progress"};
    if (::geteuid() == 0) env.insert(env.end(), {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"});
  }
#endif
  if (!mpi) argv = {DFCHAOS_BENCH_CLI, "sweep"};
  argv.insert(argv.end(), spec.begin(), spec.end());
  const ChildResult c = run_child(argv, env, true);
  ScalingRun result;
  Json& j = result.json;
  j = Json::object();
  // "ranks": MPI ranks, or OpenMP threads of the one process when no MPI driver was built.
  j.set("ranks", workers).set("seconds", c.seconds).set("exit_status", c.status);
  result.seconds = c.status == 0 ? c.seconds : NAN;
  if (mpi) {
    // "cpu seconds per rank: a b; busy seconds per rank: a b; utilization x" (the driver's --progress line)
    auto list = [&c](const std::string& key, double& sum) {
      Json values = Json::array();
      const auto at = c.text.find(key);
      if (at != std::string::npos) {
        std::istringstream in(c.text.substr(at + key.size(), c.text.find(';', at) - at - key.size()));
        sum = 0;
        for (double v; in >> v;) {
          values.push(v);
          sum += v;
        }
      }
      return values;
    };
    double busy_total = NAN;
    result.utilization = value_after(c.text, "utilization ");
    j.set("cpu_seconds_per_rank", list("cpu seconds per rank: ", result.cpu))
        .set("busy_seconds_per_rank", list("busy seconds per rank: ", busy_total))
        .set("utilization", result.utilization);
  }
  std::printf("bench: scaling: %d %s: %.2f s\n", workers, mpi ? "rank(s)" : "thread(s)", c.seconds);
  std::fflush(stdout);
  return result;
}

/// Collects seconds per iteration of every run while printing as usual.
class Collector : public benchmark::ConsoleReporter {
 public:
  Collector() : benchmark::ConsoleReporter(benchmark::ConsoleReporter::OO_Tabular) {}
  std::map<std::string, double> seconds;      ///< wall seconds per iteration
  std::map<std::string, double> cpu_seconds;  ///< CPU seconds per iteration (of the benchmark's thread)
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs)
      if (r.iterations > 0) {
        seconds[r.benchmark_name()] = r.real_accumulated_time / static_cast<double>(r.iterations);
        cpu_seconds[r.benchmark_name()] = r.cpu_accumulated_time / static_cast<double>(r.iterations);
      }
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  // Files are written only under --out=DIR, and only for a complete measurement (every benchmark
  // ran: no --benchmark_filter, no --benchmark_list_tests).
  std::string out;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--out=", 0) == 0)
      out = a.substr(6);
    else
      args.push_back(argv[i]);
  }
  if (std::find_if(args.begin(), args.end(), [](const char* a) { return std::string(a) == "--out"; }) != args.end()) {
    std::fprintf(stderr, "bench_return_map: error: out: write --out=DIR\n");
    return 2;
  }
  // Ours: Google Benchmark picks the iteration count (cycling through the phases). Baseline: fixed
  // counts of passes over all phases, since one evaluation at b/a = 1e-6 integrates a flight of up
  // to 10^6 time units.
  const int baseline_iterations[] = {8, 4, 2, 1, 1, 1};
  // sin+cos is measured before and after the rest, and the faster of the two counts (the less
  // disturbed by other work on the machine).
  benchmark::RegisterBenchmark("sincos/first", bm_sincos)->Unit(benchmark::kNanosecond);
  for (int k = 0; k < static_cast<int>(kRatios.size()); ++k) {
    benchmark::RegisterBenchmark(("T_closed_form/" + std::to_string(k)).c_str(), bm_closed_form)->Arg(k)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("T_ode_baseline/" + std::to_string(k)).c_str(), bm_ode_baseline)
        ->Arg(k)
        ->Iterations(baseline_iterations[k])
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("sincos/last", bm_sincos)->Unit(benchmark::kNanosecond);
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();

  auto faster = [](const std::map<std::string, double>& m) {
    const auto a = m.find("sincos/first"), b = m.find("sincos/last");
    return a == m.end() || b == m.end() ? NAN : std::min(a->second, b->second);
  };
  const double sincos_seconds = faster(collector.seconds), sincos_cpu_seconds = faster(collector.cpu_seconds);
  Json doc = Json::object();
  doc.set("q_over_a", kQ).set("phases", kPhases).set("sincos_seconds", sincos_seconds).set("sincos_cpu_seconds", sincos_cpu_seconds);
  Json rows = Json::array();
  std::string tex =
      "% generated by bench_return_map (make bench); do not edit\n\\begin{tabular}{rrrrrrr}\n\\toprule\n"
      "$b/a$ & dfchaos [$\\mu$s] & ODE [ms] & speed-up & dfchaos evaluations/s & "
      "ODE gave up & $\\max|T_{\\mathrm{ODE}}-T|$\\\\\n\\midrule\n";
  double ours_min = INFINITY, ours_max = 0;
  std::size_t rows_measured = 0;
  std::map<double, double> speedup;
  for (std::size_t k = 0; k < kRatios.size(); ++k) {
    const auto a = collector.seconds.find("T_closed_form/" + std::to_string(k) + "/" + std::to_string(k));
    const auto b = collector.seconds.find("T_ode_baseline/" + std::to_string(k) + "/" + std::to_string(k) +
                                          "/iterations:" + std::to_string(baseline_iterations[k]));
    if (a == collector.seconds.end()) continue;  // filtered out
    const double ours = a->second;
    const double base = b == collector.seconds.end() ? NAN : b->second / kPhases;
    // Agreement of the baseline with dfchaos on the same phases, and how often it gave up.
    int gave_up = 0;
    double max_diff = NAN;
    if (const auto it = g_baseline_T.find(k); it != g_baseline_T.end()) {
      const Parameters p(1.0, kRatios[k], kQ);
      const auto th = phases(p);
      max_diff = 0;
      for (std::size_t i = 0; i < th.size(); ++i) {
        if (std::isnan(it->second[i]))
          ++gave_up;
        else
          max_diff = std::max(max_diff, circle_distance(it->second[i], T(p, th[i])));
      }
    }
    const bool base_lower_bound = gave_up > 0;
    ++rows_measured;
    ours_min = std::min(ours_min, ours);
    ours_max = std::max(ours_max, ours);
    speedup[kRatios[k]] = base / ours;
    Json r = Json::object();
    r.set("b_over_a", kRatios[k])
        .set("dfchaos_seconds", ours)
        .set("baseline_seconds", base)
        .set("speedup", base / ours)
        .set("dfchaos_evaluations_per_second", 1.0 / ours)
        .set("baseline_gave_up", gave_up)
        .set("baseline_seconds_is_lower_bound", base_lower_bound)
        .set("max_abs_T_difference", max_diff)
        .set("dfchaos_in_sincos", ours / sincos_seconds);
    rows.push(r);
    const std::string geq = base_lower_bound ? "$\\ge$" : "";
    tex += latex_number(format_significant(kRatios[k], 1)) + " & " + format_significant(ours * 1e6, 3) + " & " +
           (std::isnan(base) ? std::string("---") : geq + latex_number(format_significant(base * 1e3, 3))) + " & " +
           (std::isnan(base) ? std::string("---") : geq + latex_number(format_significant(base / ours, 3))) + " & " +
           latex_number(format_significant(1.0 / ours, 3)) + " & " +
           (std::isnan(base) ? std::string("---") : std::to_string(gave_up) + "/" + std::to_string(kPhases)) + " & " +
           (std::isnan(max_diff) ? std::string("---") : latex_number(format_significant(max_diff, 2))) + "\\\\\n";
  }
  tex += "\\bottomrule\n\\end{tabular}\n";
  doc.set("results", rows);
  auto target = [&](const char* name, bool met, double value) {
    Json t = Json::object();
    const bool measured = !std::isnan(value);
    t.set("target", name).set("value", value).set("met", measured && met).set("measured", measured);
    std::printf("target %-55s %-12s (%.3g)\n", name, !measured ? "not measured" : met ? "met" : "MISSED", value);
    return t;
  };
  Json targets = Json::array();
  if (speedup.count(1e-2)) targets.push(target("speed-up >= 100 at b/a = 1e-2", speedup[1e-2] >= 100, speedup[1e-2]));
  if (speedup.count(1e-4)) targets.push(target("speed-up >= 10^4 at b/a = 1e-4", speedup[1e-4] >= 1e4, speedup[1e-4]));
  if (ours_max > 0 && rows_measured == kRatios.size())
    targets.push(target("dfchaos cost varies < 3x over b/a in [1e-6, 1e-1]", ours_max / ours_min < 3, ours_max / ours_min));
  const std::size_t benchmarks = 2 * kRatios.size() + 2;  // ours and the baseline per b/a, sincos twice
  const bool complete = rows_measured == kRatios.size() && collector.seconds.size() == benchmarks;
  if (out.empty()) {
    std::printf("bench: no --out=DIR given: nothing written\n");
    return 0;
  }
  if (!complete) {
    std::printf("bench: %zu of %zu benchmarks measured (a filter or a listing): nothing written\n", collector.seconds.size(), benchmarks);
    return 0;
  }
  // The plane and the scaling sweep: child processes, measured only for a complete run.
  doc.set("plane", measure_plane(sincos_cpu_seconds));
  {
#ifdef DFCHAOS_BENCH_MPI_DRIVER
    const bool mpi = true;
#else
    const bool mpi = false;
#endif
    double load[1] = {NAN};
    ::getloadavg(load, 1);
    const auto dir = std::filesystem::temp_directory_path() / ("dfchaos-bench-scaling-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    // Alternately 1, 2, 1, 2 workers; each entry of "scaling" is the fastest of its runs, the
    // least disturbed by anything else on the machine (all times are in "all_seconds").
    Json runs = Json::array();
    double best[2] = {INFINITY, INFINITY}, best_cpu[2] = {NAN, NAN}, best_utilization[2] = {NAN, NAN};
    Json best_run[2], all[2] = {Json::array(), Json::array()};
    for (int rep = 0; rep < kScalingRepeats; ++rep)
      for (int w = 0; w < 2; ++w) {
        const ScalingRun r = scaling_run(w + 1, dir / (std::to_string(w + 1) + ".tsv"), mpi);
        all[w].push(r.seconds);
        if (rep == 0 || r.seconds < best[w]) {
          best[w] = r.seconds;
          best_run[w] = r.json;
          best_cpu[w] = r.cpu;
          best_utilization[w] = r.utilization;
        }
      }
    for (int w = 0; w < 2; ++w) runs.push(best_run[w].set("all_seconds", all[w]));
    const double t1 = best[0], t2 = best[1];
    const bool identical = slurp(dir / "1.tsv") == slurp(dir / "2.tsv") && !slurp(dir / "1.tsv").empty();
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    const double efficiency = t1 / (2 * t2);
    // What the run would give on 2 otherwise idle cores: each rank at full speed, so the wall time
    // is the busiest rank's CPU time; = utilization x (CPU seconds on 1 rank / on 2 ranks). An
    // estimate (it leaves out mpiexec's start-up), recorded apart from the measured efficiency.
    const double cpu_ratio = best_cpu[0] / best_cpu[1], utilization2 = best_utilization[1];
    const double idle_estimate = utilization2 * cpu_ratio;
    doc.set("scaling", runs)
        .set("scaling_mode", mpi ? "mpi: dfchaos-sweep-mpi, mpiexec --oversubscribe --bind-to none -np R, 1 thread per rank"
                                 : "openmp: dfchaos sweep, OMP_NUM_THREADS = 1 and 2 (no MPI driver built)")
        .set("scaling_cells", kScalingCells)
        .set("scaling_observables", "covering,superstable,lyapunov,rate,period")
        .set("scaling_efficiency", efficiency)
        .set("scaling_outputs_identical", identical)
        .set("load_average_1min_before", load[0])
        .set("scaling_cpu_ratio", cpu_ratio)
        .set("scaling_efficiency_on_idle_cores_estimate", idle_estimate);
    if (load[0] > kBusyLoad)
      std::printf(
          "bench: the machine was busy (load average %.1f before the scaling runs): the measured efficiency understates;\n"
          "       on idle cores it would be about %.3f (utilization %.4f x CPU ratio %.3f)\n",
          load[0], idle_estimate, utilization2, cpu_ratio);
    targets.push(target("2-rank efficiency t1/(2 t2) >= 0.9", efficiency >= 0.9 && identical, efficiency));
  }
  doc.set("targets", targets);
  try {
    write_all_or_nothing(
        {{std::filesystem::path(out) / "bench" / "bench.json", doc.dump()}, {std::filesystem::path(out) / "bench" / "bench.tex", tex}});
  } catch (const OutputError& e) {
    std::fprintf(stderr, "bench_return_map: error: %s\n", e.what());
    return e.bad_path() ? 2 : 1;
  }
  std::printf("bench: wrote %s/bench/bench.json and %s/bench/bench.tex\n", out.c_str(), out.c_str());
  return 0;
}
