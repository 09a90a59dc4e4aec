/// @file test_support.hpp
/// @brief Shared helpers of the test suites: seeded random draws over the parameter plane.
#pragma once

#include <cmath>
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

}  // namespace dfchaos::test_support
