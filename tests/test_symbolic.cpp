// Sections 6-8: periodic orbits re-checked by numerical integration; every short word realised;
// the superstable windows against a plain grid and the width epsilon against a direct scan.
#include <gtest/gtest.h>

#include <cmath>

#include "dfchaos/ode_map.hpp"
#include "dfchaos/superstable.hpp"
#include "dfchaos/symbolic.hpp"

using namespace dfchaos;

class Symbolic : public ::testing::Test {
 protected:
  void SetUp() override {
    const Lemma4Covering c = lemma4_covering(p);
    ASSERT_TRUE(c.holds);
    g[0] = make_inverse_branch(p, c.J0);
    g[1] = make_inverse_branch(p, c.J1);
  }
  Parameters p{1.0, 0.01, 0.95};
  InverseBranch g[2];
};

TEST_F(Symbolic, PeriodicOrbitsAreOrbitsOfTheIntegratedMap) {
  for (const std::string w : {"1", "01", "001", "0001", "00001"}) {
    const ItineraryOrbit o = periodic_orbit(p, g, w);
    ASSERT_TRUE(o.itinerary_ok) << w;
    for (std::size_t j = 0; j < o.x.size(); ++j) {
      // Independent one-step check: GSL odeiv2 integration of the equations of motion.
      EXPECT_LE(circle_distance(ode_return_map_step(p, o.x[j]).T, o.x[(j + 1) % o.x.size()]), 1e-7) << w << " j=" << j;
    }
  }
}

TEST_F(Symbolic, PeriodicPointsOfDifferentWordsAreDistinctAndOrdered) {
  // Period-1 points of K0 and K1, and the period-2 orbit, are different points.
  const ItineraryOrbit a = periodic_orbit(p, g, "0"), b = periodic_orbit(p, g, "1"), c = periodic_orbit(p, g, "01");
  EXPECT_GT(std::fabs(a.x[0] - b.x[0]), 1e-3);
  EXPECT_GT(std::fabs(c.x[0] - a.x[0]), 1e-6);
  EXPECT_GT(std::fabs(c.x[1] - b.x[0]), 1e-6);
}

TEST_F(Symbolic, AllWordsOfLengthEightAreRealised) {
  int n = 0, ok = 0;
  for_each_word(p, g, 8, [&](const ItineraryOrbit& o) {
    ++n;
    if (o.itinerary_ok && o.max_step_residual < 1e-10) ++ok;
  });
  EXPECT_EQ(n, 256);
  EXPECT_EQ(ok, 256);
}

TEST(Superstable, WindowsAgreeWithAPlainGridAndEpsilonWithAScan) {
  const double q = 0.85;
  const auto w = superstable_windows(1.0, q, 1e-3, 0.02, 2000);
  ASSERT_FALSE(w.empty());
  for (int j = 0; j < 3000; ++j) {
    const double b = 1.0 / (50.0 + 950.0 * j / 2999.0);
    const SuperstableCheck c = superstable_check(Parameters(1.0, b, q), 2);
    const int cond = c.eq21 ? 21 : (c.eq22 ? 22 : 0);
    bool inside = false;
    for (const auto& x : w)
      if (b >= x.b_lo && b <= x.b_hi) inside = (x.condition == cond);
    EXPECT_EQ(cond != 0, inside) << "b=" << b;
  }
  // epsilon: T = t2 on [t2, t2 + 0.99 eps] and not at t2 + 1.01 eps, by direct evaluation.
  const double mid = 0.5 * (w[0].b_lo + w[0].b_hi);
  const Parameters p(1.0, mid, q);
  const SuperstableCheck c = superstable_check(p);
  ASSERT_GT(c.epsilon, 0);
  for (int i = 0; i <= 100; ++i) EXPECT_EQ(T(p, *p.t2() + 0.99 * c.epsilon * i / 100), *p.t2());
  EXPECT_NE(T(p, *p.t2() + 1.01 * c.epsilon), *p.t2());
}
