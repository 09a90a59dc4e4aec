// SPDX-License-Identifier: GPL-3.0-or-later
/// @file convert.hpp
/// @brief What every binding of the Python module shares: array-likes in, numpy arrays out, the
/// CLI's messages for non-finite input, a GIL-free loop that still notices Ctrl-C, and the
/// declarations of the binding groups (one function per group, called by module.cpp).
///
/// The module holds no algorithm: every number comes from one call into the library per element.
/// A new group of functions (the certified layer, for example) is one more `bind_X(py::module_&)`
/// in its own file, declared here and called from module.cpp.
///
/// Every file of the module includes this header first: it holds the type caster of Parameters
/// (below), which must be the one seen wherever a Parameters argument is converted.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "dfchaos/parameters.hpp"

namespace dfchaos::python {

namespace py = pybind11;

/// A contiguous float64 numpy array (what every array argument is converted to).
using RealArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Largest number of elements accepted in one array argument (10^8 phases take minutes and about
/// 0.8 GB per output column): a bound on every loop of the module.
inline constexpr py::ssize_t kMaxElements = 100'000'000;

/// An array-like argument as contiguous float64.
struct Reals {
  RealArray array;      ///< the values (a 0-d array for a scalar)
  bool scalar = false;  ///< the input was a scalar or a 0-d array: results are returned as scalars
  /// The shape, to give every result the shape of the input.
  std::vector<py::ssize_t> shape() const { return {array.shape(), array.shape() + array.ndim()}; }
};

/// Converts an array-like of real numbers (a float, an int, a list, any numpy array of integers or
/// floats) to contiguous float64, then checks it before any work.
/// @throws py::type_error unless it holds integers or floats (not bool, complex, str or objects).
/// @throws InvalidParameter naming `name` if it has more than kMaxElements elements, or if an
///         element is NaN or infinite (the message of the CLI, with the index of the element).
Reals as_reals(const py::handle& obj, const char* name);

/// A scalar argument: @throws InvalidParameter unless finite, with the CLI's message
/// (`theta: must be a finite number (got 'nan')`).
double finite(const char* name, double x);

/// Refuses a dfchaos.Parameters whose C++ object was never constructed: one made by
/// `Parameters.__new__(Parameters)` (or a subclass's `__new__`) without `__init__`, whose memory
/// pybind11 would otherwise allocate uninitialised on first use. Anything else passes (a wrong type
/// is left to pybind11's own TypeError).
/// @throws py::type_error saying how to build the object.
void require_constructed(py::handle obj);

/// Runs body(i) for i in [0, n) without the GIL; every 2^14 elements the GIL is taken back for an
/// instant to let Python handle a signal (Ctrl-C raises KeyboardInterrupt).
template <class Body>
void loop_without_gil(py::ssize_t n, Body&& body) {
  py::gil_scoped_release nogil;
  for (py::ssize_t i = 0; i < n; ++i) {
    body(i);
    if ((i & 0x3FFF) == 0x3FFF) {
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  }
}

/// The budget of one long call, as the tool's --max-seconds and --max-memory (kit/budget.hpp):
/// `seconds` of wall-clock time, `gib` GiB of resident memory added by the call; 0 means none.
struct CallBudget {
  double seconds = 0;  ///< wall-clock seconds; 0: no limit
  double gib = 0;      ///< GiB of resident memory the call may add; 0: no limit
};

/// Parses certify's max_seconds and max_memory with the tool's checks and messages
/// (kit::parse_budget: 0 < max-seconds <= 1e6, 0.25 <= max-memory <= 1e4).
/// @throws InvalidParameter naming max-seconds or max-memory.
CallBudget call_budget(double max_seconds, double max_memory);

/// Runs body() on a worker thread (kept and reused from call to call), with the GIL released and a
/// stop token installed
/// (dfchaos/stop.hpp), while the calling thread watches: every 10 ms the budget, every 100 ms
/// Python's signal handlers (PyErr_CheckSignals). On Ctrl-C, or when the budget runs out, the token
/// is set, the worker ends at its next poll, whatever it computed is discarded, and the call raises
/// (KeyboardInterrupt, or dfchaos.GaveUp "gave up: the time budget of S s ran out (max_seconds
/// raises it)" / "... memory budget of G GiB ..."). Otherwise body's own exception, if any, is
/// rethrown. body must not touch Python objects. The memory budget counts the resident memory of
/// the whole process (/proc/self/statm) above its level at the start of the call: what other threads
/// allocate meanwhile counts too, and it is not applied where that file cannot be read.
void run_interruptible(const std::function<void()>& body, const CallBudget& budget = {});

/// f() through run_interruptible(), returning its value.
template <class F>
auto interruptible(F&& f, const CallBudget& budget = {}) {
  std::optional<std::invoke_result_t<F&>> out;
  run_interruptible([&] { out.emplace(f()); }, budget);
  return std::move(*out);
}

/// y = f(x) elementwise over an array-like: a float for a scalar, else an array of the input's
/// shape. f runs without the GIL.
template <class F>
py::object map_reals(const py::handle& obj, const char* name, F&& f) {
  const Reals in = as_reals(obj, name);
  const double* x = in.array.data();
  if (in.scalar) return py::float_(f(x[0]));
  RealArray out(in.shape());
  double* y = out.mutable_data();
  loop_without_gil(in.array.size(), [&](py::ssize_t i) { y[i] = f(x[i]); });
  return py::object(std::move(out));
}

/// A column of short strings, as a numpy array of str (dtype `<U{width}`): allocated with the GIL,
/// filled without it (set() writes only into the array's own memory).
class StrColumn {
 public:
  /// Allocates the column, every element empty.
  StrColumn(const std::vector<py::ssize_t>& shape, py::ssize_t width);
  /// Element i becomes s (ASCII, cut at width characters). Needs no GIL.
  void set(py::ssize_t i, const char* s) {
    char32_t* cell = data_ + i * width_;
    py::ssize_t k = 0;
    for (; k < width_ && s[k] != '\0'; ++k) cell[k] = static_cast<char32_t>(static_cast<unsigned char>(s[k]));
    for (; k < width_; ++k) cell[k] = 0;
  }
  py::array array;  ///< the numpy array

 private:
  char32_t* data_ = nullptr;
  py::ssize_t width_ = 1;
};

// ---- the binding groups (one file each) ---------------------------------------------------------
void bind_parameters(py::module_& m);  ///< exceptions, constants, Parameters (bind_parameters.cpp)
void bind_map(py::module_& m);         ///< T, T1, step, orbit, scenario_names, _bench_T (bind_map.cpp)
void bind_simulate(py::module_& m);    ///< simulate (bind_simulate.cpp)
void bind_covering(py::module_& m);    ///< covering_segments, lemma4_covering (bind_covering.cpp)
void bind_certify(py::module_& m);     ///< certify: proofs in ball arithmetic (bind_certify.cpp)
void bind_orbit(py::module_& m);       ///< lyapunov, rate, period, derivative (bind_orbit.cpp)
void bind_sweep(py::module_& m);       ///< sweep: the (q/a, b/a) plane as `dfchaos sweep` (bind_sweep.cpp)

}  // namespace dfchaos::python

namespace pybind11::detail {

/// The caster of every Parameters argument of the module (by value, reference or pointer, and
/// `self` of its methods and properties): pybind11's own, after require_constructed(). pybind11
/// 2.10 lets `Parameters.__new__(Parameters)` make an instance without a C++ object and, on first
/// use, hands uninitialised memory to the function; no such object gets past this caster.
template <>
class type_caster<dfchaos::Parameters> : public type_caster_base<dfchaos::Parameters> {
 public:
  /// @throws type_error for an unconstructed Parameters (see require_constructed()).
  bool load(handle src, bool convert) {
    dfchaos::python::require_constructed(src);
    return type_caster_base<dfchaos::Parameters>::load(src, convert);
  }
};

}  // namespace pybind11::detail
