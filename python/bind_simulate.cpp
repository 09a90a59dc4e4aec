// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bind_simulate.cpp
/// @brief dfchaos.simulate: the event-driven simulation of the full system (Section 2), its event
/// log and regular samples as numpy arrays with the columns of `dfchaos simulate`.
#include <pybind11/stl.h>

#include <optional>
#include <utility>

#include "convert.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/limits.hpp"
#include "dfchaos/simulator.hpp"

namespace dfchaos::python {

namespace {

py::dict simulate_py(const Parameters& p, double x0, double y0, double v0, double t0, double t_end, const std::optional<double>& sample,
                     long long max_events) {
  // The CLI's checks of its own options (the library checks the rest, with the CLI's messages).
  SimulationOptions so;
  for (const auto& [name, v] : {std::pair{"x0", x0}, std::pair{"y0", y0}, std::pair{"v0", v0}, std::pair{"t0", t0}, std::pair{"t-end", t_end}})
    finite(name, v);
  if (sample) {
    so.sample_dt = finite("sample", *sample);
    if (!(so.sample_dt > 0)) throw InvalidParameter("sample", "sample > 0", so.sample_dt);
  }
  if (max_events < 1 || max_events > kMaxSimulationEvents)
    throw InvalidParameter("max-events", "1 <= max-events <= " + format_shortest(static_cast<double>(kMaxSimulationEvents)),
                           static_cast<double>(max_events));
  so.max_events = static_cast<long>(max_events);

  Simulation r;
  {
    py::gil_scoped_release nogil;
    r = simulate(p, x0, y0, v0, t0, t_end, so);
  }

  const std::vector<py::ssize_t> ne{static_cast<py::ssize_t>(r.events.size())};
  RealArray t(ne), phase(ne), x(ne), y(ne), vb(ne), va(ne);
  StrColumn before(ne, 1), after(ne, 1), kind(ne, 2);
  for (py::ssize_t i = 0; i < ne[0]; ++i) {
    const SimulationEvent& e = r.events[static_cast<std::size_t>(i)];
    t.mutable_data()[i] = e.t;
    phase.mutable_data()[i] = e.when.phase;
    before.set(i, regime_code(e.before));
    after.set(i, regime_code(e.after));
    kind.set(i, transition_code(e.kind));
    x.mutable_data()[i] = e.x;
    y.mutable_data()[i] = e.y;
    vb.mutable_data()[i] = e.v_before;
    va.mutable_data()[i] = e.v_after;
  }
  py::dict events;
  events["t"] = t;
  events["phase"] = phase;
  events["before"] = before.array;
  events["after"] = after.array;
  events["kind"] = kind.array;
  events["x"] = x;
  events["y"] = y;
  events["v_before"] = vb;
  events["v_after"] = va;

  const std::vector<py::ssize_t> ns{static_cast<py::ssize_t>(r.samples.size())};
  RealArray st(ns), sx(ns), sy(ns), sv(ns);
  StrColumn regime(ns, 1);
  for (py::ssize_t i = 0; i < ns[0]; ++i) {
    const Sample& s = r.samples[static_cast<std::size_t>(i)];
    st.mutable_data()[i] = s.t;
    sx.mutable_data()[i] = s.x;
    sy.mutable_data()[i] = s.y;
    sv.mutable_data()[i] = s.v;
    regime.set(i, regime_code(s.regime));
  }
  py::dict samples;
  samples["t"] = st;
  samples["x"] = sx;
  samples["y"] = sy;
  samples["v"] = sv;
  samples["regime"] = regime.array;

  py::dict final_state;
  final_state["t"] = r.final_state.t.value();
  final_state["phase"] = r.final_state.t.phase;
  final_state["x"] = r.final_state.x;
  final_state["y"] = r.final_state.y;
  final_state["v"] = r.final_state.v;
  final_state["regime"] = regime_code(r.final_state.regime);

  py::dict d;
  d["initial_regime"] = regime_code(r.initial_regime);
  d["events"] = events;
  d["samples"] = samples;
  d["final"] = final_state;
  return d;
}

}  // namespace

void bind_simulate(py::module_& m) {
  // Each docstring opens with its own signature line (with the result types pybind11 cannot name).
  py::options options;
  options.disable_function_signatures();
  m.def("simulate", &simulate_py, py::arg("p"), py::arg("x0"), py::arg("y0"), py::arg("v0"), py::arg("t0"), py::arg("t_end"), py::kw_only(),
        py::arg("sample") = py::none(), py::arg("max_events") = SimulationOptions{}.max_events,
        R"doc(simulate(p, x0, y0, v0, t0, t_end, *, sample=None, max_events=1000000) -> dict

Event-driven simulation of the full system (Section 2) from x(t0) = x0 (mass), y(t0) = y0
(delimiter), x'(t0) = v0 until t_end, in closed form between events. Any positive parameters (also
outside the paper's assumptions). Keys:
  initial_regime  'f' free flight (Eq. 3), 'p' progression (Eq. 4) or 's' stop (Eq. 5)
  events   dict of arrays, one element per regime change (the rows of `dfchaos simulate`):
           t, phase (t mod 2 pi, exact), before, after (regime codes, str arrays), kind ('fp': an
           impact starts a progression; 'is': an instantaneous stop), x, y, v_before, v_after
  samples  dict of arrays t, x, y, v, regime: the state every `sample` time units from t0
           (empty arrays when sample is None)
  final    dict t, phase, x, y, v, regime: the state at t_end
Raises ValueError (the CLI's messages) for non-finite input, |t0|, |t_end| > max_simulation_time,
x0 > y0, t_end < t0, sample <= 0, more than 5e6 samples, max_events outside [1, 1e8];
dfchaos.GaveUp if more than max_events events occur. Runs without the GIL.)doc");
}

}  // namespace dfchaos::python
