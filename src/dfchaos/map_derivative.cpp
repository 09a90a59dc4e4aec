// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/map_derivative.hpp"

#include <cmath>
#include <limits>

#include "dfchaos/errors.hpp"
#include "dfchaos/orbit.hpp"

namespace dfchaos {

MapDerivative map_derivative(const Parameters& p, const MapStep& step) {
  MapDerivative d;
  d.scenario = step.scenario;
  const double a = p.a(), b = p.b(), q = p.q(), c = b - q / 2;
  const double theta = step.theta;
  const double s1 = static_cast<double>(elapsed(Instant::at_phase(theta), step.hit.t1));
  const double v1 = step.hit.hit_velocity;
  d.dtheta1 = v1 != 0 ? (2 * b + a * std::sin(theta)) * s1 / v1 : std::numeric_limits<double>::quiet_NaN();
  if (step.scenario == Scenario::A) {
    const double denom = 2 * c + a * std::sin(step.theta2.phase);
    d.dT = (2 * b + a * std::sin(theta) - q * d.dtheta1) / denom;
  } else if (step.scenario == Scenario::Grazing || step.scenario == Scenario::Other) {
    d.dT = std::numeric_limits<double>::quiet_NaN();
  } else {
    d.flat = true;
    d.dT = 0;
  }
  return d;
}

MapDerivative map_derivative(const Parameters& p, double theta) { return map_derivative(p, return_map_step(p, theta)); }

OrbitStatistics orbit_statistics(const Parameters& p, double theta0, long long transient, long long steps, int keep) {
  if (transient < 0 || transient > 1'000'000'000) throw InvalidParameter("transient", "0 <= transient <= 10^9", static_cast<double>(transient));
  if (steps < 1 || steps > 1'000'000'000) throw InvalidParameter("steps", "1 <= steps <= 10^9", static_cast<double>(steps));
  if (keep < 0 || keep > steps) throw InvalidParameter("keep", "0 <= keep <= steps", keep);
  OrbitStatistics st;
  const double theta = T_power(p, theta0, transient);
  const double t2 = p.t2_required();
  double log_sum = 0;
  long long first_t2 = -1;
  const Orbit orbit(p, theta, steps);
  for (auto it = orbit.begin(); it != orbit.end(); ++it) {
    const MapStep& s = *it;
    const long long n = it.n();
    if (s.theta == t2) {
      if (first_t2 < 0)
        first_t2 = n;
      else if (st.period_of_t2 == 0)
        st.period_of_t2 = n - first_t2;
    }
    const MapDerivative d = map_derivative(p, s);
    if (d.flat) {
      ++st.flat_steps;
      st.last_stop_image = s.T;
    } else if (std::isfinite(d.dT))
      log_sum += std::log(std::fabs(d.dT));
    st.elapsed += s.elapsed;
    st.penetration += s.penetration;
    if (n >= steps - keep) st.tail.push_back(s.theta);
  }
  st.steps = steps;
  st.lyapunov = st.flat_steps > 0 ? -std::numeric_limits<double>::infinity() : log_sum / static_cast<double>(steps);
  st.penetration_rate = st.penetration / st.elapsed;
  return st;
}

}  // namespace dfchaos
