// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/parameters.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "dfchaos/double_double.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/phase.hpp"

namespace dfchaos {

double eq1_residual(double vartheta) { return pi - vartheta - 1.0 / std::tan(0.5 * vartheta); }

namespace {
/// Eq. (1)'s residual in long double, and its derivative -1 + 1/(2 sin^2(x/2)).
long double residual_l(long double x) { return 3.14159265358979323846264338327950288L - x - 1.0L / std::tan(0.5L * x); }
long double residual_slope_l(long double x) {
  const long double s = std::sin(0.5L * x);
  return -1.0L + 1.0L / (2 * s * s);
}

/// vartheta0 to long-double precision: GSL's Brent bracket in double, then Newton in long double.
long double vartheta0_l() {
  static const long double value = [] {
    gsl_set_error_handler_off();
    gsl_function f;
    f.function = [](double x, void*) { return eq1_residual(x); };
    f.params = nullptr;
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(gsl_root_fsolver_alloc(gsl_root_fsolver_brent),
                                                                               &gsl_root_fsolver_free);
    // eq1_residual(0.1) < 0 < eq1_residual(pi/2): the root is bracketed and unique there.
    gsl_root_fsolver_set(solver.get(), &f, 0.1, pi / 2);
    double lo = 0.1, hi = pi / 2;
    for (int iter = 0; iter < 200; ++iter) {
      gsl_root_fsolver_iterate(solver.get());
      lo = gsl_root_fsolver_x_lower(solver.get());
      hi = gsl_root_fsolver_x_upper(solver.get());
      if (gsl_root_test_interval(lo, hi, 0.0, DBL_EPSILON) == GSL_SUCCESS) break;
    }
    // The double bracket is a few ulp wide; Newton in long double (the residual's slope is about
    // 2.6 there) converges to its last bits in two or three steps.
    long double x = gsl_root_fsolver_root(solver.get());
    for (int it = 0; it < 8; ++it) {
      const long double dx = residual_l(x) / residual_slope_l(x);
      x -= dx;
      if (std::fabs(dx) <= 4 * LDBL_EPSILON * x) break;
    }
    return x;
  }();
  return value;
}
}  // namespace

double vartheta0() { return static_cast<double>(vartheta0_l()); }

double sin_vartheta0() { return static_cast<double>(std::sin(vartheta0_l())); }

namespace {
void require_in_range(const char* name, double v) {
  if (!std::isfinite(v) || !(v >= kMinParameter && v <= kMaxParameter))
    throw InvalidParameter(name, "1e-100 <= " + std::string(name) + " <= 1e100 (only b/a and q/a matter: rescale)", v);
}
}  // namespace

Parameters::Parameters(double a, double b, double q) : a_(a), b_(b), q_(q) {
  require_in_range("a", a);
  require_in_range("b", b);
  require_in_range("q", q);
  if (std::fabs((q - 2 * b) / a) < 1) {
    t0_ = wrap_phase(model::t0(a, b, q));  // the arcsine lies in (-pi/2, pi/2): t0 up to a turn
    t1_ = model::t1(a, b, q);
  }
  if (2 * b < a) {
    t2_ = model::t2(a, b);
    t3_ = model::t3(a, b);
  }
}

double Parameters::F(double t) const { return model::F(a_, b_, t); }

double Parameters::t2_required() const {
  if (!t2_) throw InvalidParameter("b", "0 < b < a/2 (otherwise F never vanishes and there is no free flight)", b_);
  return *t2_;
}
double Parameters::t3_required() const {
  t2_required();
  return *t3_;
}

void Parameters::require_in_map_domain(double theta, const std::string& name) const {
  const double t2 = t2_required(), t3 = t3_required();
  if (!in_map_domain(theta))
    throw InvalidParameter(name, "t2 <= " + name + " < t3 = [" + format_shortest(t2) + ", " + format_shortest(t3) + ")", theta);
}

void Parameters::require_return_map() const {
  if (!(2 * b_ < a_)) throw InvalidParameter("b", "0 < b < a/2 for the return map T (Eq. 2)", b_);
  if (!(q_ > 2 * b_)) throw InvalidParameter("q", "q > 2b for the return map T (otherwise progression need not stop)", q_);
  if (!(b_ >= kMinMapRatio * a_))
    throw InvalidParameter(
        "b", "b/a >= 1e-12 for the return map T (its accuracy floor, docs/accuracy.md; here b/a = " + format_shortest(b_ / a_) + ")", b_);
}

void Parameters::require_eq2() const {
  if (!(2 * b_ < a_)) throw InvalidParameter("b", "0 < b < a/2 (assumption (2))", b_);
  const double lo = a_ * sin_vartheta0();
  if (!(q_ > lo && q_ < a_))
    throw InvalidParameter("q", "a sin(vartheta0) < q < a (assumption (2)), i.e. " + format_shortest(lo) + " < q < " + format_shortest(a_), q_);
}

Assumptions Parameters::assumptions() const {
  Assumptions s{};
  s.b_in_range = b_ < a_ / 2;
  s.q_above_threshold = q_ > a_ * sin_vartheta0() && q_ < a_;
  s.eq2 = s.b_in_range && s.q_above_threshold;
  s.eq23 = q_ < a_;
  s.progression_ends = q_ > 2 * b_;
  return s;
}

std::string Assumptions::describe() const {
  std::string out = eq2 ? "(2) holds" : "(2) fails";
  if (!b_in_range)
    out += " [b >= a/2]";
  else if (!q_above_threshold)
    out += " [q outside (a sin(vartheta0), a)]";
  out += eq23 ? "; (23) holds" : "; (23) fails [q >= a]";
  if (!progression_ends) out += "; q <= 2b: progression need not stop";
  return out;
}

std::string Parameters::describe() const { return "a=" + format_shortest(a_) + " b=" + format_shortest(b_) + " q=" + format_shortest(q_); }

}  // namespace dfchaos
