// SPDX-License-Identifier: GPL-3.0-or-later
/// @file rest_start.hpp
/// @brief Internal to the first-root search (roots.hpp): a search whose origin is a root of f (a
/// start at rest, QuadraticPlusHarmonic::starts_at_rest). Near such an origin f lies below the
/// rounding noise of a direct evaluation; the sign of f there is decided from its Taylor
/// coefficients instead, in cancellation-free form. Not installed.
#pragma once

#include "dfchaos/roots.hpp"

namespace dfchaos::roots_detail {

/// What a start at rest (f(origin) = 0 exactly) leads to near the origin.
struct RestStart {
  enum Kind { Root, NoRoot, Resume } kind;  ///< a root found; no root within the limit; scan on from kRestOffset
  UpCrossing root;                          ///< (Root) the root, possibly the origin itself
  long double left_value;                   ///< (Resume) f at kRestOffset, or -1 for "negative"
  /// (Resume) Case A below: f'' < 0 at the origin beyond rounding and f' <= 0 there. Since f'' keeps
  /// its sign on a piece, f' < 0 and f falls on the whole first piece of the scan, which therefore
  /// holds no up-crossing and needs no evaluation.
  bool falling = false;
};

/// Distance from the origin at which the scan of a start at rest resumes (where it always started).
constexpr long double kRestOffset = 1e-7L;

/// What f does near an origin at rest, up to 1e-3 (or `limit`) after it: a root there (possibly the
/// origin itself, when f rises at once), no root before `limit`, or the value at kRestOffset where
/// the scan of the pieces resumes. `R` is \f$\sqrt{A^2 + B^2}\f$. Runs once per search.
RestStart rest_start(const QuadraticPlusHarmonic& f, long double R, long double limit);

}  // namespace dfchaos::roots_detail
