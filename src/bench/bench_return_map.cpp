/// @file bench_return_map.cpp
/// @brief `make bench`: evaluations of the return map T per second, dfchaos's closed-form root
/// isolation against the way one would do it without dfchaos (integrating the equations of motion
/// with GSL odeiv2 rk8pd, events located by bisection to 1e-12), at b/a = 1e-1 ... 1e-6, q/a = 0.85,
/// theta spread over [t2, t3). Both are measured in the same run. Writes BUILD/bench/bench.json and
/// BUILD/bench/bench.tex (the table of the report; not in the manifest: timings vary), and says which performance targets are met:
///   - ours at least 100 times faster than the baseline at b/a = 1e-2, 10^4 times at b/a = 1e-4;
///   - our cost per evaluation varies by less than a factor 3 over b/a in [1e-6, 1e-1].
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "dfchaos/errors.hpp"
#include "kit/output.hpp"
#include "kit/json.hpp"
#include "kit/format.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/return_map.hpp"

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

/// Collects seconds per iteration of every run while printing as usual.
class Collector : public benchmark::ConsoleReporter {
 public:
  Collector() : benchmark::ConsoleReporter(benchmark::ConsoleReporter::OO_Tabular) {}
  std::map<std::string, double> seconds;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs)
      if (r.iterations > 0) seconds[r.benchmark_name()] = r.real_accumulated_time / static_cast<double>(r.iterations);
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
    if (a.rfind("--out=", 0) == 0) out = a.substr(6);
    else args.push_back(argv[i]);
  }
  if (std::find_if(args.begin(), args.end(), [](const char* a) { return std::string(a) == "--out"; }) != args.end()) {
    std::fprintf(stderr, "bench_return_map: error: out: write --out=DIR\n");
    return 2;
  }
  // Ours: Google Benchmark picks the iteration count (cycling through the phases). Baseline: fixed
  // counts of passes over all phases, since one evaluation at b/a = 1e-6 integrates a flight of up
  // to 10^6 time units.
  const int baseline_iterations[] = {8, 4, 2, 1, 1, 1};
  for (int k = 0; k < static_cast<int>(kRatios.size()); ++k) {
    benchmark::RegisterBenchmark(("T_closed_form/" + std::to_string(k)).c_str(), bm_closed_form)->Arg(k)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("T_ode_baseline/" + std::to_string(k)).c_str(), bm_ode_baseline)
        ->Arg(k)->Iterations(baseline_iterations[k])->Unit(benchmark::kMillisecond);
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();

  Json doc = Json::object();
  doc.set("q_over_a", kQ).set("phases", kPhases);
  Json rows = Json::array();
  std::string tex = "% generated by bench_return_map (make bench); do not edit\n\\begin{tabular}{rrrrrrr}\n\\toprule\n"
                    "$b/a$ & dfchaos [$\\mu$s] & ODE [ms] & speed-up & dfchaos evaluations/s & "
                    "ODE gave up & $\\max|T_{\\mathrm{ODE}}-T|$\\\\\n\\midrule\n";
  double ours_min = INFINITY, ours_max = 0;
  std::size_t rows_measured = 0;
  std::map<double, double> speedup;
  for (std::size_t k = 0; k < kRatios.size(); ++k) {
    const auto a = collector.seconds.find("T_closed_form/" + std::to_string(k) + "/" + std::to_string(k));
    const auto b = collector.seconds.find("T_ode_baseline/" + std::to_string(k) + "/" + std::to_string(k) + "/iterations:" +
                                          std::to_string(baseline_iterations[k]));
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
        if (std::isnan(it->second[i])) ++gave_up;
        else max_diff = std::max(max_diff, circle_distance(it->second[i], T(p, th[i])));
      }
    }
    const bool base_lower_bound = gave_up > 0;
    ++rows_measured;
    ours_min = std::min(ours_min, ours);
    ours_max = std::max(ours_max, ours);
    speedup[kRatios[k]] = base / ours;
    Json r = Json::object();
    r.set("b_over_a", kRatios[k]).set("dfchaos_seconds", ours).set("baseline_seconds", base).set("speedup", base / ours)
        .set("dfchaos_evaluations_per_second", 1.0 / ours).set("baseline_gave_up", gave_up)
        .set("baseline_seconds_is_lower_bound", base_lower_bound).set("max_abs_T_difference", max_diff);
    rows.push(r);
    const std::string geq = base_lower_bound ? "$\\ge$" : "";
    tex += latex_number(format_significant(kRatios[k], 1)) + " & " + format_significant(ours * 1e6, 3) + " & " +
           (std::isnan(base) ? std::string("---") : geq + latex_number(format_significant(base * 1e3, 3))) + " & " +
           (std::isnan(base) ? std::string("---") : geq + latex_number(format_significant(base / ours, 3))) + " & " + latex_number(format_significant(1.0 / ours, 3)) +
           " & " + (std::isnan(base) ? std::string("---") : std::to_string(gave_up) + "/" + std::to_string(kPhases)) + " & " +
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
  if (ours_max > 0 && rows_measured == kRatios.size()) targets.push(target("dfchaos cost varies < 3x over b/a in [1e-6, 1e-1]", ours_max / ours_min < 3, ours_max / ours_min));
  doc.set("targets", targets);
  const bool complete = rows_measured == kRatios.size() && collector.seconds.size() == 2 * kRatios.size();
  if (out.empty()) {
    std::printf("bench: no --out=DIR given: nothing written\n");
    return 0;
  }
  if (!complete) {
    std::printf("bench: %zu of %zu benchmarks measured (a filter or a listing): nothing written\n", collector.seconds.size(),
                2 * kRatios.size());
    return 0;
  }
  try {
    write_all_or_nothing({{std::filesystem::path(out) / "bench" / "bench.json", doc.dump()},
                          {std::filesystem::path(out) / "bench" / "bench.tex", tex}});
  } catch (const OutputError& e) {
    std::fprintf(stderr, "bench_return_map: error: %s\n", e.what());
    return e.bad_path() ? 2 : 1;
  }
  std::printf("bench: wrote %s/bench/bench.json and %s/bench/bench.tex\n", out.c_str(), out.c_str());
  return 0;
}
