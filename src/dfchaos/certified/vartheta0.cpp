// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/vartheta0.hpp"

#include <cmath>

#include "dfchaos/certified/bisect.hpp"

namespace dfchaos::certified {

double correctly_rounded(const Ball& x) {
  const double d = x.mid();
  if (!std::isfinite(d) || d == 0) return NAN;
  const Ball D(d), lo(std::nextafter(d, -INFINITY)), hi(std::nextafter(d, INFINITY));
  const Ball lo_half = (D + lo) * 0.5, hi_half = (D + hi) * 0.5;  // exact: dyadic
  return lt(lo_half, x) && lt(x, hi_half) ? d : NAN;
}

Vartheta0 certify_vartheta0(long bits) {
  PrecisionScope scope(bits);
  Vartheta0 r;
  r.bits = bits;
  const Ball pi = Ball::pi();
  auto f = [&](const Ball& v) { return pi - v - cot(v * 0.5); };
  Ball lo(0.5), hi(1.0);
  if (!f(lo).is_negative() || !f(hi).is_positive()) {
    r.verdict = Outcome::fail("Eq. (1): sign change", "f(1/2) < 0 < f(1) not proved");
    return r;
  }
  // f > 0 at hi, f < 0 at lo; the search stops where the midpoint is within rounding of the root
  // (the bracket is then as narrow as it gets)
  r.value = enclose_sign_change(f, hi, lo, static_cast<int>(4 * bits));
  // The ends of the enclosure as exact numbers with proved signs: the witnesses of a certificate.
  r.bracket_lo = r.value.lower_ball();
  r.bracket_hi = r.value.upper_ball();
  if (!f(r.bracket_lo).is_negative() || !f(r.bracket_hi).is_positive()) {
    r.verdict = Outcome::fail("Eq. (1): bracket ends", "f < 0 < f at the ends of the enclosure not proved");
    return r;
  }
  r.sine = sin(r.value);
  r.value_double = correctly_rounded(r.value);
  r.sine_double = correctly_rounded(r.sine);
  r.rounding_certified = !std::isnan(r.value_double) && !std::isnan(r.sine_double);
  r.verdict = Outcome::ok();
  return r;
}

}  // namespace dfchaos::certified
