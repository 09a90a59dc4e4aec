// SPDX-License-Identifier: GPL-3.0-or-later
/// @file piece_solver.hpp
/// @brief Internal to the first-root search (roots.hpp): the first up-crossing of f on one piece,
/// where f' is monotone, so that f is monotone, convex with one minimum or concave with one
/// maximum. Not installed.
#pragma once

#include <optional>

#include "dfchaos/roots.hpp"
#include "dfchaos/roots/piecewise.hpp"

namespace dfchaos::roots_detail {

/// The first up-crossing of f on one piece [0, L] after the cursor `at` (f' monotone there), or
/// nothing; `end` receives f at the piece's end (the start of the next piece). What is known at the
/// cursor is used: the value the rest region left there (then a bound, not data), or the end of
/// the previous piece; else f(0) is evaluated. `R` is \f$\sqrt{A^2+B^2}\f$, `pieces` the work count
/// to report with a crossing.
std::optional<UpCrossing> search_piece(PieceFunction& pf, const Cursor& at, double L, long double R, long pieces, PieceEnd& end);

}  // namespace dfchaos::roots_detail
