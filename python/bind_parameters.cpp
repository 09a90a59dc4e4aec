// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bind_parameters.cpp
/// @brief dfchaos.Parameters, the exceptions (InvalidParameter is a ValueError, GaveUp a
/// RuntimeError) and the constants of the accuracy contract.
#include <pybind11/stl.h>

#include "convert.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/simulator.hpp"
#include "dfchaos/units.hpp"

namespace dfchaos::python {

namespace {

Parameters make_parameters(double a, double b, double q) { return Parameters(finite("a", a), finite("b", b), finite("q", q)); }

}  // namespace

void bind_parameters(py::module_& m) {
  // ---- exceptions ----------------------------------------------------------------------------
  // Bad input: dfchaos.InvalidParameter, a subclass of ValueError whose message is the library's
  // one line (the CLI prints it after "dfchaos: error: "), with the parameter's name as .parameter.
  // Both live as long as the process (never destroyed after the interpreter has gone).
  static auto& invalid = *new py::exception<InvalidParameter>(m, "InvalidParameter", PyExc_ValueError);
  // A bounded computation that gave up (for example a motion that never flies again).
  static auto& gave_up = *new py::exception<GaveUp>(m, "GaveUp", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidParameter& e) {
      py::object instance = py::handle(invalid)(e.what());
      instance.attr("parameter") = e.parameter();
      PyErr_SetObject(invalid.ptr(), instance.ptr());
    } catch (const GaveUp& e) {
      PyErr_SetString(gave_up.ptr(), e.what());
    }
  });
  invalid.doc() =
      "Bad input: a parameter breaks a stated condition. A subclass of ValueError; str(e) is the "
      "one-line message of the library (the CLI prints it after 'dfchaos: error: '), e.parameter "
      "the name of the offending parameter.";
  gave_up.doc() =
      "A bounded computation reached its bound without an answer (e.g. a motion that never returns "
      "to free flight, or more events than max_events). A subclass of RuntimeError.";

  // ---- constants -----------------------------------------------------------------------------
  m.attr("vartheta0") = vartheta0();
  m.attr("sin_vartheta0") = sin_vartheta0();
  m.attr("min_parameter") = kMinParameter;
  m.attr("max_parameter") = kMaxParameter;
  m.attr("min_map_ratio") = kMinMapRatio;
  m.attr("max_simulation_time") = kMaxSimulationTime;
  m.attr("max_elements") = kMaxElements;

  // ---- Parameters ----------------------------------------------------------------------------
  py::class_<Parameters>(m, "Parameters", R"doc(The parameters (a, b, q) of the oscillator (Section 2 of the paper): the mass obeys
x'' = F(t) = a sin t + 2b in free flight (Eq. 3) and x'' = F(t) - q while it drags the delimiter
(Eq. 4). Only b/a and q/a matter.

Parameters(a, b, q) accepts finite a, b, q in [min_parameter, max_parameter] = [1e-100, 1e100]
and raises ValueError (dfchaos.InvalidParameter) naming the parameter otherwise. The stronger
conditions of the paper are demanded by the functions that need them (require_return_map).
Picklable; immutable. An object made by Parameters.__new__ without __init__ is refused by every
function and method with a TypeError.)doc")
      .def(py::init(&make_parameters), py::arg("a"), py::arg("b"), py::arg("q"))
      .def_static(
          "from_physical",
          [](double mass, double omega, double amplitude, double static_force, double friction) {
            return from_physical(finite("mass", mass), finite("omega", omega), finite("amplitude", amplitude), finite("static_force", static_force),
                                 finite("friction", friction));
          },
          py::arg("mass"), py::arg("omega"), py::arg("amplitude"), py::arg("static_force"), py::arg("friction"),
          R"doc(Parameters.from_physical(mass, omega, amplitude, static_force, friction) -> Parameters

The parameters of a drilling model given in physical units (docs/units.md derives them): a mass
`mass` (kg) obeying m X'' = F0 sin(omega tau) + P in free flight and m X'' = F0 sin(omega tau) + P - Q
while it drags the delimiter, with omega the angular frequency of the forcing (rad/s), F0 =
`amplitude` the amplitude of the harmonic force (N), P = `static_force` the constant force (N) and
Q = `friction` the largest dry-friction force of the delimiter (N). Time is scaled by omega
(t = omega tau) and forces by mass * omega^2, so that
  a = F0 / (m omega^2),   b = P / (2 m omega^2),   q = Q / (m omega^2),
lengths in the unit of the input (metres for SI); back: tau = t / omega, speeds times omega.
Example: Parameters.from_physical(0.5, 100, 5000, 100, 4250) is dfchaos.Parameters(a=1, b=0.01, q=0.85).
Raises ValueError naming the argument unless each is finite and positive (the same function and
messages as `dfchaos info --physical`).)doc")
      .def_property_readonly("a", &Parameters::a, "amplitude of the harmonic forcing")
      .def_property_readonly("b", &Parameters::b, "half the constant forcing component")
      .def_property_readonly("q", &Parameters::q, "maximal dry-friction force of the delimiter")
      .def_property_readonly("c", &Parameters::c, "c = b - q/2: the progression equation (4) reads x'' = a sin t + 2c")
      .def_property_readonly("t0", &Parameters::t0, "t0 = asin((q - 2b)/a) in [0, 2 pi): F(t0) = q; None unless |q - 2b| < a")
      .def_property_readonly("t1", &Parameters::t1, "t1 = pi - asin((q - 2b)/a): F(t1) = q, F > q on (t0, t1); None unless |q - 2b| < a")
      .def_property_readonly("t2", &Parameters::t2, "t2 = pi + asin(2b/a): F(t2) = 0; None unless 2b < a")
      .def_property_readonly("t3", &Parameters::t3, "t3 = 2 pi - asin(2b/a): F(t3) = 0, F < 0 on (t2, t3), the arc of the map T; None unless 2b < a")
      .def_property_readonly(
          "vartheta0", [](const Parameters&) { return vartheta0(); },
          "vartheta0 in (0, pi/2]: the root of pi - vartheta = cot(vartheta/2) (Eq. 1); assumption (2) "
          "is a sin(vartheta0) < q < a. The same for every parameter set (also dfchaos.vartheta0).")
      .def_property_readonly(
          "assumptions",
          [](const Parameters& p) {
            const Assumptions s = p.assumptions();
            py::dict d;
            d["b_in_range"] = s.b_in_range;
            d["q_above_threshold"] = s.q_above_threshold;
            d["eq2"] = s.eq2;
            d["eq23"] = s.eq23;
            d["progression_ends"] = s.progression_ends;
            d["describe"] = s.describe();
            return d;
          },
          "Which of the paper's assumptions hold, as a dict: b_in_range (0 < b < a/2), q_above_threshold "
          "(a sin(vartheta0) < q < a), eq2 (all of Eq. 2), eq23 (Eq. 23), progression_ends (q > 2b), describe (one line).")
      .def(
          "F", [](const Parameters& p, double t) { return p.F(finite("t", t)); }, py::arg("t"),
          "F(t) = a sin t + 2b (Eq. 3). Raises ValueError unless t is finite.")
      .def("require_return_map", &Parameters::require_return_map,
           "Raises ValueError unless the return map T is defined here: b < a/2, q > 2b and b/a >= min_map_ratio.")
      .def("require_eq2", &Parameters::require_eq2, "Raises ValueError unless assumption (2) holds: 0 < b < a/2 and a sin(vartheta0) < q < a.")
      .def("describe", &Parameters::describe, "'a=... b=... q=...' in the shortest decimals that read back to the same doubles")
      .def("__repr__",
           [](const py::handle& self) -> std::string {
             // repr works on every object (debuggers and tracebacks call it): an unconstructed one
             // says so instead of raising.
             try {
               require_constructed(self);
             } catch (const py::type_error&) {
               return "<dfchaos.Parameters, not initialised>";
             }
             const auto& p = self.cast<const Parameters&>();
             // The shortest decimals that read back to the same doubles (the library's format_shortest).
             return "dfchaos.Parameters(a=" + format_shortest(p.a()) + ", b=" + format_shortest(p.b()) + ", q=" + format_shortest(p.q()) + ")";
           })
      // Equal when a, b and q are the same doubles (everything else is computed from them); hashable
      // alike, so that parameter sets can key a dict.
      .def(
          "__eq__",
          [](const Parameters& x, const py::object& y) -> py::object {
            if (!py::isinstance<Parameters>(y)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            const auto& o = y.cast<const Parameters&>();
            return py::bool_(x.a() == o.a() && x.b() == o.b() && x.q() == o.q());
          },
          py::is_operator())
      .def("__hash__", [](const Parameters& p) { return py::hash(py::make_tuple(p.a(), p.b(), p.q())); })
      .def(py::pickle([](const Parameters& p) { return py::make_tuple(p.a(), p.b(), p.q()); },
                      [](const py::tuple& t) {
                        if (t.size() != 3) throw std::runtime_error("dfchaos.Parameters: bad pickle state");
                        return make_parameters(t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>());
                      }));
}

}  // namespace dfchaos::python
