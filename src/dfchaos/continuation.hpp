// SPDX-License-Identifier: GPL-3.0-or-later
/// @file continuation.hpp
/// @brief A periodic orbit of T followed in the parameter b (a and q fixed), in floating point, up to
/// the border collision where it ends (the certified counterpart, existence over
/// each step's interval of b, is certified/continuation.hpp).
///
/// **The orbit.** A cycle \f$x_0, \dots, x_{m-1}\f$ of \f$T\f$ with \f$T(x_j) = x_{j+1 \bmod m}\f$, each step in
/// scenario A (a free flight, a progression, a free flight: T smooth, \f$T' \ne 0\f$; map_derivative.hpp)
/// on one continuity branch of \f$T_1\f$ (return_map.hpp, t1_branch). The branch of the orbit is the
/// list of these labels: the orbit is the same orbit as long as it does not change.
///
/// **A step.** From an accepted \f$(b_k, x)\f$ the next \f$b = b_k(1 \pm h)\f$ is tried with the orbit
/// predicted by the secant through the last two points and corrected by Newton's method on
/// \f$F_j(x) = T(x_j) - x_{j+1}\f$. For a cycle the Newton system \f$T'_j\delta_j - \delta_{j+1} = -F_j\f$
/// (new points \f$x_j + \delta_j\f$) is solved exactly: \f$\delta_0 = S/(1 - P)\f$ with
/// \f$P = \prod_j T'_j\f$ and \f$S = \sum_j F_j \prod_{i > j} T'_i\f$, then backwards
/// \f$\delta_j = (\delta_{j+1} - F_j)/T'_j\f$ (a contraction where \f$|T'| > 1\f$). The step is accepted when Newton converges and every point keeps
/// its scenario A and its branch label; else h is halved. The first b tried where it fails with
/// h below `min_step` is the end of the branch.
///
/// **The end.** Between the last accepted b and the first lost one (relatively at most min_step
/// apart) a point of the orbit meets a break of T: its step enters a stop plateau (a stop, \f$T' = 0\f$:
/// `plateau`); the point itself reaches \f$t_2\f$ (`reaches_t2`: the end of the stop arc \f$(t_1, t_2)\f$,
/// where \f$T'(t_2) = 0\f$; a fixed point reaching it makes \f$T(t_2) = t_2\f$, the left edge of a window
/// of Theorem 2) or \f$t_3\f$ (`reaches_t3`); or its first flight changes branch (the flight from it grazes the delimiter, a
/// discontinuity of \f$T_1\f$: `grazing`); read at the lost b from the predicted orbit, the point named.
/// `fold` when Newton fails with every point on its branch while the cycle's multiplier
/// \f$(T^m)'\f$ has come within \f$e^{\pm 0.3}\f$ of 1 (a saddle-node: the cycle meets another one, typically
/// as a point nears \f$t_2\f$, where \f$T'\f$ tends to 0); `no_convergence` when it fails otherwise;
/// `range_end` when b_end is reached; `step_budget` when max_steps run out.
#pragma once

#include <string>
#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

/// The settings of follow_periodic_orbit().
struct ContinuationSettings {
  double step = 1e-3;           ///< first relative step h in b, in (0, 0.1]
  double min_step = 1e-12;      ///< the end is located to this relative width, in [1e-15, step]
  long long max_steps = 10000;  ///< most accepted steps, 1..1e6 (halvings are bounded by min_step)
  /// Checks the bounds. @throws InvalidParameter naming step, min-step or max-steps.
  void validate() const;
};

/// Why a followed orbit ends (see the file comment).
enum class BranchEnd { RangeEnd, Plateau, ReachesT2, ReachesT3, Grazing, Fold, NoConvergence, StepBudget };
/// "range_end", "plateau", "reaches_t2", "reaches_t3", "grazing", "fold", "no_convergence", "step_budget"
const char* branch_end_name(BranchEnd e);

/// |ln (T^m)'| below which a cycle that Newton loses is taken to end in a fold (see the file comment).
inline constexpr double kFoldLogMultiplier = 0.3;

/// One accepted point of a followed orbit.
struct BranchPoint {
  double b = 0;                     ///< the parameter
  std::vector<double> x;            ///< the cycle \f$x_0, \dots, x_{m-1}\f$ (x_0 continued from the start's)
  double log_multiplier = 0;        ///< \f$\sum_j \ln|T'(x_j)|\f$
  double residual = 0;              ///< \f$\max_j |T(x_j) - x_{j+1}|\f$ after Newton
  std::vector<long long> branches;  ///< t1_branch of each point's step
};

/// A periodic orbit followed in b.
struct OrbitBranch {
  std::vector<BranchPoint> points;      ///< the accepted points, in the order followed (b monotone)
  BranchEnd end = BranchEnd::RangeEnd;  ///< why the orbit ends (see the file comment)
  long long end_point = -1;             ///< the j of the point that met the break (plateau, grazing), else -1
  double b_lost = 0;                    ///< the first b tried past the last point (NaN for range_end, step_budget)
  std::string detail;                   ///< a sentence on the end (the scenario or the branch labels seen)
};

/// Follows the cycle `x0` of T at (a, b0, q) in b towards b_end (either side of b0).
/// @throws InvalidParameter unless (a, b0, q) and (a, b_end, q) admit T, every x0_j lies in
///         [t2, t3), 1 <= m <= 64, and the start is a cycle: Newton converges at b0 with every step in
///         scenario A (else naming x0); settings as validate().
OrbitBranch follow_periodic_orbit(double a, double q, double b0, const std::vector<double>& x0, double b_end,
                                  const ContinuationSettings& settings = {});

/// Longest cycle follow_periodic_orbit() takes.
inline constexpr std::size_t kMaxContinuedPeriod = 64;

}  // namespace dfchaos
