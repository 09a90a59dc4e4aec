// SPDX-License-Identifier: GPL-3.0-or-later
/// @file range.hpp
/// @brief One axis of a parameter sweep, as the user writes it: `lo:hi:n[:kind]`.
///
/// Kinds (the values are those of kit::Axis, so that a sweep reproduces an experiment's grid bit
/// for bit):
///  - `lin` (the default): \f$lo + (hi - lo)\,i/(n-1)\f$, \f$i = 0..n-1\f$ (both ends included);
///  - `log`: \f$lo\,(hi/lo)^{i/(n-1)}\f$ (both ends included; needs \f$lo > 0\f$);
///  - `mid`: the cell centres \f$lo + (hi - lo)(i + 1/2)/n\f$ (ends excluded).
///
/// A single value may be written `x`, the same as `x:x:1`.
///
/// Conditions: lo and hi finite; \f$1 \le n \le\f$ kMaxAxisPoints; for `lin` and `log`, \f$lo < hi\f$
/// when \f$n \ge 2\f$ and \f$lo = hi\f$ when \f$n = 1\f$ (a single value); for `mid`, \f$lo < hi\f$.
/// The text is kept in a canonical form (numbers in their shortest exact decimal, the kind always
/// spelt out), so that two spellings of one grid give the same output header.
#pragma once

#include <string>
#include <utility>

#include "kit/grid.hpp"

namespace dfchaos::sweep {

/// Most points on one axis.
inline constexpr long long kMaxAxisPoints = 100'000'000;

/// How the points of a Range are spaced.
enum class Spacing { Linear, Log, Mid };

/// An axis `lo:hi:n[:lin|log|mid]` (or one value `x`) of a sweep, and of `dfchaos map --grid`.
class Range {
 public:
  /// Parses `text`, with at most `max_points` points (at most kMaxAxisPoints). Errors name
  /// `option` (e.g. "q-range") and the violated condition.
  /// @throws InvalidParameter on any malformed or inadmissible text.
  static Range parse(const std::string& option, const std::string& text, long long max_points = kMaxAxisPoints);

  /// Requires every point of the axis to lie in the open interval (open_lo, open_hi); `what` states
  /// that condition in the error. @throws InvalidParameter naming `option`.
  void require_within(const std::string& option, double open_lo, double open_hi, const std::string& what) const;

  long long size() const { return n_; }         ///< number of points n
  double operator[](long long i) const;         ///< the i-th point, 0 <= i < size()
  double lo() const { return lo_; }             ///< as written
  double hi() const { return hi_; }             ///< as written
  Spacing spacing() const { return spacing_; }  ///< lin, log or mid
  /// The canonical text `lo:hi:n:kind` (numbers in %.17g).
  std::string canonical() const;
  /// The interval point i stands for, as the `region` observable proves over it: for `lin` and
  /// `log`, from the point to the next one ([x_i, x_(i+1)]; the last point reaches as far again:
  /// x + (x - x_(n-2)), resp. x^2/x_(n-2)), so that the intervals tile [lo, beyond hi]; for `mid`,
  /// the i-th of n equal parts of [lo, hi] (its ends lo + (hi - lo) i/n, the last ending at hi
  /// exactly); for a single point, [x, x].
  std::pair<double, double> extent(long long i) const;

 private:
  double lo_ = 0, hi_ = 0;
  long long n_ = 0;
  Spacing spacing_ = Spacing::Linear;
  kit::Axis axis_;
};

}  // namespace dfchaos::sweep
