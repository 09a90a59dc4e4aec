// SPDX-License-Identifier: GPL-3.0-or-later
/// @file t_table.cpp
/// @brief The table that scripts/compare-builds.sh compares between two builds of the library: T
/// at a fixed set of phases, one line each, `b/a q/a theta T scenario` (a = 1; 17 digits).
///
/// Built outside the project against each build's libdfchaos.a, so it uses only the public API
/// that older revisions have too (Parameters, return_map_step, scenario_name, T). The phases: for
/// b/a in {0.3 ... 1e-12} and q/a in {0.85, 0.75, 0.6}, 1000 uniform random phases in [t2, t3)
/// (mt19937_64, seed 7), t2 itself, and the 8 doubles just below t3: 36 324 in all. Where the map
/// gives up or throws, T is printed as nan and the scenario as err: so at the 1 009 phases of
/// b/a = 0.3, q/a = 0.6, where q = 2b is outside the map's domain (q > 2b). They are kept so that
/// the random phases, drawn in sequence, stay those of earlier comparisons.
///
/// With `--time`: instead, the time of one evaluation of T at each b/a of `make bench`
/// (1e-1 ... 1e-6, q/a = 0.85, the bench's 16 phases), one line `b/a microseconds` each: the
/// fastest of 5 rounds of 3000 passes over the phases (steady_clock).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"

namespace {

int time_T() {
  using namespace dfchaos;
  double sink = 0;
  for (const double ba : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    const Parameters p(1.0, ba, 0.85);
    const double t2 = *p.t2(), t3 = *p.t3();
    std::vector<double> theta;  // the phases of bench_return_map
    for (int i = 0; i < 16; ++i) theta.push_back(t2 + (t3 - t2) * std::fmod(0.5 + i * 0.6180339887498949, 1.0));
    double best = INFINITY;
    for (int round = 0; round < 5; ++round) {
      const auto start = std::chrono::steady_clock::now();
      for (int pass = 0; pass < 3000; ++pass)
        for (const double th : theta) sink += T(p, th);
      const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
      best = std::min(best, us / (3000.0 * theta.size()));
    }
    std::printf("%g %.4f\n", ba, best);
  }
  return std::isfinite(sink) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace dfchaos;
  if (argc == 2 && std::string(argv[1]) == "--time") return time_T();
  if (argc != 1) {
    std::fprintf(stderr, "usage: t_table [--time]\n");
    return 2;
  }
  const double ratios[] = {0.3, 0.1, 3e-2, 1e-2, 3e-3, 1e-3, 1e-4, 1e-5, 1e-6, 1e-8, 1e-10, 1e-12};
  const double qs[] = {0.85, 0.75, 0.6};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (const double ba : ratios)
    for (const double q : qs) {
      const Parameters p(1.0, ba, q);
      if (!p.t2() || !p.t3()) continue;
      const double t2 = *p.t2(), t3 = *p.t3();
      std::vector<double> theta;
      for (int i = 0; i < 1000; ++i) theta.push_back(t2 + (t3 - t2) * uniform(rng));
      theta.push_back(t2);
      double x = t3;
      for (int i = 0; i < 8; ++i) theta.push_back(x = std::nextafter(x, 0.0));
      for (const double th : theta) {
        if (th < t2 || th >= t3) continue;
        try {
          const MapStep s = return_map_step(p, th);
          std::printf("%.17g %.17g %.17g %.17g %s\n", ba, q, th, s.T, scenario_name(s.scenario));
        } catch (const std::exception&) {
          std::printf("%.17g %.17g %.17g nan err\n", ba, q, th);
        }
      }
    }
}
