// SPDX-License-Identifier: GPL-3.0-or-later
/// @file module.cpp
/// @brief The Python module `dfchaos`: a thin layer over the C++ library (src/dfchaos). Each group
/// of functions is bound by its own bind_X() (convert.hpp); the module only converts, checks and
/// loops, every number comes from the library.
#include "convert.hpp"

#ifndef DFCHAOS_VERSION
#error "DFCHAOS_VERSION must be defined by the build"
#endif

PYBIND11_MODULE(dfchaos, m) {
  namespace dp = dfchaos::python;
  m.doc() = R"doc(dfchaos: the dry-friction oscillator of Begun and Kryzhevich, "One-dimensional chaos in a system
with dry friction: analytical approach" (arXiv:1302.3377), from Python.

A thin layer over the C++ library: the same numbers as the `dfchaos` tool, to the last bit.

  p = Parameters(a, b, q)          t0..t3, vartheta0 (Eq. 1), assumptions; picklable
  Parameters.from_physical(mass, omega, amplitude, static_force, friction)   SI units (docs/units.md)
The return map (Lemma 3), elementwise over array-likes:
  T(p, theta), T1(p, theta)        T and the next hit T1 (Eq. 11)
  step(p, theta)                   T1, theta2 (Eq. 17), T, scenario, elapsed, penetration
  derivative(p, theta)             T' (0 at a stop, nan at a grazing)
One orbit (theta0 a phase in [t2, t3)):
  orbit(p, theta0, steps)          T^n(theta0) with the columns of `dfchaos orbit`
  periodic_orbit(p, word)          the periodic orbit of itinerary (word)^infinity (Section 6)
  follow_orbit(p, word, b_end)     that orbit followed in b to where it ends (dfchaos continue)
  lyapunov(p, theta0, steps, transient), rate(...), period(...)
                                   as a cell of `dfchaos sweep`; theta0=None: the sweep's default
                                   start, the arc's midpoint
The plane, the full system, Lemma 4 and the proofs:
  sweep(q_range, b_range, ...)     numpy columns of `dfchaos sweep` and its provenance
  orbit_diagram(q_over_a, b_over_a, ...)  `dfchaos orbit-diagram`: phases per cell, stops marked
  simulate(p, x0, y0, v0, t0, t_end, sample=..., max_events=...)
  covering_segments(p), lemma4_covering(p)
  certify(what, ...)               proofs in ball arithmetic, as `dfchaos certify`: a Certified
                                   (the record as a dict; .proved, .statement, .J0, .J1 as Interval)
Constants: vartheta0, sin_vartheta0, min_parameter, max_parameter, min_map_ratio,
max_simulation_time, max_elements, scenario_names. help(dfchaos.NAME) gives the details.

Errors (the only two exception classes of the module):
  InvalidParameter   bad input; a subclass of ValueError. str(e) is the tool's one-line message
                     (the tool prints it after 'dfchaos: error: '), e.parameter the name of the
                     offending argument. Raised before any work.
  GaveUp             a bounded computation reached its bound without an answer (a motion that never
                     flies again, more events than max_events); a subclass of RuntimeError.
A wrong type (a str for a number, a bool array) raises TypeError.
Result types: Certified (certify's record, a dict with typed attributes) and Interval(lo, hi) (a
closed interval of doubles); help(dfchaos.Certified) and help(dfchaos.Interval) describe them.
Array arguments take any array-like (cast to contiguous float64) and give arrays of its shape; long
loops run in C++ without the GIL.)doc";
  m.attr("__version__") = DFCHAOS_VERSION;
  dp::bind_parameters(m);
  dp::bind_map(m);
  dp::bind_simulate(m);
  dp::bind_covering(m);
  dp::bind_certify(m);
  dp::bind_orbit(m);
  dp::bind_sweep(m);
  // What help(dfchaos) documents: every public name but the two exception classes and the two
  // result types (a tuple and a dict subclass), documented in the docstring above (pydoc would list
  // some 75 inherited methods for each exception and 100 for the dict).
  dp::py::list all;
  for (const auto& item : m.attr("__dict__").cast<dp::py::dict>()) {
    const auto name = item.first.cast<std::string>();
    if (name.rfind('_', 0) != 0 && name != "InvalidParameter" && name != "GaveUp" && name != "Interval" && name != "Certified") all.append(name);
  }
  m.attr("__all__") = all;
}
