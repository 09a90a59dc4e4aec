// SPDX-License-Identifier: GPL-3.0-or-later
// Regression tier for wrong answers at the edges of precision, one test per bug, each
// failing on the code before the fix. The accuracy of T against a 40-digit reference is checked
// by tests/precision_reference.py (CTest: precision_reference).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <string>

#include "dfchaos/double_double.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/simulator.hpp"

using namespace dfchaos;

namespace {
constexpr int kDoublesBelowT3 = 1200;       // > 1e-12 / ulp(t3) = 1124: all of [t3 - 1e-12, t3)
constexpr double kReturnRelTol = 1e-3;      // T1 vs theta + 3 (t3 - theta) (t3 from asinl, error ~1e-19)
constexpr double kReturnAbsTol = 4.45e-16;  //   plus the rounding of the phase of T1 (ulp(t3)/2)
constexpr double kScaleTol = 1e-13;         // T at a = 1e-90 vs a = 1 (same b/a, q/a)

/// F(theta) = a sin(theta) + 2b in long double: its sign is exact for doubles near t3.
long double F_ld(const Parameters& p, double theta) { return p.a() * std::sin(static_cast<long double>(theta)) + 2.0L * p.b(); }
}  // namespace

// The t3 edge. Bug: every theta in [t3 - 3e-14, t3) gave scenario G with T = theta and elapsed
// 0 (a spurious fixed point; `orbit` never advanced); and for theta in (t3 - 3e-8, t3) the contact
// at 3 (t3 - theta) was skipped and T1 came out up to 1e-6 too late. Cause: from rest the gap is
// F(theta) u^2/2 + a cos(theta) u^3/6 + ..., below rounding noise; the search took F(theta) < 2.8e-14
// for 0, saw f''' > 0 and declared a contact at the start, or else assumed f < 0 on (0, 1e-7].
// The true motion flies for 3 (t3 - theta), hits with a tiny velocity, progresses an instant,
// stops beyond t3, restarts at t0 and stops before t2 (scenario C): T = t2.
TEST(PrecisionRegression, EveryDoubleJustBelowT3MapsToT2) {
  for (const auto& [a, b, q] : {std::tuple{1.0, 0.01, 0.85}, std::tuple{2.0, 0.003, 1.7}}) {
    const Parameters p(a, b, q);
    const double t2 = *p.t2(), t3 = *p.t3();
    const long double t3_true = 2 * 3.141592653589793238462643383279502884L - std::asin(2.0L * b / a);
    double theta = t3;
    int beyond = 0;
    for (int i = 0; i < kDoublesBelowT3; ++i) {
      theta = std::nextafter(theta, 0.0);
      SCOPED_TRACE("a=" + format_double(a) + " theta=" + format_double(theta));
      const MapStep s = return_map_step(p, theta);
      EXPECT_EQ(s.T, t2);
      EXPECT_GT(s.elapsed, 3.0);
      if (F_ld(p, theta) >= 0) {  // the rounded t3 lies above the true one: at rest, F >= 0 (C')
        ++beyond;
        EXPECT_EQ(s.scenario, Scenario::Cprime);
        continue;
      }
      ASSERT_EQ(s.scenario, Scenario::C) << s.chain;
      const long double eps = t3_true - theta;
      ASSERT_EQ(s.hit.t1.turn, 0);
      EXPECT_LE(std::fabs(s.hit.t1.phase - (theta + 3 * eps)), kReturnRelTol * 3 * eps + kReturnAbsTol);
      EXPECT_GT(s.hit.t1.phase, theta);
    }
    EXPECT_LE(beyond, 1);
    EXPECT_LT(t3 - theta, 1.1e-12);
    EXPECT_GE(t3 - theta, 1e-12);
  }
}

TEST(PrecisionRegression, OrbitFromJustBelowT3Advances) {
  const Parameters p(1.0, 0.01, 0.85);
  double theta = std::nextafter(*p.t3(), 0.0);
  for (int n = 0; n < 3; ++n) {
    const MapStep s = return_map_step(p, theta);
    EXPECT_NE(s.T, theta);
    EXPECT_GT(s.elapsed, 0.0);
    theta = s.T;
  }
}

// Bug: the "negligible" threshold of the start-at-rest test had an absolute part (+1), so at
// a = 1e-90 every F(theta) counted as 0 and every theta with cos(theta) > 0 became a fixed point G.
TEST(PrecisionRegression, ScaleInvarianceAtTinyAmplitude) {
  const Parameters p(1.0, 0.01, 0.85), s(1e-90, 1e-92, 0.85e-90);
  for (double th : {3.5, 4.0, 4.7, 5.0, 5.5, 6.0, 6.2}) {
    const MapStep x = return_map_step(p, th), y = return_map_step(s, th);
    EXPECT_EQ(x.scenario, y.scenario) << "theta=" << th;
    EXPECT_NEAR(x.T, y.T, kScaleTol) << "theta=" << th;
    EXPECT_NEAR(x.hit.theta1, y.hit.theta1, kScaleTol * (1 + x.hit.theta1)) << "theta=" << th;
  }
}

// The floor: below the documented floor b/a >= kMinMapRatio, T is refused naming b (it was
// printed with 17 digits and errors up to 0.05, or gave up after 20 million pieces).
TEST(PrecisionRegression, ReturnMapRefusedBelowTheAccuracyFloor) {
  for (double ba : {1e-13, 1e-17, 1e-60}) {
    const Parameters p(1.0, ba, 0.85);
    try {
      p.require_return_map();
      FAIL() << "b/a=" << ba << " accepted";
    } catch (const InvalidParameter& e) {
      EXPECT_EQ(e.parameter(), "b");
      EXPECT_NE(std::string(e.what()).find("b/a >= 1e-12"), std::string::npos) << e.what();
    }
    EXPECT_THROW(return_map_step(p, 4.0), InvalidParameter);
  }
  EXPECT_NO_THROW(return_map_step(Parameters(1.0, kMinMapRatio, 0.85), 4.0));
  EXPECT_NO_THROW(return_map_step(Parameters(3.0, 3 * kMinMapRatio, 2.55), 4.0));
}

// The time range: t0 or t-end beyond the int64 range of Instant::from_time overflowed and gave
// an empty event log with exit status 0.
TEST(PrecisionRegression, SimulationTimesBeyondTheBoundAreRefused) {
  const Parameters p(1.0, 0.01, 0.85);
  for (double t_end : {1e20, 6e19, 1e308, 1.0000001e12}) {
    try {
      simulate(p, 0, 0, 0, 4, t_end);
      FAIL() << "t-end=" << t_end << " accepted";
    } catch (const InvalidParameter& e) {
      EXPECT_EQ(e.parameter(), "t-end");
    }
  }
  try {
    simulate(p, 0, 0, 0, 1e20, 1.00000000001e20);
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.parameter(), "t0");
  }
  EXPECT_THROW(Instant::from_time(1e20), std::domain_error);
  // Inside the bound: a simulation near t = 1e11 gives the events of the same motion started near 0
  // at the same phase.
  const double t0 = 4 + two_pi * 15915494309.0;  // ~1e11
  const double ph = Instant::from_time(t0).phase;
  const auto near0 = simulate(p, 0, 0, 0, ph, ph + 200), far = simulate(p, 0, 0, 0, t0, t0 + 200);
  ASSERT_EQ(near0.events.size(), far.events.size());
  ASSERT_GT(far.events.size(), 3u);
  for (std::size_t i = 0; i < near0.events.size(); ++i) EXPECT_NEAR(far.events[i].when.phase, near0.events[i].when.phase, 1e-12);
}

TEST(PrecisionRegression, PhaseOfLargeTimesIsExact) {
  // t = fl(k * two_pi) with two_pi the double nearest 2 pi: 2 pi = two_pi + lo, lo below from mpmath
  // (2 pi - two_pi - lo = -6e-33), and k * two_pi = t + delta exactly (delta by fma). So the exact
  // phase of t is -(k lo + delta) mod 2 pi. A long-double 2 pi (error 2.2e-19 per turn) would be off
  // by up to 3.5e-8 at k = 1.6e11.
  constexpr double lo = 2.4492935982947064e-16;
  constexpr double kPhaseTol = 4 * 8.9e-16;
  for (double k : {1e6, 123456789.0, 1.6e11, 1e14}) {
    const double t = k * two_pi;
    const double delta = std::fma(k, two_pi, -t);
    const long double e = static_cast<long double>(k) * lo + delta;  // the phase is -e mod 2 pi
    const long double expected = e > 0 ? two_pi_l - e : -e;
    const Instant i = Instant::from_time(t);
    EXPECT_NEAR(i.phase, static_cast<double>(expected), kPhaseTol) << "k=" << k;
  }
}

// The parameter range: a subnormal a gave b/a = inf, q/a = inf in `info`; parameters are now limited
// to [kMinParameter, kMaxParameter] (the motion depends only on b/a and q/a).
TEST(PrecisionRegression, ParametersOutsideTheSafeRangeAreRefused) {
  for (double bad : {1e-320, 1e-200, 1e-101, 1e101, 1e300}) {
    for (int which = 0; which < 3; ++which) {
      try {
        if (which == 0) Parameters(bad, 0.01, 0.85);
        if (which == 1) Parameters(1.0, bad, 0.85);
        if (which == 2) Parameters(1.0, 0.01, bad);
        FAIL() << "accepted " << bad;
      } catch (const InvalidParameter& e) {
        EXPECT_EQ(e.parameter(), std::string(1, "abq"[which]));
        EXPECT_NE(std::string(e.what()).find("1e-100"), std::string::npos);
      }
    }
  }
  EXPECT_NO_THROW(Parameters(kMinParameter, kMinParameter, kMinParameter));
  EXPECT_NO_THROW(Parameters(kMaxParameter, kMaxParameter, kMaxParameter));
}

// The double-double cosine behind the coefficient a cos(theta) of long flights,
// against 50-digit mpmath values (hi + lo, the rounded head and the rounded remainder).
TEST(DoubleDouble, CosineTo1e31AgainstMpmath) {
  struct Ref {
    double x, hi, lo;
  };
  constexpr double kRelTol = 1e-31;
  for (const Ref& r : {Ref{3.5, -0.9364566872907963, 3.5955391095995e-18}, Ref{4.0, -0.6536436208636119, 2.5846614087018284e-17},
                       Ref{1.6, -0.029199522301288815, 4.155359463897964e-19}, Ref{3.1431505650355778, -0.999998786456209, -7.071280470751749e-18}}) {
    const dd::DD c = dd::cos_dd(r.x);
    EXPECT_EQ(c.hi, r.hi) << "x=" << r.x;
    EXPECT_NEAR(c.lo, r.lo, kRelTol * std::fabs(r.hi)) << "x=" << r.x;
  }
}
