// SPDX-License-Identifier: GPL-3.0-or-later
// Properties of T1 (Eq. 11): monotonicity, derivative formula of the proof of Lemma 2, and the
// discontinuities (grazing points, Eq. 14) against an independent dense scan for jumps.
#include <gtest/gtest.h>

#include <cmath>

#include "dfchaos/errors.hpp"
#include "dfchaos/next_hit.hpp"

using namespace dfchaos;

TEST(NextHit, DecreasingOnL0) {
  const Parameters p(1.0, 0.01, 0.85);
  double prev = next_hit(p, 1.01 * M_PI).theta1;
  for (int i = 1; i <= 20000; ++i) {
    const double th = 1.01 * M_PI + (1.5 * M_PI - 1.01 * M_PI) * i / 20000.0;
    const double t1 = next_hit(p, th).theta1;
    ASSERT_LT(t1, prev) << "theta=" << th;
    prev = t1;
  }
}

TEST(NextHit, DThetaFormulaOfLemma2MatchesFiniteDifference) {
  const Parameters p(1.0, 0.02, 0.85);
  for (double th : {3.3, 3.9, 4.4, 5.0, 5.9}) {
    const Instant t = next_hit(p, th).t1;
    const double h = 1e-6;
    const double fd = (G1(p, th + h, t) - G1(p, th - h, t)) / (2 * h);
    EXPECT_NEAR(dG1_dtheta(p, th, t), fd, 1e-6 * (1 + std::fabs(fd)));
    EXPECT_GT(dG1_dtheta(p, th, t), 0.0);  // positive on (t2, t3), t > theta
  }
}

TEST(NextHit, RejectsThetaOutsideT2T3) {
  const Parameters p(1.0, 0.01, 0.85);
  EXPECT_THROW(next_hit(p, *p.t3()), InvalidParameter);
  EXPECT_THROW(next_hit(p, *p.t2() - 1e-9), InvalidParameter);
  EXPECT_THROW(next_hit(p, NAN), InvalidParameter);
  EXPECT_THROW(next_hit(Parameters(1.0, 0.6, 0.9), 4.0), InvalidParameter);
}

class GrazingPoints : public ::testing::TestWithParam<double> {};

TEST_P(GrazingPoints, AreTangenciesAndMatchJumpsOfADenseScan) {
  const double ba = GetParam();
  const Parameters p(1.0, ba, 0.85);
  const double lo = *p.t2() + 1e-9, hi = 1.5 * M_PI;
  const auto z = grazing_points(p, lo, hi, 400);
  if (ba <= 0.05) {
    ASSERT_FALSE(z.empty());  // flights over several forcing periods do graze
  }
  for (std::size_t i = 0; i < z.size(); ++i) {
    const auto& g = z[i];
    if (i > 0) {
      EXPECT_GT(g.z, z[i - 1].z);
    }
    const double s = g.t1_right - g.z, scale = 1 + ba * s * s;
    EXPECT_LE(std::fabs(g.residual_G1), 1e-10 * scale) << "z=" << g.z;
    EXPECT_LE(std::fabs(g.residual_dG1), 1e-7) << "z=" << g.z;  // Eq. (14)
    EXPECT_TRUE(g.newton_converged) << "z=" << g.z;
    EXPECT_GT(g.jump, 0.5) << "z=" << g.z;
    EXPECT_EQ(g.maxima_left - g.maxima_right, 1);
    EXPECT_LT(p.F(g.tangency.phase), 0.0);  // a tangency from below needs F <= 0
  }
  // Independent count: jumps of T1 on a dense grid (continuous variation per cell is far below 0.5).
  const int n = 200000;
  int jumps = 0;
  double prev = next_hit(p, lo).theta1;
  for (int i = 1; i <= n; ++i) {
    const double t1 = next_hit(p, lo + (hi - lo) * i / n).theta1;
    if (t1 - prev < -0.5) ++jumps;
    prev = t1;
  }
  EXPECT_EQ(jumps, static_cast<int>(z.size()));
}

INSTANTIATE_TEST_SUITE_P(SeveralBOverA, GrazingPoints, ::testing::Values(0.2, 0.1, 0.05, 0.02));

TEST(NextHit, DiscontinuitiesAreTheSymmetricTangenciesInClosedForm) {
  // Independent cross-check of grazing_points: on [t2, 3pi/2] every discontinuity found by the
  // label scan, bisection and Newton solves 2z - (a/b) cos z = (2k+1) pi, and vice versa.
  for (double ba : {0.05, 0.01, 0.003}) {
    const Parameters p(1.0, ba, 0.85);
    const double lo = *p.t2() + 1e-9, hi = 1.5 * M_PI;
    const auto z = grazing_points(p, lo, hi, 500);
    const auto c = symmetric_tangencies(p, lo, hi);
    ASSERT_EQ(z.size(), c.size()) << "b/a=" << ba;
    for (std::size_t k = 0; k < z.size(); ++k) {
      EXPECT_NEAR(z[k].z, c[k].z, 1e-12);
      EXPECT_NEAR(z[k].t1_right - z[k].z, c[k].flight, 1e-9 * c[k].flight);
    }
  }
}
