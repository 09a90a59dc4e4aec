// SPDX-License-Identifier: GPL-3.0-or-later
/// @file vartheta0.hpp
/// @brief Eq. (1) certified: \f$\vartheta_0 \in (0, \pi/2]\f$ with \f$\pi - \vartheta_0 = \cot(\vartheta_0/2)\f$,
/// enclosed to any number of digits, its uniqueness, \f$\sin\vartheta_0\f$, and the correctly rounded
/// doubles of both.
///
/// \f$f(\vartheta) = \pi - \vartheta - \cot(\vartheta/2)\f$ has \f$f'(\vartheta) = -1 + 1/(2\sin^2(\vartheta/2)) > 0\f$
/// on \f$(0, \pi/2)\f$ because \f$\sin^2(\vartheta/2) < \sin^2(\pi/4) = 1/2\f$ there: f increases strictly, so
/// it has at most one zero on \f$(0, \pi/2]\f$ (analytic). A certified sign change \f$f(1/2) < 0 < f(1)\f$
/// gives the zero; bisection on certified signs narrows it to the working precision.
#pragma once

#include <string>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/outcome.hpp"

namespace dfchaos::certified {

/// \f$\vartheta_0\f$ and \f$\sin\vartheta_0\f$, certified.
struct Vartheta0 {
  Outcome verdict;                  ///< proved: the unique zero on (0, pi/2] lies in `value`
  Ball value;                       ///< \f$\vartheta_0\f$
  Ball sine;                        ///< \f$\sin\vartheta_0\f$
  double value_double = 0;          ///< the double nearest to \f$\vartheta_0\f$ (when rounding_certified)
  double sine_double = 0;           ///< the double nearest to \f$\sin\vartheta_0\f$
  bool rounding_certified = false;  ///< both enclosures lie strictly inside one rounding interval of a double
  long bits = 0;                    ///< working precision
  Ball bracket_lo;                  ///< (when proved) an exact number with f(bracket_lo) < 0 proved: the witness below \f$\vartheta_0\f$
  Ball bracket_hi;                  ///< (when proved) an exact number with f(bracket_hi) > 0 proved: the witness above \f$\vartheta_0\f$
};

/// Encloses \f$\vartheta_0\f$ with `bits` bits of working precision (200 gives more than 50 digits).
Vartheta0 certify_vartheta0(long bits = 200);

/// The double nearest to every point of x, if x lies strictly inside one rounding interval; NaN otherwise.
double correctly_rounded(const Ball& x);

}  // namespace dfchaos::certified
