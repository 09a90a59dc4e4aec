// SPDX-License-Identifier: GPL-3.0-or-later
/// @file invariant_density.cpp
/// @brief The histogram estimate of the invariant density of T (invariant_density.hpp).
#include "dfchaos/invariant_density.hpp"

#include <cmath>

#include "dfchaos/errors.hpp"
#include "dfchaos/orbit.hpp"

namespace dfchaos {

double OrbitHistogram::bin_width() const { return (hi - lo) / static_cast<double>(counts.size()); }

double OrbitHistogram::bin_lo(int k) const { return lo + (hi - lo) * k / static_cast<double>(counts.size()); }

double OrbitHistogram::density(int k) const {
  return static_cast<double>(counts.at(static_cast<std::size_t>(k))) / (static_cast<double>(steps) * bin_width());
}

double OrbitHistogram::atom_mass() const { return static_cast<double>(at_t2) / static_cast<double>(steps); }

double OrbitHistogram::total_mass() const {
  long double sum = 0;
  const long double h = bin_width();
  for (std::size_t k = 0; k < counts.size(); ++k) sum += static_cast<long double>(density(static_cast<int>(k))) * h;
  return static_cast<double>(sum + atom_mass());
}

OrbitHistogram orbit_histogram(const Parameters& p, double theta0, long long transient, long long steps, int bins) {
  p.require_return_map();
  const double t2 = p.t2_required(), t3 = p.t3_required();
  if (!p.in_map_domain(theta0)) throw InvalidParameter("theta", "t2 <= theta < t3", theta0);
  if (transient < 0 || transient > 1'000'000'000) throw InvalidParameter("transient", "0 <= transient <= 10^9", static_cast<double>(transient));
  if (steps < 1 || steps > 1'000'000'000) throw InvalidParameter("steps", "1 <= steps <= 10^9", static_cast<double>(steps));
  if (bins < 1 || bins > 1'000'000) throw InvalidParameter("bins", "1 <= bins <= 10^6", bins);
  OrbitHistogram h;
  h.lo = t2;
  h.hi = t3;
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  long long visits = 0;  // of t2, from theta0 on (the transient included)
  // theta is the point with index n from theta0: noted if it is t2, counted from index `transient` on
  auto visit = [&](long long n, double theta) {
    if (theta == t2) {
      if (visits == 0)
        h.first_t2 = n;
      else if (visits == 1)
        h.t2_return = n - h.first_t2;
      ++visits;
    }
    if (n < transient) return;
    if (theta == t2) {
      ++h.at_t2;
    } else if (p.in_map_domain(theta)) {
      // the bin of theta; rounding can put a point just below t3 into bin K: clamp
      const auto k = static_cast<long long>(std::floor((theta - t2) / (t3 - t2) * bins));
      ++h.counts[static_cast<std::size_t>(std::min<long long>(std::max<long long>(k, 0), bins - 1))];
    } else {
      ++h.outside;
    }
  };
  // the points theta_0 .. theta_{transient + steps - 1}: the steps from all but the last one
  const long long points = transient + steps;
  const Orbit orbit(p, theta0, points - 1);
  double last = theta0;
  for (auto it = orbit.begin(); it != orbit.end(); ++it) {
    visit(it.n(), it->theta);
    last = it->T;
  }
  visit(points - 1, last);
  h.steps = steps;
  return h;
}

double l1_distance(const OrbitHistogram& f, const OrbitHistogram& g) {
  if (f.counts.size() != g.counts.size() || f.lo != g.lo || f.hi != g.hi)
    throw InvalidParameter("bins", "both histograms on the same bins of the same arc");
  long double sum = 0;
  const long double h = f.bin_width();
  for (std::size_t k = 0; k < f.counts.size(); ++k)
    sum += std::fabs(static_cast<long double>(f.density(static_cast<int>(k))) - g.density(static_cast<int>(k))) * h;
  return static_cast<double>(sum + std::fabs(f.atom_mass() - g.atom_mass()));
}

}  // namespace dfchaos
