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
  Parameters(a, b, q)            t0..t3, vartheta0 (Eq. 1), assumptions
  T(p, theta), T1(p, theta)      the return map (Lemma 3) and the next hit (Eq. 11), vectorized
  step(p, theta)                 T1, theta2 (Eq. 17), T, scenario, elapsed, penetration
  orbit(p, theta0, steps)        T^n(theta0) with the columns of `dfchaos orbit`
  simulate(p, x0, y0, v0, t0, t_end, sample=..., max_events=...)   the full system
  covering_segments(p), lemma4_covering(p)                          Lemma 4
Array arguments take any array-like (cast to contiguous float64) and give arrays of its shape;
the loops run in C++ without the GIL. Bad input raises ValueError (dfchaos.InvalidParameter) with
the CLI's one-line message; dfchaos.GaveUp (a RuntimeError) when a bounded computation gives up.)doc";
  m.attr("__version__") = DFCHAOS_VERSION;
  dp::bind_parameters(m);
  dp::bind_map(m);
  dp::bind_simulate(m);
  dp::bind_covering(m);
  dp::bind_certify(m);
  dp::bind_orbit(m);
  dp::bind_sweep(m);
}
