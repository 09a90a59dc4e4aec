// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bind_certify.cpp
/// @brief dfchaos.certify: the certified statements (certify/certify.hpp) from Python, with the same
/// checks and the same records as `dfchaos certify`, returned as a dict.
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <utility>
#include <variant>

#include "certify/certificate.hpp"
#include "certify/certify.hpp"
#include "convert.hpp"
#include "dfchaos/errors.hpp"
#include "kit/output.hpp"

namespace dfchaos::python {

namespace {

/// A number, or a box given as (lo, hi); each end must be finite.
using NumberOrBox = std::variant<double, std::pair<double, double>>;

certify::Range range(const char* name, const NumberOrBox& v) {
  if (const double* x = std::get_if<double>(&v)) return certify::Range::point(finite(name, *x));
  const auto& [lo, hi] = std::get<std::pair<double, double>>(v);
  const double l = finite(name, lo);
  return certify::Range{l, finite(name, hi)};
}

/// The record as Python objects: objects become dicts (keys in order), arrays lists, non-finite
/// numbers None (as they are written: null).
py::object to_python(const kit::Json::Value& v) {
  switch (v.type()) {
    case kit::Json::Value::value_t::boolean: return py::bool_(v.get<bool>());
    case kit::Json::Value::value_t::number_integer: return py::int_(v.get<long long>());
    case kit::Json::Value::value_t::number_unsigned: return py::int_(v.get<unsigned long long>());
    case kit::Json::Value::value_t::number_float: {
      const double d = v.get<double>();
      return std::isfinite(d) ? py::object(py::float_(d)) : py::object(py::none());
    }
    case kit::Json::Value::value_t::string: return py::str(v.get_ref<const std::string&>());
    case kit::Json::Value::value_t::array: {
      py::list l;
      for (const auto& x : v) l.append(to_python(x));
      return l;
    }
    case kit::Json::Value::value_t::object: {
      py::dict d;
      for (auto it = v.begin(); it != v.end(); ++it) d[py::str(it.key())] = to_python(it.value());
      return d;
    }
    default: return py::none();
  }
}

py::object certify_py(const std::string& what, double a, std::optional<NumberOrBox> b, std::optional<NumberOrBox> q, int period,
                      const std::string& segment, std::optional<std::pair<double, double>> window, std::optional<std::string> certificate) {
  certify::check_statement(what);
  if (certificate && certificate->empty()) throw InvalidParameter("certificate", "a file name (got '')");
  if (certificate && !certify::has_certificate(what))
    throw InvalidParameter("certificate",
                           std::string("a statement with a certificate format: ") + certify::kCertificateStatements + " (not certify " + what + ")");
  certify::Request r;
  r.what = what;
  r.certificate = certificate.has_value();
  r.a = finite("a", a);
  if (b) r.b = range("b", *b);
  if (q) r.q = range("q", *q);
  r.period = period;
  r.segment = segment;
  if (window) r.window = range("window", *window);
  certify::Result c;
  {
    py::gil_scoped_release nogil;
    c = certify::certify(r);
  }
  if (certificate) {
    if (c.certificate.value().is_null()) {
      c.record.set("certificate",
                   kit::Json::object()
                       .set("written", false)
                       .set("reason", c.no_certificate.empty() ? std::string("not proved: no certificate") : "not written: " + c.no_certificate));
    } else {
      try {
        c.record.set("certificate", certify::to_json(certify::write_certificate(*certificate, c.certificate)));
      } catch (const kit::OutputError& e) {
        PyErr_SetString(PyExc_OSError, ("certificate: " + kit::one_line(e.what())).c_str());
        throw py::error_already_set();
      }
    }
  }
  return to_python(c.record.value());
}

}  // namespace

void bind_certify(py::module_& m) {
  m.def("certify", &certify_py, py::arg("what"), py::arg("a") = 1.0, py::arg("b") = py::none(), py::arg("q") = py::none(), py::arg("period") = 0,
        py::arg("segment") = "L0", py::arg("window") = py::none(), py::arg("certificate") = py::none(),
        R"doc(certify(what, a=1.0, b=None, q=None, period=0, segment='L0', window=None, certificate=None) -> dict

A proof in ball arithmetic (Arb), as `dfchaos certify WHAT` gives it: `what` is one of vartheta0 (Eq. 1),
lemma1 (Lemma 1), b0 (a certified lower bound of b0(q)), discontinuities (Lemma 2, on segment L0 or L2),
covering (Lemma 4 / Theorem 1), periodic (Sections 6-7, minimal period `period`) or superstable
(Theorem 2; with `window=(lo, hi)` a window in b with both edges). `b` and `q` are numbers or (lo, hi)
boxes where the request allows them. Returns the JSON record as a dict: "proved" (True/False), the
statement, the enclosures (decimal mid and radius), and on failure the step that failed. Bad input
raises dfchaos.InvalidParameter with the CLI's message. Doubles are exact binary numbers: the proofs
are for those numbers (or every parameter of the box).

With `certificate="path"` (vartheta0, lemma1, b0, covering, superstable, discontinuities) a proved
statement's certificate (the witnesses, for the independent checker dfchaos-recheck;
docs/certificates.md) is written to path whole or not at all,
and the dict gets "certificate": {"path", "bytes", "sha256"} ({"written": False} when not proved).
A path that cannot be written raises OSError and leaves no file.)doc");
}

}  // namespace dfchaos::python
