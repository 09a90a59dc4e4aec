// SPDX-License-Identifier: GPL-3.0-or-later
// The return map T (Section 3, Lemma 3): against numerical integration (GSL odeiv2), against a
// long-double Newton refinement of its two roots, and the scenario bookkeeping.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "dfchaos/errors.hpp"
#include "dfchaos/motion.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/orbit.hpp"
#include "dfchaos/progression_stop.hpp"
#include "dfchaos/return_map.hpp"
#include "test_support.hpp"

using namespace dfchaos;

namespace {
constexpr double kOdeAgreement = 1e-7;  // exact T vs integrated T (event tolerance 1e-12)
constexpr double kAccuracy = 1e-9;      // |T - T_ref|, the accuracy promised for b/a in [1e-5, 0.2]

}  // namespace

class AgainstIntegration : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(AgainstIntegration, TAgreesWithOdeivIntegratedMap) {
  const auto [ba, qa] = GetParam();
  const Parameters p(1.0, ba, qa);
  for (int i = 0; i < 25; ++i) {
    const double th = *p.t2() + (*p.t3() - *p.t2()) * (i + 0.37) / 25;
    const MapStep s = return_map_step(p, th);
    const OdeMapStep o = ode_return_map_step(p, th);
    SCOPED_TRACE("b/a=" + std::to_string(ba) + " q/a=" + std::to_string(qa) + " theta=" + std::to_string(th));
    EXPECT_EQ(s.chain, o.chain);
    EXPECT_NEAR(s.hit.theta1, o.T1, kOdeAgreement * (1 + s.hit.theta1));
    EXPECT_NEAR(s.hit.hit_velocity, o.hit_velocity, kOdeAgreement);
    EXPECT_LE(circle_distance(s.T, o.T), kOdeAgreement);
    EXPECT_NEAR(s.elapsed, o.elapsed, kOdeAgreement * (1 + s.elapsed));
    EXPECT_NEAR(s.penetration, o.penetration, kOdeAgreement);
  }
}

INSTANTIATE_TEST_SUITE_P(ParameterSets, AgainstIntegration,
                         ::testing::Values(std::pair{0.2, 0.95}, std::pair{0.1, 0.95}, std::pair{0.05, 0.85}, std::pair{0.05, 0.7},
                                           std::pair{0.02, 0.6}, std::pair{0.02, 0.85}, std::pair{0.1, 0.45}));

TEST(ReturnMap, AccurateTo1e9AgainstLongDoubleRefinement) {
  // Reference: Newton's method in long double on Eq. (11) for theta1 and on Eq. (17) for theta2,
  // written here with plain sinl/cosl of t = theta + s (independent of the library's turn/phase
  // bookkeeping), started from the library's values. Checks the precision of T; that no earlier
  // root was skipped is checked by test_first_root.
  int checked = 0;
  for (double ba : {1e-5, 1e-4, 1e-3, 1e-2, 0.1, 0.2}) {
    test_support::Drawer draws(ba, ba, 0.5, 1.0, test_support::kSeed + static_cast<std::uint64_t>(1e6 * ba));
    for (int i = 0; i < 200; ++i) {
      const auto d = draws.next();
      const Parameters p(1.0, d.b, d.q);
      if (!(d.q > 2 * d.b)) continue;
      MapStep s;
      try {
        s = return_map_step(p, d.theta);
      } catch (const GaveUp&) {
        continue;  // eternal stick-slip: no T to compare
      }
      const long double a = 1, b = d.b, c = p.c(), th = d.theta;
      long double s1 = s.hit.theta1 - d.theta;
      for (int k = 0; k < 6; ++k) {
        const long double g = b * s1 * s1 - a * std::sin(th + s1) + a * std::cos(th) * s1 + a * std::sin(th);
        const long double dg = 2 * b * s1 - a * std::cos(th + s1) + a * std::cos(th);
        s1 -= g / dg;
      }
      const long double ref_theta1 = th + s1;
      EXPECT_NEAR(static_cast<double>(ref_theta1), s.hit.theta1, kAccuracy * (1 + s.hit.theta1));
      if (s.scenario != Scenario::A) continue;
      // theta2: first zero of the progression velocity G2 (Eq. 17), refined from the library's end.
      long double s2 = s.elapsed;
      for (int k = 0; k < 6; ++k) {
        const long double v = 2 * b * s1 + a * std::cos(th) + 2 * c * (s2 - s1) - a * std::cos(th + s2);
        const long double dv = 2 * c + a * std::sin(th + s2);
        s2 -= v / dv;
      }
      const double T_ref = static_cast<double>(std::fmod(th + s2, 6.283185307179586476925286766559005768L));
      EXPECT_LE(circle_distance(s.T, T_ref), kAccuracy) << "b/a=" << ba << " theta=" << d.theta;
      ++checked;
    }
  }
  EXPECT_GT(checked, 600);
}

TEST(ReturnMap, ScenarioBookkeepingFollowsLemma3) {
  for (auto [ba, qa] : {std::pair{0.01, 0.85}, std::pair{0.05, 0.7}, std::pair{0.1, 0.95}}) {
    const Parameters p(1.0, ba, qa);
    for (int i = 0; i < 500; ++i) {
      const double th = *p.t2() + (*p.t3() - *p.t2()) * i / 500.0;
      const MapStep s = return_map_step(p, th);
      ASSERT_GE(s.T, *p.t2());
      ASSERT_LT(s.T, *p.t3());
      ASSERT_GT(s.elapsed, 0);
      ASSERT_GE(s.penetration, 0);
      if (s.scenario == Scenario::B || s.scenario == Scenario::C) {
        EXPECT_EQ(s.T, *p.t2());  // Lemma 3
      }
      if (s.scenario == Scenario::A) {
        // Eq. (17): the progression velocity G2 vanishes at the end of the step.
        EXPECT_NEAR(G2(p, th, s.hit.t1, s.end), 0.0, 1e-9);
      }
    }
  }
}

TEST(ReturnMap, EternalStickSlipIsReportedNotLooped) {
  // The prediction, from the pieces alone: a start gives up exactly when its first progression
  // (from the impact T1 with the impact velocity, Eq. 17) stops in [t3, t0 + 2 pi) — a stop until
  // t0 — and the progression from rest at t0 repeats for ever (progression_from_t0). Anywhere else
  // the mass flies again. Checked at b = 0.45, q = 0.95 (the progression from t0 is still moving at
  // t3 and stops before the next t0: every start gives up), and at two sets where the mass always
  // flies again (Lemma 1 holds; Lemma 1 fails with scenario D).
  for (auto [ba, qa, all_give_up] : {std::tuple{0.45, 0.95, true}, std::tuple{0.01, 0.85, false}, std::tuple{0.05, 0.7, false}}) {
    const Parameters p(1.0, ba, qa);
    const bool repeats = progression_from_t0(p).repeats_for_ever;
    EXPECT_EQ(repeats, all_give_up);
    const double t0 = *p.t0(), t3 = *p.t3();
    int gave_up = 0;
    for (int i = 0; i < 200; ++i) {
      const double th = *p.t2() + (*p.t3() - *p.t2()) * i / 200.0;
      const NextHit h = next_hit(p, th);
      ASSERT_GT(h.hit_velocity, 0) << "theta=" << th;
      const auto stop = first_upcrossing(ProgressionMotion(p, h.t1, 0.0, h.hit_velocity).minus_velocity());
      ASSERT_TRUE(stop.has_value());
      const bool predicted = repeats && phase_in_arc(stop->t.phase, t3, t0);
      bool actual = false;
      try {
        return_map_step(p, th);
      } catch (const GaveUp&) {
        actual = true;
        ++gave_up;
        EXPECT_THROW(ode_return_map_step(p, th), GaveUp);
      }
      EXPECT_EQ(actual, predicted) << "b/a=" << ba << " theta=" << th << ": the first progression stops at phase " << stop->t.phase;
    }
    EXPECT_EQ(gave_up, all_give_up ? 200 : 0) << "b/a=" << ba << " q/a=" << qa;
  }
}

TEST(ReturnMap, RejectsParametersOutsideTheMapsDomain) {
  EXPECT_THROW(return_map_step(Parameters(1.0, 0.5, 0.9), 4.0), InvalidParameter);  // b >= a/2
  EXPECT_THROW(return_map_step(Parameters(1.0, 0.3, 0.5), 4.0), InvalidParameter);  // q <= 2b
  const Parameters p(1.0, 0.01, 0.85);
  EXPECT_THROW(return_map_step(p, 1.0), InvalidParameter);
  EXPECT_THROW(return_map_step(p, INFINITY), InvalidParameter);
}

TEST(MapDomain, IsTheHalfOpenArcFromT2ToT3) {
  const Parameters p(1.0, 0.01, 0.85);
  const double t2 = *p.t2(), t3 = *p.t3();
  EXPECT_TRUE(p.in_map_domain(t2));
  EXPECT_TRUE(p.in_map_domain(std::nextafter(t3, 0.0)));
  EXPECT_FALSE(p.in_map_domain(t3));
  EXPECT_FALSE(p.in_map_domain(std::nextafter(t2, 0.0)));
  EXPECT_FALSE(p.in_map_domain(NAN));
  EXPECT_FALSE(Parameters(1.0, 0.6, 0.9).in_map_domain(4.0));  // 2b > a: no t2, t3
  try {
    p.require_in_map_domain(t3, "theta0");
    ADD_FAILURE() << "t3 accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.parameter(), "theta0");
    EXPECT_NE(std::string(e.what()).find("t2 <= theta0 < t3 = [" + format_shortest(t2) + ", " + format_shortest(t3) + ")"), std::string::npos)
        << e.what();
  }
  try {
    Parameters(1.0, 0.6, 0.9).require_in_map_domain(4.0);
    ADD_FAILURE() << "a phase accepted without t2, t3";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.parameter(), "b");
  }
}

TEST(Orbit, IsTheIterationOfTWithSummedTimeAndAdvance) {
  const Parameters p(1.0, 0.01, 0.85);
  const double theta0 = *p.t2() + 0.3 * (*p.t3() - *p.t2());
  constexpr long long kSteps = 200;
  double theta = theta0;  // the orbit by hand
  long double time = theta0, y = 0;
  long long count = 0;
  const Orbit orbit(p, theta0, kSteps);
  for (auto it = orbit.begin(); it != orbit.end(); ++it) {
    const MapStep s = return_map_step(p, theta);
    ASSERT_EQ(it.n(), count);
    ASSERT_EQ(it->theta, theta);
    ASSERT_EQ(it->T, s.T);
    ASSERT_EQ(it->elapsed, s.elapsed);
    ASSERT_EQ(it.time(), time);
    ASSERT_EQ(it.y(), y);
    time += s.elapsed;
    y += s.penetration;
    theta = s.T;
    ++count;
  }
  EXPECT_EQ(count, kSteps);
  EXPECT_EQ(T_power(p, theta0, kSteps), theta);
  EXPECT_EQ(T_power(p, theta0, 0), theta0);
  EXPECT_TRUE(Orbit(p, theta0, 0).begin() == Orbit(p, theta0, 0).end());
  EXPECT_TRUE(Orbit(p, 1.0, 0).begin() == Orbit(p, 1.0, 0).end());  // nothing computed, nothing checked
  EXPECT_THROW(Orbit(p, 1.0, 1).begin(), InvalidParameter);         // the first step checks theta0
}
