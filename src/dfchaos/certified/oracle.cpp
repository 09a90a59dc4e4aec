// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/oracle.hpp"

#include <cmath>

#include "dfchaos/next_hit.hpp"

namespace dfchaos::certified::oracle {

namespace {
double clamp_theta(const Parameters& p, double theta) {
  const double t2 = *p.t2(), t3 = *p.t3();
  if (theta < t2) return t2;
  if (theta >= t3) return std::nextafter(t3, 0.0);
  return theta;
}
}  // namespace

double T1(double a, double b, double theta) {
  double t1 = NAN;
  attempt([&] {
    const Parameters p(a, b, a);  // q plays no role in T1
    if (p.t2()) t1 = next_hit(p, clamp_theta(p, theta)).t1.value();
  });
  return t1;
}

std::optional<MapStep> step(double a, double b, double q, double theta) {
  std::optional<MapStep> s;
  attempt([&] {
    const Parameters p(a, b, q);
    if (p.t2() && q > 2 * b) s = return_map_step(p, clamp_theta(p, theta));
  });
  return s;
}

double theta2(double a, double b, double q, double theta) {
  const auto s = step(a, b, q, theta);
  return s ? s->theta2.value() : NAN;
}

}  // namespace dfchaos::certified::oracle
