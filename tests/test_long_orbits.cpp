// SPDX-License-Identifier: GPL-3.0-or-later
/// @file test_long_orbits.cpp
/// @brief Reliability: orbits of 10^7 iterations of T at several parameter sets (small and large
/// b/a, Lemma 1 holding and failing) stay finite and inside [t2, t3), throw nothing, and every
/// step's elapsed time and penetration are finite and non-negative (checked on a sample of steps),
/// and every 10^5-th step along the orbit is recomputed independently by numerical integration of
/// the equations of motion (GSL odeiv2, ode_map.hpp): the states a long chaotic orbit actually
/// visits, not only the start, are checked against a reference.
/// The time per step is measured by `make bench`, not here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "dfchaos/ode_map.hpp"
#include "dfchaos/return_map.hpp"

namespace {

using namespace dfchaos;

constexpr long long kSteps = 10'000'000;
constexpr long long kFullStepEvery = 1000;      // every k-th step also through return_map_step
constexpr long long kReferenceEvery = 100'000;  // every k-th step also by numerical integration
constexpr double kOdeAgreement = 1e-7;          // |T - T_ode| per 100 time units of the step (the integration's
                                                // error grows with the flight: 1e4 time units at b/a = 1e-4)

struct Set {
  double b, q;
};

std::string set_name(const ::testing::TestParamInfo<Set>& info) {
  static const char* const names[] = {"b0_01_q0_85", "b1e_4_q0_95", "b0_05_q0_7"};
  return names[info.index];
}

class LongOrbit : public ::testing::TestWithParam<Set> {};

TEST_P(LongOrbit, TenMillionStepsStayFiniteAndInTheArc) {
  const Parameters p(1.0, GetParam().b, GetParam().q);
  const double t2 = *p.t2(), t3 = *p.t3();
  double theta = t2 + 0.3141592653589793 * (t3 - t2);
  long long outside = 0, non_finite = 0, bad_steps = 0, reference_checks = 0;
  double worst_reference = 0;
  for (long long n = 0; n < kSteps; ++n) {
    double next;
    if (n % kReferenceEvery == 0) {
      const MapStep s = return_map_step(p, theta);
      const OdeMapStep o = ode_return_map_step(p, theta);
      ++reference_checks;
      worst_reference = std::max(worst_reference, circle_distance(s.T, o.T) / std::max(1.0, s.elapsed / 100));
      EXPECT_EQ(s.chain, o.chain) << "step " << n << " theta=" << theta;
      EXPECT_NEAR(s.penetration, o.penetration, kOdeAgreement * std::max(1.0, s.elapsed / 100)) << "step " << n;
      next = s.T;
    } else if (n % kFullStepEvery == 0) {
      const MapStep s = return_map_step(p, theta);
      if (!std::isfinite(s.elapsed) || !(s.elapsed > 0) || !std::isfinite(s.penetration) || s.penetration < 0) ++bad_steps;
      next = s.T;
    } else {
      next = T(p, theta);
    }
    if (!std::isfinite(next)) {
      ++non_finite;
      break;
    }
    if (next < t2 || next >= t3) {
      ++outside;
      break;
    }
    theta = next;
  }
  EXPECT_EQ(reference_checks, kSteps / kReferenceEvery);
  EXPECT_LE(worst_reference, kOdeAgreement);
  EXPECT_EQ(non_finite, 0);
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(bad_steps, 0);
}

INSTANTIATE_TEST_SUITE_P(Sets, LongOrbit,
                         ::testing::Values(Set{0.01, 0.85},  // Lemma 1 holds, chaotic covering
                                           Set{1e-4, 0.95},  // long flights (~10^4 time units)
                                           Set{0.05, 0.7}),  // Lemma 1 fails: scenario D occurs
                         set_name);

}  // namespace
