/// @file lemma3_return_map.cpp
/// @brief Lemma 3: T(theta) = theta2 mod 2pi when that phase lies in [t2, t3), and T = t2
/// otherwise; the graph of T with its scenarios and stop arcs; cross-checks against the full
/// simulator (every point) and against numerical integration (a subset).
#include <cmath>

#include "dfchaos/ode_map.hpp"
#include "dfchaos/progression_stop.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/simulator.hpp"
#include "harness.hpp"

using namespace dfchaos;

int main(int argc, char** argv) {
  int n = 4000, ode_every = 40;
  return experiments::run(
      argc, argv, "lemma3_return_map", "Lemma 3: the return map T",
      [&](experiments::OptionSet& app) {
        app.add_option("--n", n, "grid points of theta in [t2, t3)");
        app.add_option("--ode-every", ode_every, "cross-check every k-th point by numerical integration");
      },
      [&](const experiments::Options& o, ExperimentOutput& out) {
        experiments::require_count("n", n, 10, 10'000'000);
        if (ode_every < 1) throw InvalidParameter("ode-every", "ode-every >= 1", ode_every);
        if (o.fast) { n = std::min(n, 200); ode_every = std::max(ode_every, 20); }
        out.parameter("n", std::to_string(n));
        out.parameter("ode_every", std::to_string(ode_every));
        Table summary({"b_over_a", "q_over_a", "lemma1_holds", "stop_fraction", "lemma3_violations", "max_sim_diff", "max_ode_diff",
                       "ode_points"});
        long long viol_with_lemma1 = 0, viol_without = 0;
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
                break;
              }
            if (i % ode_every == 0) {
              ++ode_points;
              ode_max = std::max(ode_max, circle_distance(ode_return_map_step(p, th).T, s.T));
            }
          }
          (lemma1 ? viol_with_lemma1 : viol_without) += viol;
          sim_worst = std::max(sim_worst, sim_max);
          ode_worst = std::max(ode_worst, ode_max);
          summary.row({ba, qa, static_cast<long long>(lemma1), static_cast<double>(stops) / n, viol, sim_max, ode_max, ode_points});
          out.table("graph-b" + format_significant(ba, 2) + "-q" + format_significant(qa, 2), graph, "T on [t2, t3) at " + p.describe());
        }
        out.table("", summary, "Lemma 3 per parameter set, with cross-checks");

        Claim l3{"lemma3.dichotomy", "Lemma 3",
                 "Where Lemma 1 holds, T(theta) is the phase of theta2 if it lies in [t2, t3), and t2 otherwise."};
        l3.evidence.set("violations", viol_with_lemma1);
        l3.holds = viol_with_lemma1 == 0;
        out.claim(l3);

        Claim l3b{"lemma3.needs_lemma1", "Lemma 3",
                  "Where Lemma 1 fails, T also takes values that are neither theta2 mod 2pi nor t2 (scenario D): Lemma 3 depends on Lemma 1."};
        l3b.evidence.set("violations_where_lemma1_fails", viol_without);
        l3b.holds = viol_without > 0;
        l3b.expected = false;
        out.claim(l3b);

        Claim xs{"lemma3.simulator_agrees", "Section 3, Lemma 3", "The full simulator's first switch to free flight has the phase T(theta), to 1e-10."};
        xs.evidence.set("max_phase_difference", sim_worst);
        xs.holds = sim_worst <= 1e-10;
        out.claim(xs);

        Claim xo{"lemma3.integration_agrees", "Lemma 3",
                 "Numerical integration of the equations of motion (GSL rk8pd, events to 1e-12) gives the same T, to 1e-7."};
        xo.evidence.set("max_phase_difference", ode_worst);
        xo.holds = ode_worst <= 1e-7;
        out.claim(xo);
        out.macro("LemmaThreeOdeDiff", ode_worst, 2);
        out.macro("LemmaThreeSimDiff", sim_worst == 0 ? std::string("0") : format_significant(sim_worst, 2));
      });
}
