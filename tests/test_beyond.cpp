/// @file test_beyond.cpp
/// @brief Cross-validation of the results beyond the paper: the perturbed integrator of Section 10
/// at eps = 0 against the exact T; T' by the implicit function theorem against finite differences;
/// the drilling-rate fiber against the simulator; the eventual regimes of the Remark of Section 9.
#include <gtest/gtest.h>

#include <cmath>

#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/eventual_regime.hpp"
#include "dfchaos/map_derivative.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/simulator.hpp"

namespace {

using namespace dfchaos;

constexpr double kPerturbedAtZeroTol = 1e-8;   // issue 6: integrated map at eps = 0 vs exact T
constexpr double kDerivativeRelTol = 1e-4;     // implicit derivative vs central differences
constexpr double kFiberRelTol = 1e-9;          // penetration carried by T vs simulator

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
  EXPECT_EQ(eventual_regime(Parameters(1.0, 0.6, 2.5), 0.0, 0.0, 40, 10).behaviour, EventualBehaviour::StaysStopped);
  EXPECT_EQ(eventual_regime(Parameters(1.0, 0.6, 1.0), 0.0, 0.0, 40, 10).behaviour, EventualBehaviour::EternalProgression);
  EXPECT_EQ(eventual_regime(Parameters(1.0, 0.01, 0.85), 0.0, 4.0, 40, 10).behaviour, EventualBehaviour::FreeFlights);
  const EventualBehaviour between = eventual_regime(Parameters(1.0, 0.6, 1.9), 0.0, 0.0, 40, 10).behaviour;
  EXPECT_TRUE(between == EventualBehaviour::EternalProgression || between == EventualBehaviour::PeriodicStickSlip);
}

TEST(EventualRegime, RejectsBadCounts) {
  EXPECT_THROW(eventual_regime(Parameters(1.0, 0.6, 1.0), 0.0, 0.0, 10, 20), InvalidParameter);
  EXPECT_THROW(orbit_statistics(Parameters(1.0, 0.01, 0.85), 4.0, -1, 10), InvalidParameter);
}

}  // namespace
