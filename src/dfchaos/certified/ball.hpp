// SPDX-License-Identifier: GPL-3.0-or-later
/// @file ball.hpp
/// @brief A small RAII value type over Arb's `arb_t` (a midpoint-radius ball of real numbers), the
/// arithmetic of the certified layer.
///
/// Every operation returns a ball that contains the exact result for every choice of the
/// arguments inside their balls (Arb's guarantee). Predicates are *certain*: `is_negative()` is
/// true only when every point of the ball is negative; false means "negative not proved", never
/// "non-negative". A double converts exactly (it is a dyadic rational), so a parameter given as a
/// double is the exact binary number, not the decimal it was typed as.
///
/// Precision: all arithmetic on a thread uses `precision()` bits (default 128), changed for a scope
/// with PrecisionScope.
#pragma once

#include <arb.h>

#include <string>
#include <utility>

#include "dfchaos/model.hpp"

namespace dfchaos::certified {

/// Makes an allocation failure inside Arb, FLINT or GMP (which cannot throw: by default they
/// print a message and abort) call `on_failure` instead, which must not return (e.g. print one
/// line and exit). Replaces their memory functions for the whole process; call before any ball
/// exists. The standard allocator is used otherwise.
void on_allocation_failure(void (*on_failure)());

/// Working precision in bits of the Ball arithmetic of this thread (default 128).
long precision();

/// Sets the working precision of this thread for the lifetime of the object.
class PrecisionScope {
 public:
  explicit PrecisionScope(long bits);  ///< @param bits at least 32
  ~PrecisionScope();
  PrecisionScope(const PrecisionScope&) = delete;
  PrecisionScope& operator=(const PrecisionScope&) = delete;

 private:
  long saved_;
};

/// A real ball \f$[m - r, m + r]\f$ (value semantics over arb_t).
class Ball {
 public:
  Ball() { arb_init(x_); }                                  ///< exactly 0
  explicit Ball(double d);                                  ///< exactly d (finite)
  explicit Ball(long n) : Ball() { arb_set_si(x_, n); }     ///< exactly n
  Ball(const Ball& o) : Ball() { arb_set(x_, o.x_); }       ///< copy
  Ball(Ball&& o) noexcept : Ball() { arb_swap(x_, o.x_); }  ///< move
  Ball& operator=(const Ball& o) {
    if (this != &o) arb_set(x_, o.x_);
    return *this;
  }  ///< copy
  Ball& operator=(Ball&& o) noexcept {
    arb_swap(x_, o.x_);
    return *this;
  }  ///< move
  ~Ball() { arb_clear(x_); }

  /// The interval \f$[lo, hi]\f$ with exact double endpoints (lo <= hi).
  static Ball interval(double lo, double hi);
  /// The smallest ball Arb builds containing both x and y (the convex hull, slightly rounded out).
  static Ball hull(const Ball& x, const Ball& y);
  /// A decimal string, enclosed (e.g. "0.85" gives a ball of radius about 1e-38 at 128 bits).
  static Ball decimal(const std::string& s);
  /// \f$\pi\f$.
  static Ball pi();

  arb_ptr get() { return x_; }           ///< the underlying arb_t
  arb_srcptr get() const { return x_; }  ///< the underlying arb_t

  /// Greatest double not above any point of the ball (\f$-\infty\f$ if unbounded).
  double lower() const;
  /// Least double not below any point of the ball.
  double upper() const;
  /// The midpoint rounded to the nearest double.
  double mid() const;
  /// The radius rounded up to a double.
  double radius() const;
  /// The lower end as an exact ball (zero radius).
  Ball lower_ball() const;
  /// The upper end as an exact ball (zero radius).
  Ball upper_ball() const;
  /// The midpoint as an exact ball (zero radius).
  Ball mid_ball() const;

  bool is_positive() const { return arb_is_positive(x_); }               ///< every point > 0
  bool is_negative() const { return arb_is_negative(x_); }               ///< every point < 0
  bool is_nonnegative() const { return arb_is_nonnegative(x_); }         ///< every point >= 0
  bool is_nonpositive() const { return arb_is_nonpositive(x_); }         ///< every point <= 0
  bool is_finite() const { return arb_is_finite(x_); }                   ///< midpoint and radius finite
  bool is_exact() const { return arb_is_exact(x_); }                     ///< radius 0
  bool contains(double d) const;                                         ///< d is in the ball
  bool contains(const Ball& y) const { return arb_contains(x_, y.x_); }  ///< y is inside this ball

  /// Arb's decimal form "[m +/- r]" with `digits` significant digits of the midpoint.
  std::string str(long digits = 20) const;
  /// The midpoint in decimal with `digits` significant digits (rounded to nearest).
  std::string mid_str(long digits = 40) const;
  /// A ball in decimal: the strings `mid` and `rad` of \f$[m \pm r]\f$.
  struct Printed {
    std::string mid;  ///< the midpoint in decimal
    std::string rad;  ///< the radius in decimal
  };
  /// A decimal ball \f$[m \pm r]\f$ that contains this ball: m is the midpoint rounded to `digits`
  /// significant digits, and r (3 significant digits) is rounded up from
  /// \f$|m - \mathrm{mid}| + \mathrm{rad}\f$, so that the rounding of the midpoint is paid for in
  /// the radius (checked in Arb before it is returned); r is "inf" for a ball that is not finite.
  Printed printed(long digits) const;
  /// The ball as a double midpoint (the nearest double to the midpoint) and a double radius,
  /// rounded up from \f$|m - \mathrm{ball}|\f$, so that \f$[m \pm r]\f$ contains the ball.
  std::pair<double, double> enclosing_doubles() const;

 private:
  arb_t x_;
};

Ball operator+(const Ball& x, const Ball& y);  ///< x + y
Ball operator-(const Ball& x, const Ball& y);  ///< x - y
Ball operator*(const Ball& x, const Ball& y);  ///< x y
Ball operator/(const Ball& x, const Ball& y);  ///< x / y (infinite radius if y contains 0)
Ball operator-(const Ball& x);                 ///< -x
Ball operator+(const Ball& x, double y);       ///< x + y (y exact)
Ball operator-(const Ball& x, double y);       ///< x - y
Ball operator*(const Ball& x, double y);       ///< x y
Ball operator*(double x, const Ball& y);       ///< x y
Ball operator/(const Ball& x, double y);       ///< x / y

Ball sin(const Ball& x);                        ///< \f$\sin x\f$
Ball cos(const Ball& x);                        ///< \f$\cos x\f$
void sin_cos(const Ball& x, Ball& s, Ball& c);  ///< both at once
Ball sqr(const Ball& x);                        ///< \f$x^2\f$ (tighter than x*x when x contains 0)
Ball sqrt(const Ball& x);                       ///< \f$\sqrt{x}\f$ (NaN-ball if x may be negative)
Ball log(const Ball& x);                        ///< \f$\ln x\f$ (NaN-ball if x may be non-positive)
Ball asin(const Ball& x);                       ///< \f$\arcsin x\f$
Ball cot(const Ball& x);                        ///< \f$\cot x\f$
Ball abs(const Ball& x);                        ///< \f$|x|\f$
Ball max(const Ball& x, const Ball& y);         ///< pointwise maximum
Ball min(const Ball& x, const Ball& y);         ///< pointwise minimum

/// Certainly \f$x < y\f$ for all points.
inline bool lt(const Ball& x, const Ball& y) { return arb_lt(x.get(), y.get()); }
/// Certainly \f$x \le y\f$ for all points.
inline bool le(const Ball& x, const Ball& y) { return arb_le(x.get(), y.get()); }

}  // namespace dfchaos::certified

/// \f$\pi\f$ in ball arithmetic, for the model's templates (dfchaos/model.hpp).
template <>
struct dfchaos::model::Constants<dfchaos::certified::Ball> {
  static dfchaos::certified::Ball pi() { return dfchaos::certified::Ball::pi(); }  ///< \f$\pi\f$
};
