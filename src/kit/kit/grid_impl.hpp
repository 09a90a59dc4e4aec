// SPDX-License-Identifier: GPL-3.0-or-later
/// @file grid_impl.hpp
/// @brief Template definitions of grid.hpp (included by it).
#pragma once

#include <atomic>
#include <exception>
#include <new>

namespace dfchaos::kit {

template <class R, class T>
std::vector<CellResult<R>> sweep_list(const std::vector<T>& items, const std::function<R(const T&)>& f, const std::string& label) {
  const long long n = static_cast<long long>(items.size());
  std::vector<CellResult<R>> out(items.size());
  Progress progress(label, n);
  std::atomic<bool> out_of_memory{false};  // not a failure of a cell; an exception cannot leave the region
#pragma omp parallel for schedule(dynamic, 1)
  for (long long k = 0; k < n; ++k) {
    if (out_of_memory.load()) continue;
    auto& cell = out[static_cast<std::size_t>(k)];
    try {
      cell.value = f(items[static_cast<std::size_t>(k)]);
    } catch (const std::bad_alloc&) {
      out_of_memory.store(true);
    } catch (const std::exception& e) {
      cell.failed = true;
      cell.error = e.what();
    }
    progress.step();
  }
  progress.done();
  if (out_of_memory.load()) throw std::bad_alloc();
  return out;
}

template <class R>
std::vector<CellResult<R>> sweep(const Axis& x, const Axis& y, const std::function<R(const Cell2&)>& f, const std::string& label) {
  std::vector<Cell2> cells;
  cells.reserve(static_cast<std::size_t>(x.size()) * static_cast<std::size_t>(y.size()));
  for (int i = 0; i < x.size(); ++i)
    for (int j = 0; j < y.size(); ++j) cells.push_back(Cell2{i, j, x[i], y[j], static_cast<long long>(i) * y.size() + j});
  return sweep_list<R, Cell2>(cells, f, label);
}

}  // namespace dfchaos::kit
