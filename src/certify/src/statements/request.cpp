// SPDX-License-Identifier: GPL-3.0-or-later
#include "request.hpp"

#include <cmath>

#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"

namespace dfchaos::certify::request {

using certified::Ball;
using certified::ParameterBox;

std::string claim_of(const Result& c) { return c.record.value().at("statement").get<std::string>(); }

double bounded(const std::string& name, double x) {
  if (!(std::fabs(x) <= kMaxParameter)) throw InvalidParameter(name, "|" + name + "| <= " + format_shortest(kMaxParameter), x);
  return x;
}

Range bounded(const std::string& name, const Range& r) {
  bounded(name, r.lo);
  if (r.lo == r.hi) return r;
  bounded(name, r.hi);
  if (!(r.lo <= r.hi)) throw InvalidParameter(name, "LO <= HI in LO:HI (got '" + format_shortest(r.lo) + ":" + format_shortest(r.hi) + "')");
  return r;
}

double amplitude(const Request& r) {
  const double a = bounded("a", r.a);
  if (!(a > 0)) throw InvalidParameter("a", "a > 0", a);
  return a;
}

ParameterBox box_from(const Request& r, bool need_q, bool allow_box) {
  const double a = amplitude(r);
  if (!r.b) throw InvalidParameter("b", "required for certify " + r.what);
  const auto [blo, bhi] = bounded("b", *r.b);
  if (!(blo > 0)) throw InvalidParameter("b", "b > 0", blo);
  if (!(2 * bhi < a)) throw InvalidParameter("b", "b < a/2", bhi);
  double qlo = 0.5 * a + 2 * bhi, qhi = qlo;
  if (need_q) {
    if (!r.q) throw InvalidParameter("q", "required for certify " + r.what);
    const Range q = bounded("q", *r.q);
    qlo = q.lo;
    qhi = q.hi;
    if (!(qlo > 2 * bhi)) throw InvalidParameter("q", "q > 2b (every progression stops)", qlo);
    if (!(qhi - 2 * blo < a)) throw InvalidParameter("q", "q - 2b < a (t0, t1 exist)", qhi);
  }
  if (!allow_box && (blo != bhi || qlo != qhi))
    throw InvalidParameter(blo != bhi ? "b" : "q", "a single value (certify " + r.what + " works at a parameter point)");
  return ParameterBox{a, blo, bhi, qlo, qhi};
}

std::pair<double, double> ratio_box(const Request& r) {
  const double a = amplitude(r);
  if (!r.q) throw InvalidParameter("q", "required for certify " + r.what);
  const Range q = bounded("q", *r.q);
  if (!(q.lo > 0)) throw InvalidParameter("q", "q > 0", q.lo);
  if (!(q.hi <= a)) throw InvalidParameter("q", "q <= a (t0 exists for every b > 0)", q.hi);
  return {(Ball(q.lo) / Ball(a)).lower(), (Ball(q.hi) / Ball(a)).upper()};
}

}  // namespace dfchaos::certify::request
