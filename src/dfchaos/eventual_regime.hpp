// SPDX-License-Identifier: GPL-3.0-or-later
/// @file eventual_regime.hpp
/// @brief The eventual behaviour of the full system (Remark of Section 9): which regimes a motion
/// still visits after a long time. Outside \f$b < a/2\f$ free flights die out; then the motion
/// either stays stopped (\f$q \ge a + 2b\f$), progresses forever (\f$q \le 2b\f$), or, in between,
/// either progresses forever or repeats every period a progression from rest at \f$t_0\f$ that
/// stops somewhere in \f$[t_1, t_0 + 2\pi)\f$ (periodic stick-slip).
#pragma once

#include "dfchaos/parameters.hpp"

namespace dfchaos {

/// The behaviours named by the Remark of Section 9, plus the one of the map T.
enum class EventualBehaviour {
  FreeFlights,         ///< free flights still occur at the end (the regime of the map T)
  StaysStopped,        ///< no motion at all over the final window
  EternalProgression,  ///< progression without stop over the final window
  PeriodicStickSlip,   ///< every period: progression from rest at t0, stop in [t1, t0 + 2pi)
  Undetermined         ///< none of these over the final window
};
const char* eventual_behaviour_name(EventualBehaviour b);  ///< "free flights", "stays stopped", ...

/// What a long simulation shows over its final window.
struct EventualRegime {
  EventualBehaviour behaviour = EventualBehaviour::Undetermined;  ///< the classification
  double fraction_free = 0;                                       ///< share of the final window in free flight
  double fraction_progression = 0;                                ///< share in progression
  double fraction_stop = 0;                                       ///< share in stop
  long long events_in_window = 0;                                 ///< regime changes inside the final window
  double last_free_time = -1;                                     ///< end of the last free flight (-1 if none after the start)
  double stick_start_phase_max_error = 0;                         ///< PeriodicStickSlip: max |start phase - t0| (wrapped)
  double stick_stop_phase_min = 0;                                ///< PeriodicStickSlip: earliest stop phase, measured from t1 (in [0, 2pi))
  double stick_stop_phase_max = 0;                                ///< and the latest
};

/// Simulates from \f$x = y = 0\f$, \f$\dot x = v_0\f$ at \f$t_0\f$ for `periods` forcing periods and
/// classifies the last `window_periods` of them. Bounded by the simulator's event limit.
/// @throws InvalidParameter for bad counts; GaveUp if the simulator's event bound is reached.
EventualRegime eventual_regime(const Parameters& p, double v0, double t0, double periods, double window_periods);

}  // namespace dfchaos
