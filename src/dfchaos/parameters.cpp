#include "dfchaos/parameters.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cfloat>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "dfchaos/double_double.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/phase.hpp"

namespace dfchaos {

InvalidParameter::InvalidParameter(const std::string& parameter, const std::string& condition, double value)
    : std::invalid_argument(parameter + ": must satisfy " + condition + " (got " + format_double(value) + ")"),
      parameter_(parameter) {}

InvalidParameter::InvalidParameter(const std::string& parameter, const std::string& condition)
    : std::invalid_argument(parameter + ": " + condition), parameter_(parameter) {}

std::string format_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

double eq1_residual(double vartheta) { return pi - vartheta - 1.0 / std::tan(0.5 * vartheta); }

double vartheta0() {
  static const double value = [] {
    gsl_set_error_handler_off();
    gsl_function f;
    f.function = [](double x, void*) { return eq1_residual(x); };
    f.params = nullptr;
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
    // eq1_residual(0.1) < 0 < eq1_residual(pi/2): the root is bracketed and unique there.
    gsl_root_fsolver_set(solver.get(), &f, 0.1, pi / 2);
    double lo = 0.1, hi = pi / 2;
    for (int iter = 0; iter < 200; ++iter) {
      gsl_root_fsolver_iterate(solver.get());
      lo = gsl_root_fsolver_x_lower(solver.get());
      hi = gsl_root_fsolver_x_upper(solver.get());
      if (gsl_root_test_interval(lo, hi, 0.0, DBL_EPSILON) == GSL_SUCCESS) break;
    }
    // Brent stops on a bracket of a few ulp; return the end with the smaller residual.
    const double x = gsl_root_fsolver_root(solver.get());
    double best = x;
    for (double cand : {lo, hi})
      if (std::fabs(eq1_residual(cand)) < std::fabs(eq1_residual(best))) best = cand;
    return best;
  }();
  return value;
}

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
  const double w = (q - 2 * b) / a;
  if (std::fabs(w) < 1) {
    const double s = std::asin(w);
    t0_ = wrap_phase(s);
    t1_ = pi - s;
  }
  if (2 * b < a) {
    const double s = std::asin(2 * b / a);
    t2_ = pi + s;
    t3_ = two_pi - s;
  }
}

double Parameters::F(double t) const { return a_ * std::sin(t) + 2 * b_; }

double Parameters::t2_required() const {
  if (!t2_) throw InvalidParameter("b", "0 < b < a/2 (otherwise F never vanishes and there is no free flight)", b_);
  return *t2_;
}
double Parameters::t3_required() const {
  t2_required();
  return *t3_;
}

void Parameters::require_return_map() const {
  if (!(2 * b_ < a_)) throw InvalidParameter("b", "0 < b < a/2 for the return map T (Eq. 2)", b_);
  if (!(q_ > 2 * b_)) throw InvalidParameter("q", "q > 2b for the return map T (otherwise progression need not stop)", q_);
  if (!(b_ >= kMinMapRatio * a_))
    throw InvalidParameter("b", "b/a >= 1e-12 for the return map T (its accuracy floor, docs/accuracy.md; here b/a = " +
                                    format_double(b_ / a_) + ")", b_);
}

Assumptions Parameters::assumptions() const {
  Assumptions s{};
  s.b_in_range = b_ < a_ / 2;
  s.q_above_threshold = q_ > a_ * std::sin(vartheta0()) && q_ < a_;
  s.eq2 = s.b_in_range && s.q_above_threshold;
  s.eq23 = q_ < a_;
  s.progression_ends = q_ > 2 * b_;
  return s;
}

std::string Assumptions::describe() const {
  std::string out = eq2 ? "(2) holds" : "(2) fails";
  if (!b_in_range) out += " [b >= a/2]";
  else if (!q_above_threshold) out += " [q outside (a sin(vartheta0), a)]";
  out += eq23 ? "; (23) holds" : "; (23) fails [q >= a]";
  if (!progression_ends) out += "; q <= 2b: progression need not stop";
  return out;
}

std::string Parameters::describe() const {
  return "a=" + format_double(a_) + " b=" + format_double(b_) + " q=" + format_double(q_);
}

// ---- phase.hpp ------------------------------------------------------------------------------

double circle_distance(double x, double y) {
  const double d = std::fabs(std::fmod(x - y, two_pi));
  return std::min(d, two_pi - d);
}

double wrap_phase(double t) {
  // fmod is exact and returns t itself when |t| < 2 pi: skip the (slow) long double fmod then.
  long double r = std::fabs(t) < two_pi ? static_cast<long double>(t) : std::fmod(static_cast<long double>(t), two_pi_l);
  if (r < 0) r += two_pi_l;
  double d = static_cast<double>(r);
  if (d >= two_pi) d = 0.0;
  return d;
}

Instant Instant::from_time(double t) {
  // Fast path (no division): a time already inside [0, 2 pi) is its own phase.
  if (t >= 0 && t < two_pi) return Instant{0, t};
  if (!(std::fabs(t) <= kMaxInstantTime))
    throw std::domain_error("Instant::from_time: |t| = " + format_double(t) + " exceeds 1e15 (callers must refuse such times)");
  // t - 2 pi k in double-double: k 2 pi = k hi + k lo with k hi exact (TwoProd) and 2 pi to 107
  // bits, so the phase is right to the last bit for every |t| <= 1e15 (a long-double 2 pi would be
  // off by 2e-19 k, 3.5e-8 at t = 1e12).
  double k = std::floor(t / two_pi);
  auto reduce = [&](double kk) {
    return dd::add(dd::two_sum(t, 0.0), dd::neg(dd::add(dd::two_prod(kk, dd::kTwoPi.hi), dd::DD{kk * dd::kTwoPi.lo, 0.0})));
  };
  dd::DD r = reduce(k);
  if (r.hi < 0 || (r.hi == 0 && r.lo < 0)) r = reduce(--k);
  else if (r.hi >= two_pi) r = reduce(++k);
  double ph = r.hi;
  std::int64_t turn = static_cast<std::int64_t>(k);
  if (ph < 0) ph = 0.0;
  if (ph >= two_pi) { ph = 0.0; ++turn; }
  return Instant{turn, ph};
}

long double elapsed(const Instant& from, const Instant& to) {
  return static_cast<long double>(to.turn - from.turn) * two_pi_l +
         (static_cast<long double>(to.phase) - static_cast<long double>(from.phase));
}

bool before(const Instant& x, const Instant& y) {
  return x.turn < y.turn || (x.turn == y.turn && x.phase < y.phase);
}

Instant advance(const Instant& t, long double delta) {
  const long double total = static_cast<long double>(t.phase) + delta;
  // Fast path, bit-identical to the general formula: the sum stays inside the same turn.
  if (total >= 0 && total < two_pi_l) {
    const double ph = static_cast<double>(total);
    if (ph < two_pi) return Instant{t.turn, ph};
  }
  const long double k = std::floor(total / two_pi_l);
  long double r = total - k * two_pi_l;
  std::int64_t turn = t.turn + static_cast<std::int64_t>(k);
  if (r < 0) { r += two_pi_l; --turn; }
  double ph = static_cast<double>(r);
  if (ph >= two_pi) { ph = 0.0; ++turn; }
  return Instant{turn, ph};
}

Instant next_at_phase(const Instant& t, double phi) {
  if (phi > t.phase) return Instant{t.turn, phi};
  return Instant{t.turn + 1, phi};
}

bool phase_in_arc(double phi, double lo, double hi) {
  if (lo <= hi) return phi >= lo && phi < hi;
  return phi >= lo || phi < hi;
}

}  // namespace dfchaos
