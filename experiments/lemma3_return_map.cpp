// SPDX-License-Identifier: GPL-3.0-or-later
/// @file lemma3_return_map.cpp
/// @brief Lemma 3: T(theta) = theta2 mod 2pi when that phase lies in [t2, t3), and T = t2
/// otherwise; the graph of T with its scenarios and stop arcs; cross-checks against the full
/// simulator (every point) and against numerical integration (a subset).
#include <algorithm>
#include <cmath>

#include "dfchaos/ode_map.hpp"
#include "dfchaos/progression_stop.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/simulator.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

const Experiment experiment{
    .title = "Lemma 3: the return map T",
    .paper = {"Lemma 3", "Eq. (17)", "Section 3"},
    .tests = {"test_return_map", "test_reduction"},
    .options = {count("n", 4000, "grid points of theta in [t2, t3)").range(10, 10'000'000).fast_value(200),
                count("ode-every", 40, "cross-check every k-th point by numerical integration").range(1, 10'000'000).fast_value(20)},
    .outputs = {data("", "Lemma 3 per parameter set, with cross-checks"), data("graph-*", "T on [t2, t3) at one parameter set")},
    .body = [](Run& run) {
      const int n = run.count_int("n"), ode_every = run.count_int("ode-every");
      constexpr double kSimulatorTolerance = 1e-10, kIntegrationTolerance = 1e-7;
      Table summary({"b_over_a", "q_over_a", "lemma1_holds", "stop_fraction", "lemma3_violations", "max_sim_diff", "max_ode_diff", "ode_points"});
      long long viol_with_lemma1 = 0, viol_without = 0, checked_with_lemma1 = 0, checked_without = 0;
      long long sim_compared = 0, ode_compared = 0;
      double sim_worst = 0, ode_worst = 0;
      for (auto [ba, qa] : {std::pair{0.01, 0.85}, std::pair{0.05, 0.85}, std::pair{0.05, 0.7}}) {
        const Parameters p(1.0, ba, qa);
        const bool lemma1 = progression_from_t0(p).stops_in_t1_t2;
        const double t2 = *p.t2(), t3 = *p.t3();
        Table graph({"theta", "T", "T1", "theta2_phase", "scenario"});
        long long stops = 0, viol = 0, ode_points = 0;
        double sim_max = 0, ode_max = 0;
        for (int i = 0; i < n; ++i) {
          const double th = t2 + (t3 - t2) * i / n;
          const MapStep s = return_map_step(p, th);
          graph.row({th, s.T, s.hit.theta1, s.theta2.phase, std::string(scenario_name(s.scenario))});
          if (s.T == t2) ++stops;
          // Lemma 3's dichotomy.
          const bool in_arc = phase_in_arc(s.theta2.phase, t2, t3);
          if (in_arc ? s.T != s.theta2.phase : s.T != t2) ++viol;
          // The simulator's first free start after theta.
          const Simulation sim = simulate(p, 0.0, 0.0, 0.0, th, th + s.elapsed + 1e-6);
          for (const auto& e : sim.events)
            if (e.after == Regime::Free && e.before != Regime::Free) {
              sim_max = std::max(sim_max, circle_distance(e.when.phase, s.T));
              ++sim_compared;
              break;
            }
          if (i % ode_every == 0) {
            ++ode_points;
            ode_max = std::max(ode_max, circle_distance(ode_return_map_step(p, th).T, s.T));
          }
        }
        (lemma1 ? viol_with_lemma1 : viol_without) += viol;
        (lemma1 ? checked_with_lemma1 : checked_without) += n;
        ode_compared += ode_points;
        sim_worst = std::max(sim_worst, sim_max);
        ode_worst = std::max(ode_worst, ode_max);
        summary.row({ba, qa, static_cast<long long>(lemma1), static_cast<double>(stops) / n, viol, sim_max, ode_max, ode_points});
        run.out.table("graph-b" + format_significant(ba, 2) + "-q" + format_significant(qa, 2), graph, "T on [t2, t3) at " + p.describe());
      }
      run.table("", summary);

      run.out
          .claim("lemma3.dichotomy", "Lemma 3", EvidenceKind::Sampled,
                 "Where Lemma 1 holds, T(theta) is the phase of theta2 if it lies in [t2, t3), and t2 otherwise.")
          .evidence("checked", checked_with_lemma1)
          .evidence("violations", viol_with_lemma1)
          .holds(viol_with_lemma1 == 0);
      run.out
          .claim("lemma3.needs_lemma1", "Lemma 3", EvidenceKind::Sampled,
                 "Where Lemma 1 fails, T also takes values that are neither theta2 mod 2pi nor t2 (scenario D): Lemma 3 depends on Lemma 1.")
          .ours()
          .not_expected()
          .evidence("checked_where_lemma1_fails", checked_without)
          .evidence("violations_where_lemma1_fails", viol_without)
          .holds(viol_without > 0);
      run.out
          .claim("lemma3.simulator_agrees", "Section 3, Lemma 3", EvidenceKind::Sampled,
                 "The full simulator's first switch to free flight has the phase T(theta), to {tol}.")
          .ours()
          .evidence("phases_compared", sim_compared)
          .evidence("phases", 3LL * n)
          .at_most("max_phase_difference", sim_worst, kSimulatorTolerance);
      run.out
          .claim("lemma3.integration_agrees", "Lemma 3", EvidenceKind::Sampled,
                 "Numerical integration of the equations of motion (GSL rk8pd, events to 1e-12) gives the same T, to {tol}.")
          .ours()
          .evidence("phases_compared", ode_compared)
          .at_most("max_phase_difference", ode_worst, kIntegrationTolerance);
      run.out.macro("LemmaThreeOdeDiff", ode_worst, 2);
      run.out.macro("LemmaThreeSimDiff", sim_worst == 0 ? std::string("0") : format_significant(sim_worst, 2));
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
