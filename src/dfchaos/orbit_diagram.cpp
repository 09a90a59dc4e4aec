// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/orbit_diagram.hpp"

#include <algorithm>
#include <string>

#include "dfchaos/errors.hpp"

namespace dfchaos {

OrbitDiagramColumn orbit_diagram_column(const Parameters& p, double theta0, long long transient, long long steps, int keep) {
  OrbitDiagramColumn c{orbit_statistics(p, theta0, transient, steps, keep), {}};
  // The cycle the orbit fell onto is that of t2: followed again from t2, with its error. When that
  // gives up, the column stays unmarked: the orbit itself was followed.
  if (c.orbit.period_of_t2 > 0) {
    try {
      c.cycle = t2_cycle(p, c.orbit.period_of_t2);
    } catch (const GaveUp&) {
      c.cycle = StopCycle{};
    } catch (const InvalidParameter&) {
      c.cycle = StopCycle{};
    }
  }
  return c;
}

void OrbitDiagramSettings::validate() const {
  if (!(theta0_fraction >= 0 && theta0_fraction < 1)) throw InvalidParameter("theta0-fraction", "0 <= f < 1", theta0_fraction);
  if (transient < 0 || transient > 100'000'000) throw InvalidParameter("transient", "0 <= transient <= 1e8", static_cast<double>(transient));
  if (steps < 1 || steps > 100'000'000) throw InvalidParameter("steps", "1 <= steps <= 1e8", static_cast<double>(steps));
  if (keep < 1 || keep > std::min<long long>(steps, 100'000))
    throw InvalidParameter("keep", "1 <= keep <= min(steps, 1e5) (steps = " + std::to_string(steps) + ")", static_cast<double>(keep));
}

double orbit_diagram_start(const Parameters& p, double theta0_fraction) {
  const double t2 = p.t2_required(), t3 = p.t3_required();
  return t2 + theta0_fraction * (t3 - t2);
}

}  // namespace dfchaos
