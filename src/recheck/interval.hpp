// SPDX-License-Identifier: GPL-3.0-or-later
/// @file interval.hpp
/// @brief The checker's arithmetic: exact binary numbers (MPFR) and closed intervals (MPFI), outward
/// rounded, at 256 bits; and the comparisons every step of a check is made of.
#pragma once

#include <mpfi.h>
#include <mpfr.h>

namespace recheck {

constexpr mpfr_prec_t kPrecision = 256;  // every number and interval of the checker

/// An exact binary number (MPFR, kPrecision bits).
struct Num {
  mpfr_t x;
  Num() { mpfr_init2(x, kPrecision); }
  Num(const Num& o) : Num() { mpfr_set(x, o.x, MPFR_RNDN); }
  Num& operator=(const Num& o) {
    mpfr_set(x, o.x, MPFR_RNDN);
    return *this;
  }
  ~Num() { mpfr_clear(x); }
};

/// A closed interval (MPFI, kPrecision bits), outward rounded.
struct Iv {
  mpfi_t x;
  Iv() { mpfi_init2(x, kPrecision); }
  explicit Iv(const Num& n) : Iv() { mpfi_set_fr(x, n.x); }
  Iv(const Num& lo, const Num& hi) : Iv() { mpfi_interv_fr(x, lo.x, hi.x); }
  explicit Iv(double d) : Iv() { mpfi_set_d(x, d); }
  Iv(double lo, double hi) : Iv() { mpfi_interv_d(x, lo, hi); }
  Iv(const Iv& o) : Iv() { mpfi_set(x, o.x); }
  Iv& operator=(const Iv& o) {
    mpfi_set(x, o.x);
    return *this;
  }
  ~Iv() { mpfi_clear(x); }
  bool negative() const { return !mpfi_nan_p(x) && mpfi_is_strictly_neg(x) > 0; }  // every point < 0
  bool positive() const { return !mpfi_nan_p(x) && mpfi_is_strictly_pos(x) > 0; }  // every point > 0
};

using Binary = int (*)(mpfi_ptr, mpfi_srcptr, mpfi_srcptr);
using Unary = int (*)(mpfi_ptr, mpfi_srcptr);
inline Iv apply(Binary f, const Iv& a, const Iv& b) {
  Iv r;
  f(r.x, a.x, b.x);
  return r;
}
inline Iv apply(Unary f, const Iv& a) {
  Iv r;
  f(r.x, a.x);
  return r;
}
inline Iv operator+(const Iv& a, const Iv& b) { return apply(mpfi_add, a, b); }
inline Iv operator-(const Iv& a, const Iv& b) { return apply(mpfi_sub, a, b); }
inline Iv operator*(const Iv& a, const Iv& b) { return apply(mpfi_mul, a, b); }
inline Iv operator/(const Iv& a, const Iv& b) { return apply(mpfi_div, a, b); }
inline Iv operator*(double k, const Iv& a) { return Iv(k) * a; }
inline Iv operator-(const Iv& a) { return apply(mpfi_neg, a); }
inline Iv sqr(const Iv& a) { return apply(mpfi_sqr, a); }
inline Iv abs(const Iv& a) { return apply(mpfi_abs, a); }
inline Iv hull(const Iv& a, const Iv& b) { return apply(mpfi_union, a, b); }
inline Iv sin(const Iv& a) { return apply(mpfi_sin, a); }
inline Iv cos(const Iv& a) { return apply(mpfi_cos, a); }
inline Iv cot(const Iv& a) { return apply(mpfi_cot, a); }
inline Iv asin(const Iv& a) { return apply(mpfi_asin, a); }
inline Iv pi() {
  Iv r;
  mpfi_const_pi(r.x);
  return r;
}
/// The upper end of x, as a thin interval.
inline Iv upper(const Iv& x) {
  Num n;
  mpfi_get_right(n.x, x.x);
  return Iv(n);
}
/// Every point of x <= every point of y (resp. <).
inline bool le(const Iv& x, const Iv& y) {
  const Iv d = y - x;
  return !mpfi_nan_p(d.x) && mpfi_is_nonneg(d.x) > 0;
}
inline bool lt(const Iv& x, const Iv& y) { return (y - x).positive(); }

}  // namespace recheck
