// SPDX-License-Identifier: GPL-3.0-or-later
// Cross-validation: the certain first-root isolation (roots.hpp) against a dense brute-force scan.
// An independent, plain-double evaluation of G1 (Eq. 11) on a fine grid, with every local maximum
// located by bisection on dG1/dt, must show no contact before the computed T1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "dfchaos/motion.hpp"
#include "dfchaos/next_hit.hpp"
#include "dfchaos/roots.hpp"
#include "test_support.hpp"

using namespace dfchaos;

namespace {
constexpr int kDraws = 10000;
constexpr double kGridStep = 0.02;  // brute-force grid (the forcing period is 2 pi)
constexpr double kMargin = 1e-6;    // points this close before T1 are not checked
constexpr double kSignTol = 1e-9;   // G1 > kSignTol * scale before T1 would be a missed contact
constexpr long kMaxPieces = 64;     // root-search work must not grow as b/a shrinks

struct PlainG1 {  // Eq. (11), written out independently of the library, in s = t - theta
  double a, b, th;
  double g(double s) const { return b * s * s - a * std::sin(th + s) + a * std::cos(th) * s + a * std::sin(th); }
  double dg(double s) const { return 2 * b * s - a * std::cos(th + s) + a * std::cos(th); }
};

/// Maximum of G1 on [s0, s1] where dG1/dt goes from + to -, by bisection on dG1/dt.
double local_max(const PlainG1& f, double s0, double s1, double& where) {
  for (int i = 0; i < 60; ++i) {
    const double m = 0.5 * (s0 + s1);
    if (f.dg(m) > 0)
      s0 = m;
    else
      s1 = m;
  }
  where = 0.5 * (s0 + s1);
  return f.g(where);
}
}  // namespace

TEST(FirstRoot, NoEarlierContactThanT1OnRandomDraws) {
  test_support::Drawer draws(1e-4, 0.2, 0.5, 1.0);
  long worst_pieces = 0;
  int maxima_checked = 0;
  for (int n = 0; n < kDraws; ++n) {
    const auto d = draws.next();
    const Parameters p(1.0, d.b, d.q);
    const NextHit h = next_hit(p, d.theta);
    const double s1 = h.theta1 - d.theta;
    const PlainG1 f{1.0, d.b, d.theta};
    const double scale = 1.0 + d.b * s1 * s1;  // size of the cancelling terms of G1 at T1
    ASSERT_GT(s1, 0) << "theta=" << d.theta << " b=" << d.b;
    ASSERT_NEAR(f.g(s1), 0.0, 1e3 * kSignTol * scale) << "T1 is not a root: theta=" << d.theta << " b=" << d.b;
    ASSERT_GE(f.dg(s1), -1e3 * kSignTol * scale);
    worst_pieces = std::max(worst_pieces, h.pieces);

    long long maxima = 0;
    bool max_near_root = false;
    double prev_d = f.dg(kGridStep * 1e-3);
    for (double s = kGridStep; s < s1 - kMargin; s += kGridStep) {
      const double gs = f.g(s), ds = f.dg(s);
      ASSERT_LE(gs, kSignTol * scale) << "missed contact at s=" << s << " before T1: theta=" << d.theta << " b=" << d.b;
      if (prev_d > 0 && ds <= 0) {
        double where = 0;
        const double gm = local_max(f, s - kGridStep, s, where);
        if (where < s1 - kMargin) {
          ASSERT_LE(gm, kSignTol * scale) << "missed contact at a local maximum s=" << where << ": theta=" << d.theta;
          ++maxima;
          ++maxima_checked;
        } else {
          max_near_root = true;
        }
      }
      prev_d = ds;
    }
    if (!max_near_root) {
      ASSERT_EQ(h.maxima_before, maxima) << "closed-form count of maxima disagrees: theta=" << d.theta << " b=" << d.b;
    }
  }
  EXPECT_GT(maxima_checked, kDraws);  // the draws do exercise flights with many humps
  EXPECT_LE(worst_pieces, kMaxPieces);
}

TEST(FirstRoot, ProgressionEndHasNoEarlierVelocityZero) {
  test_support::Drawer draws(1e-4, 0.2, 0.5, 1.0, test_support::kSeed + 7);
  for (int n = 0; n < 2000; ++n) {
    const auto d = draws.next();
    const Parameters p(1.0, d.b, d.q);
    if (!(d.q > 2 * d.b)) continue;
    const double v0 = 3 * draws.uniform();
    const ProgressionMotion m(p, Instant::at_phase(d.theta), 0.0, v0);
    const auto root = first_upcrossing(m.minus_velocity());
    ASSERT_TRUE(root.has_value());
    const double s1 = static_cast<double>(root->s);
    EXPECT_NEAR(m.velocity(root->t), 0.0, 1e-12);
    for (double s = 1e-3; s < s1 - kMargin; s += kGridStep / 4)
      ASSERT_GT(v0 + 2 * p.c() * s - (std::cos(d.theta + s) - std::cos(d.theta)), -kSignTol);
  }
}

TEST(FirstRoot, WorkIsIndependentOfSmallBOverA) {
  // Flights last ~ (a/b)|cos theta|, from 10 to 10^6 time units here; the pieces examined must not grow.
  for (double ba : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    const Parameters p(1.0, ba, 0.85);
    long worst = 0;
    for (int i = 0; i < 200; ++i) {
      const double th = *p.t2() + (*p.t3() - *p.t2()) * (i + 0.5) / 200;
      worst = std::max(worst, next_hit(p, th).pieces);
    }
    EXPECT_LE(worst, kMaxPieces) << "b/a=" << ba;
  }
}

TEST(FirstRoot, RegressionStartAtRestExactlyAtT2IsNotARoot) {
  // Bug fixed: at theta = t2 the inflection phase computed from f'' differed from t2 by an ulp, and
  // the sliver piece between them was taken for an immediate contact (T1 = t2).
  for (double ba : {1e-3, 1e-2, 0.1, 0.3}) {
    const Parameters p(1.0, ba, 0.9);
    const NextHit h = next_hit(p, *p.t2());
    EXPECT_GT(h.theta1 - *p.t2(), 1.0) << "b/a=" << ba;
  }
}

TEST(FirstRoot, RegressionGrazingContactJustAfterTheSkipWindowIsFound) {
  // Bug caught before it landed: a flight from rest in Case A of the start at rest falls on the
  // piece next to the origin, which the scan may skip unevaluated. Here (theta just below 3 pi/2,
  // b/a = 1e-10) the envelope's skip window jumped the cursor first, and the piece after the window
  // was skipped as if it were the falling one: the grazing contact one period later (relative
  // distance 1e-11 from a tangency) was missed, and T1 came out a period late. The reference
  // value is that of tests/precision_reference.py (40 digits, written from Eq. (11) alone):
  // T1 = 10.99554995361687790982548.
  const Parameters p(1.0, 1e-10, 0.85);
  const NextHit h = next_hit(p, 4.712388979803495);
  EXPECT_NEAR(h.theta1, 10.99554995361687790982548, 1e-9);
}

TEST(SolveIncreasing, HalleyWithAStartAndAJerkBoundKeepsTheRootAndSavesEvaluations) {
  // g = x - c + 0.3 sin x on [0, 4]: g' = 1 + 0.3 cos x > 0, g'' = -0.3 sin x, |g'''| <= 0.3.
  // A start near the root, and the jerk bound (which lets the solver return a corrected iterate
  // without evaluating g there), each save evaluations; the root stays within the stated
  // tolerance of a long-double bisection to the last bit; a start outside the bracket changes
  // nothing.
  long plain_total = 0, start_total = 0, jerk_total = 0, both_total = 0;
  for (int k = 0; k < 400; ++k) {
    const double c = 0.5 + 3.0 * k / 400;
    int evaluations = 0;
    auto gd = [&](double x) {
      ++evaluations;
      const long double xl = x;
      return std::tuple<long double, long double, long double>{xl - c + 0.3L * std::sin(xl), 1.0L + 0.3L * std::cos(xl), -0.3L * std::sin(xl)};
    };
    const double lo = 0, hi = 4;
    const long double g_lo = std::get<0>(gd(lo)), g_hi = std::get<0>(gd(hi));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto solve = [&](double start, double jerk, long& total) {
      evaluations = 0;
      const double root = solve_increasing(gd, lo, hi, 0.0, g_lo, g_hi, start, jerk);
      total += evaluations;
      return root;
    };
    const double plain = solve(nan, nan, plain_total);
    const int plain_evaluations = evaluations;
    long outside_total = 0;
    EXPECT_EQ(solve(-1.0, nan, outside_total), plain) << "c=" << c;
    EXPECT_EQ(outside_total, plain_evaluations);
    const double with_start = solve(c + 0.01, nan, start_total);
    const double with_jerk = solve(nan, 0.3, jerk_total);
    const double fast = solve(c + 0.01, 0.3, both_total);
    long double a = lo, b = hi;
    for (int it = 0; it < 200 && b - a > 0; ++it) {
      const long double m = 0.5L * (a + b);
      if (m <= a || m >= b) break;
      if (m - c + 0.3L * std::sin(m) < 0)
        a = m;
      else
        b = m;
    }
    const double tol = 4 * DBL_EPSILON * (hi + 1);  // the solver's stated tolerance
    for (double root : {plain, with_start, with_jerk, fast}) EXPECT_LE(std::fabs(root - static_cast<double>(b)), tol) << "c=" << c;
  }
  EXPECT_LT(start_total, plain_total);
  EXPECT_LT(jerk_total, plain_total);
  EXPECT_LT(both_total, std::min(start_total, jerk_total));
}

TEST(SolveIncreasing, TheJerkBoundKeepsAHalleyStepFromEndingTooEarlyWhereGppVanishes) {
  // g = x - pi + 0.9 sin x: at the root pi, g' = 0.1 and g'' = 0 but g''' = 0.9. From a start 1e-4
  // away, (g''/2g')^2 alone would predict an error of ~1e-19 after one Halley step; the true error
  // is about g''' e^3 / (6 g') = 1.5e-12. With the jerk bound 0.9 the step is evaluated, and the
  // root is right to the tolerance.
  const long double c = 3.14159265358979323846L;
  auto gd = [&](double x) {
    const long double xl = x;
    return std::tuple<long double, long double, long double>{xl - c + 0.9L * std::sin(xl), 1.0L + 0.9L * std::cos(xl), -0.9L * std::sin(xl)};
  };
  const double lo = 2, hi = 4, tol = 4 * DBL_EPSILON * (hi + 1);
  const double root = solve_increasing(gd, lo, hi, 0.0, std::get<0>(gd(lo)), std::get<0>(gd(hi)), 3.1416926535897933, 0.9);
  EXPECT_LE(std::fabs(root - 3.141592653589793), tol);
}

TEST(SolveIncreasing, RegressionConvergedNewtonStopsWithoutBisecting) {
  // Bug fixed: once converged, the last Newton correction (a few ulp) landed on the bracket end
  // that the same iteration had just moved to x, was rejected as leaving the bracket, and the
  // solver bisected ~50 more times. Newton from a secant start needs well under 12 evaluations on
  // these smooth increasing functions; the root must still be right to the stated tolerance.
  int worst = 0;
  for (int k = 0; k < 400; ++k) {
    const double c = 0.5 + 3.0 * k / 400;  // roots spread over (0, 4)
    int evaluations = 0;
    auto gd = [&](double x) {
      ++evaluations;
      return std::pair<long double, long double>{static_cast<long double>(x) - c + 0.3L * std::sin(x), 1.0L + 0.3L * std::cos(x)};
    };
    const double lo = 0, hi = 4;
    const double root = solve_increasing(gd, lo, hi, 0.0, gd(lo).first, gd(hi).first);
    evaluations -= 2;  // the two end values above
    worst = std::max(worst, evaluations);
    // Reference: plain bisection in long double to the last bit.
    long double a = lo, b = hi;
    for (int it = 0; it < 200 && b - a > 0; ++it) {
      const long double m = 0.5L * (a + b);
      if (m <= a || m >= b) break;
      if (m - c + 0.3L * std::sin(static_cast<double>(m)) < 0)
        a = m;
      else
        b = m;
    }
    EXPECT_NEAR(root, static_cast<double>(b), 4 * DBL_EPSILON * (hi + 1)) << "c=" << c;
  }
  EXPECT_LE(worst, 12);
}
