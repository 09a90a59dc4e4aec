#include "dfchaos/motion.hpp"

#include <cmath>

namespace dfchaos {

const char* regime_code(Regime r) {
  switch (r) {
    case Regime::Free: return "f";
    case Regime::Progression: return "p";
    case Regime::Stop: return "s";
  }
  return "?";
}

FreeMotion::FreeMotion(const Parameters& p, const Instant& start_, double x_s, double v_s)
    : a(p.a()), b(p.b()), start(start_), x_start(x_s), v_start(v_s) {}

double FreeMotion::position(const Instant& t) const {
  const long double s = elapsed(start, t);
  const long double poly = (b * s + (v_start + a * std::cos(start.phase))) * s + x_start + a * std::sin(start.phase);
  return static_cast<double>(poly - a * std::sin(t.phase));
}

double FreeMotion::velocity(const Instant& t) const {
  const long double s = elapsed(start, t);
  return static_cast<double>(2 * b * s + v_start + a * std::cos(start.phase) - a * std::cos(t.phase));
}

QuadraticPlusHarmonic FreeMotion::gap(double y) const {
  QuadraticPlusHarmonic f;
  f.origin = start;
  f.alpha = b;
  f.beta = static_cast<long double>(v_start) + a * std::cos(start.phase);
  // (x_start - y) is formed first: exactly 0 at contact, so that f(origin) = 0 exactly.
  f.gamma = static_cast<long double>(x_start - y) + a * std::sin(start.phase);
  f.A = -a;
  f.B = 0;
  f.starts_at_rest = (x_start == y && v_start == 0);
  return f;
}

ProgressionMotion::ProgressionMotion(const Parameters& p, const Instant& start_, double x_s, double v_s)
    : a(p.a()), c(p.c()), start(start_), x_start(x_s), v_start(v_s) {}

double ProgressionMotion::position(const Instant& t) const {
  const long double s = elapsed(start, t);
  const long double poly = (c * s + (v_start + a * std::cos(start.phase))) * s + x_start + a * std::sin(start.phase);
  return static_cast<double>(poly - a * std::sin(t.phase));
}

double ProgressionMotion::velocity(const Instant& t) const {
  const long double s = elapsed(start, t);
  return static_cast<double>(v_start + 2 * c * s - a * (std::cos(t.phase) - std::cos(start.phase)));
}

QuadraticPlusHarmonic ProgressionMotion::minus_velocity() const {
  QuadraticPlusHarmonic f;
  f.origin = start;
  f.alpha = 0;
  f.beta = -2.0L * c;
  f.gamma = -static_cast<long double>(v_start) - a * std::cos(start.phase);
  f.A = 0;
  f.B = a;
  f.starts_at_rest = (v_start == 0);
  return f;
}

}  // namespace dfchaos
