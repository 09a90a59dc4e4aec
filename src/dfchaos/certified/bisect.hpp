// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bisect.hpp
/// @brief The ball form of dfchaos::bisect: the enclosure of the sign change of a function that is
/// positive at one end of a bracket and negative at the other, by bisection on exact midpoints.
#pragma once

#include <optional>

#include "dfchaos/bisect.hpp"
#include "dfchaos/certified/ball.hpp"

namespace dfchaos::certified {

/// A ball holding the zero of `f` between `lo` and `hi` (lo may lie on either side of hi), where f
/// is continuous with exactly one sign change, \f$f > 0\f$ at lo and \f$f < 0\f$ at hi (not checked:
/// the caller proves it). Each step evaluates f on the exact midpoint (mid_ball) of the current
/// ends and keeps the half whose ends f proves of opposite sign; it stops after `max_iterations`
/// steps or at the first midpoint where the sign of f is not proved. Returns the hull of the final
/// ends: every zero between them, hence the zero when it is unique on the bracket.
template <class F>
Ball enclose_sign_change(F&& f, const Ball& lo, const Ball& hi, int max_iterations) {
  const auto [l, h] = bisect_bracket(
      lo, hi, max_iterations, [](const Ball& a, const Ball& b) -> std::optional<Ball> { return ((a + b) * 0.5).mid_ball(); },
      [&f](const Ball& m) -> std::optional<bool> {
        const Ball v = f(m);
        if (v.is_positive()) return true;
        if (v.is_negative()) return false;
        return std::nullopt;
      });
  return Ball::hull(l, h);
}

}  // namespace dfchaos::certified
