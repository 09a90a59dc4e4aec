// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/eventual_regime.hpp"

#include <algorithm>
#include <cmath>

#include "dfchaos/errors.hpp"
#include "dfchaos/simulator.hpp"

namespace dfchaos {

const char* eventual_behaviour_name(EventualBehaviour b) {
  switch (b) {
    case EventualBehaviour::FreeFlights: return "free flights";
    case EventualBehaviour::StaysStopped: return "stays stopped";
    case EventualBehaviour::EternalProgression: return "eternal progression";
    case EventualBehaviour::PeriodicStickSlip: return "periodic stick-slip";
    case EventualBehaviour::Undetermined: break;
  }
  return "undetermined";
}

EventualRegime eventual_regime(const Parameters& p, double v0, double t0, double periods, double window_periods) {
  if (!std::isfinite(periods) || periods < 1 || periods > 1e6) throw InvalidParameter("periods", "1 <= periods <= 10^6", periods);
  if (!std::isfinite(window_periods) || window_periods <= 0 || window_periods >= periods)
    throw InvalidParameter("window", "0 < window < periods", window_periods);
  const double t_end = t0 + periods * two_pi, w0 = t_end - window_periods * two_pi;
  const Simulation sim = simulate(p, 0.0, 0.0, v0, t0, t_end);
  EventualRegime r;
  double in[3] = {0, 0, 0};
  Regime current = sim.initial_regime;
  double since = t0;
  auto account = [&](double until) {
    const double lo = std::max(since, w0), hi = std::min(until, t_end);
    if (hi > lo) in[static_cast<int>(current)] += hi - lo;
  };
  const bool has_t0 = p.t0().has_value();
  double start_err = 0, stop_min = two_pi, stop_max = 0;
  long long starts = 0, stops = 0;
  for (const auto& e : sim.events) {
    account(e.t);
    if (current == Regime::Free) r.last_free_time = e.t;
    if (e.t >= w0) {
      ++r.events_in_window;
      if (e.after == Regime::Progression && e.before == Regime::Stop && has_t0) {
        const double d = std::fabs(std::remainder(e.when.phase - *p.t0(), two_pi));
        start_err = std::max(start_err, d);
        ++starts;
      }
      if (e.before == Regime::Progression && e.after == Regime::Stop && has_t0) {
        const double from_t1 = wrap_phase(e.when.phase - *p.t1());
        stop_min = std::min(stop_min, from_t1);
        stop_max = std::max(stop_max, from_t1);
        ++stops;
      }
    }
    current = e.after;
    since = e.t;
  }
  account(t_end);
  if (current == Regime::Free) r.last_free_time = t_end;
  const double total = in[0] + in[1] + in[2];
  r.fraction_free = in[static_cast<int>(Regime::Free)] / total;
  r.fraction_progression = in[static_cast<int>(Regime::Progression)] / total;
  r.fraction_stop = in[static_cast<int>(Regime::Stop)] / total;
  if (r.fraction_free > 0) {
    r.behaviour = EventualBehaviour::FreeFlights;
  } else if (r.events_in_window == 0 && current == Regime::Stop) {
    r.behaviour = EventualBehaviour::StaysStopped;
  } else if (r.events_in_window == 0 && current == Regime::Progression) {
    r.behaviour = EventualBehaviour::EternalProgression;
  } else if (starts > 0 && stops > 0 && start_err < 1e-9 && stop_max < two_pi - (*p.t1() - *p.t0()) + 1e-9) {
    // every restart at t0, every stop in [t1, t0 + 2pi): the stop phase measured from t1 is below
    // the length of the arc [t1, t0 + 2pi)
    r.behaviour = EventualBehaviour::PeriodicStickSlip;
    r.stick_start_phase_max_error = start_err;
    r.stick_stop_phase_min = stop_min;
    r.stick_stop_phase_max = stop_max;
  }
  return r;
}

}  // namespace dfchaos
