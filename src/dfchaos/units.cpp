// SPDX-License-Identifier: GPL-3.0-or-later
/// @file units.cpp
/// @brief The physical model to (a, b, q) (units.hpp, docs/units.md).
#include "dfchaos/units.hpp"

#include <cmath>

#include "dfchaos/errors.hpp"

namespace dfchaos {

namespace {
double positive(const char* name, const char* unit, double x) {
  if (!(std::isfinite(x) && x > 0)) throw InvalidParameter(name, std::string("0 < ") + name + " < inf (" + unit + ")", x);
  return x;
}
}  // namespace

namespace {
/// s = (m omega) omega, the force per unit of length (N/m for SI input), finite and positive.
double force_per_length(double mass, double omega) {
  const double s = mass * omega * omega;
  if (!(std::isfinite(s) && s > 0)) throw InvalidParameter("omega", "mass * omega^2 finite and positive", s);
  return s;
}
}  // namespace

double length_scale(double mass, double omega, double amplitude) {
  positive("mass", "kg", mass);
  positive("omega", "rad/s", omega);
  positive("amplitude", "N", amplitude);
  return amplitude / force_per_length(mass, omega);
}

Parameters from_physical(double mass, double omega, double amplitude, double static_force, double friction) {
  positive("mass", "kg", mass);
  positive("omega", "rad/s", omega);
  positive("amplitude", "N", amplitude);
  positive("static_force", "N", static_force);
  positive("friction", "N", friction);
  const double s = force_per_length(mass, omega);
  return Parameters(length_scale(mass, omega, amplitude), static_force / (2 * s), friction / s);
}

}  // namespace dfchaos
