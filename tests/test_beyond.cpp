// SPDX-License-Identifier: GPL-3.0-or-later
/// @file test_beyond.cpp
/// @brief Cross-validation of the results beyond the paper: the perturbed integrator of Section 10
/// at eps = 0 against the exact T; T' by the implicit function theorem against finite differences;
/// the drilling-rate fiber against the simulator; the eventual regimes of the Remark of Section 9.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/eventual_regime.hpp"
#include "dfchaos/map_derivative.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/simulator.hpp"
#include "dfchaos/superstable.hpp"

#include "test_support.hpp"

namespace {

using namespace dfchaos;

constexpr double kPerturbedAtZeroTol = 1e-8;  // integrated map at eps = 0 vs exact T
constexpr double kDerivativeRelTol = 1e-4;    // implicit derivative vs central differences
constexpr double kFiberRelTol = 1e-9;         // penetration carried by T vs simulator

TEST(PerturbedMap, AgreesWithExactTAtZeroPerturbation) {
  for (double b : {0.05, 0.01}) {
    const Parameters p(1.0, b, 0.9);
    OdeMapOptions o;
    o.perturbation = [](double, double, double) { return 0.0; };
    const double t2 = *p.t2(), t3 = *p.t3();
    for (int i = 0; i < 25; ++i) {
      const double th = t2 + (t3 - t2) * (i + 0.37) / 25;
      EXPECT_LT(circle_distance(ode_return_map_step(p, th, o).T, T(p, th)), kPerturbedAtZeroTol) << "b=" << b << " theta=" << th;
    }
  }
}

TEST(PerturbedMap, PerturbationChangesTheMap) {
  // A test that can fail the other way: a nonzero G must move T (else the perturbation is ignored).
  const Parameters p(1.0, 0.01, 0.9);
  OdeMapOptions o;
  o.perturbation = [](double t, double, double) { return 1e-3 * std::cos(2 * t + 1); };
  const double th = *p.t2() + 0.4 * (*p.t3() - *p.t2());
  EXPECT_GT(circle_distance(ode_return_map_step(p, th, o).T, T(p, th)), 1e-6);
}

TEST(MapDerivative, MatchesCentralDifferences) {
  long long compared = 0;
  for (double b : {0.05, 0.01, 0.002}) {
    const Parameters p(1.0, b, 0.85);
    const double t2 = *p.t2(), t3 = *p.t3();
    for (int i = 1; i < 300; ++i) {
      const double th = t2 + (t3 - t2) * i / 300;
      const LabelledStep c = continuity_label(p, th);
      const MapDerivative d = map_derivative(p, c.step);
      if (d.flat) {
        EXPECT_EQ(d.dT, 0.0);
        continue;
      }
      if (!std::isfinite(d.dT)) continue;
      const double h = 1e-6 / std::max(1.0, std::fabs(d.dT));
      const LabelledStep lo = continuity_label(p, th - h), hi = continuity_label(p, th + h);
      if (!(lo.label == c.label) || !(hi.label == c.label) || lo.step.scenario != Scenario::A || hi.step.scenario != Scenario::A) continue;
      const double fd = (hi.step.T - lo.step.T) / (2 * h);
      EXPECT_LT(std::fabs(fd - d.dT) / std::max(1.0, std::fabs(d.dT)), kDerivativeRelTol) << "b=" << b << " theta=" << th;
      ++compared;
    }
  }
  EXPECT_GT(compared, 100);
}

TEST(DrillingRate, FiberMatchesSimulator) {
  const Parameters p(1.0, 0.02, 0.85);
  double theta = *p.t2() + 0.3 * (*p.t3() - *p.t2()), t_total = 0, y_total = 0;
  const double start = theta;
  for (int i = 0; i < 200; ++i) {
    const MapStep s = return_map_step(p, theta);
    t_total += s.elapsed;
    y_total += s.penetration;
    theta = s.T;
  }
  const Simulation sim = simulate(p, 0.0, 0.0, 0.0, start, start + t_total);
  EXPECT_LT(std::fabs(sim.final_state.y - y_total) / y_total, kFiberRelTol);
  const OrbitStatistics st = orbit_statistics(p, start, 0, 200);
  EXPECT_NEAR(st.penetration_rate, y_total / t_total, 1e-12 * y_total / t_total);
}

TEST(EventualRegime, CasesOfTheRemarkOfSection9) {
  // Each case of the Remark from three different initial states (v0, t0): the eventual behaviour
  // depends on the parameters only. The expected behaviour is predicted independently: q >= a + 2b
  // stays stopped; q <= 2b (c >= 0) progresses for ever; 2b < q < a + 2b with b >= a/2 repeats a
  // progression from rest at t0 that stops within the period (its velocity
  // -a (cos t - cos t0) + 2c (t - t0) is negative at t0 + 2 pi), at the first zero of that velocity,
  // found here by a plain scan; b < a/2 keeps free flights.
  struct Case {
    double b, q;
    EventualBehaviour expected;
  };
  const Case cases[] = {{0.6, 2.5, EventualBehaviour::StaysStopped},        {0.6, 1.0, EventualBehaviour::EternalProgression},
                        {0.6, 1.15, EventualBehaviour::EternalProgression},  // 2b - a < q < 2b
                        {0.6, 1.9, EventualBehaviour::PeriodicStickSlip},   {0.7, 1.5, EventualBehaviour::PeriodicStickSlip},
                        {0.01, 0.85, EventualBehaviour::FreeFlights}};
  for (const Case& k : cases) {
    const Parameters p(1.0, k.b, k.q);
    double predicted_stop_from_t1 = NAN;  // stick-slip: the stop phase, measured from t1
    if (k.expected == EventualBehaviour::PeriodicStickSlip) {
      const double t0 = *p.t0(), t1 = *p.t1(), c = p.c();
      for (int i = 1; i <= 2'000'000; ++i) {
        const double t = t0 + two_pi * i / 2'000'000;
        if (-(std::cos(t) - std::cos(t0)) + 2 * c * (t - t0) < 0) {
          predicted_stop_from_t1 = wrap_phase(t - t1);
          break;
        }
      }
      ASSERT_FALSE(std::isnan(predicted_stop_from_t1)) << "b=" << k.b << " q=" << k.q;
    }
    for (auto [v0, t0] : {std::pair{0.0, 0.0}, std::pair{0.5, 1.7}, std::pair{2.0, 4.0}}) {
      const EventualRegime r = eventual_regime(p, v0, t0, 40, 10);
      EXPECT_EQ(r.behaviour, k.expected) << "b=" << k.b << " q=" << k.q << " v0=" << v0 << " t0=" << t0 << ": "
                                         << eventual_behaviour_name(r.behaviour);
      if (k.expected == EventualBehaviour::PeriodicStickSlip) {
        EXPECT_NEAR(r.stick_stop_phase_min, predicted_stop_from_t1, 1e-5);
        EXPECT_NEAR(r.stick_stop_phase_max, predicted_stop_from_t1, 1e-5);
        EXPECT_LE(r.stick_start_phase_max_error, 1e-9);
      }
    }
  }
}

TEST(EventualRegime, OverlapOfTheRemarkRangesProgressesForEver) {
  constexpr double kInstantStopShare = 1e-8;  // share of time stopped that counts as instantaneous stops
  // The Remark of Section 9 gives q <= 2b an everlasting progression and (2b - a, a + 2b) "everlasting
  // progression or periodic stick-slip": the two ranges overlap on (2b - a, 2b]. The experiment reads the
  // second as 2b < q < a + 2b; this checks that on the overlap the motion does what both cases allow.
  // Independent prediction: with c = b - q/2 >= 0, a progression from rest at t0 has the velocity
  // -a (cos t - cos t0) + 2c (t - t0), positive on (t0, t0 + 2 pi) (checked by a plain scan), so it
  // never stops for a whole period and never does later (the term 2c (t - t0) only grows).
  for (const double b : {0.5, 0.75, 2.0})
    for (const double s : {0.05, 0.5, 0.95, 1.0}) {  // q = 2b - a + s a; s = 1 is q = 2b
      const double q = 2 * b - 1.0 + s;
      const Parameters p(1.0, b, q);
      ASSERT_GE(p.c(), -1e-15) << "b=" << b << " q=" << q;
      const double t0 = *p.t0();
      for (int i = 1; i < 100'000; ++i) {
        const double t = t0 + two_pi * i / 100'000;
        ASSERT_GT(-(std::cos(t) - std::cos(t0)) + 2 * p.c() * (t - t0), 0.0) << "b=" << b << " q=" << q << " t=" << t;
      }
      for (auto [v0, start] : {std::pair{0.0, 0.0}, std::pair{0.5, 1.7}, std::pair{2.0, 4.0}}) {
        const EventualRegime r = eventual_regime(p, v0, start, 40, 10);
        EXPECT_EQ(r.fraction_free, 0.0) << "b=" << b << " q=" << q;
        if (s < 1.0) {
          EXPECT_EQ(r.behaviour, EventualBehaviour::EternalProgression)
              << "b=" << b << " q=" << q << " v0=" << v0 << " t0=" << start << ": " << eventual_behaviour_name(r.behaviour);
        } else {
          // q = 2b: the velocity a (1 - cos t) touches zero once per period, an instantaneous stop that
          // the simulator may record as a stop of rounding length; no stop of positive length.
          EXPECT_TRUE(r.behaviour == EventualBehaviour::EternalProgression || r.behaviour == EventualBehaviour::PeriodicStickSlip)
              << "b=" << b << " v0=" << v0 << " t0=" << start << ": " << eventual_behaviour_name(r.behaviour);
          EXPECT_LE(r.fraction_stop, kInstantStopShare) << "b=" << b << " v0=" << v0 << " t0=" << start;
        }
      }
    }
}

TEST(EventualRegime, RejectsBadCounts) {
  EXPECT_THROW(eventual_regime(Parameters(1.0, 0.6, 1.0), 0.0, 0.0, 10, 20), InvalidParameter);
  EXPECT_THROW(orbit_statistics(Parameters(1.0, 0.01, 0.85), 4.0, -1, 10), InvalidParameter);
}

}  // namespace

// ---- t2_cycle: is a computed return of t2 a superstable cycle of T? --------------------------

TEST(StopCycle, TheoremTwoFixedPointIsResolved) {
  // b/a where Theorem 2's conditions hold at q/a = 0.85 (a value of the drilling-rate basins).
  const Parameters p(1.0, 0.01515540569613256, 0.85);
  const StopCycle c = t2_cycle(p, 100);
  EXPECT_EQ(c.period, 1);
  EXPECT_EQ(c.stops, 1);
  EXPECT_TRUE(c.resolved);
  // Independently: superstable_check measures the stop arc [t2, t2 + epsilon) by a scan and bisection;
  // the radius t2_cycle probed (margin times the error at t2) cannot exceed it.
  const SuperstableCheck s = superstable_check(p, 2000);
  EXPECT_TRUE(s.fixed);
  EXPECT_GT(s.epsilon, 0);
  EXPECT_LE(c.margin * kStopCycleStepError, s.epsilon * (1 + 1e-9));
  // The orbit moved by 1e-8 after its first step (here: t2 + 1e-8, in the stop arc) closes the same cycle.
  EXPECT_TRUE(stop_cycle_survives_shift(p, c, 1e-8));
}

TEST(StopCycle, PeriodTwoCycleIsResolvedAndSurvivesAPerturbedStart) {
  const Parameters p(1.0, 0.0008768960966052783, 0.85);
  const StopCycle c = t2_cycle(p, 100);
  EXPECT_EQ(c.period, 2);
  EXPECT_TRUE(c.resolved);
  EXPECT_GE(c.margin, kStopCycleSafety);
  EXPECT_FALSE(c.lost);
  EXPECT_EQ(first_visit(p, *p.t2(), *p.t2(), 10), 2);
  EXPECT_TRUE(stop_cycle_survives_shift(p, c, 1e-8));
  EXPECT_EQ(t2_cycle(p, c.period).period, c.period);  // a bound equal to the period closes it
}

TEST(StopCycle, AReturnAfterTheDerivativeHasExplodedIsNotResolved) {
  // Near the gallery's b/a = 0.01 (q/a = 0.85) the computed orbit of t2 often returns to t2 after
  // hundreds or thousands of steps, but |(T^k)'(t2)| passes 2^52 after a few dozen: such a return
  // is a cycle of the rounding. Which b/a gives one, and after how many steps, changes with any
  // ulp-level change of T (b/a = 0.01 itself returned after 943 steps until the root solver's
  // start changed, and not within 40000 since), so the parameters are taken from a list: the
  // first whose orbit of t2 returns after more than 100 and at most 40000 steps.
  std::optional<Parameters> chosen;
  StopCycle c;
  for (double b : test_support::kRoundingCycleCandidates) {
    const Parameters q(1.0, b, 0.85);
    c = t2_cycle(q, 40000);
    if (c.period > 100) {
      chosen = q;
      break;
    }
  }
  ASSERT_TRUE(chosen.has_value()) << "no computed orbit of t2 in the list returns within 40000 steps: extend the list";
  const Parameters& p = *chosen;
  EXPECT_FALSE(c.resolved);
  EXPECT_TRUE(c.lost);  // the error reached 1e-3 long before the stop
  EXPECT_EQ(c.margin, 0);
  EXPECT_EQ(first_visit(p, *p.t2(), *p.t2(), c.period), c.period);
  EXPECT_EQ(t2_cycle(p, c.period).period, c.period);
  // Independently: an orbit moved by 1e-12 after its first step (far inside the error budget) does
  // not close the same cycle. (Moved at t2 itself, the shift would be lost: T'(t2) = 0.)
  EXPECT_LT(std::fabs(map_derivative(p, *p.t2()).dT), 1e-10);
  EXPECT_FALSE(stop_cycle_survives_shift(p, c, 1e-12));
}

TEST(StopCycle, RejectsBadBounds) {
  const Parameters p(1.0, 0.01, 0.85);
  EXPECT_THROW(t2_cycle(p, 0), InvalidParameter);
  EXPECT_THROW(t2_cycle(p, 10, 0.0), InvalidParameter);
  EXPECT_THROW(t2_cycle(p, 10, 1.0), InvalidParameter);
  EXPECT_THROW(first_visit(p, *p.t2(), *p.t2(), 0), InvalidParameter);
  EXPECT_THROW(first_visit(p, *p.t3(), *p.t2(), 5), InvalidParameter);               // theta outside [t2, t3)
  EXPECT_THROW(stop_cycle_survives_shift(p, StopCycle{}, 1e-12), InvalidParameter);  // period 0
  StopCycle five;
  five.image = *p.t2();
  five.period = 5;
  EXPECT_THROW(stop_cycle_survives_shift(p, five, 0.0), InvalidParameter);
  EXPECT_THROW(t2_cycle(p, 10'000'001), InvalidParameter);
  EXPECT_THROW(t2_cycle(p, 10, NAN), InvalidParameter);
  EXPECT_THROW(stop_cycle(p, *p.t3(), 10), InvalidParameter);  // an image outside [t2, t3)
}

TEST(StopCycle, NoRepeatWithinTheBoundIsNotACycle) {
  // The computed orbit of t2 at the gallery's parameters returns only after hundreds of steps.
  const Parameters p(1.0, 0.01, 0.85);
  const StopCycle c = t2_cycle(p, 5);
  EXPECT_EQ(c.period, 0);
  EXPECT_FALSE(c.resolved);
  EXPECT_EQ(c.margin, 0);
  EXPECT_EQ(first_visit(p, *p.t2(), *p.t2(), 5), 0);
  EXPECT_FALSE(c.lost);  // five steps: the error is still far below every arc
  // Two hundred steps of a chaotic orbit: no return, and the error has long passed 1e-3, so that the
  // computed orbit's not closing says nothing about the true one (plane.stop_cells_superstable
  // counts such a cell as undecided, not against the claim).
  const StopCycle far = t2_cycle(p, 200);
  EXPECT_EQ(far.period, 0);
  EXPECT_TRUE(far.lost);
}
