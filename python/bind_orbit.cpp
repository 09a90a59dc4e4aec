// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bind_orbit.cpp
/// @brief The observables of one orbit at one parameter set, as a sweep's cell computes them:
/// dfchaos.lyapunov, dfchaos.rate, dfchaos.period (sweep::plane_orbit, the rule of the sweep's
/// columns) and dfchaos.derivative (T', map_derivative, which the Lyapunov exponent sums).
#include <pybind11/stl.h>

#include <optional>
#include <vector>

#include "convert.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/map_derivative.hpp"
#include "sweep/cell.hpp"
#include "sweep/orbit_diagram.hpp"
#include "sweep/spec.hpp"

namespace dfchaos::python {

namespace {

/// The orbit observables of `p` from theta0 (the sweep's default start when none), after the
/// checks of `dfchaos sweep` on the counts (the same messages) and of `dfchaos orbit` on theta0.
sweep::PlaneOrbit orbit_observables(const Parameters& p, std::optional<double> theta0, long long steps, long long transient, bool statistics,
                                    const sweep::PeriodSettings* period) {
  p.require_return_map();
  sweep::OrbitSettings o;
  o.transient = transient;
  o.steps = steps;
  o.validate();
  if (period) period->validate();
  double start = 0;
  if (theta0) {
    start = finite("theta0", *theta0);
    p.require_in_map_domain(start, "theta0");
  } else {
    start = sweep::orbit_start(p, o.theta0_fraction);  // the sweep's default start, t2 + (t3 - t2)/2
  }
  const sweep::PeriodSettings settings = period ? *period : sweep::PeriodSettings{};
  return interruptible([&] { return sweep::plane_orbit(p, start, o, settings, statistics, period != nullptr); });
}

}  // namespace

void bind_orbit(py::module_& m) {
  py::options options;
  options.disable_function_signatures();
  const sweep::OrbitSettings orbit_defaults;
  const sweep::PeriodSettings period_defaults;

  m.def(
      "lyapunov",
      [](const Parameters& p, std::optional<double> theta0, long long steps, long long transient) {
        return orbit_observables(p, theta0, steps, transient, true, nullptr).lyapunov;
      },
      py::arg("p"), py::arg("theta0") = py::none(), py::arg("steps") = orbit_defaults.steps, py::arg("transient") = orbit_defaults.transient,
      R"doc(lyapunov(p, theta0=None, steps=1000, transient=1000) -> float

The Lyapunov exponent of the orbit of the return map T from the phase theta0: `transient` steps
discarded, then (1/steps) * sum of ln|T'(theta_n)| over the next `steps` steps; -inf as soon as one
of those steps has a stop (T' = 0 there: a superstable step); a step at a grazing (T' undefined)
adds nothing. The `lyapunov` column of `dfchaos sweep`, computed by the same C++ function: equal to
a one-cell sweep with the same parameters to the last bit.

theta0: a phase in [t2, t3), as in orbit(); None (the default) starts where a sweep starts by
default, t2 + (t3 - t2)/2. (The tool's `sweep --theta0-fraction` is a fraction f of the arc:
theta0 = p.t2 + f * (p.t3 - p.t2) here gives its start to the last bit.)
Raises ValueError (dfchaos.InvalidParameter, the tool's messages) unless the map is defined (as T),
theta0 is in [t2, t3), 1 <= steps <= 1e8 and 0 <= transient <= 1e8; dfchaos.GaveUp if the motion
never flies again. Runs without the GIL (about 2 us per step); Ctrl-C raises KeyboardInterrupt within a
fraction of a second.)doc");

  m.def(
      "rate",
      [](const Parameters& p, std::optional<double> theta0, long long steps, long long transient) {
        return orbit_observables(p, theta0, steps, transient, true, nullptr).rate;
      },
      py::arg("p"), py::arg("theta0") = py::none(), py::arg("steps") = orbit_defaults.steps, py::arg("transient") = orbit_defaults.transient,
      R"doc(rate(p, theta0=None, steps=1000, transient=1000) -> float

The mean drilling speed along the orbit of T from theta0: the delimiter's advance over the elapsed
time of the `steps` steps after the `transient` discarded ones (units of the parameters per unit of
the dimensionless time t; docs/units.md converts it to metres per second). The `rate` column of
`dfchaos sweep`, by the same C++ function: equal to a one-cell sweep to the last bit.
Arguments and errors as lyapunov().)doc");

  m.def(
      "period",
      [](const Parameters& p, std::optional<double> theta0, long long steps, long long transient, long long period_max, double period_tol) {
        const sweep::PeriodSettings s{.max = period_max, .tol = period_tol};
        return static_cast<long long>(orbit_observables(p, theta0, steps, transient, false, &s).period);
      },
      py::arg("p"), py::arg("theta0") = py::none(), py::arg("steps") = orbit_defaults.steps, py::arg("transient") = orbit_defaults.transient,
      py::arg("period_max") = period_defaults.max, py::arg("period_tol") = period_defaults.tol,
      R"doc(period(p, theta0=None, steps=1000, transient=1000, period_max=64, period_tol=1e-9) -> int

The period of the cycle that the computed orbit of T closes at its end: with
e = T^(transient + steps)(theta0), the smallest k <= period_max with |T^k(e) - e| <= period_tol on
the circle; 0 when there is none (a chaotic orbit, a longer cycle or a slower approach). A cycle of
the computed orbit: through a stop it may be a cycle of the rounding (see dfchaos sweep --help).
The `period` column of `dfchaos sweep`, by the same C++ function: equal to a one-cell sweep with the
same settings. Arguments and errors as lyapunov(), and ValueError unless 1 <= period_max <= 10000
and 1e-15 <= period_tol <= 1e-3 (the messages name period-max and period-tol, as the tool does).)doc");

  const OrbitDiagramSettings diagram;
  m.def(
      "orbit_diagram",
      [](const py::handle& q_over_a, const py::handle& b_over_a, double a, double theta0_fraction, long long transient, long long steps,
         long long keep) {
        const Reals qs = as_reals(q_over_a, "q_over_a"), bs = as_reals(b_over_a, "b_over_a");
        const std::vector<double> q(qs.array.data(), qs.array.data() + qs.array.size()), b(bs.array.data(), bs.array.data() + bs.array.size());
        const OrbitDiagramSettings set{finite("theta0_fraction", theta0_fraction), transient, steps, keep};
        set.validate();
        sweep::check_orbit_diagram_size(static_cast<double>(q.size()), static_cast<double>(b.size()), set);  // before the result arrays
        const double av = finite("a", a);
        const auto cells = static_cast<py::ssize_t>(q.size() * b.size());
        std::vector<double> theta, lyapunov(static_cast<std::size_t>(cells));
        std::vector<long long> period(static_cast<std::size_t>(cells));
        std::vector<bool> superstable(static_cast<std::size_t>(cells));
        interruptible([&] {
          sweep::orbit_diagram(av, q, b, set, [&](long long i, const OrbitDiagramColumn& c) {
            if (theta.empty()) theta.reserve(static_cast<std::size_t>(cells * keep));
            theta.insert(theta.end(), c.orbit.tail.begin(), c.orbit.tail.end());
            lyapunov[static_cast<std::size_t>(i)] = c.orbit.lyapunov;
            period[static_cast<std::size_t>(i)] = c.orbit.period_of_t2;
            superstable[static_cast<std::size_t>(i)] = c.cycle.resolved;
          });
          return 0;
        });
        py::array_t<double> qa(cells), ba(cells), ly(cells), th({cells, static_cast<py::ssize_t>(keep)});
        py::array_t<long long> pe(cells);
        py::array_t<bool> su(cells);
        const auto nb = static_cast<py::ssize_t>(b.size());
        for (py::ssize_t i = 0; i < cells; ++i) {
          qa.mutable_at(i) = q[static_cast<std::size_t>(i / nb)];
          ba.mutable_at(i) = b[static_cast<std::size_t>(i % nb)];
          ly.mutable_at(i) = lyapunov[static_cast<std::size_t>(i)];
          pe.mutable_at(i) = period[static_cast<std::size_t>(i)];
          su.mutable_at(i) = superstable[static_cast<std::size_t>(i)];
        }
        std::copy(theta.begin(), theta.end(), th.mutable_data());
        py::dict out;
        out["q_over_a"] = qa;
        out["b_over_a"] = ba;
        out["theta"] = th;
        out["lyapunov"] = ly;
        out["period_of_t2"] = pe;
        out["superstable"] = su;
        return out;
      },
      py::arg("q_over_a"), py::arg("b_over_a"), py::arg("a") = 1.0, py::arg("theta0_fraction") = diagram.theta0_fraction,
      py::arg("transient") = diagram.transient, py::arg("steps") = diagram.steps, py::arg("keep") = diagram.keep,
      R"doc(orbit_diagram(q_over_a, b_over_a, a=1.0, theta0_fraction=0.377, transient=500, steps=256, keep=64) -> dict

`dfchaos orbit-diagram` (the same C++ function, to the last bit) over the cells of the axes q/a
(outer) and b/a (inner), each a number or a 1-d array-like: numpy arrays, one entry per cell, of
q_over_a, b_over_a, theta (shape (cells, keep): the last phases of the orbit from t2 +
theta0_fraction (t3 - t2)), lyapunov (-inf when a step stopped), period_of_t2 (the return time of
t2, else 0) and superstable (that return resolved as a superstable cycle, Theorem 2). Settings,
bounds and messages as the tool's (`dfchaos orbit-diagram --help`); runs without the GIL.)doc");

  m.def(
      "derivative",
      [](const Parameters& p, const py::handle& theta) {
        p.require_return_map();
        return map_reals(theta, "theta", [&p](double x) { return map_derivative(p, x).dT; });
      },
      py::arg("p"), py::arg("theta"), R"doc(derivative(p, theta) -> float or numpy.ndarray

T'(theta), the derivative of the return map (Lemma 3), as the library computes it for the Lyapunov
exponent (map_derivative: the implicit function theorem on Eqs. 11 and 17):
  scenario A                 the derivative, (2b + a sin theta - q T1'(theta)) / (2c + a sin theta2)
  B, C, C', D, D' (a stop)   exactly 0.0: the next flight starts at an instant that does not depend on
                             theta, so T is locally constant (a superstable step)
  G (grazing), 'other'       nan: T is not differentiable there (T1 jumps at a grazing)
step(p, theta)["scenario"] tells which case applies. lyapunov(p, theta, steps=1, transient=0) is
math.log(abs(derivative(p, theta))) to the last bit when that is finite (-inf when it is 0).
theta and errors as for T (array-likes give arrays of their shape; the loop runs without the GIL).)doc");
}

}  // namespace dfchaos::python
