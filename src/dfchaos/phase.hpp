// SPDX-License-Identifier: GPL-3.0-or-later
/// @file phase.hpp
/// @brief Instants split into whole forcing periods and a phase, so that long flights keep an exact phase.
///
/// The forcing \f$F(t) = a\sin t + 2b\f$ has period \f$2\pi\f$. Flights last up to
/// \f$\sim a/b\f$ time units (\f$10^5\f$ and more for small \f$b/a\f$), and the return map needs
/// the phase \f$\varphi = t \bmod 2\pi\f$ of their end to \f$10^{-10}\f$. Storing \f$t\f$ as one
/// double would lose digits of the phase; an Instant stores \f$t = 2\pi\,\mathrm{turn} + \varphi\f$
/// with an integer turn and \f$\varphi \in [0, 2\pi)\f$, and trigonometric functions are only ever
/// evaluated at \f$\varphi\f$.
#pragma once

#include <cstdint>

namespace dfchaos {

/// \f$2\pi\f$ rounded to double.
inline constexpr double two_pi = 6.283185307179586476925286766559;
/// \f$2\pi\f$ rounded to long double (used to measure long elapsed times).
inline constexpr long double two_pi_l = 6.283185307179586476925286766559005768L;
/// \f$\pi\f$ rounded to double.
inline constexpr double pi = 3.141592653589793238462643383279;

/// Reduces any finite real \f$t\f$ to its phase \f$t \bmod 2\pi \in [0, 2\pi)\f$.
double wrap_phase(double t);

/// Distance of two phases on the circle, \f$\min_k |x - y + 2\pi k| \in [0, \pi]\f$.
double circle_distance(double x, double y);

/// Largest \f$|t|\f$ that Instant::from_time accepts: there the turn count is about \f$1.6\cdot 10^{14}\f$,
/// far inside int64, and the double-double reduction still gives the phase to the last bit.
inline constexpr double kMaxInstantTime = 1e15;

/// An instant \f$t = 2\pi\,\mathrm{turn} + \mathrm{phase}\f$, \f$\mathrm{phase} \in [0, 2\pi)\f$.
struct Instant {
  std::int64_t turn = 0;  ///< number of whole forcing periods
  double phase = 0.0;     ///< \f$\varphi \in [0, 2\pi)\f$

  /// The instant as one real number (loses phase digits for large turns: for output only).
  double value() const { return static_cast<double>(static_cast<long double>(turn) * two_pi_l + phase); }

  /// Splits a real time into turn and phase, the phase correctly rounded (double-double reduction).
  /// @throws std::domain_error if \f$|t| >\f$ kMaxInstantTime or t is not finite (a bug of the
  ///         caller: user-given times are checked before, e.g. by simulate()).
  static Instant from_time(double t);
  /// The instant in turn 0 with the given phase (any real, reduced mod \f$2\pi\f$).
  static Instant at_phase(double phase) { return from_time(phase); }

  /// Equal turn and equal phase.
  friend bool operator==(const Instant&, const Instant&) = default;
};

/// \f$t_{\mathrm{to}} - t_{\mathrm{from}}\f$ in long double.
long double elapsed(const Instant& from, const Instant& to);

/// Strict order of instants.
bool before(const Instant& x, const Instant& y);

/// The instant \f$t + \Delta\f$ for \f$\Delta \ge 0\f$ (phase renormalised into \f$[0, 2\pi)\f$).
Instant advance(const Instant& t, long double delta);

/// The first instant strictly after \f$t\f$ whose phase is \f$\varphi\f$ (\f$\varphi\in[0,2\pi)\f$).
Instant next_at_phase(const Instant& t, double phi);

/// Whether the phase \f$\varphi\f$ lies in the half-open arc \f$[lo, hi)\f$ of the circle
/// (the arc may wrap through 0 when \f$lo > hi\f$).
bool phase_in_arc(double phi, double lo, double hi);

}  // namespace dfchaos
