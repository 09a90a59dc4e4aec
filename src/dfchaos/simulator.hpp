// SPDX-License-Identifier: GPL-3.0-or-later
/// @file simulator.hpp
/// @brief Event-driven simulation of the full system \f$(x, y, \dot x, \text{regime})\f$ (Section 2).
///
/// Works for all positive parameters — also \f$b \ge a/2\f$, \f$q \le 2b\f$, \f$q \ge a + 2b\f$
/// (Remark of Section 9) — stepping through regime_chain.hpp with the closed forms of motion.hpp.
/// Every loop is bounded: reaching max_events or max_samples is an error, not a hang.
///
/// Two forms of one computation: the streaming form hands each event and sample to a
/// SimulationSink as it is found and keeps none (memory flat in their number, as `dfchaos simulate`
/// needs for \f$10^8\f$ events); the vector form collects them in a Simulation through it.
#pragma once

#include <vector>

#include "dfchaos/parameters.hpp"
#include "dfchaos/regime_chain.hpp"

namespace dfchaos {

/// One logged event: a regime change (fp or is), or a grazing touch (is, free to free).
struct SimulationEvent {
  double t = 0;                                             ///< instant (real)
  Instant when;                                             ///< the same as turn and phase
  Regime before = Regime::Free;                             ///< regime before the event
  Regime after = Regime::Free;                              ///< regime after the event
  TransitionKind kind = TransitionKind::InstantaneousStop;  ///< fp or is
  double x = 0;                                             ///< position of the mass
  double y = 0;                                             ///< position of the delimiter
  double v_before = 0;                                      ///< velocity just before
  double v_after = 0;                                       ///< velocity just after
};

/// A state sampled on a regular time grid.
struct Sample {
  double t = 0;                  ///< time
  double x = 0;                  ///< position of the mass
  double y = 0;                  ///< position of the delimiter
  double v = 0;                  ///< velocity of the mass
  Regime regime = Regime::Free;  ///< regime at t
};

/// Largest \f$|t_0|\f$, \f$|t_{end}|\f$ accepted by simulate(): a double time near \f$10^{12}\f$ is
/// resolved to \f$1.2\cdot 10^{-4}\f$ (the printed event times and the sample grid), and the phases
/// (exact there) are what the dynamics depends on. Larger times are refused, not wrapped.
inline constexpr double kMaxSimulationTime = 1e12;

/// Bounds and sampling of a simulation.
struct SimulationOptions {
  double sample_dt = 0;          ///< spacing of samples; 0 for none
  long max_events = 1'000'000;   ///< more events than this before t_end is an error
  long max_samples = 5'000'000;  ///< more samples than this is refused up front
};

/// The receiver of a simulation as it happens (the streaming form of simulate()), which keeps nothing
/// itself. The calls come in time order: start() once, after the input has been checked (bad input
/// throws before any call); then every event and every sample, a sample at
/// \f$t_k = t_0 + k\,\Delta t\f$ before an event at instant \f$t\f$ when \f$t_k < t\f$, after it
/// otherwise (a sample at the instant of an event shows the state after the event). An exception
/// thrown by the sink ends the simulation and propagates.
class SimulationSink {
 public:
  virtual ~SimulationSink() = default;
  /// Once, first: the regime chosen at the initial state (Simulation::initial_regime).
  virtual void start(Regime initial_regime) = 0;
  /// Each regime change or grazing touch, in time order (an element of Simulation::events).
  virtual void event(const SimulationEvent& e) = 0;
  /// Each regular sample, in time order (an element of Simulation::samples).
  virtual void sample(const Sample& s) = 0;
};

/// The outcome of a simulation.
struct Simulation {
  Regime initial_regime = Regime::Free;  ///< regime chosen at the initial state
  std::vector<SimulationEvent> events;   ///< every regime change, in time order
  std::vector<Sample> samples;           ///< the regular samples (if requested)
  MechanicalState final_state;           ///< at t_end
};

/// Simulates from \f$x(t_0) = x_0\f$, \f$y(t_0) = y_0\f$, \f$\dot x(t_0) = v_0\f$ until \f$t_{end}\f$,
/// handing each event and sample to `sink` as it is found (the streaming form: memory does not grow
/// with the number of events or samples). The events are the regime changes and grazing touches of
/// the regime chain (regime_chain.hpp) from \f$t_0\f$ up to \f$t_{end}\f$; the samples are the states at
/// \f$t_k = t_0 + k\,\Delta t \le t_{end}\f$, \f$k = 0, 1, \dots\f$, with
/// \f$\Delta t\f$ = options.sample_dt (none when 0).
/// @return the state at \f$t_{end}\f$ (Simulation::final_state).
/// @throws InvalidParameter (`x0`, `y0`, `v0`, `t0`, `t-end`, `sample`) for non-finite values,
///         \f$|x_0|, |y_0|, |v_0| >\f$ kMaxParameter, \f$|t_0|\f$ or \f$|t_{end}| >\f$
///         kMaxSimulationTime, \f$x_0 > y_0\f$, \f$t_{end} < t_0\f$, a negative sample step or more
///         than options.max_samples samples; before any call of the sink.
/// @throws GaveUp if more than options.max_events events occur before \f$t_{end}\f$: the sink has
///         then received start(), the first max_events events and the samples before the next one.
MechanicalState simulate(const Parameters& p, double x0, double y0, double v0, double t0, double t_end, const SimulationOptions& options,
                         SimulationSink& sink);

/// The vector form: the same simulation (the streaming form above, its calls collected in order), as
/// one Simulation held in memory (72 bytes per event and 40 per sample).
/// @throws InvalidParameter, GaveUp as the streaming form.
Simulation simulate(const Parameters& p, double x0, double y0, double v0, double t0, double t_end, const SimulationOptions& options = {});

/// The state at instant t of the regime segment that starts in state s (no event in between).
MechanicalState state_in_segment(const Parameters& p, const MechanicalState& s, const Instant& t);

}  // namespace dfchaos
