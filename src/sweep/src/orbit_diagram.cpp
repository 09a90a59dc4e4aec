// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/orbit_diagram.hpp"

#include <algorithm>
#include <exception>
#include <string>

#include "dfchaos/errors.hpp"

namespace dfchaos::sweep {

void check_orbit_diagram_size(double nq, double nb, const OrbitDiagramSettings& settings) {
  const double cells = nq * nb;
  if (cells * static_cast<double>(settings.keep) > static_cast<double>(kMaxOrbitDiagramRows))
    throw InvalidParameter("keep", "cells x keep at most 1e8 rows (" + format_shortest(cells) + " cells of q-range x b-range)",
                           static_cast<double>(settings.keep));
  if (cells * static_cast<double>(settings.transient + settings.steps) > static_cast<double>(kMaxOrbitDiagramWork))
    throw InvalidParameter("steps",
                           "cells x (transient + steps) at most 1e9 evaluations of T (" + format_shortest(cells) + " cells of q-range x b-range)",
                           static_cast<double>(settings.steps));
}

void orbit_diagram(double a, const std::vector<double>& q_over_a, const std::vector<double>& b_over_a, const OrbitDiagramSettings& settings,
                   const std::function<void(long long cell, const OrbitDiagramColumn& column)>& sink) {
  settings.validate();
  const auto nq = static_cast<long long>(q_over_a.size()), nb = static_cast<long long>(b_over_a.size());
  if (nq < 1) throw InvalidParameter("q-range", "at least one value of q/a");
  if (nb < 1) throw InvalidParameter("b-range", "at least one value of b/a");
  check_orbit_diagram_size(static_cast<double>(nq), static_cast<double>(nb), settings);
  if (!(a >= kMinParameter && a <= kMaxParameter))
    throw InvalidParameter("a", format_shortest(kMinParameter) + " <= a <= " + format_shortest(kMaxParameter), a);
  const long long n = nq * nb;
  auto cell = [&](long long i) {
    const double q = q_over_a[static_cast<std::size_t>(i / nb)], b = b_over_a[static_cast<std::size_t>(i % nb)];
    try {
      const Parameters p(a, a * b, a * q);
      p.require_return_map();
      return p;
    } catch (const InvalidParameter& e) {
      // the axis at fault: the one that varies when only one does; else that of the parameter
      // named (q for q, b for the rest: b, b/a, b < a/2)
      const char* axis = nb > 1 && nq == 1 ? "b-range" : (nq > 1 && nb == 1 ? "q-range" : (e.parameter() == "q" ? "q-range" : "b-range"));
      throw InvalidParameter(axis,
                             "T must be defined at every cell; at q/a = " + format_shortest(q) + ", b/a = " + format_shortest(b) + ": " + e.what());
    }
  };
  for (long long i = 0; i < n; ++i) cell(i);  // every cell checked before any is computed
  constexpr long long kChunk = 64;            // cells computed at a time, then handed over in order
  std::vector<OrbitDiagramColumn> col;
  std::vector<std::exception_ptr> err;
  for (long long start = 0; start < n; start += kChunk) {
    const long long m = std::min(kChunk, n - start);
    col.assign(static_cast<std::size_t>(m), {});
    err.assign(static_cast<std::size_t>(m), nullptr);
#pragma omp parallel for schedule(dynamic)
    for (long long j = 0; j < m; ++j) {
      try {
        const Parameters p = cell(start + j);
        const double theta0 = orbit_diagram_start(p, settings.theta0_fraction);
        col[static_cast<std::size_t>(j)] = orbit_diagram_column(p, theta0, settings.transient, settings.steps, static_cast<int>(settings.keep));
      } catch (...) {
        err[static_cast<std::size_t>(j)] = std::current_exception();
      }
    }
    for (long long j = 0; j < m; ++j) {
      if (err[static_cast<std::size_t>(j)]) std::rethrow_exception(err[static_cast<std::size_t>(j)]);
      sink(start + j, col[static_cast<std::size_t>(j)]);
    }
  }
}

}  // namespace dfchaos::sweep
