// SPDX-License-Identifier: GPL-3.0-or-later
// Section 10: the perturbation G, the stop-release phase t2^eps, the integrated perturbed map and
// the persistence search of the covering (perturbed.hpp). Cross-checks: G's bounds by finite
// differences; t2^eps against the closed form at eps = 0 and a dense scan of the force otherwise;
// T_eps at eps = 0 against the exact T; the phases u, w the search returns re-evaluated by an
// integration with a perturbation written out here; the continuity check against a jump of the
// exact T located independently. Failure tier: a perturbation too large for the stop release.
#include <gtest/gtest.h>

#include <cmath>

#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/perturbed.hpp"
#include "dfchaos/return_map.hpp"

using namespace dfchaos;

namespace {

constexpr double kAtZeroTol = 1e-8;              // integrated map at eps = 0 against the exact T
constexpr double kReleaseClosedFormTol = 4e-15;  // t2^0 against pi + asin(2b/a)
constexpr double kReleaseResidualTol = 1e-14;    // the force at t2^eps
constexpr double kScanStep = 1e-5;               // dense scan of the force for its first zero
constexpr double kDerivativeStep = 1e-6;         // finite differences of G

const double kTop = 1.5 * M_PI;

/// G written out again, independently of the library.
double G_here(double eps, double t, double v) { return eps * (std::cos(2 * t + 1) + v / (1 + v * v)); }

TEST(PerturbationG, BoundsAndIndependenceOfX) {
  for (double eps : {1e-3, 0.1}) {
    double max_G = 0, max_dt = 0, max_dv = 0;
    for (int i = 0; i <= 200; ++i)
      for (int j = 0; j <= 200; ++j) {
        const double t = 2 * M_PI * i / 200, v = -20.0 + 40.0 * j / 200;
        const double g = perturbation_G(eps, t, 0.0, v);
        EXPECT_DOUBLE_EQ(g, G_here(eps, t, v));
        EXPECT_EQ(g, perturbation_G(eps, t, 123.4, v));  // no dependence on x
        max_G = std::max(max_G, std::fabs(g));
        const double h = kDerivativeStep;
        max_dt = std::max(max_dt, std::fabs(perturbation_G(eps, t + h, 0, v) - perturbation_G(eps, t - h, 0, v)) / (2 * h));
        max_dv = std::max(max_dv, std::fabs(perturbation_G(eps, t, 0, v + h) - perturbation_G(eps, t, 0, v - h)) / (2 * h));
      }
    EXPECT_LE(max_G, 1.5 * eps);
    EXPECT_GT(max_G, 1.4 * eps);  // the bound is nearly reached (not a vanishing G)
    EXPECT_LE(max_dt, 2 * eps * (1 + 1e-6));
    EXPECT_LE(max_dv, eps * (1 + 1e-6));
  }
  EXPECT_EQ(perturbation_G(0.0, 1.0, 2.0, 3.0), 0.0);
}

TEST(StopRelease, IsT2AtZeroPerturbation) {
  for (double b : {0.05, 0.01, 1e-3}) {
    const Parameters p(1.0, b, 0.9);
    EXPECT_NEAR(perturbed_stop_release(p, 0.0), M_PI + std::asin(2 * b), kReleaseClosedFormTol) << "b=" << b;
  }
}

TEST(StopRelease, IsTheFirstZeroOfThePerturbedForceAfterPi) {
  const Parameters p(1.0, 0.01, 0.95);
  for (double eps : {1e-4, 1e-2, 0.1, 0.5}) {
    const double r = perturbed_stop_release(p, eps);
    auto force = [&](double t) { return std::sin(t) + 2 * 0.01 + G_here(eps, t, 0.0); };
    EXPECT_LE(std::fabs(force(r)), kReleaseResidualTol) << "eps=" << eps;
    // Independent: a dense scan from pi - 1/2 for the first sign change of the force.
    double t = M_PI - 0.5;
    while (force(t + kScanStep) > 0) t += kScanStep;
    EXPECT_GE(r, t) << "eps=" << eps;
    EXPECT_LE(r, t + kScanStep) << "eps=" << eps;
  }
  // It moves with the perturbation (the perturbation is not ignored).
  EXPECT_GT(std::fabs(perturbed_stop_release(p, 1e-2) - *p.t2()), 1e-4);
}

TEST(StopRelease, RejectsAPerturbationThatKeepsTheForceNegative) {
  const Parameters p(1.0, 0.01, 0.95);
  try {
    perturbed_stop_release(p, -1.0);  // the force is already negative at pi - 1/2
    FAIL() << "no exception";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.parameter(), "eps");
  }
}

TEST(PerturbedT, AgreesWithTheExactMapAtZeroAndMovesOtherwise) {
  const Parameters p(1.0, 0.01, 0.95);
  const double t2 = *p.t2(), t3 = *p.t3();
  for (int i = 0; i < 10; ++i) {
    const double th = t2 + (t3 - t2) * (i + 0.41) / 10;
    EXPECT_LT(circle_distance(perturbed_T(p, 0.0, th), T(p, th)), kAtZeroTol) << "theta=" << th;
  }
  const double th = t2 + 0.4 * (t3 - t2);
  EXPECT_GT(circle_distance(perturbed_T(p, 1e-3, th), T(p, th)), 1e-6);
  EXPECT_THROW(perturbed_T(p, 0.0, t3 + 0.1), InvalidParameter);
}

/// A phase where the exact T jumps by more than 0.1, located by bisection of T on a dense scan of
/// [lo, hi] (NaN if none).
double jump_of_T(const Parameters& p, double lo, double hi) {
  const int n = 4000;
  double prev = T(p, lo);
  for (int i = 1; i <= n; ++i) {
    const double x = lo + (hi - lo) * i / n, Tx = T(p, x);
    if (std::fabs(Tx - prev) > 0.1) {
      double a = lo + (hi - lo) * (i - 1) / n, b = x, Ta = prev, Tb = Tx;
      for (int k = 0; k < 60 && b - a > 1e-14; ++k) {
        const double m = 0.5 * (a + b), Tm = T(p, m);
        if (std::fabs(Tm - Ta) >= std::fabs(Tb - Tm)) {
          b = m;
          Tb = Tm;
        } else {
          a = m;
          Ta = Tm;
        }
      }
      if (std::fabs(Tb - Ta) > 0.1) return 0.5 * (a + b);
    }
    prev = Tx;
  }
  return NAN;
}

class PerturbedCoveringTest : public ::testing::Test {
 protected:
  void SetUp() override {
    c = lemma4_covering(p);
    ASSERT_TRUE(c.holds);
    search.grid = 40;
  }
  Parameters p{1.0, 0.01, 0.95};
  Lemma4Covering c;
  PerturbedCoveringSearch search;
};

TEST_F(PerturbedCoveringTest, ContinuityCheckSeesAJumpAndNotOnACoveringSegment) {
  EXPECT_TRUE(perturbed_continuous_between(p, 0.0, c.J0.lo, c.J0.hi, search));
  const double z = jump_of_T(p, c.J0.hi, kTop);
  ASSERT_TRUE(std::isfinite(z));
  std::vector<PerturbedSample> graph;
  EXPECT_FALSE(perturbed_continuous_between(p, 0.0, z - 1e-3, z + 1e-3, search, &graph, 1));
  ASSERT_FALSE(graph.empty());
  EXPECT_EQ(graph.front().segment, 1);
  EXPECT_GT(graph.front().theta, z - 1e-3);  // the grid values after x0
}

TEST_F(PerturbedCoveringTest, PersistsAtZeroWithTheEndValuesOfTheExactMap) {
  std::vector<PerturbedSample> graph;
  const PerturbedCovering r = perturbed_covering(p, c, 0.0, search, &graph);
  EXPECT_NEAR(r.t2_eps, *p.t2(), kReleaseClosedFormTol);
  ASSERT_TRUE(r.both());
  const CoveringSegment* J[2] = {&c.J0, &c.J1};
  for (int i = 0; i < 2; ++i) {
    // Independent: the exact map at the phases found.
    EXPECT_NEAR(T(p, r.u[i]), *p.t2(), kAtZeroTol) << i;
    EXPECT_GE(T(p, r.w[i]), kTop - kAtZeroTol) << i;
    const double reach = search.margin * (J[i]->hi - J[i]->lo);
    EXPECT_LE(std::fabs(r.u[i] - J[i]->theta_at_t2), reach * (1 + 1e-12)) << i;
    EXPECT_LE(std::fabs(r.w[i] - J[i]->theta_at_top), reach * (1 + 1e-12)) << i;
  }
  EXPECT_EQ(graph.size(), 2u * static_cast<std::size_t>(search.grid - 1));
}

TEST_F(PerturbedCoveringTest, PersistsForASmallPerturbationCheckedByAnIndependentIntegration) {
  const double eps = 1e-3;
  const PerturbedCovering r = perturbed_covering(p, c, eps, search);
  ASSERT_TRUE(r.both());
  OdeMapOptions o;
  o.perturbation = [eps](double t, double, double v) { return G_here(eps, t, v); };
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(ode_return_map_step(p, r.u[i], o).T, r.t2_eps, 1e-9) << i;
    EXPECT_GE(ode_return_map_step(p, r.w[i], o).T, kTop) << i;
  }
  // The perturbation moved the stop arc: u is not the unperturbed one.
  const PerturbedCovering r0 = perturbed_covering(p, c, 0.0, search);
  EXPECT_NE(r.u[0], r0.u[0]);
}

// Regression: at eps = 0.01 the stop arc next to J0 has grown over J0's end, and the
// search returned that end itself as u (the unperturbed value to the last digit) instead of the
// arc's edge. u must now be the edge on the side of w: on the arc at u, off it 1e-5 beyond.
TEST_F(PerturbedCoveringTest, RegressionUIsTheEdgeOfTheStopArcNotTheEndOfJ) {
  const double eps = 1e-2;
  const PerturbedCovering r = perturbed_covering(p, c, eps, search);
  OdeMapOptions o;
  o.perturbation = [eps](double t, double, double v) { return G_here(eps, t, v); };
  const CoveringSegment* J[2] = {&c.J0, &c.J1};
  for (int i = 0; i < 2; ++i) {
    if (!(std::isfinite(r.u[i]) && std::isfinite(r.w[i]))) continue;
    const double towards_w = r.w[i] > r.u[i] ? 1.0 : -1.0;
    EXPECT_NEAR(ode_return_map_step(p, r.u[i], o).T, r.t2_eps, 1e-9) << i;
    EXPECT_GT(std::fabs(ode_return_map_step(p, r.u[i] + towards_w * 1e-5, o).T - r.t2_eps), 1e-9) << i;
    EXPECT_NE(r.u[i], J[i]->theta_at_t2) << i;
  }
  ASSERT_TRUE(std::isfinite(r.u[0]));
}

}  // namespace
