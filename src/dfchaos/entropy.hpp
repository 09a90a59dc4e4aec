// SPDX-License-Identifier: GPL-3.0-or-later
/// @file entropy.hpp
/// @brief Section 7: a lap-count estimate of the topological entropy of \f$T\f$, to set beside the
/// lower bound \f$h_{top}(T) \ge \ln 2\f$ that the semi-conjugacy \f$H\circ T = S\circ H\f$ with the
/// full shift on two symbols gives.
///
/// For a piecewise monotone map \f$f\f$ of an interval, the lap number \f$\ell(f^n)\f$ is the number
/// of maximal intervals on which \f$f^n\f$ is monotone, and \f$h_{top}(f) = \lim_n \frac1n\ln\ell(f^n)\f$
/// (Misiurewicz–Szlenk). We sample: the grid of \f$N\f$ cell centres
/// \f$x_i = lo + (hi - lo)(i + \tfrac12)/N\f$ is pushed through \f$f\f$ n times, and the laps of
/// \f$f^n\f$ are counted as the maximal runs of the sequence \f$f^n(x_0), f^n(x_1), \dots\f$ along which
/// the successive differences keep one sign (equal neighbours are skipped, so the arcs where
/// \f$T \equiv t_2\f$ do not split a lap). This is a lower count: laps narrower than the grid step
/// are missed. A jump of \f$T\f$ splits a lap only where it reverses the direction of motion.
#pragma once

#include <functional>
#include <vector>

#include "dfchaos/parameters.hpp"

namespace dfchaos {

/// The number of maximal monotone runs of a sequence: 1 plus the number of sign changes between
/// successive nonzero differences \f$y_{i+1} - y_i\f$ (an empty or constant sequence has one run).
long long monotone_runs(const std::vector<double>& y);

/// The laps of \f$f^n\f$ seen on the grid, and the entropy estimate they give.
struct LapCount {
  int n = 0;                    ///< the iterate
  long long laps = 0;           ///< \f$\ell(f^n)\f$ counted on the grid (monotone_runs of \f$f^n(x_i)\f$)
  double entropy_estimate = 0;  ///< \f$\frac1n \ln \ell(f^n)\f$
};

/// Lap counts of \f$f, f^2, \dots, f^{n_{max}}\f$ on the grid of `grid` cell centres of [lo, hi]
/// (see the file comment). @throws InvalidParameter unless grid >= 2, n_max >= 1 and lo < hi.
std::vector<LapCount> lap_counts(const std::function<double(double)>& f, double lo, double hi, int grid, int n_max);

/// Lap counts of the return map \f$T\f$ on \f$[t_2, t_3)\f$ (Section 7).
/// @throws InvalidParameter unless the return map is defined, and as above.
std::vector<LapCount> lap_counts(const Parameters& p, int grid, int n_max);

}  // namespace dfchaos
