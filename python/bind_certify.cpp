/// @file bind_certify.cpp
/// @brief dfchaos.certify: the certified layer (issue 14) from Python — the same requests and the
/// same JSON records as `dfchaos certify`, returned as a dict.
#include <pybind11/stl.h>

#include <optional>
#include <utility>
#include <variant>

#include "certify.hpp"
#include "convert.hpp"
#include "dfchaos/errors.hpp"

namespace dfchaos::python {

namespace {

/// A parameter as the CLI spells it: "X", or "LO:HI" for a box, with 17 significant digits.
std::string spelled(const char* name, const std::variant<double, std::pair<double, double>>& v) {
  if (const double* x = std::get_if<double>(&v)) return format_double(finite(name, *x));
  const auto& [lo, hi] = std::get<std::pair<double, double>>(v);
  return format_double(finite(name, lo)) + ":" + format_double(finite(name, hi));
}

py::dict certify_py(const std::string& what, double a, std::optional<std::variant<double, std::pair<double, double>>> b,
                    std::optional<std::variant<double, std::pair<double, double>>> q, int period, const std::string& segment,
                    std::optional<std::pair<double, double>> window) {
  cli::CertifyOptions o;
  o.what = what;
  o.a = format_double(finite("a", a));
  if (b) o.b = spelled("b", *b);
  if (q) o.q = spelled("q", *q);
  o.period = period;
  o.segment = segment;
  if (window) o.window = format_double(finite("window", window->first)) + ":" + format_double(finite("window", window->second));
  cli::CertifyResult r;
  {
    py::gil_scoped_release nogil;
    r = cli::certify(o);
  }
  py::dict d = py::module_::import("json").attr("loads")(r.json);
  return d;
}

}  // namespace

void bind_certify(py::module_& m) {
  m.def("certify", &certify_py, py::arg("what"), py::arg("a") = 1.0, py::arg("b") = py::none(), py::arg("q") = py::none(),
        py::arg("period") = 0, py::arg("segment") = "L0", py::arg("window") = py::none(),
        R"doc(certify(what, a=1.0, b=None, q=None, period=0, segment='L0', window=None) -> dict

A proof in ball arithmetic (Arb), as `dfchaos certify WHAT` gives it: `what` is one of vartheta0 (Eq. 1),
lemma1 (Lemma 1), b0 (a certified lower bound of b0(q)), discontinuities (Lemma 2, on segment L0 or L2),
covering (Lemma 4 / Theorem 1), periodic (Sections 6-7, minimal period `period`) or superstable
(Theorem 2; with `window=(lo, hi)` a window in b with both edges). `b` and `q` are numbers or (lo, hi)
boxes where the request allows them. Returns the JSON record as a dict: "proved" (True/False), the
statement, the enclosures (decimal mid and radius), and on failure the step that failed. Bad input
raises dfchaos.InvalidParameter with the CLI's message. Doubles are exact binary numbers: the proofs
are for those numbers (or every parameter of the box).)doc");
}

}  // namespace dfchaos::python
