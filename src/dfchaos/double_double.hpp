// SPDX-License-Identifier: GPL-3.0-or-later
/// @file double_double.hpp
/// @brief Internal: double-double numbers (an unevaluated sum hi + lo, about 107 bits) built from
/// error-free transformations, and \f$\cos\f$ of a double to that precision.
///
/// Used where a quantity is multiplied by a flight time of up to \f$10^{12}\f$: the polynomial part
/// of a gap re-centred far from its origin (roots.cpp), and \f$a\cos\theta\f$, the coefficient of
/// \f$s = t - \theta\f$ in the free-flight gap (motion.cpp). Not part of the public interface.
#pragma once

#include <cmath>

namespace dfchaos::dd {

/// hi + lo with \f$|lo| \le \mathrm{ulp}(hi)/2\f$.
struct DD {
  double hi;  ///< the leading double
  double lo;  ///< the trailing double, the rounding error of hi
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
/// Veltkamp's split: a = hi + lo exactly, each half with at most 26 significant bits.
inline DD split(double a) {
  const double t = 134217729.0 * a;  // 2^27 + 1
  const double hi = t - (t - a);
  return {hi, a - hi};
}
/// Dekker's TwoProduct: \f$ab = p + e\f$ exactly (for |ab| far from overflow). Plain arithmetic
/// rather than std::fma, which without -mfma is a library call and costs several times more.
inline DD two_prod(double a, double b) {
  const double p = a * b;
  const DD x = split(a), y = split(b);
  return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
}
/// x + y to about 107 bits (the accurate sum: both parts added with TwoSum).
inline DD add(DD x, DD y) {
  DD s = two_sum(x.hi, y.hi);
  const DD t = two_sum(x.lo, y.lo);
  s.lo += t.hi;
  s = fast_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return fast_two_sum(s.hi, s.lo);
}
/// -x, exactly.
inline DD neg(DD x) { return {-x.hi, -x.lo}; }
/// x·y to about 106 bits (the product of the leading parts exact, the cross terms in double).
inline DD mul(DD x, DD y) {
  DD p = two_prod(x.hi, y.hi);
  p.lo += x.hi * y.lo + x.lo * y.hi;
  return fast_two_sum(p.hi, p.lo);
}
/// x·y for a double y, to about 106 bits.
inline DD mul(DD x, double y) {
  DD p = two_prod(x.hi, y);
  p.lo += x.lo * y;
  return fast_two_sum(p.hi, p.lo);
}
/// x/y for a double y: the quotient of the leading part and one correction step.
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
/// hi + lo rounded to a long double.
inline long double to_long_double(DD x) { return static_cast<long double>(x.hi) + x.lo; }

/// \f$2\pi\f$ = hi + lo to \f$6\cdot 10^{-33}\f$.
inline constexpr DD kTwoPi{6.283185307179586, 2.4492935982947064e-16};

/// \f$x = n\pi/2 + r\f$ for a double \f$|x| \le 8\f$, \f$|r| \le \pi/4\f$: \f$\pi/2\f$ in three parts,
/// the reduction exact to about \f$10^{-32}\f$. Returns \f$n \bmod 4\f$.
inline long reduce_pio2(double x, DD& r) {
  constexpr double pio2_1 = 1.5707963267948966, pio2_2 = 6.123233995736766e-17, pio2_3 = -1.4973849048591698e-33;
  const double n = std::nearbyint(x / pio2_1);
  r = add(two_sum(x, 0.0), neg(two_prod(n, pio2_1)));
  r = add(r, neg(two_prod(n, pio2_2)));
  r = add(r, DD{-n * pio2_3, 0.0});
  return static_cast<long>(n) & 3;
}

/// \f$\cos x\f$ for a double \f$|x| \le 8\f$, to about \f$10^{-31}\f$: with \f$x = n\pi/2 + r\f$
/// (reduce_pio2), the Taylor polynomial of \f$\cos r\f$ or \f$\sin r / r\f$ in \f$y = r^2\f$ to degree
/// 15 (remainder below \f$(\pi/4)^{32}/32! < 10^{-38}\f$) by Horner's rule: the terms of degree
/// \f$\ge 8\f$ (below \f$10^{-15}\f$) in double, the others in double-double with coefficients
/// \f$1/k!\f$ computed once.
inline DD cos_dd(double x) {
  struct Table {
    DD inv_fact[34];  // 1/k!, k = 0..33
    Table() {
      inv_fact[0] = {1.0, 0.0};
      for (int k = 1; k < 34; ++k) inv_fact[k] = div(inv_fact[k - 1], static_cast<double>(k));
    }
  };
  static const Table t;
  DD r;
  const long q = reduce_pio2(x, r);
  const DD y = mul(r, r);
  // cos r = sum_k (-1)^k y^k/(2k)!,  sin r = r sum_k (-1)^k y^k/(2k+1)!,  k = 0..15
  const int odd = (q == 1 || q == 3) ? 1 : 0;
  double tail = -t.inv_fact[30 + odd].hi;  // k = 15, sign (-1)^15
  for (int k = 14; k >= 8; --k) tail = tail * y.hi + ((k % 2) ? -1.0 : 1.0) * t.inv_fact[2 * k + odd].hi;
  DD sum{tail, 0.0};
  for (int k = 7; k >= 0; --k) {
    const DD c = t.inv_fact[2 * k + odd];
    sum = add(mul(sum, y), (k % 2) ? neg(c) : c);
  }
  if (odd) sum = mul(sum, r);
  // cos(n pi/2 + r): q = 0: cos r; 1: -sin r; 2: -cos r; 3: sin r.
  return (q == 1 || q == 2) ? neg(sum) : sum;
}

/// \f$\cos x\f$ for a double \f$|x| \le 8\f$ in long double (error about 1 ulp, \f$10^{-19}\f$):
/// \f$r = x - n\pi/2\f$ by Cody and Waite's reduction in long double (\f$\pi/2\f$ in three parts, the
/// first two short enough that \f$n\f$ times them is exact), then the Taylor polynomial of
/// \f$\cos r\f$ or \f$\sin r\f$ on \f$|r| \le \pi/4\f$ (cosl would run its slow general reduction).
inline long double cos_ld(double x) {
  constexpr double c1 = 3373259426.0 / 2147483648.0;           // pi/2 to 32 bits
  constexpr double c2 = 560513588.0 / 9223372036854775808.0;   // the next 30 bits
  constexpr long double c3 = 8.333742918520878328295864e-20L;  // the rest
  const double n = std::nearbyint(x * 0.63661977236758134);
  const long double r = ((static_cast<long double>(x) - n * c1) - static_cast<long double>(n) * c2) - n * c3;
  // Taylor polynomials on |r| <= pi/4 (remainders below (pi/4)^24/24! ~ 1e-26): cheaper than the
  // library's long-double kernels.
  const long double y = r * r;
  const long q = static_cast<long>(n) & 3;
  long double p = 0;
  // inv[j][k] = 1/((2k - 1 + j)(2k + j)), j = 0 for cos, 1 for sin
  struct Inv {
    long double v[2][12];
    constexpr Inv() : v{} {
      for (int j = 0; j < 2; ++j)
        for (int k = 1; k < 12; ++k) v[j][k] = 1.0L / ((2.0L * k - 1 + j) * (2.0L * k + j));
    }
  };
  static constexpr Inv inv{};
  const int j = (q == 0 || q == 2) ? 0 : 1;
  for (int k = 11; k >= 1; --k) p = (1.0L - p) * y * inv.v[j][k];  // nested Horner form
  p = j ? r * (1.0L - p) : 1.0L - p;
  return (q == 1 || q == 2) ? -p : p;
}

}  // namespace dfchaos::dd
