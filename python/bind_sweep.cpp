// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bind_sweep.cpp
/// @brief dfchaos.sweep: the observables over a (q/a, b/a) grid as `dfchaos sweep` computes them
/// (the same Spec, the same checks, the same OpenMP engine, sweep::compute_cells), returned as
/// numpy columns and the header's provenance instead of a TSV file.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "convert.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/units.hpp"
#include "kit/provenance.hpp"
#include "sweep/cell.hpp"
#include "sweep/engine.hpp"
#include "sweep/header.hpp"
#include "sweep/run.hpp"
#include "sweep/spec.hpp"

namespace dfchaos::python {

namespace {

/// An axis as the tool writes it ("lo:hi:n[:kind]" or "x"), as a tuple (lo, hi, n[, kind]), or one
/// number x (the axis x:x:1, as the tool's `--q-range 0.85`).
using AxisArg = std::variant<std::string, std::tuple<double, double, long long>, std::tuple<double, double, long long, std::string>, double>;
/// The observables as the tool writes them ("covering,period") or as a list of names.
using ObservablesArg = std::variant<std::string, std::vector<std::string>>;

/// The text of an axis: a tuple is spelt with %.17g, which reads back to the same doubles.
std::string axis_text(const AxisArg& v) {
  if (const auto* s = std::get_if<std::string>(&v)) return *s;
  if (const auto* x = std::get_if<double>(&v)) return format_double(*x);
  if (const auto* t = std::get_if<std::tuple<double, double, long long>>(&v))
    return format_double(std::get<0>(*t)) + ":" + format_double(std::get<1>(*t)) + ":" + std::to_string(std::get<2>(*t));
  const auto& t = std::get<std::tuple<double, double, long long, std::string>>(v);
  return format_double(std::get<0>(t)) + ":" + format_double(std::get<1>(t)) + ":" + std::to_string(std::get<2>(t)) + ":" + std::get<3>(t);
}

std::string observables_text(const ObservablesArg& v) {
  if (const auto* s = std::get_if<std::string>(&v)) return *s;
  std::string s;
  const auto& names = std::get<std::vector<std::string>>(v);
  for (std::size_t k = 0; k < names.size(); ++k) s += (k ? "," : "") + names[k];
  return s;
}

/// The provenance of the header as a dict (see the docstring of sweep()).
py::dict provenance(const sweep::Spec& spec) {
  py::dict d;
  d["title"] = std::string(sweep::kTitleLine.substr(2));
  d["version"] = kit::version();
  d["git_hash"] = kit::git_hash();
  d["compiler"] = kit::compiler_id();
  for (const std::string& line : spec.header_lines()) {
    std::size_t at = line.find(" = ");
    std::size_t skip = 3;
    if (at == std::string::npos) {
      at = line.find(": ");
      skip = 2;
    }
    if (at == std::string::npos) continue;  // every line of Spec::header_lines() has one or the other
    d[py::str(line.substr(0, at))] = line.substr(at + skip);
  }
  d["columns"] = spec.columns();
  d["header"] = sweep::header_text(spec, std::nullopt);
  return d;
}

py::tuple sweep_py(const AxisArg& q_range, const AxisArg& b_range, double a, const ObservablesArg& observables, long long max_branches,
                   long long superstable_scan, double theta0_fraction, long long transient, long long steps, long long period_max, double period_tol,
                   long long region_max_boxes, long long max_proofs, const std::optional<std::tuple<double, double, double>>& physical) {
  // The checks of SweepArguments::resolve, in its order and with its option names.
  sweep::Spec s;
  s.a = finite("a", a);
  if (physical) {
    if (a != sweep::Spec{}.a) throw InvalidParameter("a", "give a or physical=(mass, omega, amplitude), not both");
    s.physical = {.mass = finite("mass", std::get<0>(*physical)),
                  .omega = finite("omega", std::get<1>(*physical)),
                  .amplitude = finite("amplitude", std::get<2>(*physical))};
    s.a = length_scale(s.physical.mass, s.physical.omega, s.physical.amplitude);
  }
  s.q_over_a = sweep::Range::parse("q-range", axis_text(q_range));
  s.b_over_a = sweep::Range::parse("b-range", axis_text(b_range));
  s.observables = sweep::ObservableSet::parse("observables", observables_text(observables));
  s.superstable_scan = superstable_scan;
  s.covering_max_branches = max_branches;
  s.orbit.theta0_fraction = finite("theta0-fraction", theta0_fraction);
  s.orbit.transient = transient;
  s.orbit.steps = steps;
  s.period.max = period_max;
  s.period.tol = finite("period-tol", period_tol);
  s.region_max_boxes = region_max_boxes;
  s.max_proofs = max_proofs;
  s.validate();

  const long long cells = s.cells();
  const std::vector<std::string> names = s.columns();  // index, q_over_a, b_over_a, status, ..., error
  const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(cells)};
  py::array_t<long long> index(shape);
  std::vector<RealArray> values;  // q_over_a, b_over_a, then the observables' columns: all but index, status, error
  for (std::size_t k = 0; k + 3 < names.size(); ++k) values.emplace_back(shape);
  StrColumn status(shape, 12);  // "inadmissible"
  std::vector<std::string> errors(static_cast<std::size_t>(cells));

  long long* idx = index.mutable_data();
  std::vector<double*> out;
  for (auto& v : values) out.push_back(v.mutable_data());
  run_interruptible([&] {  // the whole grid on one thread of its own, chunk by chunk
    for (long long first = 0; first < cells; first += sweep::kDefaultChunk) {
      const long long n = std::min(sweep::kDefaultChunk, cells - first);
      std::vector<long long> chunk(static_cast<std::size_t>(n));
      for (long long k = 0; k < n; ++k) chunk[static_cast<std::size_t>(k)] = first + k;
      const std::vector<sweep::CellValues> cv = sweep::compute_cells(s, chunk, nullptr);
      for (long long k = 0; k < n; ++k) {
        const sweep::CellValues& v = cv[static_cast<std::size_t>(k)];
        const long long i = first + k;
        idx[i] = v.index;
        std::size_t c = 0;
        out[c++][i] = v.q_over_a;
        out[c++][i] = v.b_over_a;
        status.set(i, sweep::status_name(v.status));
        // The observables in the order of their columns, as format_row writes them.
        for (double x : sweep::observable_values(s, v)) out[c++][i] = x;
        errors[static_cast<std::size_t>(i)] = sweep::error_field(v);
      }
    }
  });

  py::dict columns;
  columns["index"] = index;
  std::size_t c = 0;
  for (std::size_t k = 1; k + 1 < names.size(); ++k) columns[py::str(names[k])] = k == 3 ? py::object(status.array) : py::object(values[c++]);
  py::list err;
  for (const auto& e : errors) err.append(py::str(e));
  columns["error"] = py::module_::import("numpy").attr("array")(err, py::arg("dtype") = "str");
  return py::make_tuple(columns, provenance(s));
}

}  // namespace

void bind_sweep(py::module_& m) {
  const sweep::Spec d;
  m.def("sweep", &sweep_py, py::arg("q_range"), py::arg("b_range"), py::arg("a") = d.a, py::arg("observables") = sweep::kDefaultObservables,
        py::arg("max_branches") = d.covering_max_branches, py::arg("superstable_scan") = d.superstable_scan,
        py::arg("theta0_fraction") = d.orbit.theta0_fraction, py::arg("transient") = d.orbit.transient, py::arg("steps") = d.orbit.steps,
        py::arg("period_max") = d.period.max, py::arg("period_tol") = d.period.tol, py::arg("region_max_boxes") = d.region_max_boxes,
        py::arg("max_proofs") = d.max_proofs, py::kw_only(), py::arg("physical") = py::none(),
        R"doc(sweep(q_range, b_range, a=1.0, observables='covering,superstable,lyapunov,rate,period', max_branches=1000000,
      superstable_scan=400, theta0_fraction=0.5, transient=1000, steps=1000, period_max=64, period_tol=1e-9,
      region_max_boxes=4000, max_proofs=20000000, *, physical=None)
    -> (columns, provenance)

The observables over a grid of the (q/a, b/a) plane, as `dfchaos sweep` computes them: the same checks
and messages, the same C++ engine on the same OpenMP threads (OMP_NUM_THREADS), the same numbers to the
last bit. Each keyword is the tool's option of the same name (--q-range, --max-branches, ...), except
theta0_fraction, the tool's --theta0-fraction: a fraction f in [0, 1) of the arc, theta_0 = t2 + f (t3 - t2)
(elsewhere in this module theta0 is a phase).

q_range, b_range: an axis as the tool writes it, 'lo:hi:n[:lin|log|mid]' or 'x', a tuple (lo, hi, n) or
  (lo, hi, n, kind), or one number x; both ends included for lin and log (one value x is (x, x, 1)),
  cell centres for mid.
observables: a comma-separated string or a list of names among covering, superstable, lyapunov, rate,
  period, certified, region, entropy (the columns always come in that order).
physical: (mass, omega, amplitude) in kg, rad/s and N, the tool's --physical (instead of a, which
  must then be left at 1): a = amplitude/(mass omega^2) metres, the axes read as q/a = friction/amplitude
  and b/a = static force/(2 amplitude), the column rate becomes rate_m_per_s and the columns friction_N
  and static_N (the forces of each cell) come before error (docs/units.md).

Returns a tuple:
  columns     a dict of numpy arrays, one element per cell, keyed by the tool's column names, in its
              order: index (int64; index = i * n_b + j, i over q/a, j over b/a), q_over_a, b_over_a,
              status (str: ok, inadmissible, error), the observables' columns (float64: covering,
              superstable, epsilon, lyapunov, rate, period, certified, certified_step, region,
              region_uniform, region_boxes, region_stop, entropy_lower, entropy_upper, entropy_laps; nan where not
              computed) and error (str: 'observable: message', '-' when none). pandas.DataFrame(columns)
              is the tool's table.
  provenance  a dict of str: title, version, git_hash, compiler, then each 'key = value' line of the
              tool's header (a, q_over_a, b_over_a, observables, max_branches, ..., cells, status) with
              its text as written there, columns (the list of column names) and header (the tool's
              whole header text, byte for byte, '#' lines and the column line).
Raises ValueError (dfchaos.InvalidParameter) with the tool's message, naming the tool's option, before
any work. The cells are computed without the GIL; Ctrl-C raises KeyboardInterrupt within a fraction of
a second (each cell's computation polls for it) and returns nothing.)doc");
}

}  // namespace dfchaos::python
