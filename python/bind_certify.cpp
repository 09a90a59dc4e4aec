// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bind_certify.cpp
/// @brief dfchaos.certify: the certified statements (certify/certify.hpp) from Python, with the same
/// checks and the same records as `dfchaos certify`, returned as a dfchaos.Certified (the record as
/// a dict, with typed attributes; J0, J1 and the enclosures as dfchaos.Interval).
#include <pybind11/eval.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "certify/certificate.hpp"
#include "certify/certify.hpp"
#include "certify/statements.hpp"
#include "convert.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "kit/budget.hpp"
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
                      const std::string& segment, std::optional<std::pair<double, double>> window, std::optional<std::string> certificate,
                      double max_seconds, double max_memory, const std::string& word) {
  certify::check_statement(what);
  if (certificate && certificate->empty()) throw InvalidParameter("certificate", "a file name (got '')");
  certify::Request r;
  r.what = what;
  r.certificate = certificate.has_value();
  r.a = finite("a", a);
  if (b) r.b = range("b", *b);
  if (q) r.q = range("q", *q);
  r.period = period;
  r.word = word;
  r.segment = segment;
  if (window) r.window = range("window", *window);
  if (certificate) {
    try {
      certify::check_certificate_path(*certificate);  // before the proof, not after it
    } catch (const kit::OutputError& e) {
      PyErr_SetString(PyExc_OSError, kit::one_line(e.what()).c_str());
      throw py::error_already_set();
    }
  }
  const CallBudget budget = call_budget(max_seconds, max_memory);
  certify::Result c = interruptible([&] { return certify::certify(r); }, budget);
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
  py::object result = py::module_::import("dfchaos").attr("Certified")(to_python(c.record.value()));
  result.attr("what") = what;
  return result;
}

/// The Python side of the results: Interval (a closed interval of doubles, from a [lo, hi] pair or
/// rounded outward from a decimal ball) and Certified (the record, a dict, with typed attributes).
/// Pure Python types: no object of them holds C++ state.
constexpr const char* kResultTypes = R"py(
import collections as _collections
import decimal as _decimal
import fractions as _fractions
import math as _math
import numbers as _numbers


def _end(name, x):
    """An end of an Interval: a real number that is exactly a double, not NaN (infinite ends are
    allowed). Rounding an end to a double could move it inward, so an inexact one is refused."""
    if isinstance(x, bool) or not isinstance(x, _numbers.Real):
        raise ValueError(f"{name}: must be a real number (got {x!r})")
    try:
        v = float(x)
    except OverflowError:
        raise ValueError(f"{name}: lies beyond the doubles (got {x!r})") from None
    if _math.isnan(v):
        raise ValueError(f"{name}: must be a number, not NaN")
    if not _math.isinf(v) and v != x:
        raise ValueError(f"{name}: must be exactly a double (got {x!r}); Interval.from_ball rounds a decimal ball outward")
    return v


def _ball_part(ball, name):
    """ball[name] (mid or rad of a certified record's ball) as an exact fraction: a finite decimal."""
    try:
        text = ball[name]
    except (KeyError, TypeError):
        raise ValueError(f"{name}: missing from the ball {ball!r} (a dict with 'mid' and 'rad')") from None
    try:
        d = _decimal.Decimal(text)
    except (_decimal.InvalidOperation, TypeError, ValueError):
        raise ValueError(f"{name}: must be a decimal number (got {text!r})") from None
    if not d.is_finite():
        raise ValueError(f"{name}: must be a finite decimal number (got {text!r})")
    return _fractions.Fraction(d)


class Interval(_collections.namedtuple("Interval", "lo hi")):
    """Interval(lo, hi): the closed interval [lo, hi] of doubles (exact binary numbers), lo <= hi
    (ValueError naming lo, hi or both otherwise, or for an end that is NaN, not a real number, or not
    exactly a double; infinite ends are allowed).
    x in I tests lo <= x <= hi. Interval.from_ball({'mid': '...', 'rad': '...'}) is the smallest
    interval of doubles that contains the decimal ball mid +- rad of a certified record (rounded
    outward: it contains everything the ball contains); ValueError naming mid or rad unless both are
    finite decimals and rad >= 0."""
    __slots__ = ()

    def __new__(cls, lo, hi):
        lo, hi = _end("lo", lo), _end("hi", hi)
        if not lo <= hi:
            raise ValueError(f"lo, hi: must satisfy lo <= hi (got lo={lo!r}, hi={hi!r})")
        return super().__new__(cls, lo, hi)

    @classmethod
    def _make(cls, iterable):
        return cls(*iterable)

    def __contains__(self, x):
        return self.lo <= x <= self.hi

    @property
    def width(self):
        """hi - lo (rounded to nearest)."""
        return self.hi - self.lo

    @classmethod
    def from_ball(cls, ball):
        mid, rad = (_ball_part(ball, k) for k in ("mid", "rad"))
        if rad < 0:
            raise ValueError(f"rad: must be >= 0 (got {ball['rad']!r})")
        lo, hi = mid - rad, mid + rad
        try:
            down, up = float(lo), float(hi)
        except OverflowError:
            raise ValueError(f"mid, rad: the ball {ball['mid']!r} +- {ball['rad']!r} reaches beyond the doubles") from None
        if _fractions.Fraction(down) > lo:
            down = _math.nextafter(down, -_math.inf)
        if _fractions.Fraction(up) < hi:
            up = _math.nextafter(up, _math.inf)
        return cls(down, up)


def _is_ball(v):
    return isinstance(v, dict) and set(v) == {"mid", "rad"}


class Certified(dict):
    """The answer of dfchaos.certify: the JSON record of `dfchaos certify` as a dict (equal to
    json.loads of the tool's output but for the time taken), with typed attributes:
      what          the statement asked for ('covering', 'lemma1', ...)
      proved        True when proved in ball arithmetic; False means not proved (never "false")
      statement     what exactly is proved, and for which parameters
      failed_step, detail, refuted   why not (None when proved)
      J0, J1        the covering segments as Interval (covering, periodic; None when absent)
      enclosures    every top-level enclosure of the record as an Interval (rounded outward)
      certificate   with certify(..., certificate=path): {'path', 'bytes', 'sha256'} or
                    {'written': False, 'reason': ...}; None when not asked for"""
    __slots__ = ("what",)

    proved = property(lambda self: self["proved"])
    statement = property(lambda self: self["statement"])
    failed_step = property(lambda self: self.get("failed_step"))
    detail = property(lambda self: self.get("detail"))
    refuted = property(lambda self: self.get("refuted"))
    J0 = property(lambda self: Interval(*self["J0"]) if "J0" in self else None)
    J1 = property(lambda self: Interval(*self["J1"]) if "J1" in self else None)
    certificate = property(lambda self: self.get("certificate"))

    @property
    def enclosures(self):
        return {k: Interval.from_ball(v) for k, v in self.items() if _is_ball(v)}

    def __repr__(self):
        what = getattr(self, "what", "?")
        parts = [f"proved={self.get('proved')!r}"]
        if not self.get("proved", True):
            parts.append(f"failed_step={self.get('failed_step')!r}")
        for name in ("J0", "J1"):
            if name in self:
                parts.append(f"{name}={getattr(self, name)!r}")
        return f"<dfchaos.Certified {what}: {', '.join(parts)}>"
)py";

/// The docstring of dfchaos.certify: the statements listed from the registry (certify/statements.hpp).
const char* certify_doc() {
  static const std::string doc = [] {
    std::string d =
        "certify(what, a=1.0, b=None, q=None, period=0, segment='L0', window=None, certificate=None,\n"
        "        max_seconds=60, max_memory=2, *, word='') -> Certified\n\n"
        "A proof in ball arithmetic (Arb), as `dfchaos certify WHAT` gives it.\n`what` is one of " +
        certify::statement_names(" or ") + " (what each proves: `dfchaos certify --help`).";
    return d + R"doc(
periodic takes `period` (itinerary (0^(M-1)1)^infinity) or a primitive `word` over 0, 1 of 1 to 64 letters;
superstable with `window=(lo, hi)` certifies a window in b and its edges; discontinuities reads `segment`
(L0 or L2); arc-l1 and lemma4-uniform read a and the box `q` of q/a. `b` and `q` are numbers or (lo, hi)
boxes where the request allows them. Returns a dfchaos.Certified: the JSON record of the tool as a
dict ("proved" True/False, the statement, the enclosures as decimal mid and radius, on failure the
step that failed) whose attributes give the answer typed: .proved, .statement, .failed_step,
.J0 and .J1 as dfchaos.Interval(lo, hi), .enclosures (each ball as an Interval rounded outward),
.certificate (see help(dfchaos.Certified)). The C++ API is called directly. Bad input
raises dfchaos.InvalidParameter with the CLI's message. Doubles are exact binary numbers: the proofs
are for those numbers (or every parameter of the box).

With `certificate="path"` a proved statement's certificate (the witnesses, for the independent checker
dfchaos-recheck; docs/certificates.md) is written to path whole or not at all, and the dict gets
"certificate": {"path", "bytes", "sha256"} ({"written": False} when not proved). A path that cannot
be written raises OSError and leaves no file.

The budget is the tool's (--max-seconds, --max-memory): at most max_seconds seconds of wall-clock time
(0 < max_seconds <= 1e6) and max_memory GiB of resident memory added by the call (0.25 <= max_memory
<= 1e4; the tool limits the address space of its process instead). When either runs out the proof is
abandoned and dfchaos.GaveUp is raised ("gave up: the time budget of 60 s ran out (max_seconds raises
it)"); Ctrl-C raises KeyboardInterrupt within a fraction of a second. Either way no certificate is
written. The proof runs on a worker thread of the module, without the GIL.)doc";
  }();
  return doc.c_str();
}

}  // namespace

void bind_certify(py::module_& m) {
  py::dict scope;
  scope["__name__"] = "dfchaos";
  py::exec(kResultTypes, scope);
  m.attr("Interval") = scope["Interval"];
  m.attr("Certified") = scope["Certified"];
  m.def("certify", &certify_py, py::arg("what"), py::arg("a") = 1.0, py::arg("b") = py::none(), py::arg("q") = py::none(), py::arg("period") = 0,
        py::arg("segment") = "L0", py::arg("window") = py::none(), py::arg("certificate") = py::none(),
        py::arg("max_seconds") = kit::kDefaultBudgetSeconds, py::arg("max_memory") = kit::kDefaultBudgetGiB, py::kw_only(), py::arg("word") = "",
        certify_doc());
  // The same at the point of a dfchaos.Parameters, as the module's other functions take it.
  m.def(
      "certify",
      [](const std::string& what, const Parameters& p, int period, const std::string& segment, std::optional<std::pair<double, double>> window,
         std::optional<std::string> certificate, double max_seconds, double max_memory, const std::string& word) {
        return certify_py(what, p.a(), NumberOrBox{p.b()}, NumberOrBox{p.q()}, period, segment, window, std::move(certificate), max_seconds,
                          max_memory, word);
      },
      py::arg("what"), py::arg("parameters"), py::arg("period") = 0, py::arg("segment") = "L0", py::arg("window") = py::none(),
      py::arg("certificate") = py::none(), py::arg("max_seconds") = kit::kDefaultBudgetSeconds, py::arg("max_memory") = kit::kDefaultBudgetGiB,
      py::kw_only(), py::arg("word") = "",
      R"doc(certify(what, parameters, period=0, segment='L0', window=None, certificate=None, max_seconds=60, max_memory=2, *, word='') -> Certified

The same as certify(what, a, b, q, ...) at the point (a, b, q) of a dfchaos.Parameters.)doc");
}

}  // namespace dfchaos::python
