// SPDX-License-Identifier: GPL-3.0-or-later
// Section 7: the lap-count entropy estimate (entropy.hpp). Unit tests of the run count, and
// cross-checks of lap_counts against maps whose lap numbers are known in closed form: the tent map
// (2^n laps), the Chebyshev map x -> 4x^3 - 3x (3^n laps), a map with a flat arc (one lap). Then
// the return map T where Lemma 4's covering holds (the estimate is at least ln 2, as Section 7's
// semi-conjugacy with the full shift implies). Failure tier: bad grids and parameters rejected.
#include <gtest/gtest.h>

#include <cmath>

#include "dfchaos/covering.hpp"
#include "dfchaos/entropy.hpp"
#include "dfchaos/errors.hpp"

using namespace dfchaos;

namespace {

constexpr double kEstimateTol = 1e-12;  // (1/n) ln(laps) against the exact (1/n) ln(k^n)

TEST(MonotoneRuns, KnownSequences) {
  EXPECT_EQ(monotone_runs({}), 1);
  EXPECT_EQ(monotone_runs({2.0}), 1);
  EXPECT_EQ(monotone_runs({1, 2, 3, 4}), 1);
  EXPECT_EQ(monotone_runs({4, 3, 2, 1}), 1);
  EXPECT_EQ(monotone_runs({1, 2, 1}), 2);
  EXPECT_EQ(monotone_runs({1, 2, 1, 2, 1, 2}), 5);
  EXPECT_EQ(monotone_runs({1, 1, 1}), 1);
}

TEST(MonotoneRuns, EqualNeighboursDoNotSplitARun) {
  // Plateaus (T's arcs where T = t2) inside a monotone stretch, and between a rise and a fall.
  EXPECT_EQ(monotone_runs({1, 2, 2, 2, 3}), 1);
  EXPECT_EQ(monotone_runs({0, 0, 1, 1, 0, 0}), 2);
  EXPECT_EQ(monotone_runs({3, 2, 2, 1, 2}), 2);
}

TEST(LapCounts, TentMapHasTwoToTheNLaps) {
  const auto tent = [](double x) { return 1 - std::fabs(2 * x - 1); };
  const auto laps = lap_counts(tent, 0.0, 1.0, 100000, 6);
  ASSERT_EQ(laps.size(), 6u);
  for (const LapCount& l : laps) {
    EXPECT_EQ(l.laps, 1LL << l.n) << "n=" << l.n;
    EXPECT_NEAR(l.entropy_estimate, std::log(2.0), kEstimateTol) << "n=" << l.n;
  }
}

TEST(LapCounts, ChebyshevMapHasThreeToTheNLaps) {
  // 4x^3 - 3x = cos(3 arccos x): its n-th iterate is cos(3^n arccos x), with 3^n laps on [-1, 1].
  const auto cheb = [](double x) { return 4 * x * x * x - 3 * x; };
  const auto laps = lap_counts(cheb, -1.0, 1.0, 200000, 4);
  long long expected = 1;
  for (const LapCount& l : laps) {
    expected *= 3;
    EXPECT_EQ(l.laps, expected) << "n=" << l.n;
    EXPECT_NEAR(l.entropy_estimate, std::log(3.0), kEstimateTol) << "n=" << l.n;
  }
}

TEST(LapCounts, FlatArcKeepsOneLapAndZeroEntropy) {
  // Non-decreasing with a flat arc, like T on a stop arc: one lap, estimate 0.
  const auto f = [](double x) { return std::min(2 * x, 1.0); };
  for (const LapCount& l : lap_counts(f, 0.0, 1.0, 1000, 3)) {
    EXPECT_EQ(l.laps, 1) << "n=" << l.n;
    EXPECT_EQ(l.entropy_estimate, 0.0);
  }
}

TEST(LapCounts, GridIsTheCellCentres) {
  // The identity has one lap; the grid seen through a recording map is lo + (hi - lo)(i + 1/2)/N.
  std::vector<double> seen;
  lap_counts(
      [&](double x) {
        seen.push_back(x);
        return x;
      },
      2.0, 3.0, 4, 1);
  ASSERT_EQ(seen.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(seen[static_cast<std::size_t>(i)], 2.0 + (3.0 - 2.0) * (i + 0.5) / 4);
}

TEST(LapCounts, ReturnMapWithACoveringHasEntropyEstimateAtLeastLn2) {
  // Where Lemma 4's two covering segments exist, T^n has at least 2^n laps (each J_i covers both).
  const Parameters p(1.0, 0.01, 0.95);
  ASSERT_TRUE(lemma4_covering(p).holds);
  const auto laps = lap_counts(p, 20000, 2);
  ASSERT_EQ(laps.size(), 2u);
  for (const LapCount& l : laps) {
    EXPECT_GE(l.laps, 1LL << l.n) << "n=" << l.n;
    EXPECT_GE(l.entropy_estimate, std::log(2.0)) << "n=" << l.n;
  }
  // The overload on Parameters is the generic count applied to T on [t2, t3).
  const auto generic = lap_counts([&](double x) { return T(p, x); }, *p.t2(), *p.t3(), 20000, 2);
  for (std::size_t k = 0; k < laps.size(); ++k) EXPECT_EQ(laps[k].laps, generic[k].laps);
}

TEST(LapCounts, RejectsBadInput) {
  const auto id = [](double x) { return x; };
  EXPECT_THROW(lap_counts(id, 0.0, 1.0, 1, 1), InvalidParameter);
  EXPECT_THROW(lap_counts(id, 0.0, 1.0, 10, 0), InvalidParameter);
  EXPECT_THROW(lap_counts(id, 1.0, 1.0, 10, 1), InvalidParameter);
  EXPECT_THROW(lap_counts(Parameters(1.0, 0.6, 0.95), 100, 1), InvalidParameter);  // b >= a/2: no return map
}

}  // namespace
