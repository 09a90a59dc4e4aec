// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bisect.hpp
/// @brief The boundary of a predicate on an interval, by bisection: the one loop every threshold
/// search of dfchaos uses (b0 of Lemma 1, window edges of Theorem 2, edges of covering segments,
/// and, through certified/bisect.hpp, the enclosures of the certified layer).
#pragma once

#include <cmath>
#include <optional>
#include <utility>

namespace dfchaos {

/// The bisection loop, for any type of point X (double, or a ball of the certified layer): at most
/// `max_iterations` times, `midpoint(lo, hi)` gives the point m to test (std::nullopt: the bracket is
/// final), and `holds(m)` whether the predicate holds there (true: m becomes lo; false: m becomes hi;
/// std::nullopt: it cannot tell, and the bracket is final). Returns the final (lo, hi).
template <class X, class Midpoint, class Holds>
std::pair<X, X> bisect_bracket(X lo, X hi, int max_iterations, Midpoint&& midpoint, Holds&& holds) {
  for (int it = 0; it < max_iterations; ++it) {
    const std::optional<X> m = midpoint(lo, hi);
    if (!m) break;
    const std::optional<bool> h = holds(*m);
    if (!h) break;
    (*h ? lo : hi) = *m;
  }
  return {lo, hi};
}

/// When a bisection stops: after `max_iterations` halvings, or when the bracket is at most
/// `abs_tol + rel_tol·|hi|` wide (hi: the end where the predicate is false), or when the midpoint
/// is no longer strictly inside (adjacent doubles), whichever comes first.
struct BisectStop {
  int max_iterations = 200;  ///< halvings at most
  double abs_tol = 0;        ///< absolute width tolerance
  double rel_tol = 0;        ///< width tolerance relative to |hi|
};

/// The boundary of `pred` between `lo`, where it holds, and `hi`, where it does not (neither is
/// evaluated; lo may lie on either side of hi). Returns the final bracket (lo', hi'): pred(lo')
/// holds, pred(hi') does not, and the boundary lies between them if pred changes only once there
/// (otherwise: some boundary). The bracket is never wider than the input. `pred` returns bool, or
/// std::optional<bool> whose std::nullopt (no answer at that point) ends the bisection there.
template <class Pred>
std::pair<double, double> bisect(Pred&& pred, double lo, double hi, BisectStop stop = {}) {
  return bisect_bracket(
      lo, hi, stop.max_iterations,
      [&stop](double l, double h) -> std::optional<double> {
        if (!(std::fabs(h - l) > stop.abs_tol + stop.rel_tol * std::fabs(h))) return std::nullopt;
        const double m = 0.5 * (l + h);
        if (m == l || m == h) return std::nullopt;
        return m;
      },
      [&pred](double m) -> std::optional<bool> { return pred(m); });
}

}  // namespace dfchaos
