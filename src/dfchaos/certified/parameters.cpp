// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/parameters.hpp"

#include <cmath>

#include "dfchaos/errors.hpp"
#include "dfchaos/model.hpp"

namespace dfchaos::certified {

std::string ParameterBox::describe() const {
  auto range = [](double lo, double hi) { return lo == hi ? format_shortest(lo) : "[" + format_shortest(lo) + ", " + format_shortest(hi) + "]"; };
  return "a=" + format_shortest(a) + " b=" + range(b_lo, b_hi) + " q=" + range(q_lo, q_hi);
}

ParameterBalls::ParameterBalls(const ParameterBox& box) : box_(box) {
  if (!std::isfinite(box.a) || !(box.a > 0)) throw InvalidParameter("a", "a > 0 and finite", box.a);
  if (!std::isfinite(box.b_lo) || !(box.b_lo > 0)) throw InvalidParameter("b", "b > 0 and finite", box.b_lo);
  if (!std::isfinite(box.b_hi) || !(box.b_hi >= box.b_lo)) throw InvalidParameter("b", "b_lo <= b_hi, finite", box.b_hi);
  if (!std::isfinite(box.q_lo) || !(box.q_lo > 0)) throw InvalidParameter("q", "q > 0 and finite", box.q_lo);
  if (!std::isfinite(box.q_hi) || !(box.q_hi >= box.q_lo)) throw InvalidParameter("q", "q_lo <= q_hi, finite", box.q_hi);
  a = Ball(box.a);
  b = Ball::interval(box.b_lo, box.b_hi);
  q = Ball::interval(box.q_lo, box.q_hi);
  b_lo = Ball(box.b_lo);
  b_hi = Ball(box.b_hi);
  q_lo = Ball(box.q_lo);
  q_hi = Ball(box.q_hi);
  two_c = model::two_c(b, q);
  pi = Ball::pi();
  two_pi = 2.0 * pi;
  t0 = model::t0(a, b, q);
  t1 = model::t1(a, b, q);
  t2 = model::t2(a, b);
  t3 = model::t3(a, b);
  t2_at_b_lo = t2_of(b_lo);
  t2_at_b_hi = t2_of(b_hi);
}

Outcome ParameterBalls::admissible() const {
  if (!lt(2.0 * b, a)) return Outcome::fail("admissibility", "2b < a not proved over " + box_.describe());
  if (!lt(2.0 * b, q)) return Outcome::fail("admissibility", "q > 2b not proved over " + box_.describe());
  if (!lt(q - 2.0 * b, a)) return Outcome::fail("admissibility", "q - 2b < a not proved over " + box_.describe());
  if (!t0.is_finite() || !t2.is_finite()) return Outcome::fail("admissibility", "phases not enclosed");
  return Outcome::ok();
}

Ball ParameterBalls::F(const Ball& t) const { return model::F(a, b, t); }

Ball ParameterBalls::t2_of(const Ball& bb) const { return model::t2(a, bb); }

}  // namespace dfchaos::certified
