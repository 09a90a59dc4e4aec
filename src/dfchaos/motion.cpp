// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/motion.hpp"

#include <cmath>

#include "dfchaos/double_double.hpp"

namespace dfchaos {

namespace {
/// A flight lasts up to about a/b time units, and the coefficient beta of s in the gap carries its
/// rounding error times s into the gap. Up to a/b = 100 the double product a cos(theta) (error
/// ~2e-16 a, so ~2e-14 a in the gap) is kept, as it always was; above it a cos(theta) is formed in
/// long double (error ~1e-19 a, so ~1e-13 a in the gap at a/b = 1e6), and above a/b = 1e6 a
/// double-double tail adds the bits beyond long double: near a discontinuity of T1, where the
/// contact is nearly tangential, an error e in the gap moves T1 by e / |slope| (measured at
/// b/a = 1e-7 and relative distance 1e-11 from a discontinuity: 2e-9 in long double, 3e-12 with
/// the tail; tests/precision_reference.py).
constexpr double kLongDoubleBetaRatio = 100;
constexpr double kLongFlightRatio = 1e6;  ///< see kLongDoubleBetaRatio
}  // namespace

const char* regime_code(Regime r) {
  switch (r) {
    case Regime::Free: return "f";
    case Regime::Progression: return "p";
    case Regime::Stop: return "s";
  }
  return "?";
}

double HarmonicMotion::position(const Instant& t) const {
  const long double s = elapsed(start, t);
  const long double poly = (k * s + (v_start + a * std::cos(start.phase))) * s + x_start + a * std::sin(start.phase);
  return static_cast<double>(poly - a * std::sin(t.phase));
}

double HarmonicMotion::velocity(const Instant& t) const {
  const long double s = elapsed(start, t);
  return static_cast<double>(v_start + 2 * k * s - a * (std::cos(t.phase) - std::cos(start.phase)));
}

FreeMotion::FreeMotion(const Parameters& p, const Instant& start_, double x_s, double v_s)
    : HarmonicMotion{p.a(), p.b(), start_, x_s, v_s}, starts_at_t2(p.t2() && start_.phase == *p.t2()) {}

QuadraticPlusHarmonic FreeMotion::gap(double y) const {
  QuadraticPlusHarmonic f;
  f.origin = start;
  const double b = k;
  f.alpha = b;
  double sn, cs;
  ::sincos(start.phase, &sn, &cs);  // (glibc: one call for both)
  // beta multiplies s, up to 10^12 for small b/a (see kLongDoubleBetaRatio).
  if (a > kLongFlightRatio * b) {
    // Flights of more than ~10^6 time units (b/a < 1e-6): beta + beta_tail = v + a cos(theta) to
    // about 1e-31 relative.
    const dd::DD exact = dd::add(dd::two_sum(v_start, 0.0), dd::mul(dd::cos_dd(start.phase), a));
    f.beta = dd::to_long_double(exact);
    f.beta_tail = dd::to_long_double(dd::add(exact, dd::neg(dd::of(f.beta))));
  } else if (a > kLongDoubleBetaRatio * b) {
    f.beta = static_cast<long double>(v_start) + a * dd::cos_ld(start.phase);
  } else {
    f.beta = static_cast<long double>(v_start) + a * cs;
  }
  // (x_start - y) is formed first: exactly 0 at contact, so that f(origin) = 0 exactly.
  f.gamma = static_cast<long double>(x_start - y) + a * sn;
  f.A = -a;
  f.B = 0;
  f.starts_at_rest = (x_start == y && v_start == 0);
  f.origin_at_inflection = f.starts_at_rest && starts_at_t2;  // F(t2) = 0 by definition
  f.origin_trig = true;
  f.origin_sin = sn;
  f.origin_cos = cs;
  return f;
}

ProgressionMotion::ProgressionMotion(const Parameters& p, const Instant& start_, double x_s, double v_s)
    : HarmonicMotion{p.a(), p.c(), start_, x_s, v_s} {}

QuadraticPlusHarmonic ProgressionMotion::minus_velocity() const {
  QuadraticPlusHarmonic f;
  f.origin = start;
  f.alpha = 0;
  f.beta = -2.0L * k;
  double sn, cs;
  ::sincos(start.phase, &sn, &cs);  // (glibc: one call for both)
  f.gamma = -static_cast<long double>(v_start) - a * cs;
  f.A = 0;
  f.B = a;
  f.starts_at_rest = (v_start == 0);
  f.origin_trig = true;
  f.origin_sin = sn;
  f.origin_cos = cs;
  return f;
}

}  // namespace dfchaos
