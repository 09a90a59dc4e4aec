// SPDX-License-Identifier: GPL-3.0-or-later
/// @file motion.hpp
/// @brief The three regimes of Section 2 and their closed-form solutions (Eqs. 3–7).
///
/// Positions are measured from any fixed origin; only the gap \f$x - y \le 0\f$ matters for events.
#pragma once

#include "dfchaos/parameters.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/roots.hpp"

namespace dfchaos {

/// The regimes that last over open time intervals (Section 2): free (f), progression (p), stop (s).
enum class Regime { Free, Progression, Stop };

/// "f", "p" or "s", the paper's labels.
const char* regime_code(Regime r);

/// The motion \f$\ddot x = a\sin t + 2k\f$ shared by free flight (Eq. 3, \f$k = b\f$) and progression
/// (Eqs. 4, 6, \f$k = c = b - q/2\f$): from \f$x(t_s) = x_s\f$, \f$\dot x(t_s) = v_s\f$, with \f$s = t - t_s\f$,
/// \f[ x(t) = -a\sin t + k s^2 + (v_s + a\cos t_s)s + x_s + a\sin t_s, \qquad
///     \dot x(t) = v_s + 2ks - a(\cos t - \cos t_s). \f]
/// (Eq. 7 is the velocity with \f$k = c\f$, \f$t_s = t_0\f$, \f$v_s = 0\f$.)
///
/// The accurate form of the plain formulas of model.hpp (model::G1 for a free flight from rest,
/// model::progression_velocity_from_rest for a progression from rest): the elapsed time \f$s\f$ is
/// formed from two Instants in long double and the forcing is evaluated at phases, so that flights
/// of many periods keep their digits. test_model checks that the two forms agree.
struct HarmonicMotion {
  double a;        ///< forcing amplitude \f$a\f$
  double k;        ///< half the constant force of the regime: \f$b\f$ (free) or \f$c\f$ (progression)
  Instant start;   ///< \f$t_s\f$
  double x_start;  ///< \f$x_s = x(t_s)\f$
  double v_start;  ///< \f$v_s = \dot x(t_s)\f$

  /// \f$x(t)\f$ by the closed form above.
  double position(const Instant& t) const;
  /// \f$\dot x(t)\f$ by the closed form above.
  double velocity(const Instant& t) const;
};

/// Free motion (Eq. 3): \f$\ddot x = a\sin t + 2b\f$, delimiter at rest at \f$y\f$ (HarmonicMotion with
/// \f$k = b\f$).
struct FreeMotion : HarmonicMotion {
  bool starts_at_t2;  ///< \f$t_s\f$ has the phase \f$t_2\f$ (where \f$F = 0\f$ by definition)

  /// The motion of this regime through the given state at \f$t_s\f$.
  FreeMotion(const Parameters& p, const Instant& start, double x_start, double v_start);
  /// The gap \f$x(t) - y\f$ as a QuadraticPlusHarmonic: its first up-crossing is the next contact.
  /// Starts at rest when the mass starts at the delimiter with zero velocity (Eq. 10).
  QuadraticPlusHarmonic gap(double y) const;
};

/// Motion with progression (Eqs. 4, 6): \f$\ddot x = a\sin t + 2c\f$, \f$y = x\f$, \f$2c = 2b - q\f$
/// (HarmonicMotion with \f$k = c\f$).
struct ProgressionMotion : HarmonicMotion {
  /// The motion of this regime through the given state at \f$t_s\f$.
  ProgressionMotion(const Parameters& p, const Instant& start, double x_start, double v_start);
  /// \f$-\dot x(t)\f$ as a QuadraticPlusHarmonic: its first up-crossing is where progression stops.
  QuadraticPlusHarmonic minus_velocity() const;
};

}  // namespace dfchaos
