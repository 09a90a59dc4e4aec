// SPDX-License-Identifier: GPL-3.0-or-later
/// @file negativity.hpp
/// @brief Proving \f$f < 0\f$ on a whole interval by adaptive bisection with certified tests: the
/// work-horse of "no earlier root" (T1, Eq. 11) and "no earlier stop" (θ2, Eq. 17).
///
/// On a sub-interval \f$X = [x_1, x_2]\f$ with midpoint \f$m\f$ and half-width \f$r\f$, \f$f < 0\f$
/// on \f$X\f$ is proved by the first of these that succeeds (all evaluated in ball arithmetic):
///  1. an *envelope* supplied by the function (e.g. for \f$G_1\f$ the convex quadratic
///     \f$U(s) = bs^2 + as\cos\theta + a\sin\theta + a \ge G_1\f$, model::G1_envelope_from_start(): negative at both ends of X
///     means negative on X), which skips long stretches of a flight in one step;
///  2. second-order Taylor: \f$f(x) \le f(m) + r|f'(m)| + \tfrac{r^2}{2}\max(0, \sup_X f'') < 0\f$;
///  3. monotonicity: \f$f' > 0\f$ on X (\f$f'(m) \pm r\sup_X|f''|\f$) and \f$f(x_2) < 0\f$, or \f$f' < 0\f$
///     on X and \f$f(x_1) < 0\f$.
/// If \f$f(m) > 0\f$ is certain the statement is **refuted**. Otherwise X is halved. The work is
/// bounded by the Budget and by a minimum width (relative \f$2^{-(p-12)}\f$ at precision p).
#pragma once

#include <string>
#include <vector>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/outcome.hpp"

namespace dfchaos::certified {

/// A function for prove_negative(): enclosures of \f$f, f', f''\f$ over balls, and an optional
/// envelope test.
class NegativityTarget {
 public:
  virtual ~NegativityTarget() = default;
  virtual Ball value(const Ball& x) const = 0;      ///< \f$f\f$ over x
  virtual Ball slope(const Ball& x) const = 0;      ///< \f$f'\f$ over x
  virtual Ball curvature(const Ball& x) const = 0;  ///< \f$f''\f$ over x
  /// True only if \f$f < 0\f$ is proved on \f$[lo, hi]\f$ by a cheap majorant.
  virtual bool envelope_negative(const Ball& lo, const Ball& hi) const {
    (void)lo;
    (void)hi;
    return false;
  }
  /// Name of the variable in messages ("s", "t").
  virtual std::string variable() const { return "x"; }
};

/// Statistics of one call.
struct NegativityStats {
  long tests = 0;     ///< sub-intervals examined
  long envelope = 0;  ///< closed by the envelope
  long taylor = 0;    ///< closed by the Taylor bound
  long monotone = 0;  ///< closed by monotonicity
};

/// Which of the three tests of the file comment closed a sub-interval.
enum class NegativityTest { Envelope, Taylor, Monotone };
/// "envelope", "taylor", "monotone" (the names certificates use).
const char* negativity_test_name(NegativityTest t);

/// One closed sub-interval \f$[lo, hi]\f$ (exact ends) of a proof of \f$f < 0\f$ and the test that
/// closed it: a witness that an independent checker re-evaluates (docs/certificates.md).
struct NegativityPiece {
  Ball lo;              ///< left end (exact)
  Ball hi;              ///< right end (exact)
  NegativityTest test;  ///< the test that proved \f$f < 0\f$ on it
};
/// The pieces of one proof, covering its interval.
using NegativityRecord = std::vector<NegativityPiece>;

/// Proves \f$f < 0\f$ on the closed interval \f$[lo, hi]\f$ (exact balls, lo <= hi).
/// `step` names the statement in a failure ("T1: no earlier root"). With `record`, the closed
/// sub-intervals are appended to it (in the order they were closed).
Outcome prove_negative(const NegativityTarget& f, const Ball& lo, const Ball& hi, Budget& budget, const std::string& step,
                       NegativityStats* stats = nullptr, NegativityRecord* record = nullptr);

}  // namespace dfchaos::certified
