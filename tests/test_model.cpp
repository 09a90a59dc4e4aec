// SPDX-License-Identifier: GPL-3.0-or-later
// The model's formulas (dfchaos/model.hpp) in their three arithmetics:
//  - the core's accurate forms (the gap G1 as a QuadraticPlusHarmonic re-centred in double-double,
//    the motions of HarmonicMotion with long-double elapsed times) agree with the plain templates
//    evaluated in long double, at many phases and elapsed times;
//  - the ball instantiation encloses the long-double one (the same formula in both arithmetics);
//  - the switching phases of Parameters and of the certified ParameterBalls are the templates' values.
//  - the templates that replaced written-out copies (the envelope of the gap, the slope of the force,
//    the velocity of Eq. 8) give the values of those copies, in double and in balls.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/parameters.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/motion.hpp"
#include "dfchaos/next_hit.hpp"
#include "dfchaos/progression_stop.hpp"
#include "dfchaos/return_map.hpp"
#include "test_support.hpp"

using namespace dfchaos;
using certified::Ball;

namespace {

// Relative agreement of the accurate and the plain forms, measured against the size of the terms
// of the formula (b s^2 + a |s| + 2a for G1): both are far more accurate than this at the elapsed
// times drawn here (up to 10^4, where a long-double s is resolved to 1e-15).
constexpr long double kRelTol = 1e-13L;
// Draws of (b/a, q/a, theta), and elapsed times per draw.
constexpr int kDraws = 400;
const std::vector<double> kElapsed = {1e-3, 0.37, 1.0, 2.9, 7.5, 31.0, 250.0, 4096.5};

/// The instant theta + s in theta's turn numbering, and the same time as a long double.
struct Time {
  Instant at;
  long double t;
};
Time time_after(double theta, double s) {
  const Instant at = Instant::from_time(theta + s);
  return {at, theta + elapsed(Instant::at_phase(theta), at)};
}

}  // namespace

TEST(ModelFormulas, GapOfTheCoreAgreesWithThePlainFormula) {
  test_support::Drawer draw(1e-4, 0.3, 0.6, 0.99);
  long checked = 0;
  for (int i = 0; i < kDraws; ++i) {
    const auto d = draw.next();
    const Parameters p(1.0, d.b, d.q);
    const long double a = 1.0L, b = d.b, th = d.theta;
    for (double s : kElapsed) {
      const Time t = time_after(d.theta, s);
      const long double S = t.t - th;
      const long double scale = b * S * S + a * std::fabs(S) + 2 * a;
      // G1 (Eq. 11): the re-centred evaluation of the search against the plain template.
      EXPECT_NEAR(G1(p, d.theta, t.at), model::G1(a, b, th, t.t), kRelTol * scale) << p.describe() << " theta=" << d.theta << " s=" << s;
      // dG1/dt: the search's slope, and the free motion's velocity (Eq. 3 from rest).
      const long double v = model::dG1_dt(a, b, th, t.t), vscale = 2 * b * std::fabs(S) + 2 * a;
      EXPECT_NEAR(dG1_dt(p, d.theta, t.at), v, kRelTol * vscale) << p.describe() << " theta=" << d.theta << " s=" << s;
      const FreeMotion free(p, Instant::at_phase(d.theta), 0.0, 0.0);
      EXPECT_NEAR(free.velocity(t.at), v, kRelTol * vscale);
      EXPECT_NEAR(free.position(t.at), model::G1(a, b, th, t.t), kRelTol * scale);
      ++checked;
    }
  }
  EXPECT_EQ(checked, kDraws * static_cast<long>(kElapsed.size()));
}

TEST(ModelFormulas, ProgressionOfTheCoreAgreesWithThePlainFormula) {
  test_support::Drawer draw(1e-4, 0.3, 0.6, 0.99);
  for (int i = 0; i < kDraws; ++i) {
    const auto d = draw.next();
    const Parameters p(1.0, d.b, d.q);
    ASSERT_TRUE(p.t0());
    const long double a = 1.0L, b = d.b, q = d.q, t0 = *p.t0();
    const ProgressionMotion prog(p, Instant::at_phase(*p.t0()), 0.0, 0.0);
    for (double s : kElapsed) {
      const Time t = time_after(*p.t0(), s);
      const long double S = t.t - t0;
      // Eq. (7): the progression from rest at t0.
      EXPECT_NEAR(prog.velocity(t.at), model::progression_velocity_from_rest(a, model::two_c(b, q), t0, t.t),
                  kRelTol * (std::fabs(2 * b - q) * std::fabs(S) + 2 * a))
          << p.describe() << " s=" << s;
    }
    // Eq. (17) in its two forms: from the start, and shifted by the constant of a search.
    const long double th = d.theta, th1 = th + 3.7L, t = th1 + 1.3L, c2 = model::two_c(b, q);
    EXPECT_NEAR(model::G2(a, b, q, th, th1, t), model::G2_shifted(a, c2, model::G2_constant(a, b, c2, th, th1), t), 1e-15L * (1 + th1));
    // G2 at t = theta1 is the impact velocity dG1/dt(theta, theta1).
    EXPECT_NEAR(model::G2(a, b, q, th, th1, th1), model::dG1_dt(a, b, th, th1), 1e-15L * (1 + th1));
  }
}

TEST(ModelFormulas, BallsEncloseTheLongDoubleValues) {
  test_support::Drawer draw(1e-4, 0.3, 0.6, 0.99);
  auto encloses = [](const Ball& x, long double v, long double scale) {
    const long double tol = 1e-17L * scale;  // the long-double evaluation's own rounding
    return x.lower() - tol <= v && v <= x.upper() + tol;
  };
  for (int i = 0; i < kDraws; ++i) {
    const auto d = draw.next();
    const Ball a(1.0), b(d.b), q(d.q), th(d.theta);
    const long double al = 1.0L, bl = d.b, ql = d.q, thl = d.theta;
    EXPECT_TRUE(encloses(model::t0(a, b, q), model::t0(al, bl, ql), 8));
    EXPECT_TRUE(encloses(model::t1(a, b, q), model::t1(al, bl, ql), 8));
    EXPECT_TRUE(encloses(model::t2(a, b), model::t2(al, bl), 8));
    EXPECT_TRUE(encloses(model::t3(a, b), model::t3(al, bl), 8));
    for (double s : {0.25, 3.0, 40.0}) {
      const long double tl = thl + s;
      const Ball t = th + Ball(s);
      EXPECT_TRUE(encloses(model::G1(a, b, th, t), model::G1(al, bl, thl, tl), 4 + bl * s * s + s)) << d.theta << " " << s;
      EXPECT_TRUE(encloses(model::dG1_dt(a, b, th, t), model::dG1_dt(al, bl, thl, tl), 4 + bl * s));
      EXPECT_TRUE(encloses(model::G2(a, b, q, th, t, t + Ball(1.5)), model::G2(al, bl, ql, thl, tl, tl + 1.5L), 4 + s));
      EXPECT_TRUE(encloses(model::F(a, b, t), model::F(al, bl, tl), 4));
    }
  }
}

TEST(ModelFormulas, BothLayersTakeTheirPhasesFromTheTemplates) {
  test_support::Drawer draw(1e-6, 0.45, 0.3, 0.99);
  for (int i = 0; i < kDraws; ++i) {
    const auto d = draw.next();
    const Parameters p(1.0, d.b, d.q);
    ASSERT_TRUE(p.t0() && p.t2());
    // Parameters: the double instantiation, t0 reduced to [0, 2 pi).
    EXPECT_EQ(*p.t0(), wrap_phase(model::t0(1.0, d.b, d.q)));
    EXPECT_EQ(*p.t1(), model::t1(1.0, d.b, d.q));
    EXPECT_EQ(*p.t2(), model::t2(1.0, d.b));
    EXPECT_EQ(*p.t3(), model::t3(1.0, d.b));
    EXPECT_EQ(p.F(d.theta), d.b * 2 + std::sin(d.theta));
    // The certified ParameterBalls at the point: balls that contain the doubles.
    const certified::ParameterBalls m(certified::ParameterBox::point(p));
    EXPECT_LE(m.t2.lower(), *p.t2() + 4e-16);
    EXPECT_GE(m.t2.upper(), *p.t2() - 4e-16);
    EXPECT_LE(m.t3.lower(), *p.t3() + 8e-16);
    EXPECT_GE(m.t3.upper(), *p.t3() - 8e-16);
  }
}

TEST(ModelFormulas, TheEnvelopeOfTheGapAgreesInBothLayers) {
  test_support::Drawer draw(1e-4, 0.3, 0.6, 0.99);
  for (int i = 0; i < kDraws; ++i) {
    const auto d = draw.next();
    const Parameters p(1.0, d.b, d.q);
    const double a = 1.0, b = d.b, st = std::sin(d.theta), ct = std::cos(d.theta);
    // The core's form of the same bound: the gap's coefficients, alpha s^2 + beta s + gamma + |A|.
    const QuadraticPlusHarmonic f = G1_function(p, d.theta);
    const Ball A(a), B(b), ST(st), CT(ct);
    for (double s : kElapsed) {
      const double U = model::G1_envelope_from_start(a, b, st, ct, s);
      // The expression the certified FlightGap wrote out before.
      EXPECT_EQ(U, b * (s * s) + a * ct * s + a * st + a);
      const long double S = s, core = (f.alpha * S + (f.beta + f.beta_tail)) * S + f.gamma + std::fabs(f.A);
      EXPECT_NEAR(core, U, kRelTol * (b * S * S + a * S + 2 * a)) << p.describe() << " theta=" << d.theta << " s=" << s;
      // An envelope: above the gap.
      EXPECT_LE(model::G1_from_start(a, b, st, ct, s, d.theta + s), U + 1e-15 * (b * s * s + a * s + 2 * a));
      const Ball UB = model::G1_envelope_from_start(A, B, ST, CT, Ball(s));
      const double tol = 1e-15 * (b * s * s + a * s + 2 * a);  // the double evaluation's rounding
      EXPECT_TRUE(UB.lower() - tol <= U && U <= UB.upper() + tol) << UB.str(20) << " " << U;
    }
  }
}

TEST(ModelFormulas, TheSlopeOfTheForceInBothLayers) {
  test_support::Drawer draw(1e-4, 0.3, 0.6, 0.99);
  for (int i = 0; i < kDraws; ++i) {
    const auto d = draw.next();
    const double a = 1.0 + d.q, t = d.theta + 7 * d.q;
    // The expression the certified MinusVelocity wrote out before, and a central difference of F.
    EXPECT_EQ(model::dF_dt(a, t), a * std::cos(t));
    const double h = 1e-5;
    EXPECT_NEAR(model::dF_dt(a, t), (model::F(a, d.b, t + h) - model::F(a, d.b, t - h)) / (2 * h), 1e-9);
    const Ball DB = model::dF_dt(Ball(a), Ball(t));
    EXPECT_TRUE(DB.lower() - 1e-15 * a <= a * std::cos(t) && a * std::cos(t) <= DB.upper() + 1e-15 * a);
  }
}

TEST(ModelFormulas, Eq8IsTheVelocityOfTheProgressionFromRest) {
  test_support::Drawer draw(1e-4, 0.3, 0.6, 0.99);
  for (int i = 0; i < kDraws; ++i) {
    const auto d = draw.next();
    const Parameters p(1.0, d.b, d.q);
    if (!(d.q > 2 * d.b)) continue;
    const double t0 = *p.t0(), t2 = *p.t2(), a = 1.0;
    // The expression progression_from_t0 wrote out before (t2 follows t0 in the same turn).
    const double before = -a * std::cos(t2) + a * std::cos(t0) + 2 * p.c() * (t2 - t0);
    EXPECT_NEAR(progression_from_t0(p).eq8_velocity_at_t2, before, 1e-14) << p.describe();
    const Ball v = model::progression_velocity_from_rest(Ball(a), model::two_c(Ball(d.b), Ball(d.q)), Ball(t0), Ball(t2));
    EXPECT_TRUE(v.lower() - 1e-13 <= before && before <= v.upper() + 1e-13) << v.str(20) << " " << before;
  }
}
