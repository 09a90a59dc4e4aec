// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/simulator.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "dfchaos/errors.hpp"
#include "dfchaos/motion.hpp"

namespace dfchaos {

MechanicalState state_in_segment(const Parameters& p, const MechanicalState& s, const Instant& t) {
  MechanicalState out = s;
  out.t = t;
  switch (s.regime) {
    case Regime::Free: {
      const FreeMotion m(p, s.t, s.x, s.v);
      out.x = m.position(t);
      out.v = m.velocity(t);
      break;
    }
    case Regime::Progression: {
      const ProgressionMotion m(p, s.t, s.x, s.v);
      out.x = out.y = m.position(t);
      out.v = m.velocity(t);
      break;
    }
    case Regime::Stop: out.v = 0; break;
  }
  return out;
}

MechanicalState simulate(const Parameters& p, double x0, double y0, double v0, double t0, double t_end, const SimulationOptions& options,
                         SimulationSink& sink) {
  auto finite = [](const char* name, double v) {
    if (!std::isfinite(v)) throw InvalidParameter(name, std::string(name) + " finite", v);
  };
  finite("x0", x0);
  finite("y0", y0);
  finite("v0", v0);
  finite("t0", t0);
  finite("t-end", t_end);
  // Positions and velocities on the scale of the parameters' range: beyond it x(t) can overflow.
  for (const auto& [name, v] : {std::pair{"x0", x0}, std::pair{"y0", y0}, std::pair{"v0", v0}})
    if (!(std::fabs(v) <= kMaxParameter)) throw InvalidParameter(name, std::string("|") + name + "| <= " + format_shortest(kMaxParameter), v);
  for (const auto& [name, v] : {std::pair{"t0", t0}, std::pair{"t-end", t_end}})
    if (!(std::fabs(v) <= kMaxSimulationTime))
      throw InvalidParameter(
          name, std::string("|") + name + "| <= " + format_shortest(kMaxSimulationTime) + " (beyond it a double time no longer resolves 1e-4)", v);
  if (x0 > y0) throw InvalidParameter("x0", "x0 <= y0 (the mass cannot pass the delimiter)", x0);
  if (t_end < t0) throw InvalidParameter("t-end", "t-end >= t0 = " + format_shortest(t0), t_end);
  if (!std::isfinite(options.sample_dt) || options.sample_dt < 0) throw InvalidParameter("sample", "sample >= 0 and finite", options.sample_dt);
  long n_samples = 0;
  if (options.sample_dt > 0) {
    const double n = std::floor((t_end - t0) / options.sample_dt) + 1;
    if (!(n <= static_cast<double>(options.max_samples)))
      throw InvalidParameter("sample", "(t-end - t0)/sample + 1 <= " + format_shortest(static_cast<double>(options.max_samples)) + " samples",
                             options.sample_dt);
    n_samples = static_cast<long>(n);
  }

  const Instant start = Instant::from_time(t0), stop = Instant::from_time(t_end);
  MechanicalState s{start, classify(p, start, x0, y0, v0), x0, y0, v0};
  if (x0 == y0 && s.regime != Regime::Free && s.regime != Regime::Progression) s.v = 0;
  sink.start(s.regime);

  long next_sample = 0;
  auto emit_samples_until = [&](const Instant& segment_end, bool inclusive) {
    while (next_sample < n_samples) {
      const double ts = t0 + static_cast<double>(next_sample) * options.sample_dt;
      const Instant is = Instant::from_time(ts);
      if (before(segment_end, is) || (!inclusive && is == segment_end)) break;
      const MechanicalState m = state_in_segment(p, s, before(is, s.t) ? s.t : is);
      sink.sample(Sample{ts, m.x, m.y, m.v, m.regime});
      ++next_sample;
    }
  };

  long n_events = 0;
  while (true) {
    SearchLimits lim;
    lim.horizon = elapsed(s.t, stop);
    const auto tr = next_transition(p, s, lim);
    if (!tr || before(stop, tr->t)) break;
    emit_samples_until(tr->t, false);
    if (n_events >= options.max_events)
      throw GaveUp("simulate: more than " + std::to_string(options.max_events) + " events before t-end=" + format_shortest(t_end) +
                   "; raise the event limit or shorten the time span");
    SimulationEvent e;
    e.when = tr->t;
    e.t = tr->t.value();
    e.before = tr->from;
    e.after = tr->to;
    e.kind = tr->kind;
    e.x = tr->x;
    e.y = tr->y;
    e.v_before = tr->v_before;
    e.v_after = tr->v_after;
    sink.event(e);
    ++n_events;
    s = tr->after();
  }
  emit_samples_until(stop, true);
  return state_in_segment(p, s, stop);
}

Simulation simulate(const Parameters& p, double x0, double y0, double v0, double t0, double t_end, const SimulationOptions& options) {
  // The streaming form, its calls collected in order.
  struct Collect final : SimulationSink {
    Simulation& sim;
    explicit Collect(Simulation& s) : sim(s) {}
    void start(Regime initial_regime) override { sim.initial_regime = initial_regime; }
    void event(const SimulationEvent& e) override { sim.events.push_back(e); }
    void sample(const Sample& s) override { sim.samples.push_back(s); }
  };
  Simulation sim;
  Collect collect(sim);
  sim.final_state = simulate(p, x0, y0, v0, t0, t_end, options, collect);
  return sim;
}

}  // namespace dfchaos
