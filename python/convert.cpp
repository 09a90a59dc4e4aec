// SPDX-License-Identifier: GPL-3.0-or-later
/// @file convert.cpp
/// @brief Array-likes to contiguous float64 with the checks of convert.hpp, and string columns.
#include "convert.hpp"

#include <cmath>
#include <cstring>

#include "dfchaos/errors.hpp"

namespace dfchaos::python {

namespace {
/// A non-finite value as Python spells it ('nan', 'inf', '-inf'), as the CLI quotes its text.
std::string spell(double x) { return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf"); }
}  // namespace

double finite(const char* name, double x) {
  if (!std::isfinite(x)) throw InvalidParameter(name, "must be a finite number (got '" + spell(x) + "')");
  return x;
}

Reals as_reals(const py::handle& obj, const char* name) {
  py::array any = py::array::ensure(obj);
  if (!any) throw py::type_error(std::string(name) + ": expected a real number or an array-like of real numbers");
  const char kind = any.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + ": expected real numbers, got an array of dtype " + py::str(any.dtype()).cast<std::string>());
  const py::ssize_t n = any.size();  // checked before the copy (a broadcast view can be huge)
  if (n > kMaxElements)
    throw InvalidParameter(name, "number of elements <= " + format_shortest(static_cast<double>(kMaxElements)), static_cast<double>(n));
  Reals r;
  r.array = RealArray::ensure(any);
  if (!r.array) throw py::type_error(std::string(name) + ": cannot be converted to float64");
  r.scalar = r.array.ndim() == 0;
  const double* x = r.array.data();
  for (py::ssize_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) {
      if (r.scalar) finite(name, x[i]);
      throw InvalidParameter(name, "must be a finite number (got '" + spell(x[i]) + "' at flat index " + std::to_string(i) + ")");
    }
  return r;
}

void require_constructed(py::handle obj) {
  if (!obj || obj.is_none()) return;
  const py::detail::type_info* type = py::detail::get_type_info(typeid(Parameters));
  if (type == nullptr || PyObject_TypeCheck(obj.ptr(), type->type) == 0) return;
  auto* instance = reinterpret_cast<py::detail::instance*>(obj.ptr());
  if (!instance->get_value_and_holder(type).holder_constructed())
    throw py::type_error(
        "dfchaos.Parameters: this object was never initialised (made by Parameters.__new__ without __init__); "
        "build it as dfchaos.Parameters(a, b, q)");
}

StrColumn::StrColumn(const std::vector<py::ssize_t>& shape, py::ssize_t width)
    : array(py::dtype("<U" + std::to_string(width)), shape), width_(width) {
  data_ = static_cast<char32_t*>(array.mutable_data());
  std::memset(static_cast<void*>(data_), 0, static_cast<std::size_t>(array.nbytes()));
}

}  // namespace dfchaos::python
