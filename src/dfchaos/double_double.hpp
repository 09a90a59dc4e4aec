/// @file double_double.hpp
/// @brief Internal: double-double numbers (an unevaluated sum hi + lo, about 107 bits) built from
/// error-free transformations, and \f$\cos\f$ of a double to that precision.
///
/// Used where a quantity is multiplied by a flight time of up to \f$10^{8}\f$: the polynomial part
/// of a gap re-centred far from its origin (roots.cpp), and \f$a\cos\theta\f$, the coefficient of
/// \f$s = t - \theta\f$ in the free-flight gap (motion.cpp). Not part of the public interface.
#pragma once

#include <cmath>

namespace dfchaos::dd {

/// hi + lo with \f$|lo| \le \mathrm{ulp}(hi)/2\f$.
struct DD {
  double hi, lo;
};

/// Knuth's TwoSum: \f$a + b = s + e\f$ exactly.
inline DD two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
/// Dekker's FastTwoSum, for \f$|a| \ge |b|\f$.
inline DD fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
/// TwoProd with a fused multiply-add: \f$ab = p + e\f$ exactly.
inline DD two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}
inline DD add(DD x, DD y) {
  DD s = two_sum(x.hi, y.hi);
  const DD t = two_sum(x.lo, y.lo);
  s.lo += t.hi;
  s = fast_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return fast_two_sum(s.hi, s.lo);
}
inline DD neg(DD x) { return {-x.hi, -x.lo}; }
inline DD mul(DD x, DD y) {
  DD p = two_prod(x.hi, y.hi);
  p.lo += x.hi * y.lo + x.lo * y.hi;
  return fast_two_sum(p.hi, p.lo);
}
inline DD mul(DD x, double y) {
  DD p = two_prod(x.hi, y);
  p.lo += x.lo * y;
  return fast_two_sum(p.hi, p.lo);
}
inline DD div(DD x, double y) {
  const double q1 = x.hi / y;
  const DD p = two_prod(q1, y);
  const double q2 = ((x.hi - p.hi) - p.lo + x.lo) / y;
  return fast_two_sum(q1, q2);
}
/// A long double (64-bit significand) is exactly the sum of two doubles.
inline DD of(long double x) {
  const double hi = static_cast<double>(x);
  return {hi, static_cast<double>(x - hi)};
}
inline long double to_long_double(DD x) { return static_cast<long double>(x.hi) + x.lo; }

/// \f$2\pi\f$ = hi + lo to \f$6\cdot 10^{-33}\f$.
inline constexpr DD kTwoPi{6.283185307179586, 2.4492935982947064e-16};

/// \f$\cos x\f$ for a double \f$|x| \le 8\f$, to about \f$10^{-31}\f$: \f$x = n\pi/2 + r\f$ with
/// \f$|r| \le \pi/4\f$ (\f$\pi/2\f$ in three parts, the reduction exact to \f$10^{-32}\f$), then the
/// Taylor series of \f$\cos r\f$ or \f$\sin r\f$ summed until the terms fall below \f$10^{-34}\f$
/// (at most 17 terms).
inline DD cos_dd(double x) {
  constexpr double pio2_1 = 1.5707963267948966, pio2_2 = 6.123233995736766e-17, pio2_3 = -1.4973849048591698e-33;
  const double n = std::nearbyint(x / pio2_1);
  DD r = add(two_sum(x, 0.0), neg(two_prod(n, pio2_1)));
  r = add(r, neg(two_prod(n, pio2_2)));
  r = add(r, DD{-n * pio2_3, 0.0});
  const DD r2 = mul(r, r);
  const long q = static_cast<long>(n) & 3;
  // cos r = sum (-1)^k r^2k/(2k)!,  sin r = r sum (-1)^k r^2k/(2k+1)!
  const bool want_sin = (q == 1 || q == 3);
  DD term{1.0, 0.0}, sum{1.0, 0.0};
  for (int k = 1; k <= 17; ++k) {
    const double d = want_sin ? (2.0 * k) * (2.0 * k + 1) : (2.0 * k - 1) * (2.0 * k);
    term = neg(div(mul(term, r2), d));
    sum = add(sum, term);
    if (std::fabs(term.hi) < 1e-34) break;
  }
  if (want_sin) sum = mul(sum, r);
  // cos(n pi/2 + r): q = 0: cos r; 1: -sin r; 2: -cos r; 3: sin r.
  return (q == 1 || q == 2) ? neg(sum) : sum;
}

}  // namespace dfchaos::dd
