// SPDX-License-Identifier: GPL-3.0-or-later
// Cross-validation: the closed-form solutions of the regimes (Eqs. 3-7) against a direct
// numerical integration of the equations of motion with GSL odeiv2 (rk8pd).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dfchaos/motion.hpp"
#include "dfchaos/progression_stop.hpp"
#include "test_support.hpp"

using namespace dfchaos;

namespace {
constexpr double kOdeTol = 1e-9;  // agreement of position and velocity over 50 time units

struct Rhs {
  double a, force_const;  // x'' = a sin t + force_const
};
int rhs(double t, const double y[], double dydt[], void* params) {
  const auto* r = static_cast<const Rhs*>(params);
  dydt[0] = y[1];
  dydt[1] = r->a * std::sin(t) + r->force_const;
  return GSL_SUCCESS;
}

/// Integrates x'' = a sin t + k from (t0, x0, v0) to t1.
std::pair<double, double> integrate(double a, double k, double t0, double x0, double v0, double t1) {
  Rhs r{a, k};
  gsl_odeiv2_system sys{rhs, nullptr, 2, &r};
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, 1e-14, 1e-14);
  double t = t0, y[2] = {x0, v0};
  const int status = gsl_odeiv2_driver_apply(d, &t, t1, y);
  gsl_odeiv2_driver_free(d);
  EXPECT_EQ(status, GSL_SUCCESS);
  return {y[0], y[1]};
}
}  // namespace

TEST(ClosedForms, FreeMotionEq3MatchesOdeIntegration) {
  std::mt19937_64 rng(test_support::kSeed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int n = 0; n < 200; ++n) {
    const double b = 0.2 * U(rng) + 1e-4, t0 = 20 * U(rng) - 5, x0 = U(rng) - 2, v0 = 2 * U(rng) - 1;
    const Parameters p(1.0, b, 0.9);
    const FreeMotion m(p, Instant::from_time(t0), x0, v0);
    for (double dt : {0.3, 3.0, 17.0, 50.0}) {
      const auto [x, v] = integrate(1.0, 2 * b, t0, x0, v0, t0 + dt);
      const Instant t = Instant::from_time(t0 + dt);
      EXPECT_NEAR(m.position(t), x, kOdeTol * (1 + std::fabs(x))) << "b=" << b << " t0=" << t0 << " dt=" << dt;
      EXPECT_NEAR(m.velocity(t), v, kOdeTol * (1 + std::fabs(v)));
    }
  }
}

TEST(ClosedForms, ProgressionEq6MatchesOdeIntegration) {
  std::mt19937_64 rng(test_support::kSeed + 1);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int n = 0; n < 200; ++n) {
    const double b = 0.2 * U(rng) + 1e-4, q = 0.5 + 0.5 * U(rng), t0 = 20 * U(rng) - 5, x0 = U(rng), v0 = 2 * U(rng);
    const Parameters p(1.0, b, q);
    const ProgressionMotion m(p, Instant::from_time(t0), x0, v0);
    for (double dt : {0.3, 3.0, 17.0}) {
      const auto [x, v] = integrate(1.0, 2 * b - q, t0, x0, v0, t0 + dt);
      const Instant t = Instant::from_time(t0 + dt);
      EXPECT_NEAR(m.position(t), x, kOdeTol * (1 + std::fabs(x)));
      EXPECT_NEAR(m.velocity(t), v, kOdeTol * (1 + std::fabs(v)));
    }
  }
}

TEST(ClosedForms, Eq7IsTheProgressionVelocityFromRestAtT0) {
  const Parameters p(1.0, 0.02, 0.8);
  const double t0 = *p.t0();
  const ProgressionMotion m(p, Instant::at_phase(t0), 0.0, 0.0);
  for (double t = t0; t < t0 + 6; t += 0.37) {
    const double eq7 = -p.a() * (std::cos(t) - std::cos(t0)) + 2 * p.c() * (t - t0);
    EXPECT_NEAR(m.velocity(Instant::from_time(t)), eq7, 1e-13);
  }
}

TEST(ClosedForms, EventFunctionsAreGapAndMinusVelocity) {
  const Parameters p(1.0, 0.03, 0.85);
  const FreeMotion f(p, Instant::from_time(4.0), -0.3, 0.2);
  const auto gap = f.gap(0.1);
  const ProgressionMotion g(p, Instant::from_time(1.0), 0.5, 0.7);
  const auto mv = g.minus_velocity();
  for (double t = 4.0; t < 30; t += 1.3) {
    const Instant i = Instant::from_time(t);
    EXPECT_NEAR(static_cast<double>(gap.value(i)), f.position(i) - 0.1, 1e-12);
    EXPECT_NEAR(static_cast<double>(gap.slope(i)), f.velocity(i), 1e-12);
    EXPECT_NEAR(static_cast<double>(mv.value(i)), -g.velocity(i), 1e-12);
  }
}

TEST(ProgressionFromT0, StopsWhereTheVelocityOfEq7FirstVanishes) {
  // Lemma 1's object computed by progression_from_t0, against a plain scan of Eq. (7) for its
  // first zero after t0, and the sign of Eq. (8) at t2, at parameters where Lemma 1 holds and where
  // it fails (scenario D: the stop falls in [t2, t3); and the repeating stick-slip).
  for (auto [ba, qa] : {std::pair{0.01, 0.85}, std::pair{0.05, 0.7}, std::pair{0.45, 0.95}}) {
    const Parameters p(1.0, ba, qa);
    const ProgressionFromT0 r = progression_from_t0(p);
    const double t0 = *p.t0(), c = p.c();
    double scan_t4 = NAN;
    constexpr int kScan = 4'000'000;
    for (int i = 1; i <= kScan; ++i) {
      const double t = t0 + 2 * two_pi * i / kScan;
      if (-(std::cos(t) - std::cos(t0)) + 2 * c * (t - t0) <= 0) {
        scan_t4 = t;
        break;
      }
    }
    ASSERT_FALSE(std::isnan(scan_t4)) << ba;
    EXPECT_NEAR(r.t4_value, scan_t4, 2 * 2 * two_pi / kScan) << "b/a=" << ba << " q/a=" << qa;
    const double t2 = *p.t2(), t1 = *p.t1();
    EXPECT_EQ(r.stops_in_t1_t2, scan_t4 >= t1 && scan_t4 <= t2);
    EXPECT_NEAR(r.eq8_velocity_at_t2, -(std::cos(t2) - std::cos(t0)) + 2 * c * (t2 - t0), 1e-12);
    EXPECT_EQ(r.proof_bound, 1 + std::cos(t0) - (qa - 2 * ba) * (pi - t0) < 0);
  }
  EXPECT_TRUE(progression_from_t0(Parameters(1.0, 0.01, 0.85)).stops_in_t1_t2);
  EXPECT_FALSE(progression_from_t0(Parameters(1.0, 0.05, 0.7)).stops_in_t1_t2);
  EXPECT_TRUE(progression_from_t0(Parameters(1.0, 0.45, 0.95)).repeats_for_ever);
}
