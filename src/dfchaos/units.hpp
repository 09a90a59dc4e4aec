// SPDX-License-Identifier: GPL-3.0-or-later
/// @file units.hpp
/// @brief From the physical quantities of a drilling model to the parameters \f$(a, b, q)\f$ of
/// Section 2: time scaled by the forcing frequency, forces by mass times frequency squared. The
/// derivation, with a worked example, is docs/units.md.
///
/// The physical model (assumed; the paper states only the non-dimensional one): a mass \f$m\f$ at
/// position \f$X(\tau)\f$, pushed by \f$f(\tau) = F_0 \sin(\omega\tau) + P\f$ (harmonic amplitude
/// \f$F_0\f$, angular frequency \f$\omega\f$, static force \f$P\f$), against a delimiter whose dry
/// friction holds up to a force \f$Q\f$:
/// \f[ m X'' = F_0 \sin(\omega\tau) + P \quad\text{(free flight)}, \qquad
///     m X'' = F_0 \sin(\omega\tau) + P - Q \quad\text{(progression)}. \f]
/// With \f$t = \omega\tau\f$ and \f$x = X\f$ (lengths kept in the caller's unit), \f$X'' = \omega^2
/// \ddot x\f$, so dividing by \f$m\omega^2\f$ gives Eqs. (3) and (4),
/// \f$\ddot x = a\sin t + 2b\f$ and \f$\ddot x = a\sin t + 2b - q\f$, with
/// \f[ a = \frac{F_0}{m\omega^2}, \qquad b = \frac{P}{2m\omega^2}, \qquad q = \frac{Q}{m\omega^2}. \f]
/// a, b, q are lengths (metres for SI input). Back: \f$\tau = t/\omega\f$, a velocity
/// \f$X' = \omega\dot x\f$, the drilling speed \f$\omega\f$ times a rate in units of a per unit of t.
#pragma once

#include "dfchaos/parameters.hpp"

namespace dfchaos {

/// The length \f$a = F_0/s\f$ with \f$s = (m\,\omega)\,\omega\f$: the forcing amplitude of Eq. (3) in
/// the caller's unit of length, the scale of every length of the model (only b/a and q/a matter).
/// @throws InvalidParameter naming mass, omega or amplitude unless each is finite and positive,
/// or omega when \f$m\omega^2\f$ overflows or underflows.
double length_scale(double mass, double omega, double amplitude);

/// The parameters \f$(a, b, q) = (F_0/s,\ P/(2s),\ Q/s)\f$ with \f$s = (m\,\omega)\,\omega\f$ (in that
/// order of rounding): Eqs. (3)-(4) for the physical model of the file comment.
/// @param mass          \f$m\f$, the mass (kg)
/// @param omega         \f$\omega\f$, the angular frequency of the forcing (rad/s)
/// @param amplitude     \f$F_0\f$, the amplitude of the harmonic force (N)
/// @param static_force  \f$P\f$, the constant force pushing the mass towards the delimiter (N)
/// @param friction      \f$Q\f$, the largest dry-friction force of the delimiter (N)
/// @throws InvalidParameter naming the argument unless each is finite and positive, or naming
/// a, b or q (Parameters' message) when a result leaves [kMinParameter, kMaxParameter].
Parameters from_physical(double mass, double omega, double amplitude, double static_force, double friction);

}  // namespace dfchaos
