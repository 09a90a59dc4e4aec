// SPDX-License-Identifier: GPL-3.0-or-later
/// @file grid.hpp
/// @brief Parameter axes and grids with a deterministic order, and a parallel sweep over a grid
/// that records a failure per cell instead of stopping, with progress on stderr.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace dfchaos::kit {

/// One axis of a grid: n values between lo and hi.
class Axis {
 public:
  /// n values lo + (hi − lo)·i/(n − 1), i = 0..n−1 (n ≥ 2; the last is hi up to rounding).
  static Axis linear(double lo, double hi, int n);
  /// n cell centres lo + (hi − lo)·(i + ½)/n, i = 0..n−1 (n ≥ 1).
  static Axis centres(double lo, double hi, int n);
  /// n values lo·(hi/lo)^{i/(n−1)}, i = 0..n−1 (0 < lo, n ≥ 2).
  static Axis log(double lo, double hi, int n);
  /// n values lo·ratio^{i/(n−1)} (the same as log(lo, lo·ratio, n), but with the ratio given).
  static Axis log_ratio(double lo, double ratio, int n);

  int size() const { return n_; }      ///< number of values
  double operator[](int i) const;      ///< the i-th value (0 <= i < size())
  std::vector<double> values() const;  ///< all values, in order

 private:
  enum class Kind { Linear, Centres, Log };
  Kind kind_ = Kind::Linear;
  double lo_ = 0, hi_ = 0, ratio_ = 1;
  int n_ = 0;
};

/// A cell of a two-dimensional grid; index = i·ny + j (first axis slowest).
struct Cell2 {
  int i = 0, j = 0;     ///< indices on the first and second axis
  double x = 0, y = 0;  ///< the values
  long long index = 0;  ///< the position in the deterministic order
};

/// Outcome of one cell of a sweep: the value, or the message of the exception it threw.
template <class R>
struct CellResult {
  R value{};            ///< the result (default-constructed when failed)
  bool failed = false;  ///< the cell threw
  std::string error;    ///< its message
};

/// Progress of a long loop on stderr: a counter with an estimate of the time left, updated at most
/// twice a second, only when stderr is a terminal or `always` is set. Thread-safe.
class Progress {
 public:
  Progress(std::string label, long long total, bool always = false);
  ~Progress();
  void step(long long n = 1);  ///< n more items done
  void done();                 ///< the final line

 private:
  std::string label_;
  long long total_, done_ = 0;
  bool enabled_, finished_ = false;
  double start_, last_;
};

/// Runs `f` on every cell of the grid x × y, in parallel (OpenMP, dynamic schedule), and returns
/// the results in the deterministic order (index = i·ny + j), independent of the thread count.
/// An exception in a cell is recorded in that cell; the sweep goes on.
template <class R>
std::vector<CellResult<R>> sweep(const Axis& x, const Axis& y, const std::function<R(const Cell2&)>& f, const std::string& label = "sweep");

/// The same over a list of items (one dimension).
template <class R, class T>
std::vector<CellResult<R>> sweep_list(const std::vector<T>& items, const std::function<R(const T&)>& f, const std::string& label = "sweep");

}  // namespace dfchaos::kit

#include "kit/grid_impl.hpp"
