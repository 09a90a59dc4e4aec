// SPDX-License-Identifier: GPL-3.0-or-later
/// @file sec2_model.cpp
/// @brief Section 2: the assumptions (2), the closed-form solutions of the regimes (Eqs. 3–7)
/// against numerical integration, the stop regime (Eq. 5), and Section 3's reduction to starts at
/// rest in [t2, t3) (Eq. 10) from arbitrary initial states.
#include <algorithm>
#include <cmath>
#include <random>

#include "dfchaos/motion.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/simulator.hpp"
#include "kit/experiment.hpp"
#include "kit/grid.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {
constexpr double kClosedFormTol = 1e-9;  // |closed form - integration|, relative to 1 + |value|
constexpr std::uint64_t kSeed = 20130214;
}  // namespace

const Experiment experiment{
    .title = "Section 2: assumptions (2), closed forms (3)-(7), the stop (5), and starts at rest (10)",
    .paper = {"Eq. (2)", "Eq. (3)", "Eq. (4)", "Eq. (5)", "Eq. (6)", "Eq. (7)", "Eq. (10)", "Section 2"},
    .tests = {"test_motion", "test_reduction", "test_parameters"},
    .options = {count("n", 400, "random states per check").range(10, 1'000'000).fast_value(40),
                count("grid", 200, "grid points per axis of the (q/a, b/a) region of (2)").range(2, 10000).fast_value(20)},
    .outputs = {data("closed-forms", "closed forms (Eqs. 3, 6, 7) against numerical integration at random states"),
                data("reach", "from random initial states: the first start of free flight from rest at the delimiter")},
    .body = [](Run& run) {
      const int n = run.count_int("n"), ng = run.count_int("grid");
      std::mt19937_64 rng(kSeed);
      std::uniform_real_distribution<double> U(0.0, 1.0);

      // Eq. (2): over the region a sin(vartheta0) < q < a, 0 < b < min(a/2, a sin(vartheta0)/2), the
      // phases t0 < t1 and t2 < t3 exist and c = b - q/2 < 0, so every progression ends.
      const double s0 = sin_vartheta0();
      long long grid_points = 0, violations = 0;
      const Axis q_axis = Axis::centres(s0, 1.0, ng), b_axis = Axis::log(1e-8, s0 / 2 * (1 - 1e-9), ng);
      for (int i = 0; i < ng; ++i)
        for (int j = 0; j < ng; ++j) {
          const Parameters p(1.0, b_axis[j], q_axis[i]);
          ++grid_points;
          if (!(p.assumptions().eq2 && p.t0() && p.t2() && *p.t0() < *p.t1() && *p.t2() < *p.t3() && p.c() < 0)) ++violations;
        }
      run.out
          .claim("eq2.phases_and_progression_end", "Eq. (2)", EvidenceKind::Sampled,
                 "Under (2) with b/a < sin(vartheta0)/2 (so that q > 2b), both F - q and F change sign (t0 < t1 and t2 < t3 "
                 "exist) and c = b - q/2 < 0, so every progression ends: the map T is defined.")
          .ours()
          .evidence("grid_points", grid_points)
          .evidence("violations", violations)
          .holds(violations == 0 && grid_points > 0);

      // Eqs. (3), (6), (7): closed forms against integration of x'' = a sin t + C.
      Table cf({"regime", "b_over_a", "q_over_a", "t0", "x0", "v0", "duration", "x_closed", "x_integrated", "v_closed", "v_integrated"});
      double worst = 0;
      for (int k = 0; k < n; ++k) {
        const double b = 0.2 * U(rng) + 1e-4, q = 0.5 + 0.5 * U(rng), t0 = 20 * U(rng) - 5, x0 = U(rng) - 2, v0 = 2 * U(rng) - 1;
        const double dt = 50 * U(rng);
        const Parameters p(1.0, b, q);
        const Instant t = Instant::from_time(t0 + dt);
        const FreeMotion f(p, Instant::from_time(t0), x0, v0);
        const ProgressionMotion g(p, Instant::from_time(t0), x0, std::fabs(v0));
        const auto [xf, vf] = integrate_forced_motion(1.0, 2 * b, t0, x0, v0, t0 + dt);
        const auto [xg, vg] = integrate_forced_motion(1.0, 2 * b - q, t0, x0, std::fabs(v0), t0 + dt);
        for (auto [name, xc, xi, vc, vi] :
             {std::tuple{"free (3)", f.position(t), xf, f.velocity(t), vf}, std::tuple{"progression (6)", g.position(t), xg, g.velocity(t), vg}}) {
          worst = std::max({worst, std::fabs(xc - xi) / (1 + std::fabs(xi)), std::fabs(vc - vi) / (1 + std::fabs(vi))});
          if (k < 100) cf.row({std::string(name), b, q, t0, x0, v0, dt, xc, xi, vc, vi});
        }
      }
      // Eq. (7): from rest at t0 the velocity is -a (cos t - cos t0) + 2c (t - t0).
      double worst7 = 0;
      for (int k = 0; k < n; ++k) {
        const double b = 0.1 * U(rng) + 1e-4, q = s0 + (1 - s0) * U(rng), dt = 2 * pi * U(rng);
        const Parameters p(1.0, b, q);
        const double t0 = *p.t0();
        const double v7 = -(std::cos(t0 + dt) - std::cos(t0)) + 2 * p.c() * dt;
        const auto [x, v] = integrate_forced_motion(1.0, 2 * p.c(), t0, 0.0, 0.0, t0 + dt);
        (void)x;
        worst7 = std::max(worst7, std::fabs(v7 - v) / (1 + std::fabs(v)));
      }
      run.table("closed-forms", cf);
      run.out
          .claim("eq3_7.closed_forms", "Eqs. (3)-(7)", EvidenceKind::Sampled,
                 "The closed-form solutions of the free regime (3) and of the progression (6), and the velocity (7) from rest at t0, "
                 "agree with numerical integration of the equations of motion (GSL rk8pd) to {tol} (relative to 1 + |value|) at "
                 "random states and durations up to 50.")
          .evidence("states", static_cast<long long>(n))
          .evidence("worst_eq3_eq6", worst)
          .evidence("worst_eq7", worst7)
          .at_most("worst", std::max(worst, worst7), kClosedFormTol);

      // Eq. (5) and Eq. (10): from random initial states at parameters of (2), the simulated motion
      // stops only at rest at the delimiter, and reaches a start of free flight from rest at the
      // delimiter (Eq. 10) at a phase of [t2, t3).
      Table reach({"b_over_a", "q_over_a", "t0", "x0", "v0", "first_free_start", "phase", "stop_violations"});
      long long reached = 0, not_reached = 0, stop_violations = 0, stops = 0;
      for (int k = 0; k < n; ++k) {
        const double b = std::exp(std::log(1e-3) + std::log(50.0) * U(rng)), q = s0 + (1 - s0) * U(rng);
        const double t0 = 20 * U(rng), gap = U(rng) < 0.3 ? 0.0 : -U(rng), v0 = 2 * U(rng) - 1;
        const Parameters p(1.0, b, q);
        // A first flight from (gap, v0) lasts at most about 2(|v0| + 2a)/(2b): the horizon covers it.
        const double horizon = 60 * two_pi + 10 * (std::fabs(v0) + 2) / b;
        const Simulation sim = simulate(p, gap, 0.0, v0, t0, t0 + horizon);
        double first = NAN, phase = NAN;
        long long viol = 0;
        for (const auto& e : sim.events) {
          if (e.after == Regime::Stop) {
            ++stops;
            if (!(e.x == e.y && e.v_after == 0)) ++viol;  // Eq. (5): x = y, velocity zero
          }
          if (std::isnan(first) && e.after == Regime::Free && e.before != Regime::Free) {
            first = e.t;
            phase = e.when.phase;
            if (!(e.x == e.y && e.v_after == 0 && phase_in_arc(phase, *p.t2(), *p.t3()))) ++viol;
          }
        }
        stop_violations += viol;
        (std::isnan(first) ? not_reached : reached)++;
        if (k < 200) reach.row({b, q, t0, gap, v0, first, phase, viol});
      }
      run.table("reach", reach);
      run.out
          .claim("eq10.reached_from_any_state", "Section 3, Eq. (10)", EvidenceKind::Sampled,
                 "Whatever the initial state, the motion reaches a start of free flight from rest at the delimiter (Eq. 10) at a phase of "
                 "[t2, t3) (within 60 periods after the longest possible first flight), and every stop is at rest at the delimiter (Eq. 5).")
          .evidence("initial_states", static_cast<long long>(n))
          .evidence("reached", reached)
          .evidence("not_reached", not_reached)
          .evidence("stops", stops)
          .evidence("violations", stop_violations)
          .holds(not_reached == 0 && stop_violations == 0);
      run.out.macro("SecTwoClosedFormWorst", std::max(worst, worst7), 2);
      run.out.macro("SecTwoStates", std::to_string(n));
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
