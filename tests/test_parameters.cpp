// SPDX-License-Identifier: GPL-3.0-or-later
// Unit tests: vartheta0 of Eq. (1), the switching phases, parameter validation.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/phase.hpp"

using namespace dfchaos;

namespace {
constexpr double kResidualTol = 1e-15;       // |Eq. (1) residual| at the computed vartheta0
constexpr double kUlpTol = 2 * DBL_EPSILON;  // relative distance to the long-double reference

/// Independent reference: bisection in long double (64-bit mantissa) on pi - x - cot(x/2).
long double vartheta0_long_double() {
  const long double pil = 3.141592653589793238462643383279502884L;
  long double lo = 0.1L, hi = pil / 2;
  for (int i = 0; i < 200; ++i) {
    const long double m = 0.5L * (lo + hi);
    if (pil - m - 1.0L / std::tan(0.5L * m) < 0)
      lo = m;
    else
      hi = m;
  }
  return 0.5L * (lo + hi);
}
}  // namespace

TEST(Vartheta0, ResidualOfEq1IsBelowTolerance) { EXPECT_LT(std::fabs(eq1_residual(vartheta0())), kResidualTol); }

TEST(Vartheta0, AgreesWithLongDoubleBisection) {
  const long double ref = vartheta0_long_double();
  EXPECT_LE(std::fabs(static_cast<long double>(vartheta0()) - ref), kUlpTol * ref);
}

TEST(Vartheta0, ResidualChangesSignOnlyOnce) {
  // Eq. (1)'s residual increases on (0, pi/2]: sampled, it is monotone and crosses zero once.
  int crossings = 0;
  double prev = eq1_residual(1e-3);
  for (int i = 1; i <= 10000; ++i) {
    const double x = 1e-3 + (M_PI / 2 - 1e-3) * i / 10000.0;
    const double r = eq1_residual(x);
    EXPECT_GT(r, prev);
    if ((prev < 0) != (r < 0)) ++crossings;
    prev = r;
  }
  EXPECT_EQ(crossings, 1);
}

TEST(Vartheta0, MatchesPaperDigits) {
  // The paper prints 0.81047 and 0.724611; both must be the correctly rounded values.
  EXPECT_NEAR(vartheta0(), 0.81047, 0.5e-5);
  EXPECT_NEAR(sin_vartheta0(), 0.724611, 0.5e-6);
}

TEST(Phases, AreZerosOfTheForce) {
  for (double b : {1e-5, 1e-3, 0.05, 0.2, 0.49})
    for (double q : {0.3, 0.75, 0.95}) {
      const Parameters p(1.0, b, q);
      ASSERT_TRUE(p.t2() && p.t3());
      EXPECT_NEAR(p.F(*p.t2()), 0.0, 1e-15);
      EXPECT_NEAR(p.F(*p.t3()), 0.0, 1e-15);
      EXPECT_LT(p.F(0.5 * (*p.t2() + *p.t3())), 0.0);  // F < 0 inside (t2, t3)
      ASSERT_TRUE(p.t0() && p.t1());
      EXPECT_NEAR(p.F(*p.t0()), q, 1e-15);
      EXPECT_NEAR(p.F(*p.t1()), q, 1e-15);
    }
}

TEST(Phases, UndefinedOutsideTheirRange) {
  EXPECT_FALSE(Parameters(1.0, 0.5, 0.5).t2());  // 2b = a: F >= 0
  EXPECT_FALSE(Parameters(1.0, 0.1, 1.3).t0());  // q - 2b >= a: F never exceeds q
  EXPECT_THROW(Parameters(1.0, 0.6, 0.8).t2_required(), InvalidParameter);
}

TEST(Parameters, ScaleInvariancePhasesDependOnRatiosOnly) {
  const Parameters p(1.0, 0.01, 0.85), r(7.5, 0.075, 6.375);
  EXPECT_NEAR(*p.t0(), *r.t0(), 1e-14);
  EXPECT_NEAR(*p.t2(), *r.t2(), 1e-14);
  EXPECT_NEAR(*p.t3(), *r.t3(), 1e-14);
}

TEST(Parameters, RejectsNonFiniteAndNonPositive) {
  for (double bad : std::initializer_list<double>{0.0, -1.0, NAN, INFINITY, -INFINITY}) {
    EXPECT_THROW(Parameters(bad, 0.1, 0.8), InvalidParameter);
    EXPECT_THROW(Parameters(1.0, bad, 0.8), InvalidParameter);
    EXPECT_THROW(Parameters(1.0, 0.1, bad), InvalidParameter);
  }
  try {
    Parameters(1.0, -0.1, 0.8);
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.parameter(), "b");
    EXPECT_NE(std::string(e.what()).find("b:"), std::string::npos);
  }
}

TEST(Parameters, AssumptionsReportEq2AndEq23) {
  const double s0 = sin_vartheta0();
  EXPECT_TRUE(Parameters(1.0, 0.01, 0.85).assumptions().eq2);
  EXPECT_FALSE(Parameters(1.0, 0.01, s0 - 1e-9).assumptions().eq2);
  EXPECT_TRUE(Parameters(1.0, 0.01, s0 + 1e-9).assumptions().eq2);
  EXPECT_TRUE(Parameters(1.0, 0.01, 0.5).assumptions().eq23);
  EXPECT_FALSE(Parameters(1.0, 0.01, 1.0).assumptions().eq23);
  EXPECT_FALSE(Parameters(1.0, 0.6, 0.9).assumptions().b_in_range);
  EXPECT_FALSE(Parameters(1.0, 0.3, 0.5).assumptions().progression_ends);
  EXPECT_THROW(Parameters(1.0, 0.3, 0.5).require_return_map(), InvalidParameter);
}

// ---- phase.hpp: instants as whole turns plus a phase ---------------------------------------

TEST(Phase, WrapPhaseAndCircleDistanceKnownValues) {
  EXPECT_EQ(wrap_phase(1.0), 1.0);
  EXPECT_DOUBLE_EQ(wrap_phase(-1.0), two_pi - 1.0);
  EXPECT_DOUBLE_EQ(wrap_phase(two_pi + 0.5), 0.5);
  EXPECT_EQ(wrap_phase(0.0), 0.0);
  const double w = wrap_phase(1e6);  // 1e6 = 159154 turns + 0.943...
  EXPECT_NEAR(w, 1e6 - 159154 * 6.283185307179586476925286766559, 1e-9);
  EXPECT_GE(w, 0.0);
  EXPECT_LT(w, two_pi);
  EXPECT_NEAR(circle_distance(0.1, two_pi - 0.1), 0.2, 1e-15);
  EXPECT_DOUBLE_EQ(circle_distance(1.0, 1.0 + pi), pi);
  EXPECT_EQ(circle_distance(2.0, 2.0), 0.0);
}

TEST(Phase, InstantSplitsTimeIntoTurnAndPhase) {
  const Instant a = Instant::from_time(3 * two_pi + 1.25);
  EXPECT_EQ(a.turn, 3);
  EXPECT_NEAR(a.phase, 1.25, 1e-14);
  const Instant b = Instant::from_time(-0.5);
  EXPECT_EQ(b.turn, -1);
  EXPECT_NEAR(b.phase, two_pi - 0.5, 1e-15);
  EXPECT_NEAR(a.value(), 3 * two_pi + 1.25, 1e-14);
  EXPECT_EQ(Instant::from_time(1.0), (Instant{0, 1.0}));  // inside [0, 2 pi): exact
}

TEST(Phase, AdvanceElapsedAndOrderAreConsistent) {
  const Instant t{5, 6.0};
  const Instant u = advance(t, 1.0L);  // crosses into the next turn
  EXPECT_EQ(u.turn, 6);
  EXPECT_NEAR(u.phase, 7.0 - two_pi, 1e-15);
  EXPECT_NEAR(static_cast<double>(elapsed(t, u)), 1.0, 1e-15);
  const Instant far = advance(t, 1e7L);  // a long flight keeps the phase
  EXPECT_NEAR(static_cast<double>(elapsed(t, far)), 1e7, 1e-8);
  EXPECT_TRUE(before(t, u));
  EXPECT_FALSE(before(u, t));
  EXPECT_FALSE(before(t, t));
  EXPECT_EQ(next_at_phase(t, 6.1), (Instant{5, 6.1}));
  EXPECT_EQ(next_at_phase(t, 6.0), (Instant{6, 6.0}));  // strictly after
  EXPECT_EQ(next_at_phase(t, 1.0), (Instant{6, 1.0}));
}

TEST(Phase, ArcsMayWrapThroughZero) {
  EXPECT_TRUE(phase_in_arc(1.0, 0.5, 2.0));
  EXPECT_TRUE(phase_in_arc(0.5, 0.5, 2.0));   // closed at the left
  EXPECT_FALSE(phase_in_arc(2.0, 0.5, 2.0));  // open at the right
  EXPECT_TRUE(phase_in_arc(6.0, 5.0, 1.0));   // [5, 2 pi) U [0, 1)
  EXPECT_TRUE(phase_in_arc(0.2, 5.0, 1.0));
  EXPECT_FALSE(phase_in_arc(3.0, 5.0, 1.0));
}

TEST(Vartheta0, RegressionCorrectlyRoundedDoubles) {
  // The double of vartheta0 was one ulp too high (0.81047028317537073): Brent's bracket stopped a few
  // ulp wide and the end with the smaller double residual is not the nearest double. The nearest
  // doubles of the 50-digit values 0.810470283175370624794807... and 0.724611353776708475738990...
  // are these (hexadecimal: exact).
  EXPECT_EQ(vartheta0(), 0x1.9ef5f6013c747p-1);
  EXPECT_EQ(vartheta0(), 0.8104702831753706);
  EXPECT_EQ(sin_vartheta0(), 0.7246113537767085);
}

TEST(Parameters, RegressionAssumption2NamesTheParameterThatBreaksIt) {
  // sec6/sec7/sec10 refused q = sin(vartheta0) naming b (the covering search failed instead of the
  // assumption being checked); q up to 1e308 was accepted. Assumption (2) is checked by one function.
  try {
    Parameters(1.0, 0.01, 0.7246113537767085).require_eq2();
    FAIL() << "q at the threshold accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.parameter(), "q");
  }
  try {
    Parameters(1.0, 0.6, 0.9).require_eq2();
    FAIL() << "b >= a/2 accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.parameter(), "b");
  }
  EXPECT_THROW(Parameters(1.0, 0.01, 1.0).require_eq2(), InvalidParameter);
  EXPECT_NO_THROW(Parameters(1.0, 0.01, 0.85).require_eq2());
  EXPECT_NO_THROW(Parameters(2.0, 0.02, 1.7).require_eq2());
}

TEST(Format, ShortestReadsBackToTheSameDouble) {
  EXPECT_EQ(dfchaos::format_shortest(0.85), "0.85");
  EXPECT_EQ(dfchaos::format_double(0.85), "0.84999999999999998");
  EXPECT_EQ(dfchaos::format_shortest(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(dfchaos::format_shortest(5e-5), "5e-5");  // not to_chars's "5e-05"
  EXPECT_EQ(dfchaos::format_shortest(1e300), "1e300");
  EXPECT_EQ(dfchaos::format_shortest(-2.5e-300), "-2.5e-300");
  EXPECT_EQ(dfchaos::format_shortest(1e-100), "1e-100");
  // Every double of a spread of magnitudes reads back exactly, and no shorter decimal would.
  double x = 1.2345678901234567e-12;
  for (int k = 0; k < 200; ++k, x *= 1.3771) {
    const std::string s = dfchaos::format_shortest(x);
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), x) << s;
    EXPECT_LE(s.size(), dfchaos::format_double(x).size()) << s;
    // Its significant digits d: the nearest decimal of d - 1 digits (the closest of all of them to x)
    // reads back to another double, so no shorter decimal names x. (Not a proof at a power of two,
    // where the doubles below are twice as dense as above and a farther decimal may still read back;
    // none of these values is one.)
    const std::string mantissa = s.substr(0, s.find('e'));
    std::string digits;
    for (char ch : mantissa)
      if (ch >= '0' && ch <= '9') digits += ch;
    digits.erase(0, digits.find_first_not_of('0'));
    digits.erase(digits.find_last_not_of('0') + 1);  // zeros ending an integer are not significant
    const int d = static_cast<int>(digits.size());
    if (d > 1) {
      char shorter[64];
      std::snprintf(shorter, sizeof shorter, "%.*e", d - 2, x);
      EXPECT_NE(std::strtod(shorter, nullptr), x) << s << " vs " << shorter;
    }
  }
  EXPECT_EQ(Parameters(1.0, 0.003, 0.85).describe(), "a=1 b=0.003 q=0.85");
}
