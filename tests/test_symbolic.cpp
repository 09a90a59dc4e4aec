// SPDX-License-Identifier: GPL-3.0-or-later
// Sections 6-8: periodic orbits re-checked by numerical integration; every short word realised;
// the superstable windows against a plain grid and the width epsilon against a direct scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

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
  // The periodic point with itinerary sigma = (w)^infinity lies in K_{sigma_0}; K0 lies left of K1.
  // Between two itineraries that first differ at index n, the order of the points is the order of
  // K_{sigma_n} and K_{tau_n}, reversed once for every decreasing branch among the common prefix
  // sigma_0 .. sigma_{n-1} (each inverse branch preserves or reverses order). Checked for all words
  // of length <= 4: a prediction from symbols alone against the computed points.
  const bool increasing[2] = {g[0].k_at_t2 < g[0].k_at_top, g[1].k_at_t2 < g[1].k_at_top};
  ASSERT_LT(std::max(g[0].k_at_t2, g[0].k_at_top), std::min(g[1].k_at_t2, g[1].k_at_top));  // K0 left of K1
  constexpr int kHorizon = 24;  // symbols compared: more than any two distinct periods <= 4 need
  auto sequence = [](const std::string& w) {
    std::string s;
    while (s.size() < kHorizon) s += w;
    return s.substr(0, kHorizon);
  };
  std::vector<std::pair<std::string, double>> points;  // (infinite itinerary, point)
  for (int n = 1; n <= 4; ++n)
    for (int bits = 0; bits < (1 << n); ++bits) {
      std::string w;
      for (int k = n - 1; k >= 0; --k) w += ((bits >> k) & 1) ? '1' : '0';
      const std::string sigma = sequence(w);
      bool seen = false;
      for (const auto& pt : points) seen = seen || pt.first == sigma;
      if (seen) continue;  // (01)^inf and (0101)^inf are the same point
      const ItineraryOrbit o = periodic_orbit(p, g, w);
      ASSERT_TRUE(o.itinerary_ok) << w;
      points.emplace_back(sigma, o.x[0]);
    }
  ASSERT_EQ(points.size(), 22u);  // the distinct periodic sequences of least period 1, 2, 3, 4: 2 + 2 + 6 + 12
  auto predicted_less = [&](const std::string& s, const std::string& t) {
    bool flip = false;
    for (std::size_t k = 0; k < s.size(); ++k) {
      if (s[k] != t[k]) return (s[k] < t[k]) != flip;
      if (!increasing[s[k] - '0']) flip = !flip;
    }
    ADD_FAILURE() << "equal itineraries " << s;
    return false;
  };
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (i == j) continue;
      EXPECT_NE(points[i].second, points[j].second) << points[i].first << " " << points[j].first;
      EXPECT_EQ(points[i].second < points[j].second, predicted_less(points[i].first, points[j].first))
          << points[i].first << " at " << points[i].second << ", " << points[j].first << " at " << points[j].second;
    }
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
