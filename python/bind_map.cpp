// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bind_map.cpp
/// @brief The return map: dfchaos.T (Lemma 3), dfchaos.T1 (Eq. 11), dfchaos.step (with theta2 of
/// Eq. 17, the scenario of Section 3, elapsed time and penetration) and dfchaos.orbit, vectorized
/// over numpy arrays by a C++ loop without the GIL; dfchaos._bench_T times the bare C++ loop.
#include <chrono>

#include "convert.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/limits.hpp"
#include "dfchaos/next_hit.hpp"
#include "dfchaos/orbit.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos::python {

namespace {

/// Longest scenario name ("other"): the width of the str columns.
constexpr py::ssize_t kScenarioWidth = 5;

/// The columns of step() for an array of phases.
struct StepColumns {
  RealArray theta, T1, theta2, T, elapsed, penetration;
  StrColumn scenario;
  explicit StepColumns(const std::vector<py::ssize_t>& shape)
      : theta(shape), T1(shape), theta2(shape), T(shape), elapsed(shape), penetration(shape), scenario(shape, kScenarioWidth) {}
  void set(py::ssize_t i, const MapStep& s) {
    theta.mutable_data()[i] = s.theta;
    T1.mutable_data()[i] = s.hit.theta1;
    theta2.mutable_data()[i] = s.theta2.value();
    T.mutable_data()[i] = s.T;
    elapsed.mutable_data()[i] = s.elapsed;
    penetration.mutable_data()[i] = s.penetration;
    scenario.set(i, scenario_name(s.scenario));
  }
  py::dict dict() const {
    py::dict d;
    d["theta"] = theta;
    d["T1"] = T1;
    d["theta2"] = theta2;
    d["T"] = T;
    d["scenario"] = scenario.array;
    d["elapsed"] = elapsed;
    d["penetration"] = penetration;
    return d;
  }
};

py::dict step_dict(const MapStep& s) {
  py::dict d;
  d["theta"] = s.theta;
  d["T1"] = s.hit.theta1;
  d["theta2"] = s.theta2.value();
  d["T"] = s.T;
  d["scenario"] = scenario_name(s.scenario);
  d["elapsed"] = s.elapsed;
  d["penetration"] = s.penetration;
  d["chain"] = s.chain;
  d["progressions"] = s.progressions;
  d["hit_velocity"] = s.hit.hit_velocity;
  return d;
}

py::object step(const Parameters& p, const py::handle& theta) {
  p.require_return_map();
  const Reals in = as_reals(theta, "theta");
  const double* x = in.array.data();
  if (in.scalar) return step_dict(return_map_step(p, x[0]));
  StepColumns out(in.shape());
  loop_without_gil(in.array.size(), [&](py::ssize_t i) { out.set(i, return_map_step(p, x[i])); });
  return out.dict();
}

py::dict orbit(const Parameters& p, double theta0, long long steps) {
  p.require_return_map();
  finite("theta0", theta0);
  p.require_in_map_domain(theta0, "theta0");  // before any work, as the CLI
  if (steps < 1 || steps > kMaxOrbitSteps)
    throw InvalidParameter("steps", "1 <= steps <= " + format_shortest(static_cast<double>(kMaxOrbitSteps)), static_cast<double>(steps));
  const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(steps)};
  RealArray theta(shape), elapsed(shape), penetration(shape), time(shape), y(shape);
  StrColumn scenario(shape, kScenarioWidth);
  double *th = theta.mutable_data(), *el = elapsed.mutable_data(), *pe = penetration.mutable_data();
  double *ti = time.mutable_data(), *yy = y.mutable_data();
  const Orbit orbit(p, theta0, steps);
  Orbit::iterator it;
  loop_without_gil(shape[0], [&](py::ssize_t n) {
    if (n == 0)
      it = orbit.begin();
    else
      ++it;
    th[n] = it->theta;
    scenario.set(n, scenario_name(it->scenario));
    el[n] = it->elapsed;
    pe[n] = it->penetration;
    ti[n] = static_cast<double>(it.time());
    yy[n] = static_cast<double>(it.y());
  });
  py::dict d;
  d["theta"] = theta;
  d["scenario"] = scenario.array;
  d["elapsed"] = elapsed;
  d["penetration"] = penetration;
  d["time"] = time;
  d["y"] = y;
  return d;
}

/// Seconds taken by the bare C++ loop `T(p, theta[i])` over the array (no conversion, no result
/// array): the reference cost per evaluation for the timing test.
double bench_T(const Parameters& p, const RealArray& theta) {
  const double* x = theta.data();
  const py::ssize_t n = theta.size();
  py::gil_scoped_release nogil;
  double sum = 0;
  const auto start = std::chrono::steady_clock::now();
  for (py::ssize_t i = 0; i < n; ++i) sum += T(p, x[i]);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  volatile double sink = sum;  // keeps the loop
  (void)sink;
  return seconds;
}

}  // namespace

void bind_map(py::module_& m) {
  // Each docstring opens with its own signature line (with the result types pybind11 cannot name).
  py::options options;
  options.disable_function_signatures();
  py::tuple names(8);
  const Scenario all[] = {Scenario::A, Scenario::B, Scenario::C, Scenario::D, Scenario::Cprime, Scenario::Dprime, Scenario::Grazing, Scenario::Other};
  for (std::size_t k = 0; k < 8; ++k) names[k] = scenario_name(all[k]);
  m.attr("scenario_names") = names;

  m.def(
      "T",
      [](const Parameters& p, const py::handle& theta) {
        p.require_return_map();
        return map_reals(theta, "theta", [&p](double x) { return T(p, x); });
      },
      py::arg("p"), py::arg("theta"), R"doc(T(p, theta) -> float or numpy.ndarray

The return map T of Lemma 3 (Section 3): the phase in [t2, t3) at which the motion started at rest
at the delimiter at phase theta (Eq. 10) next switches to free flight, following the general chain
of regimes (progression, stops, restarts at t0) without assuming Lemma 1.

theta: a phase in [t2, t3), or any array-like of them (converted to contiguous float64). A scalar
gives a float, an array an array of the same shape. The loop runs in C++ without the GIL.
Raises ValueError (dfchaos.InvalidParameter) unless b < a/2, q > 2b, b/a >= min_map_ratio and every
theta lies in [t2, t3) (the CLI's messages; a NaN or inf element is named with its index before any
work); dfchaos.GaveUp if the motion never flies again (eternal stick-slip).
Accuracy: docs/accuracy.md (within 1e-11 of the exact T, 1e-9 near discontinuities of T1).
Equal to the T column of `dfchaos map` to the last bit.)doc");

  m.def(
      "T1",
      [](const Parameters& p, const py::handle& theta) {
        p.require_return_map();
        return map_reals(theta, "theta", [&p](double x) { return next_hit(p, x).theta1; });
      },
      py::arg("p"), py::arg("theta"), R"doc(T1(p, theta) -> float or numpy.ndarray

The next-hit map T1 of Eq. (11): the first instant theta1 > theta at which the mass, started at rest
at the delimiter at phase theta, returns to it (the first zero of
G1(theta, t) = b (t - theta)^2 - a sin t + a cos(theta) (t - theta) + a sin(theta)).
An instant, not a phase: it may exceed 2 pi by many periods.

theta and errors as for T (the same conditions as `dfchaos map`, so the same messages).
Equal to the T1 column of `dfchaos map` to the last bit.)doc");

  m.def("step", &step, py::arg("p"), py::arg("theta"), R"doc(step(p, theta) -> dict

One application of T from theta, with what happened on the way. Keys:
  theta        the start phase (Eq. 10)
  T1           the next hit T1(theta), an instant (Eq. 11)
  theta2       where the first progression stops, the first zero of G2 (Eq. 17), an instant
               (equal to T1 after a grazing touch, when no progression happens)
  T            T(theta) in [t2, t3) (Lemma 3)
  scenario     the scenario of Section 3: one of scenario_names
               ('A', 'B', 'C', 'D', "C'", "D'", 'G' for a grazing touch, 'other')
  elapsed      the time from theta to the next start of free flight
  penetration  the advance of the delimiter during that time
For a scalar theta the values are Python scalars, and three more keys are given: chain (the
regimes visited, e.g. 'f>p>s>f'), progressions (their number) and hit_velocity (the impact
velocity at T1; 0 at a grazing contact). For an array the values are arrays of theta's shape
(scenario a numpy array of str, dtype '<U5').
Errors as for T. Equal to the columns of `dfchaos map` to the last bit.)doc");

  m.def("orbit", &orbit, py::arg("p"), py::arg("theta0"), py::arg("steps"), R"doc(orbit(p, theta0, steps) -> dict of numpy arrays of length steps

The orbit theta_n = T^n(theta0), n = 0 .. steps-1, of the return map T (Lemma 3), with the
columns of `dfchaos orbit` (row n is element n; element 0 is theta0):
  theta        theta_n
  scenario     the scenario of the step from theta_n (numpy str array, values in scenario_names)
  elapsed      the duration of that step
  penetration  the advance of the delimiter during that step
  time         the time at which theta_n starts (theta0 at n = 0)
  y            the delimiter's position at that time (0 at n = 0)
time and y are summed in long double, as the CLI does.
Raises ValueError unless the map is defined, theta0 is in [t2, t3) and 1 <= steps <= 1e8;
dfchaos.GaveUp if the motion never flies again. Each step has T's accuracy; errors grow along
the orbit by |T'|: a long orbit is a faithful pseudo-orbit. Runs without the GIL; Ctrl-C stops it.)doc");

  m.def(
      "_bench_T",
      [](const Parameters& p, const py::handle& theta) {
        p.require_return_map();
        const Reals in = as_reals(theta, "theta");
        return bench_T(p, in.array);
      },
      py::arg("p"), py::arg("theta"),
      "_bench_T(p, theta) -> float\n\nSeconds taken by the bare C++ loop over T(p, theta[i]) (no conversion, no "
      "result array): the reference cost per evaluation for dfchaos.T (tests/python/test_timing.py).");
}

}  // namespace dfchaos::python
