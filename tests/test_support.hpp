// SPDX-License-Identifier: GPL-3.0-or-later
/// @file test_support.hpp
/// @brief Shared helpers of the test suites: seeded random draws over the parameter plane, and the
/// b/a candidates of the tests that need a cycle of the rounding.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "dfchaos/parameters.hpp"

namespace dfchaos::test_support {

/// A fixed seed: every run draws the same cases, so a failure reproduces.
inline constexpr std::uint64_t kSeed = 20130214;

/// Draws (b/a, q/a, theta) with a = 1, b/a log-uniform in [ba_lo, ba_hi], q/a uniform in (qa_lo, qa_hi),
/// theta uniform in [t2, t3).
struct Draw {
  double b, q, theta;
};

class Drawer {
 public:
  Drawer(double ba_lo, double ba_hi, double qa_lo, double qa_hi, std::uint64_t seed = kSeed)
      : rng_(seed), log_ba_(std::log(ba_lo), std::log(ba_hi)), qa_(qa_lo, qa_hi), unit_(0.0, 1.0) {}
  Draw next() {
    Draw d;
    d.b = std::exp(log_ba_(rng_));
    d.q = qa_(rng_);
    const Parameters p(1.0, d.b, d.q);
    d.theta = *p.t2() + (*p.t3() - *p.t2()) * unit_(rng_);
    return d;
  }
  double uniform() { return unit_(rng_); }

 private:
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> log_ba_, qa_, unit_;
};

/// Values of b/a (a = 1, q/a = 0.85) near 0.01, tried in order by the tests that need a computed
/// orbit of t2 that returns to t2 through the rounding (a cycle of the rounding, not of T): which
/// b/a gives one changes with any ulp-level change of T, so those tests take the first of this list
/// that qualifies, and fail (asking for a longer list) when none does.
inline constexpr std::array<double, 10> kRoundingCycleCandidates = {0.0089, 0.0096, 0.0101, 0.0102, 0.0091, 0.0094, 0.0095, 0.0107, 0.0114, 0.0085};

}  // namespace dfchaos::test_support
