// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/oracle.hpp"

#include <cmath>
#include <exception>
#include <new>

#include "dfchaos/next_hit.hpp"
#include "dfchaos/stop.hpp"

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
  try {
    const Parameters p(a, b, a);  // q plays no role in T1
    if (!p.t2()) return NAN;
    return next_hit(p, clamp_theta(p, theta)).t1.value();
  } catch (const Stopped&) {
    throw;  // a stop request (stop.hpp): not an answer of the search
  } catch (const std::bad_alloc&) {
    throw;  // memory ran out: not an answer of the search
  } catch (const std::exception&) {
    return NAN;
  }
}

std::optional<MapStep> step(double a, double b, double q, double theta) {
  try {
    const Parameters p(a, b, q);
    if (!p.t2() || !(q > 2 * b)) return std::nullopt;
    return return_map_step(p, clamp_theta(p, theta));
  } catch (const Stopped&) {
    throw;  // a stop request (stop.hpp): not an answer of the search
  } catch (const std::bad_alloc&) {
    throw;  // memory ran out: not an answer of the search
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

double theta2(double a, double b, double q, double theta) {
  const auto s = step(a, b, q, theta);
  return s ? s->theta2.value() : NAN;
}

}  // namespace dfchaos::certified::oracle
