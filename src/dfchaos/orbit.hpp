// SPDX-License-Identifier: GPL-3.0-or-later
/// @file orbit.hpp
/// @brief The orbit \f$\theta_{n+1} = T(\theta_n)\f$ of the return map, as a range of its steps:
/// the one loop over \f$T\f$ that every orbit of the library, the tool and the Python module walks.
///
/// Element \f$n\f$ of `Orbit(p, theta0, steps)` is the MapStep from \f$\theta_n = T^n(\theta_0)\f$
/// (its `theta` is \f$\theta_n\f$, its `T` is \f$\theta_{n+1}\f$), for \f$n = 0, \dots,\f$ steps - 1.
/// A step is computed when the iterator reaches it (begin() computes step 0, each increment the
/// next one), so exactly `steps` evaluations of \f$T\f$ are made, none after the last element, and
/// a step at which \f$T\f$ gives up ends the walk after the elements before it. The iterator also
/// carries the instant \f$\widehat T^{\,n}\f$ at which \f$\theta_n\f$ starts and the delimiter's
/// position there, both sums of the steps' `elapsed` and `penetration` in long double.
#pragma once

#include <cstddef>
#include <iterator>

#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

/// The first `steps` steps of the orbit of \f$\theta_0\f$ under \f$T\f$ (a single-pass range).
///
/// Nothing is checked or computed at construction: the first step checks what return_map_step
/// checks (\f$T\f$'s assumptions, \f$\theta_0 \in [t_2, t_3)\f$ under the name `theta`). A caller
/// that must refuse bad input before any output calls Parameters::require_return_map() and
/// Parameters::require_in_map_domain() itself.
class Orbit {
 public:
  /// Walks the orbit; `*it` is the current step.
  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;  ///< a single pass: each step is computed once
    using value_type = MapStep;                         ///< one step of T
    using difference_type = std::ptrdiff_t;             ///< (iterator requirements)
    using pointer = const MapStep*;                     ///< (iterator requirements)
    using reference = const MapStep&;                   ///< (iterator requirements)

    iterator() = default;  ///< the end of every orbit

    const MapStep& operator*() const { return step_; }    ///< the step from \f$\theta_n\f$
    const MapStep* operator->() const { return &step_; }  ///< the step from \f$\theta_n\f$
    long long n() const { return n_; }                    ///< the index \f$n\f$ of the current step
    /// The instant at which \f$\theta_n\f$ starts: \f$\theta_0\f$ plus the elapsed times of the
    /// steps before, summed in long double.
    long double time() const { return time_; }
    /// The delimiter's position at time(): the sum of the penetrations of the steps before
    /// (0 at \f$n = 0\f$), in long double.
    long double y() const { return y_; }

    /// Moves to step \f$n + 1\f$, computing it unless it is past the last one.
    /// @throws GaveUp as return_map_step.
    iterator& operator++();
    void operator++(int) { ++*this; }  ///< as ++it (an input iterator's post-increment)

    /// Equal when both are past the end or both at the same index of the same orbit.
    friend bool operator==(const iterator& x, const iterator& y) { return x.at_end() == y.at_end() && (x.at_end() || x.n_ == y.n_); }

   private:
    friend class Orbit;
    iterator(const Parameters& p, double theta0, long long steps);
    bool at_end() const { return p_ == nullptr || n_ >= steps_; }

    const Parameters* p_ = nullptr;
    long long steps_ = 0, n_ = 0;
    MapStep step_;
    long double time_ = 0, y_ = 0;
  };

  /// The orbit of `theta0` for `steps` steps (none if steps <= 0). `p` must outlive the range.
  Orbit(const Parameters& p, double theta0, long long steps) : p_(&p), theta0_(theta0), steps_(steps) {}

  /// Computes step 0. @throws InvalidParameter, GaveUp as return_map_step.
  iterator begin() const { return iterator(*p_, theta0_, steps_); }
  iterator end() const { return {}; }  ///< past the last step

 private:
  const Parameters* p_;
  double theta0_;
  long long steps_;
};

/// \f$T^n(\theta)\f$ for \f$n \ge 0\f$ (\f$\theta\f$ itself for \f$n = 0\f$): the last step's image.
/// @throws as return_map_step (for \f$n \ge 1\f$).
double T_power(const Parameters& p, double theta, long long n);

}  // namespace dfchaos
