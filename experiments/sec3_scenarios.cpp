/// @file sec3_scenarios.cpp
/// @brief Section 3: which scenarios (A, B, C, C', D, D') occur, on which arcs of [t2, t3); one
/// simulated example of each; and the claim that a progression never stops inside (t0, t1).
#include <cmath>
#include <map>

#include "dfchaos/progression_stop.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/simulator.hpp"
#include "harness.hpp"

using namespace dfchaos;

namespace {
long long regime_number(Regime r) { return r == Regime::Free ? 0 : (r == Regime::Progression ? 1 : 2); }

/// Time history of a simulation from rest at the delimiter at t_start, sampled n times.
Table history(const Parameters& p, double t_start, double duration, int n) {
  SimulationOptions o;
  o.sample_dt = duration / n;
  const Simulation s = simulate(p, 0.0, 0.0, 0.0, t_start, t_start + duration, o);
  Table t({"t_minus_start", "x", "y", "v", "regime"});
  for (const auto& x : s.samples) t.row({x.t - t_start, x.x, x.y, x.v, regime_number(x.regime)});
  return t;
}
}  // namespace

int main(int argc, char** argv) {
  int n = 4000;
  return experiments::run(
      argc, argv, "sec3_scenarios", "Section 3: scenarios of the motion between two free flights",
      [&](experiments::OptionSet& app) { app.add_option("--n", n, "grid points of theta in [t2, t3) per parameter set"); },
      [&](const experiments::Options& o, ExperimentOutput& out) {
        experiments::require_count("n", n, 10, 10'000'000);
        if (o.fast) n = std::min(n, 200);
        out.parameter("n", std::to_string(n));
        const std::vector<std::pair<double, double>> sets = {{0.01, 0.85}, {0.05, 0.85}, {0.1, 0.95},
                                                             {0.002, 0.8}, {0.05, 0.7},  {0.01, 0.6}};
        Table counts({"b_over_a", "q_over_a", "lemma1_holds", "A", "B", "C", "D", "G", "other"});
        Table arcs({"b_over_a", "q_over_a", "scenario", "theta_lo", "theta_hi", "points"});
        std::string counts_tex;
        Table phases({"b_over_a", "q_over_a", "t0", "t1", "t2", "t3"});
        for (const auto& [ba, qa] : sets) {
          const Parameters p(1.0, ba, qa);
          phases.row({ba, qa, *p.t0(), *p.t1(), *p.t2(), *p.t3()});
        }
        out.table("phases", phases, "the switching phases t0, t1 (zeros of F - q) and t2, t3 (zeros of F) per parameter set");
        std::map<std::string, std::pair<Parameters, double>> example;
        long long stops_inside = 0, progression_ends = 0, other = 0, d_with_lemma1 = 0;
        for (const auto& [ba, qa] : sets) {
          const Parameters p(1.0, ba, qa);
          const bool lemma1 = progression_from_t0(p).stops_in_t1_t2;
          const double t2 = *p.t2(), t3 = *p.t3(), t0 = *p.t0(), t1 = *p.t1();
          std::map<std::string, long long> c;
          std::string run_sc;
          double run_lo = t2, run_hi = t2;
          long long run_n = 0;
          for (int i = 0; i < n; ++i) {
            const double th = t2 + (t3 - t2) * i / n;
            const MapStep s = return_map_step(p, th);
            const std::string sc = scenario_name(s.scenario);
            ++c[sc];
            if (s.scenario == Scenario::Other) ++other;
            if (s.scenario == Scenario::D && lemma1) ++d_with_lemma1;
            if (!example.count(sc)) example.emplace(sc, std::make_pair(p, th));
            if (sc != run_sc) {
              if (run_n) arcs.row({ba, qa, run_sc, run_lo, run_hi, run_n});
              run_sc = sc;
              run_lo = th;
              run_n = 0;
            }
            run_hi = th;
            ++run_n;
            // Independent look at the same step through the simulator's event log: where do
            // progressions stop?
            const Simulation sim = simulate(p, 0.0, 0.0, 0.0, th, th + s.elapsed + 1e-9);
            for (const auto& e : sim.events)
              if (e.before == Regime::Progression) {
                ++progression_ends;
                if (phase_in_arc(e.when.phase, t0, t1) && e.when.phase != t0) ++stops_inside;
              }
          }
          arcs.row({ba, qa, run_sc, run_lo, run_hi, run_n});
          counts.row({ba, qa, static_cast<long long>(lemma1), c["A"], c["B"], c["C"], c["D"], c["G"], c["other"]});
          counts_tex += format_significant(ba, 3) + " & " + format_significant(qa, 3) + " & " + (lemma1 ? "holds" : "fails");
          for (const char* k : {"A", "B", "C", "D", "G", "other"}) counts_tex += " & " + std::to_string(c[k]);
          counts_tex += "\\\\\n";
        }
        {
          std::string tex = "\\begin{tabular}{rrcrrrrrr}\n\\toprule\n$b/a$ & $q/a$ & Lemma 1 & A & B & C & D & grazing & other\\\\\n\\midrule\n";
          tex += counts_tex;
          tex += "\\bottomrule\n\\end{tabular}\n";
          out.latex("sec3_counts", tex);
        }
        out.table("counts", counts, "number of grid phases theta in [t2, t3) per scenario");
        out.table("arcs", arcs, "maximal runs of grid phases with the same scenario");

        // One example motion per scenario met on the grids, over one step of T plus a little.
        std::string met;
        for (const auto& [sc, pt] : example) {
          const MapStep s = return_map_step(pt.first, pt.second);
          std::string part = sc == "C'" ? "Cprime" : (sc == "D'" ? "Dprime" : sc);
          out.table("example-" + part, history(pt.first, pt.second, s.elapsed * 1.15 + 1.0, o.fast ? 200 : 3000),
                    "scenario " + sc + ": " + pt.first.describe() + ", theta=" + format_double(pt.second));
          met += (met.empty() ? "" : ", ") + sc;
        }
        // C' and D' start with a zero-velocity contact at t3: a codimension-two event for flights
        // from [t2, t3), so the grids do not meet it. Shown from rest at the contact at t3.
        for (auto [part, ba, qa] : {std::tuple{"Cprime", 0.01, 0.85}, std::tuple{"Dprime", 0.05, 0.7}}) {
          const Parameters p(1.0, ba, qa);
          out.table(std::string("example-") + part, history(p, *p.t3(), 2 * two_pi, o.fast ? 200 : 3000),
                    std::string(part) + " tail: rest at the delimiter at t3, " + p.describe());
        }

        Claim inside{"sec3.no_stop_in_t0_t1", "Section 3",
                     "A progression never stops while the phase is inside (t0, t1), where F exceeds q."};
        inside.evidence.set("progression_ends_examined", progression_ends).set("ends_inside", stops_inside);
        inside.holds = stops_inside == 0 && progression_ends > 0;
        out.claim(inside);

        Claim complete{"sec3.scenarios_complete", "Section 3",
                       "Every step of T on the grids follows one of the listed scenarios (A, B, C, D, or a grazing touch)."};
        complete.evidence.set("other_chains", other);
        complete.holds = other == 0;
        out.claim(complete);

        Claim noD{"sec3.lemma1_excludes_D", "Section 3, Lemma 1",
                  "Where Lemma 1's conclusion holds, scenario D does not occur."};
        noD.evidence.set("D_steps_where_lemma1_holds", d_with_lemma1);
        noD.holds = d_with_lemma1 == 0;
        out.claim(noD);
        out.macro("SecThreeScenariosMet", met);
      });
}
