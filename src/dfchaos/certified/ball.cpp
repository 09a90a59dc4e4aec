// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/ball.hpp"

#include <flint/flint.h>
#include <gmp.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace dfchaos::certified {

namespace {
void (*g_on_failure)() = nullptr;
void* checked(void* p) {
  if (p == nullptr && g_on_failure != nullptr) g_on_failure();
  return p;
}
void* alloc_or_fail(std::size_t n) { return checked(std::malloc(n)); }
void* calloc_or_fail(std::size_t n, std::size_t size) { return checked(std::calloc(n, size)); }
void* realloc_or_fail(void* p, std::size_t n) {
  void* q = std::realloc(p, n);
  return n == 0 ? q : checked(q);  // realloc to 0 bytes may return null: not a failure
}
void* gmp_realloc_or_fail(void* p, std::size_t, std::size_t n) { return realloc_or_fail(p, n); }
void gmp_free(void* p, std::size_t) { std::free(p); }
}  // namespace

void on_allocation_failure(void (*on_failure)()) {
  g_on_failure = on_failure;
  __flint_set_memory_functions(alloc_or_fail, calloc_or_fail, realloc_or_fail, std::free);
  mp_set_memory_functions(alloc_or_fail, gmp_realloc_or_fail, gmp_free);
}

namespace {
thread_local long g_prec = 128;

std::string take(char* s) {
  std::string r(s);
  flint_free(s);
  return r;
}
}  // namespace

long precision() { return g_prec; }

PrecisionScope::PrecisionScope(long bits) : saved_(g_prec) {
  if (bits < 32) throw std::invalid_argument("PrecisionScope: at least 32 bits");
  g_prec = bits;
}
PrecisionScope::~PrecisionScope() { g_prec = saved_; }

Ball::Ball(double d) : Ball() {
  if (!std::isfinite(d)) throw std::invalid_argument("Ball: non-finite double");
  arb_set_d(x_, d);
}

Ball Ball::interval(double lo, double hi) {
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) throw std::invalid_argument("Ball::interval: need finite lo <= hi");
  Ball r;
  arf_t a, b;
  arf_init(a);
  arf_init(b);
  arf_set_d(a, lo);
  arf_set_d(b, hi);
  arb_set_interval_arf(r.x_, a, b, g_prec);
  arf_clear(a);
  arf_clear(b);
  return r;
}

Ball Ball::hull(const Ball& x, const Ball& y) {
  Ball r;
  arb_union(r.x_, x.x_, y.x_, g_prec);
  return r;
}

Ball Ball::decimal(const std::string& s) {
  Ball r;
  if (arb_set_str(r.x_, s.c_str(), g_prec) != 0) throw std::invalid_argument("Ball::decimal: not a number: " + s);
  return r;
}

Ball Ball::pi() {
  Ball r;
  arb_const_pi(r.x_, g_prec);
  return r;
}

double Ball::lower() const {
  arf_t t;
  arf_init(t);
  arb_get_lbound_arf(t, x_, g_prec);
  const double d = arf_get_d(t, ARF_RND_FLOOR);
  arf_clear(t);
  return d;
}

double Ball::upper() const {
  arf_t t;
  arf_init(t);
  arb_get_ubound_arf(t, x_, g_prec);
  const double d = arf_get_d(t, ARF_RND_CEIL);
  arf_clear(t);
  return d;
}

double Ball::mid() const { return arf_get_d(arb_midref(x_), ARF_RND_NEAR); }

double Ball::radius() const { return mag_get_d(arb_radref(x_)); }

Ball Ball::lower_ball() const {
  Ball r;
  arf_t t;
  arf_init(t);
  arb_get_lbound_arf(t, x_, g_prec);
  arb_set_arf(r.x_, t);
  arf_clear(t);
  return r;
}

Ball Ball::upper_ball() const {
  Ball r;
  arf_t t;
  arf_init(t);
  arb_get_ubound_arf(t, x_, g_prec);
  arb_set_arf(r.x_, t);
  arf_clear(t);
  return r;
}

Ball Ball::mid_ball() const {
  Ball r;
  arb_set_arf(r.x_, arb_midref(x_));
  return r;
}

bool Ball::contains(double d) const {
  if (!std::isfinite(d)) return false;
  arf_t t;
  arf_init(t);
  arf_set_d(t, d);
  const bool c = arb_contains_arf(x_, t);
  arf_clear(t);
  return c;
}

std::string Ball::str(long digits) const { return take(arb_get_str(x_, digits, 0)); }

std::string Ball::mid_str(long digits) const {
  Ball m = mid_ball();
  return take(arb_get_str(m.x_, digits, ARB_STR_NO_RADIUS));
}

std::pair<double, double> Ball::enclosing_doubles() const {
  const double m = mid();
  return {m, abs(*this - Ball(m)).upper()};
}

Ball::Printed Ball::printed(long digits) const {
  // A ball that is not finite (an infinite radius, or a midpoint beyond the doubles) encloses
  // everything it may stand for only with an infinite radius.
  if (!arb_is_finite(x_)) return Printed{mid_str(digits), "inf"};
  Printed p{mid_str(digits), "0"};
  // (Enough bits that the decimal midpoint is parsed far below its own last digit.)
  const PrecisionScope scope(std::max(precision(), 4 * digits + 64));
  // Every x of the ball lies within |x - m| <= e of the printed midpoint m (as a decimal ball:
  // the decimal need not be a binary number).
  const Ball e = abs(*this - Ball::decimal(p.mid));
  double r = e.upper();
  if (r == 0) return p;
  if (!std::isfinite(r)) {
    p.rad = "inf";
    return p;
  }
  r = std::max(r, DBL_MIN);  // (from a subnormal, r (1 + 1%) could round back to r)
  // %.3g rounds to nearest, by at most half a unit in its third digit (0.5% relative): from
  // r (1 + 1%) the printed radius is above r. Checked, and widened again if it were not.
  for (int attempt = 0; attempt < 8; ++attempt) {
    r *= 1.01;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.3g", r);
    if (le(e, Ball::decimal(buf).lower_ball())) {  // every |x - m| <= the printed radius
      p.rad = buf;
      return p;
    }
  }
  throw std::logic_error("Ball::printed: no enclosing radius found for " + str(20));
}

Ball operator+(const Ball& x, const Ball& y) {
  Ball r;
  arb_add(r.get(), x.get(), y.get(), g_prec);
  return r;
}
Ball operator-(const Ball& x, const Ball& y) {
  Ball r;
  arb_sub(r.get(), x.get(), y.get(), g_prec);
  return r;
}
Ball operator*(const Ball& x, const Ball& y) {
  Ball r;
  arb_mul(r.get(), x.get(), y.get(), g_prec);
  return r;
}
Ball operator/(const Ball& x, const Ball& y) {
  Ball r;
  arb_div(r.get(), x.get(), y.get(), g_prec);
  return r;
}
Ball operator-(const Ball& x) {
  Ball r;
  arb_neg(r.get(), x.get());
  return r;
}
Ball operator+(const Ball& x, double y) { return x + Ball(y); }
Ball operator-(const Ball& x, double y) { return x - Ball(y); }
Ball operator*(const Ball& x, double y) { return x * Ball(y); }
Ball operator*(double x, const Ball& y) { return Ball(x) * y; }
Ball operator/(const Ball& x, double y) { return x / Ball(y); }

Ball sin(const Ball& x) {
  Ball r;
  arb_sin(r.get(), x.get(), g_prec);
  return r;
}
Ball cos(const Ball& x) {
  Ball r;
  arb_cos(r.get(), x.get(), g_prec);
  return r;
}
void sin_cos(const Ball& x, Ball& s, Ball& c) { arb_sin_cos(s.get(), c.get(), x.get(), g_prec); }
Ball sqr(const Ball& x) {
  Ball r;
  arb_sqr(r.get(), x.get(), g_prec);
  return r;
}
Ball sqrt(const Ball& x) {
  Ball r;
  arb_sqrt(r.get(), x.get(), g_prec);
  return r;
}
Ball log(const Ball& x) {
  Ball r;
  arb_log(r.get(), x.get(), g_prec);
  return r;
}
Ball asin(const Ball& x) {
  Ball r;
  arb_asin(r.get(), x.get(), g_prec);
  return r;
}
Ball cot(const Ball& x) {
  Ball r;
  arb_cot(r.get(), x.get(), g_prec);
  return r;
}
Ball abs(const Ball& x) {
  Ball r;
  arb_abs(r.get(), x.get());
  return r;
}
Ball max(const Ball& x, const Ball& y) {
  Ball r;
  arb_max(r.get(), x.get(), y.get(), g_prec);
  return r;
}
Ball min(const Ball& x, const Ball& y) {
  Ball r;
  arb_min(r.get(), x.get(), y.get(), g_prec);
  return r;
}

}  // namespace dfchaos::certified
