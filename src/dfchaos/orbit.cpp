// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/orbit.hpp"

#include "dfchaos/stop.hpp"

namespace dfchaos {

Orbit::iterator::iterator(const Parameters& p, double theta0, long long steps) : p_(&p), steps_(steps), time_(theta0) {
  if (steps_ > 0) step_ = return_map_step(p, theta0);
}

Orbit::iterator& Orbit::iterator::operator++() {
  poll_stop();  // stop.hpp: every step of an orbit is a poll
  time_ += step_.elapsed;
  y_ += step_.penetration;
  if (++n_ < steps_) step_ = return_map_step(*p_, step_.T);
  return *this;
}

double T_power(const Parameters& p, double theta, long long n) {
  for (const MapStep& s : Orbit(p, theta, n)) theta = s.T;
  return theta;
}

}  // namespace dfchaos
