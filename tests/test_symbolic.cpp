// SPDX-License-Identifier: GPL-3.0-or-later
// Sections 6-8: periodic orbits re-checked by numerical integration; every short word realised;
// the superstable windows against a plain grid and the width epsilon against a direct scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "dfchaos/continuation.hpp"
#include "dfchaos/errors.hpp"
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

TEST(Superstable, JoinWindowsJoinsExactlyTheWindowsThatShareAnEnd) {
  EXPECT_TRUE(join_windows({}).empty());
  const std::vector<SuperstableWindow> w = {{0.1, 0.2, 21}, {0.2, 0.25, 22}, {0.3, 0.4, 22}, {0.4, 0.5, 21}, {0.6, 0.7, 21}};
  const auto j = join_windows(w);
  ASSERT_EQ(j.size(), 3U);
  EXPECT_EQ(j[0].b_lo, 0.1);
  EXPECT_EQ(j[0].b_hi, 0.25);
  EXPECT_TRUE(j[0].has21 && j[0].has22);
  EXPECT_EQ(j[0].first, 0U);
  EXPECT_EQ(j[0].last, 2U);
  EXPECT_EQ(j[1].b_lo, 0.3);
  EXPECT_EQ(j[1].b_hi, 0.5);
  EXPECT_EQ(j[1].first, 2U);
  EXPECT_EQ(j[1].last, 4U);
  EXPECT_EQ(j[2].b_lo, 0.6);
  EXPECT_TRUE(j[2].has21 && !j[2].has22);
  // A gap of one ulp is a gap: only equal ends join.
  EXPECT_EQ(join_windows({{0.1, 0.2, 21}, {std::nextafter(0.2, 1.0), 0.3, 22}}).size(), 2U);
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

// ---- continuation.hpp: a periodic orbit followed in b --------------------------------------------

TEST(Continuation, FollowedOrbitIsTheInverseBranchOrbitNearTheStart) {
  // Newton's continuation and the inverse-branch solver of symbolic.hpp are independent routes to the
  // orbit of itinerary w^infinity. The solver takes Lemma 4's J0, J1 as found at each b, which may
  // jump to other segments farther away; within 1% of the start they are the same here, and so must
  // the orbits be.
  const double q = 0.85, b0 = 3e-3;
  for (const std::string word : {"01", "001", "0111"}) {
    const ItineraryOrbit start = periodic_orbit(Parameters(1.0, b0, q), word);
    ContinuationSettings s;
    s.step = 1e-3;
    const OrbitBranch br = follow_periodic_orbit(1.0, q, b0, start.x, 3.03e-3, s);
    EXPECT_EQ(br.end, BranchEnd::RangeEnd) << word << ": " << br.detail;
    ASSERT_GE(br.points.size(), 5U) << word;
    EXPECT_EQ(br.points.back().b, 3.03e-3);
    for (std::size_t k = 0; k < br.points.size(); ++k) {
      const BranchPoint& pt = br.points[k];
      const ItineraryOrbit ref = periodic_orbit(Parameters(1.0, pt.b, q), word);
      for (std::size_t j = 0; j < word.size(); ++j) EXPECT_NEAR(pt.x[j], ref.x[j], 1e-11) << word << " b=" << pt.b << " j=" << j;
      EXPECT_NEAR(pt.log_multiplier, ref.log_expansion, 1e-6 * std::fabs(ref.log_expansion)) << word;
      EXPECT_LE(pt.residual, 1e-10);
    }
  }
}

TEST(Continuation, EndsWhereItsEndIsLocatedToMinStep) {
  const double q = 0.85, b0 = 3e-3;
  const ItineraryOrbit start = periodic_orbit(Parameters(1.0, b0, q), "01");
  // Up in b the orbit's x_0 nears t2, where T' tends to 0: the multiplier falls to 1, a fold.
  for (double b_end : {0.2}) {
    const OrbitBranch br = follow_periodic_orbit(1.0, q, b0, start.x, b_end);
    ASSERT_EQ(br.end, BranchEnd::Fold) << branch_end_name(br.end) << ": " << br.detail;
    EXPECT_LT(std::fabs(br.points.back().log_multiplier), kFoldLogMultiplier);
    EXPECT_LT(br.points.back().x[0] - *Parameters(1.0, br.points.back().b, q).t2(), 1e-3);
    const double last = br.points.back().b;
    EXPECT_LE(std::fabs(br.b_lost - last), 1e-12 * last * (1 + 1e-12));
    EXPECT_NE(br.b_lost, last);
    // b is monotone towards b_end
    for (std::size_t k = 1; k < br.points.size(); ++k) EXPECT_EQ(br.points[k].b > br.points[k - 1].b, b_end > b0);
  }
}

TEST(Continuation, RefusesANonCycleAndBadSettings) {
  const Parameters p(1.0, 3e-3, 0.85);
  const ItineraryOrbit start = periodic_orbit(p, "01");
  std::vector<double> outside = {*p.t3() + 0.1};
  EXPECT_THROW(follow_periodic_orbit(1.0, 0.85, 3e-3, outside, 4e-3), InvalidParameter);
  EXPECT_THROW(follow_periodic_orbit(1.0, 0.85, 3e-3, {}, 4e-3), InvalidParameter);
  ContinuationSettings s;
  s.step = 0;
  EXPECT_THROW(follow_periodic_orbit(1.0, 0.85, 3e-3, start.x, 4e-3, s), InvalidParameter);
  s = {};
  s.min_step = 1e-2;  // above step
  EXPECT_THROW(follow_periodic_orbit(1.0, 0.85, 3e-3, start.x, 4e-3, s), InvalidParameter);
  s = {};
  s.max_steps = 3;
  const OrbitBranch br = follow_periodic_orbit(1.0, 0.85, 3e-3, start.x, 4e-3, s);
  EXPECT_EQ(br.end, BranchEnd::StepBudget);
  EXPECT_EQ(br.points.size(), 4U);
}
