// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/negativity.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "dfchaos/certified/cover.hpp"

namespace dfchaos::certified {

const char* negativity_test_name(NegativityTest t) {
  switch (t) {
    case NegativityTest::Envelope: return "envelope";
    case NegativityTest::Taylor: return "taylor";
    case NegativityTest::Monotone: return "monotone";
  }
  return "?";
}

Outcome prove_negative(const NegativityTarget& f, const Ball& lo, const Ball& hi, Budget& budget, const std::string& step, NegativityStats* stats,
                       NegativityRecord* record) {
  NegativityStats local;
  NegativityStats& st = stats ? *stats : local;
  if (!le(lo, hi)) return Outcome::fail(step, "empty or unordered interval " + lo.mid_str(17) + " .. " + hi.mid_str(17));
  // Minimum half-width: below it a sub-interval is reported undecided.
  const Ball scale = max(abs(lo), abs(hi)) + Ball(1.0);
  Ball min_r = scale * Ball(std::ldexp(1.0, -static_cast<int>(precision() - 12)));
  using Cell = std::pair<Ball, Ball>;
  auto check = [&](const Cell& c, int) {
    const auto& [x1, x2] = c;
    ++st.tests;
    if (!budget.spend())
      return CellVerdict::stop(Outcome::fail(
          step, "budget of " + std::to_string(budget.max_tests) + " interval tests spent near " + f.variable() + " = " + x1.mid_str(17)));
    if (f.envelope_negative(x1, x2)) {
      ++st.envelope;
      if (record) record->push_back({x1, x2, NegativityTest::Envelope});
      return CellVerdict::proved();
    }
    const Ball m = ((x1 + x2) * 0.5).mid_ball();
    const Ball r = max(x2 - m, m - x1).upper_ball();
    const Ball X = Ball::hull(x1, x2);
    const Ball fm = f.value(m);
    if (fm.is_positive()) return CellVerdict::stop(Outcome::refute(step, f.variable() + " = " + m.mid_str(20) + " gives f = " + fm.str(6) + " > 0"));
    const Ball dm = f.slope(m);
    const Ball cX = f.curvature(X);
    const Ball taylor = fm + r * abs(dm) + 0.5 * sqr(r) * max(cX, Ball(0.0));
    if (taylor.is_negative()) {
      ++st.taylor;
      if (record) record->push_back({x1, x2, NegativityTest::Taylor});
      return CellVerdict::proved();
    }
    const Ball dX = dm + Ball::interval(-1.0, 1.0) * r * cX;
    if ((dX.is_positive() && f.value(x2).is_negative()) || (dX.is_negative() && f.value(x1).is_negative())) {
      ++st.monotone;
      if (record) record->push_back({x1, x2, NegativityTest::Monotone});
      return CellVerdict::proved();
    }
    Outcome undecided = Outcome::fail(step, "undecided near " + f.variable() + " = " + m.mid_str(20) + " (f = " + fm.str(6) + ")");
    return lt(r, min_r) ? CellVerdict::stop(std::move(undecided)) : CellVerdict::split(std::move(undecided));
  };
  // Halves at the exact midpoint (a ball of radius 0); the minimum width above ends the splitting.
  auto split = [](const Cell& c, int) {
    const Ball m = ((c.first + c.second) * 0.5).mid_ball();
    return std::optional<std::pair<Cell, Cell>>(std::make_pair(Cell(c.first, m), Cell(m, c.second)));
  };
  return cover(Cell(lo, hi), check, split, std::numeric_limits<int>::max());
}

}  // namespace dfchaos::certified
