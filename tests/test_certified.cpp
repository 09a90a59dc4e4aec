// SPDX-License-Identifier: GPL-3.0-or-later
// The certified layer, in tiers:
//  - unit: the Ball wrapper, vartheta0's digits and correctly rounded doubles;
//  - cross-validation: certified enclosures of T1, theta2 and T contain the floating layer's values
//    (within its stated accuracy) on many phases and parameters; Lemma 2's count matches the closed
//    form of the floating layer;
//  - failure: a proof fails where the statement is false (no covering at (0.85, 0.02); no
//    superstability just outside a window edge; a phase ball straddling a discontinuity of T1, or a
//    jump of T, is never proved continuous; Lemma 1 below q = a sin(vartheta0)).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <omp.h>

#include "certify/json.hpp"
#include "certify/statements.hpp"
#include "dfchaos/certified/arc_l1.hpp"
#include "dfchaos/certified/bisect.hpp"
#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/entropy.hpp"
#include "dfchaos/certified/graph.hpp"
#include "dfchaos/certified/laps.hpp"
#include "dfchaos/certified/lemma4_uniform.hpp"
#include "dfchaos/certified/periodic.hpp"
#include "dfchaos/certified/rectangle.hpp"
#include "dfchaos/certified/region.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/next_hit.hpp"
#include "dfchaos/progression_stop.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/superstable.hpp"
#include "dfchaos/symbolic.hpp"

using namespace dfchaos;
using namespace dfchaos::certified;
using namespace dfchaos::certify;

namespace {

// The floating layer computes instants (T1, theta2) to about 1e-12 relative and T to about 1e-10
// (docs/accuracy.md); its values must lie within these of the certified enclosures.
constexpr double kInstantRelTol = 1e-10;
constexpr double kPhaseAbsTol = 1e-9;
// Phases per parameter set in the cross-validation, and the share of them that must be proved
// (the rest lie too close to a grazing or a jump of T for a thin ball: "not proved" is allowed there).
constexpr int kPhases = 150;
constexpr double kMinProvedShare = 0.9;

bool within(const Ball& enclosure, double value, double tol) { return enclosure.lower() - tol <= value && value <= enclosure.upper() + tol; }

}  // namespace

TEST(CertifiedBall, ExactDoublesAndCertainPredicates) {
  const Ball x(0.1);
  EXPECT_TRUE(x.is_exact());
  EXPECT_EQ(x.lower(), 0.1);
  EXPECT_EQ(x.upper(), 0.1);
  const Ball d = Ball::decimal("0.1");  // the decimal, not the double
  EXPECT_FALSE(d.is_exact());
  EXPECT_FALSE(d.contains(0.1));
  const Ball i = Ball::interval(-1, 2);
  EXPECT_FALSE(i.is_positive());
  EXPECT_FALSE(i.is_negative());
  EXPECT_TRUE((i + 1.5).is_positive());
  EXPECT_TRUE(lt(Ball(1.0), Ball(2.0)));
  EXPECT_FALSE(lt(i, Ball(1.0)));
}

TEST(CertifiedBisect, EnclosesTheSignChangeAndStopsWhereTheSignIsNotProved) {
  auto f = [](const Ball& x) { return Ball(2.0) - x * x; };  // > 0 at 1, < 0 at 2: the zero sqrt 2
  // the ball holds the zero: f is proved positive at its lower end and negative at its upper end
  auto holds_root = [&f](const Ball& z) { return f(z.lower_ball()).is_positive() && f(z.upper_ball()).is_negative(); };
  const Ball z = enclose_sign_change(f, Ball(1.0), Ball(2.0), 200);
  EXPECT_TRUE(holds_root(z));
  EXPECT_TRUE(lt(z.upper_ball() - z.lower_ball(), Ball(1e-30)));      // 128-bit arithmetic: far below a double's ulp
  const Ball z10 = enclose_sign_change(f, Ball(1.0), Ball(2.0), 10);  // 10 halvings of [1, 2]
  EXPECT_TRUE(holds_root(z10));
  EXPECT_NEAR(z10.upper() - z10.lower(), 1.0 / 1024, 1e-8);  // (a hull's radius is rounded up to 30 bits)
  // lo on the right of hi
  const Ball w = enclose_sign_change([&f](const Ball& x) { return -f(x); }, Ball(2.0), Ball(1.0), 200);
  EXPECT_TRUE(holds_root(w));
  // a function whose sign is never proved: nothing is halved
  const Ball u = enclose_sign_change([](const Ball& x) { return Ball::hull(x - Ball(10.0), x + Ball(10.0)); }, Ball(1.0), Ball(2.0), 200);
  EXPECT_NEAR(u.lower(), 1.0, 1e-8);
  EXPECT_NEAR(u.upper(), 2.0, 1e-8);
}

TEST(CertifiedCover, ProvesCellsLeftToRightAndStopsWhereACellCannotBeSplit) {
  // x^2 - 2 < 0 on [0, 1.4]: the check proves a cell no wider than 1/4 whose upper end is below sqrt 2
  // in ball arithmetic.
  std::vector<Span> proved;
  auto negative = [&proved](const Span& c, int) {
    if (c.second - c.first <= 0.25 && (sqr(Ball(c.second)) - 2.0).is_negative()) {
      proved.push_back(c);
      return CellVerdict::proved();
    }
    return CellVerdict::split(Outcome::fail("x^2 < 2", "at " + std::to_string(c.second)));
  };
  EXPECT_TRUE(cover(Span(0.0, 1.4), negative, halve, 60));
  ASSERT_EQ(proved.size(), 8U);          // widths 1.4 / 8 = 0.175
  EXPECT_EQ(proved.front().first, 0.0);  // the cells tile [0, 1.4] in order, left half first
  EXPECT_EQ(proved.back().second, 1.4);
  for (std::size_t i = 1; i < proved.size(); ++i) EXPECT_EQ(proved[i - 1].second, proved[i].first);
  // Past the zero: the cell [lo, hi] with lo < sqrt 2 <= hi is split until it is two adjacent doubles.
  proved.clear();
  const Outcome at_root = cover(Span(0.0, 2.0), negative, halve, 2000);
  EXPECT_FALSE(at_root);
  EXPECT_EQ(at_root.step, "x^2 < 2");
  EXPECT_LE(proved.back().second, std::sqrt(2.0));
  // The depth limit: no cell below depth 2 (width 0.35), so [0, 1.4] is not proved.
  int checks = 0;
  auto count = [&checks, &negative](const Span& c, int depth) {
    ++checks;
    EXPECT_LE(depth, 2);
    return negative(c, depth);
  };
  proved.clear();
  EXPECT_FALSE(cover(Span(0.0, 1.4), count, halve, 2));
  EXPECT_EQ(checks, 3);  // [0, 1.4], [0, 0.7], [0, 0.35]: the first cell at the limit ends the cover
  // A stop ends the cover at once, with its outcome (a refutation here).
  checks = 0;
  const Outcome refuted = cover(
      Span(0.0, 1.0),
      [&checks](const Span&, int) {
        return ++checks == 2 ? CellVerdict::stop(Outcome::refute("s", "d")) : CellVerdict::split(Outcome::fail("s", "d"));
      },
      halve, 60);
  EXPECT_TRUE(refuted.refuted);
  EXPECT_EQ(checks, 2);
  EXPECT_FALSE(halve(Span(1.0, std::nextafter(1.0, 2.0)), 0));  // two adjacent doubles: no midpoint inside
}

TEST(CertifyRegistry, OneEntryPerStatementEachWithItsProver) {
  std::vector<std::string> names;
  for (const Statement& s : statements()) {
    EXPECT_FALSE(s.summary.empty()) << s.name;
    EXPECT_NE(s.run, nullptr) << s.name;
    EXPECT_EQ(&statement(s.name), &s);  // found by its name
    EXPECT_EQ(std::count(names.begin(), names.end(), s.name), 0) << s.name;
    names.push_back(s.name);
  }
  EXPECT_GE(names.size(), 9U);
  // A name that is not in the registry: one message naming "what" and listing every statement.
  try {
    check_statement("lemma5");
    ADD_FAILURE() << "lemma5 accepted";
  } catch (const InvalidParameter& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("what"), std::string::npos) << m;
    for (const std::string& n : names) EXPECT_NE(m.find(n), std::string::npos) << m;
  }
  // A request runs its statement's prover: vartheta0 through certify() and through the entry agree.
  Request r;
  r.what = "vartheta0";
  EXPECT_EQ(dfchaos::certify::certify(r).record.dump(0), statement("vartheta0").run(r).record.dump(0));
  // The word is read only by a statement that takes an itinerary.
  r.word = "01";
  EXPECT_THROW(dfchaos::certify::certify(r), InvalidParameter);
}

TEST(CertifiedVartheta0, DigitsAndCorrectlyRoundedDoubles) {
  const Vartheta0 v = certify_vartheta0(200);
  ASSERT_TRUE(v.verdict.proved);
  ASSERT_TRUE(v.rounding_certified);
  EXPECT_EQ(v.value.mid_str(40).substr(0, 40), "0.81047028317537062479480742736238154592");
  EXPECT_EQ(v.sine.mid_str(40).substr(0, 40), "0.72461135377670847573899045352563178434");
  EXPECT_LT(v.value.radius(), 1e-50);
  // The correctly rounded doubles end ...706 and ...085 (the GSL root printed ...707 and ...086).
  EXPECT_EQ(v.value_double, 0.8104702831753706);
  EXPECT_EQ(v.sine_double, 0.7246113537767085);
  EXPECT_EQ(shortest_double(v.value_double), "0.8104702831753706");
  EXPECT_EQ(shortest_double(v.sine_double), "0.7246113537767085");
}

// Cross-validation: the certified T1, theta2 and T at thin phases and on small balls contain the
// floating layer's values.
TEST(CertifiedReturnMap, EnclosuresContainTheFloatingValues) {
  const double params[][2] = {{0.85, 1e-4}, {0.85, 1e-3}, {0.8, 3e-3}, {0.95, 1e-2}, {0.9, 5e-2}};
  for (const auto& pq : params) {
    const double q = pq[0], b = pq[1];
    const Parameters p(1, b, q);
    const ParameterBalls m(ParameterBox::point(p));
    const double t2 = *p.t2(), t3 = *p.t3();
    int proved = 0;
    for (int i = 0; i < kPhases; ++i) {
      const double th = t2 + (t3 - t2) * std::fmod(0.5 + i * 0.6180339887498949, 1.0);
      const MapStep s = return_map_step(p, th);
      Budget budget;
      const MapStepProof t = certify_T(m, StartSet::point(th), budget);
      if (!t.verdict) continue;
      ++proved;
      const double T1 = s.hit.t1.value(), th2 = s.theta2.value();
      EXPECT_TRUE(within(t.t1.enclosure, T1, kInstantRelTol * std::fabs(T1))) << "b=" << b << " theta=" << th << " T1=" << T1;
      if (t.theta2.verdict) {
        EXPECT_TRUE(within(t.theta2.enclosure, th2, kInstantRelTol * std::fabs(th2))) << "b=" << b << " theta=" << th;
      }
      EXPECT_TRUE(within(t.T, s.T, kPhaseAbsTol)) << "b=" << b << " theta=" << th << " T=" << s.T << " enclosure " << t.T.str(15);
      if (t.constant_t2) {
        EXPECT_EQ(s.T, t2) << "b=" << b << " theta=" << th;
      }
      // A small ball around the phase: its enclosure holds the floating value at the centre.
      Budget b2;
      const MapStepProof tb = certify_T(m, StartSet::interval(th - 1e-9, th + 1e-9), b2);
      if (tb.verdict) {
        EXPECT_TRUE(within(tb.T, s.T, kPhaseAbsTol)) << "ball at theta=" << th;
      }
    }
    EXPECT_GE(proved, static_cast<int>(kMinProvedShare * kPhases)) << "b=" << b << " q=" << q;
  }
}

TEST(CertifiedReturnMap, StartAtT2UsesTheCubicTerm) {
  const ParameterBalls m(ParameterBox::point(1, 0.0641, 0.85));
  Budget budget;
  const FirstHitProof t = certify_T1(m, StartSet::from_t2(m, m.t2.upper()), budget);
  ASSERT_TRUE(t.verdict.proved) << t.verdict.describe();
  const MapStep s = return_map_step(Parameters(1, 0.0641, 0.85), *Parameters(1, 0.0641, 0.85).t2());
  EXPECT_TRUE(within(t.enclosure, s.hit.t1.value(), kInstantRelTol * s.hit.t1.value()));
}

// Failure tier: a ball straddling a discontinuity of T1 is never proved continuous.
TEST(CertifiedReturnMap, BallAcrossADiscontinuityOfT1IsNotProved) {
  const DiscontinuityProof d = prove_discontinuities(1, 0.01, L_101pi_100(), L_3pi_2());
  ASSERT_TRUE(d.verdict.proved) << d.verdict.describe();
  const ParameterBalls m(ParameterBox::point(1, 0.01, 0.85));
  for (const auto& z : d.z) {
    for (double r : {1e-3, 1e-6, 1e-10, 1e-13}) {
      Budget budget;
      const FirstHitProof t = certify_T1(m, StartSet::interval(z.z.mid() - r, z.z.mid() + r), budget);
      EXPECT_FALSE(t.verdict.proved) << "z=" << z.z.mid() << " r=" << r;
    }
  }
}

// Failure tier: a ball across the jump of T between the two covering segments is not proved.
TEST(CertifiedReturnMap, BallAcrossAJumpOfTIsNotProved) {
  const CoveringProof c = prove_covering(ParameterBox::point(1, 0.001, 0.85));
  ASSERT_TRUE(c.verdict.proved);
  const ParameterBalls m(c.box);
  Budget budget;
  const MapStepProof t = certify_T(m, StartSet::interval(c.J0.hi, c.J1.lo), budget);
  EXPECT_FALSE(t.verdict.proved);
  // Nor any cover of that gap by balls of width 1e-7 (T jumps inside it).
  bool all = true;
  for (double x = c.J0.hi; x < c.J1.lo && all; x += 1e-7) {
    Budget b2;
    all = certify_T(m, StartSet::interval(x, std::min(x + 1e-7, c.J1.lo)), b2).verdict.proved;
  }
  EXPECT_FALSE(all);
}

TEST(CertifiedLemma1, ProvedAboveAndRefutedBelowTheThreshold) {
  const Lemma1Proof yes = certify_lemma1(ParameterBalls(ParameterBox::point(1, 0.001, 0.85)));
  EXPECT_TRUE(yes.verdict.proved);
  EXPECT_TRUE(yes.u_at_t2.is_negative());
  // q/a = 0.70 < sin(vartheta0): the progression from t0 does not stop before t2 (Eq. 9 fails).
  const Lemma1Proof no = certify_lemma1(ParameterBalls(ParameterBox::point(1, 0.001, 0.70)));
  EXPECT_FALSE(no.verdict.proved);
  EXPECT_TRUE(no.verdict.refuted);
  const ProgressionFromT0 f = progression_from_t0(Parameters(1, 0.001, 0.70));
  EXPECT_FALSE(f.stops_in_t1_t2);
  // The certified b0 bound lies below the floating estimate, within the requested resolution.
  const Lemma1Bound bnd = lemma1_b0_lower_bound(1, 0.85);
  ASSERT_TRUE(bnd.verdict.proved);
  EXPECT_LT(bnd.b_low, bnd.b_float);
  EXPECT_GT(bnd.b_low, 0.99 * bnd.b_float);
  EXPECT_TRUE(certify_lemma1(ParameterBalls(ParameterBox{1, 0.5 * bnd.b_low, bnd.b_low, 0.85, 0.85})).verdict.proved);
}

TEST(CertifiedLemma2, CountAndEnclosuresMatchTheClosedForm) {
  for (double b : {0.01, 0.003}) {
    const DiscontinuityProof d = prove_discontinuities(1, b, L_101pi_100(), L_3pi_2());
    ASSERT_TRUE(d.verdict.proved) << d.verdict.describe();
    const auto f = symmetric_tangencies(Parameters(1, b, 0.85), 101 * M_PI / 100, 1.5 * M_PI);
    ASSERT_EQ(d.z.size(), f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
      EXPECT_TRUE(within(d.z[i].z, f[i].z, 1e-12)) << i;
      EXPECT_TRUE(d.z[i].jump.is_positive());
      // T1 jumps down at z as theta increases: the floating T1 just left of z is after the tangency.
      EXPECT_GT(next_hit(Parameters(1, b, 0.85), d.z[i].z.lower() - 1e-9).theta1, d.z[i].t_star.upper());
    }
  }
}

TEST(CertifiedCovering, ProvedAtTheIssuePointsNotAtB002) {
  const double pts[][2] = {{0.85, 0.001}, {0.85, 0.003}, {0.95, 0.01}, {0.85, 5e-5}};
  for (const auto& pq : pts) {
    const CoveringProof c = prove_covering(ParameterBox::point(1, pq[1], pq[0]));
    ASSERT_TRUE(c.verdict.proved) << c.verdict.describe();
    EXPECT_LT(c.J0.hi, c.J1.lo);
    EXPECT_GE(c.J0.lo, *Parameters(1, pq[1], pq[0]).t2());
    EXPECT_LE(c.J1.hi, 1.5 * M_PI);
    EXPECT_LT(c.seconds, 30.0);  // the cost bound per proof
    // The floating T at the ends agrees with what was proved there.
    const Parameters p(1, pq[1], pq[0]);
    for (const SegmentProof* J : {&c.J0, &c.J1}) {
      EXPECT_GE(T(p, J->theta_top), 1.5 * M_PI);
      EXPECT_EQ(T(p, J->theta_t2), *p.t2());
    }
  }
  const CoveringProof none = prove_covering(ParameterBox::point(1, 0.02, 0.85));
  EXPECT_FALSE(none.verdict.proved);
  EXPECT_FALSE(none.verdict.step.empty());
  // A segment that does not cover (both ends with T = t2) is not proved.
  const CoveringProof c = prove_covering(ParameterBox::point(1, 0.001, 0.85));
  const ParameterBalls m(c.box);
  Candidate bad{c.J0.theta_t2, c.J0.theta_t2 - 1e-6};
  EXPECT_FALSE(prove_segment(m, bad).verdict.proved);
}

TEST(CertifiedCovering, SmallParameterBoxProvedLargeOneNot) {
  const ParameterBox small{1, 0.003, 0.003 + 1e-8, 0.85, 0.855};
  EXPECT_TRUE(prove_covering(small).verdict.proved);
  const ParameterBox large{1, 0.003, 0.0031, 0.85, 0.85};  // T1 moves by tens of units across it
  EXPECT_FALSE(prove_covering(large).verdict.proved);
}

TEST(CertifiedPeriodic, EveryPeriodUpToTwelveWithItsItinerary) {
  const CoveringProof c = prove_covering(ParameterBox::point(1, 0.003, 0.85));
  ASSERT_TRUE(c.verdict.proved);
  const Parameters p(1, 0.003, 0.85);
  for (int m = 1; m <= 12; ++m) {
    const PeriodicProof o = prove_periodic(c, m);
    ASSERT_TRUE(o.verdict.proved) << "m=" << m << ": " << o.verdict.describe();
    ASSERT_EQ(o.orbit.size(), static_cast<std::size_t>(m));
    for (int j = 0; j < m; ++j) {
      const SegmentProof& J = o.word[static_cast<std::size_t>(j)] == '1' ? c.J1 : c.J0;
      EXPECT_GE(o.orbit[static_cast<std::size_t>(j)].lower(), J.lo);
      EXPECT_LE(o.orbit[static_cast<std::size_t>(j)].upper(), J.hi);
      EXPECT_LT(o.orbit[static_cast<std::size_t>(j)].radius(), 1e-15);
    }
    // One floating step from the enclosed point lands next to the next enclosed point.
    const double x0 = o.orbit[0].mid(), x1 = o.orbit[static_cast<std::size_t>(1 % m)].mid();
    EXPECT_NEAR(T(p, x0), x1, 1e-9);
    EXPECT_TRUE(o.log_multiplier.is_positive());
  }
  const CoveringProof none = prove_covering(ParameterBox::point(1, 0.02, 0.85));
  EXPECT_FALSE(prove_periodic(none, 3).verdict.proved);
}

TEST(CertifiedSuperstable, WindowEdgesAndNoSuperstabilityOutside) {
  const double lo = 0.0640755627691, hi = 0.064187276763;  // floating estimate of the window near 0.0641
  const WindowProof w = prove_window(1, 0.85, lo, hi);
  ASSERT_TRUE(w.verdict.proved) << w.verdict.describe();
  EXPECT_LT(w.left_out, w.left_in);
  EXPECT_LT(w.right_in, w.right_out);
  EXPECT_GT(w.inside.eps, 0);
  EXPECT_TRUE(w.inside.condition == 21 || w.inside.condition == 22);
  // Just outside either edge: refuted (T(t2) in the free arc).
  for (double b : {w.left_out, w.right_out}) {
    const SuperstableProof s = prove_superstable(1, b, 0.85);
    EXPECT_FALSE(s.verdict.proved) << b;
    EXPECT_TRUE(s.verdict.refuted) << b;
  }
  // The floating layer agrees: superstable inside, not outside.
  EXPECT_TRUE(superstable_check(Parameters(1, 0.5 * (lo + hi), 0.85), 2000).fixed);
  EXPECT_FALSE(superstable_check(Parameters(1, w.right_out, 0.85), 2).fixed);
}

// Erratum: Theorem 2's hypotheses (2) and (22) hold, but b > b0(q): T(t2) != t2.
TEST(CertifiedSuperstable, Theorem2NeedsLemma1) {
  const Theorem2Counterexample x = prove_theorem2_counterexample(1, 0.10854, 0.85);
  ASSERT_TRUE(x.verdict.proved) << x.verdict.describe();
  const MapStep s = return_map_step(Parameters(1, 0.10854, 0.85), *Parameters(1, 0.10854, 0.85).t2());
  EXPECT_EQ(s.scenario, Scenario::D);
  EXPECT_TRUE(within(x.T, s.T, kPhaseAbsTol));
  EXPECT_FALSE(prove_superstable(1, 0.10854, 0.85).verdict.proved);
  // Below b0(q) there is no such counterexample at a superstable point.
  EXPECT_FALSE(prove_theorem2_counterexample(1, 0.0641, 0.85).verdict.proved);
}

TEST(CertifiedRegion, SmallBandIsDeterministicAndProved) {
  RegionOptions o;
  o.b_lo = 1.999e-3;
  o.b_hi = 2e-3;
  o.q_lo = 0.9;
  o.q_hi = 0.92;
  o.q_columns = 2;
  o.max_boxes = 200;
  const RegionResult r = certify_region(o);
  EXPECT_GT(r.boxes_proved, 0);
  for (const auto& c : r.columns)
    for (const auto& b : c.boxes) {
      EXPECT_GE(b.b_lo, o.b_lo);
      EXPECT_LE(b.b_hi, o.b_hi);
    }
}

// The arc L1 of Lemma 4's proof (arc_l1.hpp), proved for every b/a up to eps_max at once: the floating
// layer, with its own root searches, must agree on sampled starts, from b/a = 1e-9 up to eps_max and
// from 197 pi/100 up to t3 (the degenerate corner where the flight shrinks to nothing). The first
// contact lies in [theta + A/g_hi, theta + A/g_lo] and after t3, the progression stops within W of it
// and before t0 + 2 pi: scenario C (the mass waits for t0), or D where Lemma 1 fails.
TEST(CertifiedArcL1, ProvedForEveryRatioAndTheFloatingStepsAgree) {
  const ArcL1Proof pr = prove_arc_l1(0.72, 1.0);
  ASSERT_TRUE(pr.verdict.proved) << pr.verdict.describe();
  EXPECT_GT(pr.eps_max, 0.047);  // sin(3 pi/100)/2 = 0.04705...: nothing smaller is needed
  EXPECT_LE(2 * pr.eps_max, std::sin(0.03 * M_PI) * (1 + 1e-15));
  const double t0_margin = pr.t0_min.lower() - pr.S - pr.W;
  ASSERT_GT(t0_margin, 0);
  unsigned seed = 12345;
  const auto uniform = [&seed] {
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 8) & 0xFFFFFF) / 16777216.0;
  };
  int c_count = 0;
  for (int i = 0; i < 3000; ++i) {
    const double eps = std::exp(std::log(1e-9) + uniform() * (std::log(pr.eps_max) - std::log(1e-9)));
    const double kappa = 0.72 + 0.279 * uniform();
    const Parameters p(1, eps, kappa);
    const double t3 = *p.t3(), lo = 1.97 * M_PI;
    if (!(t3 > lo)) continue;
    // half the starts uniform on L1, half at distance 10^-u (u in [2, 8]) below t3
    const double th = i % 2 == 0 ? lo + (t3 - lo) * uniform() : t3 - (t3 - lo) * std::pow(10.0, -2 - 6 * uniform());
    if (!(th >= lo && th < t3)) continue;
    const MapStep s = return_map_step(p, th);
    const double delta = 2 * M_PI - th, A = 0.5 * (std::sin(delta) - 2 * eps);
    const double flight = s.hit.t1.value() - th, th2 = s.theta2.value();
    const std::string at = "b/a=" + std::to_string(eps) + " q/a=" + std::to_string(kappa) + " theta=t3-" + std::to_string(t3 - th);
    EXPECT_GE(flight, A / pr.g_hi * (1 - 1e-9)) << at;
    EXPECT_LE(flight, A / pr.g_lo * (1 + 1e-9)) << at;
    EXPECT_GT(s.hit.t1.value(), t3) << at;
    EXPECT_GT(th2, s.hit.t1.value() - 1e-12) << at;
    EXPECT_LE(th2 - s.hit.t1.value(), pr.W) << at;
    EXPECT_LT(th2, *p.t0() + 2 * M_PI) << at;
    EXPECT_TRUE(s.scenario == Scenario::C || s.scenario == Scenario::D) << at << " scenario " << static_cast<int>(s.scenario);
    if (s.scenario == Scenario::C) {
      EXPECT_EQ(s.T, *p.t2()) << at;
      ++c_count;
    }
  }
  EXPECT_GT(c_count, 1000);
}

TEST(CertifiedArcL1, NotProvedWhereTheProgressionMayNotStopInTime) {
  const ArcL1Proof pr = prove_arc_l1(0.3, 1.0);
  EXPECT_FALSE(pr.verdict.proved);
  EXPECT_NE(pr.verdict.step.find("progression"), std::string::npos) << pr.verdict.describe();
}

// Lemma 4 for every b/a <= eps* (lemma4_uniform.hpp): the floating layer, with its own scan for the
// discontinuities of T1 (branch labels, both families of Eq. 14) and its own T, must show what the
// argument of docs/certified.md derives from the certified inequalities: on L2 the discontinuities
// are exactly the symmetric tangencies (at least three); T(z_i + 0) lies in [99pi/50, 199pi/100];
// along a branch T1 decreases, and T = theta2 mod 2pi (scenario A) decreases until theta2 leaves
// [t2, t3) through t2; just left of z_(i+1) the progression stops in the stop arc (t3, t0 + 2pi),
// so T = t2 there where Lemma 1 holds (q/a = 0.85; at 0.65 < sin(vartheta0) it does not).
namespace {

/// The floating checks of the argument on the segment [pi + w_a, pi + w_b] at (eps, kappa).
void check_branches(double w_a, double w_b, double eps, double kappa) {
  const Parameters p(1, eps, kappa);
  const std::string at =
      "b/a=" + std::to_string(eps) + " q/a=" + std::to_string(kappa) + " w in [" + std::to_string(w_a) + ", " + std::to_string(w_b) + "]";
  const double lo = M_PI + w_a, hi = M_PI + w_b, two_pi = 2 * M_PI;
  const std::vector<GrazingPoint> gp = grazing_points(p, lo, hi, 4000);
  const std::vector<SymmetricTangency> sym = symmetric_tangencies(p, lo, hi);
  ASSERT_GE(sym.size(), 3u) << at;
  ASSERT_EQ(gp.size(), sym.size()) << at;
  for (std::size_t i = 0; i < sym.size(); ++i) EXPECT_NEAR(gp[i].z, sym[i].z, 1e-9 * std::fabs(sym[i].z)) << at << " i=" << i;
  const double t2 = *p.t2(), t3 = *p.t3(), t0 = *p.t0();
  for (std::size_t i = 0; i + 1 < 3; ++i) {
    const double z0 = sym[i].z, w = sym[i + 1].z - z0;
    std::vector<double> frac;  // of the branch: near z_i, uniform, then geometric towards z_(i+1)
    frac.push_back(1e-9);
    for (int j = 1; j < 400; ++j) frac.push_back(j / 400.0);
    for (int m = 3; m <= 9; ++m) frac.push_back(1 - std::pow(10.0, -m));
    double last_T = 0, last_T1 = 0;
    bool left_free = false;
    const double T_start = two_pi - (z0 - M_PI);  // T(z_i + 0) = T1(z_i) mod 2pi = 2pi - w_i
    for (std::size_t j = 0; j < frac.size(); ++j) {
      const double th = z0 + w * frac[j];
      const MapStep s = return_map_step(p, th);
      const double th2 = std::fmod(s.theta2.value(), two_pi);
      if (j == 0) {
        EXPECT_NEAR(s.T, T_start, 5e-3) << at << " T(z_i + 0), approached like a square root";
        EXPECT_GT(s.T, 1.5 * M_PI) << at;
      } else {
        EXPECT_LT(s.hit.t1.value(), last_T1) << at << " T1 decreases on the branch, theta=" << th;
      }
      last_T1 = s.hit.t1.value();
      if (!left_free && !(th2 > t2 && th2 < t3)) {
        // theta2 leaves (t2, t3) through t2: the first step outside has T = t2 (step 3 of the argument).
        EXPECT_EQ(s.T, t2) << at << " theta2 left (t2, t3) elsewhere than through t2, theta=" << th << " scenario " << static_cast<int>(s.scenario);
        left_free = true;
      }
      if (!left_free) {
        EXPECT_EQ(s.scenario, Scenario::A) << at << " theta=" << th;
        if (j > 0) {
          EXPECT_LT(s.T, last_T) << at << " T decreases until theta2 leaves [t2, t3), theta=" << th;
        }
      }
      last_T = s.T;
      if (j + 1 == frac.size()) {
        EXPECT_TRUE(th2 > t3 || th2 < t2) << at << " stop arc left of z_(i+1): theta2 mod 2pi = " << th2;
        if (kappa > sin_vartheta0() && (th2 > t3 || th2 < t0)) {
          EXPECT_EQ(s.T, t2) << at << " T = t2 just left of z_(i+1)";
        }
      }
    }
    EXPECT_TRUE(left_free) << at << " branch " << i;
  }
}

}  // namespace

// Why (I9) (Lemma 1) is needed: below sin(vartheta0) the first zero of the progression's velocity jumps
// to phase t0 along a branch before theta2 reaches t2, the mass then stops at t4 in (t2, t3), and T
// never reaches t2 on the branch (a referee's counterexample: q/a = 0.65, b/a = 1e-5, the paper's L2).
// The proof refuses such boxes at (I9).
TEST(CertifiedLemma4Uniform, WithoutLemma1ABranchStopsAboveT2) {
  EXPECT_FALSE(prove_lemma4_uniform(0.62, 0.999).verdict.proved);
  EXPECT_NE(prove_lemma4_uniform(0.62, 0.999).verdict.step.find("(I9)"), std::string::npos);
  const Parameters p(1, 1e-5, 0.65);
  const std::vector<SymmetricTangency> sym = symmetric_tangencies(p, 1.01 * M_PI, 1.02 * M_PI);
  ASSERT_GE(sym.size(), 2u);
  double T_min = 10;
  for (int j = 1; j < 4000; ++j) T_min = std::min(T_min, return_map_step(p, sym[0].z + (sym[1].z - sym[0].z) * j / 4000.0).T);
  EXPECT_GT(T_min, *p.t2() + 0.1) << "T on the first branch of L2 stays above t4, well above t2";
}

TEST(CertifiedLemma4Uniform, ProvedAndTheFloatingBranchesAgree) {
  const Lemma4UniformProof pr = prove_lemma4_uniform(0.73, 0.999);  // the paper's L2
  ASSERT_TRUE(pr.verdict.proved) << pr.verdict.describe();
  EXPECT_GT(pr.eps_star, 7.8e-5);
  for (double eps : {0.999 * pr.eps_star, 3e-5, 1e-5, 1e-6})
    for (double kappa : {0.75, 0.85}) check_branches(pr.w_a, pr.w_b, eps, kappa);
  // A wider segment (best_lemma4_uniform): larger b/a.
  for (double kappa : {0.75, 0.85}) {
    const Lemma4UniformProof wide = best_lemma4_uniform(kappa, 0.999);
    ASSERT_TRUE(wide.verdict.proved) << wide.verdict.describe();
    EXPECT_GT(wide.eps_star, 4 * pr.eps_star) << "q/a=" << kappa;
    for (double f : {0.999, 0.5, 0.1}) check_branches(wide.w_a, wide.w_b, f * wide.eps_star, kappa);
  }
}

// prove_rectangle: the uniform route where it applies (exactly), boxes above it, and the stops.
TEST(CertifiedRectangle, UniformRouteAppliesExactlyWhereItsProofHolds) {
  const Lemma4UniformProof u = prove_lemma4_uniform(0.85, 0.86);  // the paper's L2: every b/a <= eps*
  ASSERT_TRUE(u.verdict.proved) << u.verdict.describe();
  const double e = u.eps_star;
  // Inside: the whole rectangle, no box.
  RectangleProof r = prove_rectangle(1, e / 8, e / 2, 0.85, 0.86, u);
  EXPECT_EQ(r.proved_fraction(), 1);
  EXPECT_EQ(r.attempts, 0);
  EXPECT_EQ(r.stop, RectangleStop::Decided);
  EXPECT_EQ(r.uniform_bound, e);
  // The same rectangle scaled by a = 2: only ratios matter, and the comparisons are exact.
  r = prove_rectangle(2, e / 4, e, 1.7, 1.72, u);
  EXPECT_EQ(r.proved_fraction(), 1) << r.uniform_length;
  // Straddling eps*: the uniform part ends at eps* exactly; above it one box is allowed.
  RectangleOptions one;
  one.max_boxes = 1;
  r = prove_rectangle(1, e / 2, 2 * e, 0.85, 0.86, u, one);
  EXPECT_EQ(r.uniform_length, e - e / 2);
  EXPECT_EQ(r.attempts, 1);
  EXPECT_EQ(r.stop, RectangleStop::BoxBudget);
  EXPECT_LT(r.proved_fraction(), 1);
  EXPECT_GE(r.proved_fraction(), 1.0 / 3);
  // A q range reaching outside the proof's box, or a proof not proved: no uniform route.
  for (const RectangleProof& x :
       {prove_rectangle(1, e / 8, e / 2, 0.8499999, 0.86, u, one), prove_rectangle(1, e / 8, e / 2, 0.85, 0.8600001, u, one),
        prove_rectangle(1, e / 8, e / 2, 0.85, 0.86, Lemma4UniformProof{}, one)}) {
    EXPECT_EQ(x.uniform_bound, 0);
    EXPECT_EQ(x.uniform_length, 0);
  }
  for (auto bad : {std::array<double, 5>{1, 0, 1e-3, 0.85, 0.86},
                   {1, 2e-3, 1e-3, 0.85, 0.86},
                   {1, 1e-3, 1e-3, 0.85, 0.86},
                   {0, 1e-3, 2e-3, 0.85, 0.86},
                   {1, 1e-3, 2e-3, 0.86, 0.85},
                   {1, 1e-3, NAN, 0.85, 0.86}})
    EXPECT_THROW(prove_rectangle(bad[0], bad[1], bad[2], bad[3], bad[4], u), std::invalid_argument);
}

TEST(CertifiedRectangle, BoxesAboveTheBoundAndGivingUpBeyondTheCovering) {
  // Above any uniform bound, in the solid covering region (docs/cluster.md): proved by boxes.
  RectangleProof r = prove_rectangle(1, 5e-3, 5.005e-3, 0.9, 0.91, Lemma4UniformProof{});
  EXPECT_EQ(r.proved_fraction(), 1);
  EXPECT_GT(r.boxes_proved, 0);
  EXPECT_EQ(r.stop, RectangleStop::Decided);
  EXPECT_EQ(r.box_length, r.b_hi - r.b_lo);
  // Far above the sampled edge no box is proved: the run of failures stops it.
  RectangleOptions o;
  o.max_failed_run = 3;
  r = prove_rectangle(1, 0.03, 0.031, 0.9, 0.91, Lemma4UniformProof{}, o);
  EXPECT_EQ(r.proved_fraction(), 0);
  EXPECT_EQ(r.boxes_failed, 3);
  EXPECT_EQ(r.stop, RectangleStop::FailedRun);
  EXPECT_LT(r.b_reached, 0.031);
}

TEST(CertifiedContinuation, EveryStepOfAFollowedOrbitIsProvedAndAFalseCycleIsNot) {
  // The orbit of itinerary (001)^infinity followed from b/a = 3e-3 up to 3.05e-3: for every b between
  // two consecutive rows a cycle exists in the boxes (covering relations over the b-interval).
  const double q = 0.85, b0 = 3e-3;
  const ItineraryOrbit start = periodic_orbit(Parameters(1.0, b0, q), "001");
  const OrbitBranch br = follow_periodic_orbit(1.0, q, b0, start.x, 3.05e-3);
  ASSERT_GE(br.points.size(), 3U);
  const std::vector<int> proved = prove_branch_steps(1.0, q, br);
  ASSERT_EQ(proved.size(), br.points.size());
  EXPECT_EQ(proved[0], -1);
  for (std::size_t k = 1; k < proved.size(); ++k) EXPECT_EQ(proved[k], 1) << "step " << k << " b=" << br.points[k].b;
  // The boxes contain the floating cycle at every row of the interval's ends.
  const CycleIntervalProof c = prove_cycle_on_interval(1.0, q, br.points[0].b, br.points[1].b, br.points[0].x, br.points[1].x);
  ASSERT_TRUE(c.verdict.proved);
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_TRUE(c.X[j].contains(br.points[0].x[j]));
    EXPECT_TRUE(c.X[j].contains(br.points[1].x[j]));
  }
  // Not a cycle: x_1 and x_2 exchanged. The relations fail (or T is not continuous on the widened boxes).
  std::vector<double> swapped = br.points[0].x;
  std::swap(swapped[1], swapped[2]);
  EXPECT_FALSE(prove_cycle_on_interval(1.0, q, br.points[0].b, br.points[1].b, swapped, swapped).verdict.proved);
  // Bad input is refused without a proof.
  EXPECT_FALSE(prove_cycle_on_interval(1.0, q, 3.1e-3, 3e-3, br.points[0].x, br.points[1].x).verdict.proved);
  EXPECT_FALSE(prove_cycle_on_interval(1.0, q, 3e-3, 3.1e-3, br.points[0].x, {1.0}).verdict.proved);
}

TEST(CollatzWielandt, UpperBoundEnclosesKnownSpectralRadii) {
  // All ones (n x n): rho = n. [[1, 1], [1, 0]]: the golden ratio. A row without ones is allowed.
  BandMatrix full;
  for (int j = 0; j < 7; ++j) full.first.push_back(0), full.last.push_back(6);
  const double r7 = collatz_wielandt_upper(full);
  EXPECT_GE(r7, 7.0);
  EXPECT_LT(r7, 7.0 * (1 + 1e-12));
  BandMatrix fib;
  fib.first = {0, 0, 2};
  fib.last = {1, 0, 1};  // row 2 is empty
  const double golden = 0.5 * (1 + std::sqrt(5.0));
  const double rf = collatz_wielandt_upper(fib);
  EXPECT_GE(rf, golden);
  EXPECT_LT(rf, golden * (1 + 1e-9));
  EXPECT_EQ(fib.ones(), 3);
}

TEST(CertifiedLaps, CountMatchesTheFloatingBreaksAndBoundsAreOrdered) {
  // At (q/a, b/a) = (0.95, 0.01), against T on a fine floating grid: the steps y_{i+1} - y_i keep
  // one sign along a lap, so each run of two or more steps of one sign (zero steps, on a plateau,
  // skipped; a lone step of the other sign is a jump between two laps) lies in its own lap. The
  // certified partition may add laps (any doubt adds one), but only a few here.
  const double b = 0.01, q = 0.95;
  const EntropyBracket e = prove_entropy_bracket(1.0, b, q);
  ASSERT_TRUE(e.verdict.proved) << e.verdict.describe();
  const LapPartition& p = e.partition;
  const Parameters par(1.0, b, q);
  const double t2 = *par.t2(), t3 = *par.t3();
  const int grid = 200000;
  long long runs = 0, run_length = 0;
  int sign = 0;
  double previous = T(par, t2);
  for (int i = 1; i < grid; ++i) {
    const double y = T(par, t2 + (t3 - t2) * i / grid), d = y - previous;
    previous = y;
    if (d == 0) continue;
    const int s = d > 0 ? 1 : -1;
    if (s == sign) {
      if (++run_length == 2) ++runs;
    } else {
      sign = s, run_length = 1;
    }
  }
  EXPECT_GE(static_cast<long long>(p.laps.size()), runs);
  EXPECT_LE(static_cast<long long>(p.laps.size()), runs + 3);
  // Laps ascending, covering [t2, t3) without holes.
  EXPECT_LE(p.laps.front().lo, t2);
  EXPECT_GE(p.laps.back().hi, t3);
  for (std::size_t j = 1; j < p.laps.size(); ++j) EXPECT_LE(p.laps[j].lo, p.laps[j - 1].hi) << "hole before lap " << j;
  // ln 2 < lower <= upper <= ln(laps).
  EXPECT_GT(e.h_lower(), std::log(2.0));
  EXPECT_LE(e.h_lower(), e.h_upper());
  EXPECT_LE(e.h_upper(), e.log_laps.upper());
  // The other certified lower bound (covering graph on grid segments, entropy.hpp) is below this upper.
  const EntropyProof g = prove_entropy_bound(1.0, b, q);
  ASSERT_TRUE(g.verdict.proved);
  EXPECT_LE(g.log_rho_lower.lower(), e.h_upper());
  // The same on one thread (the parts are joined in order).
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const EntropyBracket one = prove_entropy_bracket(1.0, b, q);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.partition.laps.size(), p.laps.size());
  EXPECT_EQ(one.rho_upper, e.rho_upper);
  EXPECT_EQ(one.rho_lower, e.rho_lower);
}

TEST(CertifiedLaps, RejectsParametersOutsideTheModel) {
  EXPECT_FALSE(prove_laps(1.0, 0.6, 0.95).verdict.proved);   // b >= a/2
  EXPECT_FALSE(prove_laps(1.0, 0.01, 0.01).verdict.proved);  // q <= 2b
  EXPECT_FALSE(prove_entropy_bracket(1.0, 0.6, 0.95).verdict.proved);
}
