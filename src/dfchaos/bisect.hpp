/// @file bisect.hpp
/// @brief The boundary of a predicate on an interval, by bisection: the one loop every threshold
/// search of dfchaos uses (b0 of Lemma 1, window edges of Theorem 2, edges of covering segments...).
#pragma once

#include <cmath>
#include <utility>

namespace dfchaos {

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
/// (otherwise: some boundary). The bracket is never wider than the input.
template <class Pred>
std::pair<double, double> bisect(Pred&& pred, double lo, double hi, BisectStop stop = {}) {
  for (int it = 0; it < stop.max_iterations && std::fabs(hi - lo) > stop.abs_tol + stop.rel_tol * std::fabs(hi); ++it) {
    const double m = 0.5 * (lo + hi);
    if (m == lo || m == hi) break;
    if (pred(m)) lo = m;
    else hi = m;
  }
  return {lo, hi};
}

}  // namespace dfchaos
