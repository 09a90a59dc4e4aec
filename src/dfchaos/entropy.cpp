// SPDX-License-Identifier: GPL-3.0-or-later
/// @file entropy.cpp
/// @brief Lap counts and the entropy estimate of Section 7 (entropy.hpp).
#include "dfchaos/entropy.hpp"

#include <cmath>

#include "dfchaos/errors.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

long long monotone_runs(const std::vector<double>& y) {
  long long runs = 1;
  int dir = 0;
  for (std::size_t i = 1; i < y.size(); ++i) {
    const double d = y[i] - y[i - 1];
    const int s = d > 0 ? 1 : (d < 0 ? -1 : 0);
    if (s != 0 && dir != 0 && s != dir) ++runs;
    if (s != 0) dir = s;
  }
  return runs;
}

std::vector<LapCount> lap_counts(const std::function<double(double)>& f, double lo, double hi, int grid, int n_max) {
  if (grid < 2) throw InvalidParameter("grid", "grid >= 2", grid);
  if (n_max < 1) throw InvalidParameter("n_max", "n_max >= 1", n_max);
  if (!(lo < hi)) throw InvalidParameter("lo", "lo < hi (a non-empty interval)", lo);
  std::vector<double> x(static_cast<std::size_t>(grid));
  for (int i = 0; i < grid; ++i) x[static_cast<std::size_t>(i)] = lo + (hi - lo) * (i + 0.5) / grid;
  std::vector<LapCount> out;
  for (int n = 1; n <= n_max; ++n) {
    for (auto& v : x) v = f(v);
    const long long laps = monotone_runs(x);
    out.push_back({n, laps, std::log(static_cast<double>(laps)) / n});
  }
  return out;
}

std::vector<LapCount> lap_counts(const Parameters& p, int grid, int n_max) {
  p.require_return_map();
  return lap_counts([&p](double theta) { return T(p, theta); }, p.t2_required(), p.t3_required(), grid, n_max);
}

}  // namespace dfchaos
