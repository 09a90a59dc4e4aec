/// @file sec9_regimes.cpp
/// @brief The Remark of Section 9, by the full event-driven simulator: outside b < a/2 free flights
/// die out; then q >= a + 2b leads to a permanent stop, q <= 2b to an everlasting progression, and
/// q in between to either an everlasting progression or a periodic stick-slip (progression from
/// rest at t0, stop in [t1, t0 + 2pi)), whatever the initial state. Each case is simulated from
/// several initial states; the eventual behaviour is read off the final window of the simulation.
#include <cmath>
#include <string>
#include <vector>

#include "dfchaos/eventual_regime.hpp"
#include "dfchaos/simulator.hpp"
#include "harness.hpp"

using namespace dfchaos;

namespace {

struct Case {
  std::string name;     ///< part name of the time-history table
  double b, q;          ///< with a = 1
  std::string remark;   ///< what the Remark predicts
  std::vector<EventualBehaviour> allowed;  ///< the behaviours that agree with it
};

long long regime_number(Regime r) { return r == Regime::Free ? 0 : (r == Regime::Progression ? 1 : 2); }

}  // namespace

int main(int argc, char** argv) {
  double periods = 60;
  return experiments::run(
      argc, argv, "sec9_regimes", "Remark of Section 9: eventual regimes outside b < a/2, by the full simulator",
      [&](experiments::OptionSet& app) { app.add_option("--periods", periods, "forcing periods simulated per initial state"); },
      [&](const experiments::Options& o, ExperimentOutput& out) {
        experiments::require_range("periods", periods, 10, 1e5);
        if (o.fast) periods = std::min(periods, 20.0);
        out.parameter("periods", periods);
        const double window = periods / 4;
        using EB = EventualBehaviour;
        const std::vector<Case> cases = {
            {"stop", 0.6, 2.5, "q >= a + 2b: eventually stopped for ever", {EB::StaysStopped}},
            {"progression", 0.6, 1.0, "q <= 2b: an everlasting progression starts", {EB::EternalProgression}},
            {"between-high", 0.6, 1.9, "2b < q < a + 2b: everlasting progression or periodic stick-slip", {EB::EternalProgression, EB::PeriodicStickSlip}},
            {"between-low", 0.6, 1.3, "2b < q < a + 2b: everlasting progression or periodic stick-slip", {EB::EternalProgression, EB::PeriodicStickSlip}},
            {"b-large-q-small", 1.5, 1.0, "q <= 2b (b >= a/2): an everlasting progression starts", {EB::EternalProgression}},
            {"reference", 0.01, 0.85, "b < a/2 (the paper's case): free flights go on (contrast)", {EB::FreeFlights}},
        };
        const std::vector<std::pair<double, double>> starts = {{0.0, 0.0}, {0.0, 2.0}, {1.5, 4.0}, {-1.0, 5.5}};  // (v0, t0)
        Table t({"case", "b_over_a", "q_over_a", "v0", "t0", "behaviour", "fraction_free", "fraction_progression", "fraction_stop",
                 "events_in_window", "last_free_time", "stick_stop_from_t1_min", "stick_stop_from_t1_max"});
        std::string tex = "\\begin{tabular}{lrrlll}\n\\toprule\ncase & $b/a$ & $q/a$ & the Remark predicts & observed (all starts) & agrees\\\\\n\\midrule\n";
        int disagreements = 0, independent_of_start = 0;
        Json evidence = Json::object();
        for (const auto& c : cases) {
          const Parameters p(1.0, c.b, c.q);
          std::string seen;
          bool ok = true, same = true;
          EB first = EB::Undetermined;
          for (std::size_t k = 0; k < starts.size(); ++k) {
            const auto [v0, t0] = starts[k];
            const EventualRegime r = eventual_regime(p, v0, t0, periods, window);
            t.row({c.name, c.b, c.q, v0, t0, std::string(eventual_behaviour_name(r.behaviour)), r.fraction_free, r.fraction_progression,
                   r.fraction_stop, static_cast<long long>(r.events_in_window), r.last_free_time, r.stick_stop_phase_min, r.stick_stop_phase_max});
            if (std::find(c.allowed.begin(), c.allowed.end(), r.behaviour) == c.allowed.end()) ok = false;
            if (k == 0) first = r.behaviour;
            else if (r.behaviour != first) same = false;
            if (seen.find(eventual_behaviour_name(r.behaviour)) == std::string::npos)
              seen += (seen.empty() ? "" : ", ") + std::string(eventual_behaviour_name(r.behaviour));
          }
          if (!ok) ++disagreements;
          if (same) ++independent_of_start;
          evidence.set(c.name, seen);
          tex += c.name + " & " + format_significant(c.b, 3) + " & " + format_significant(c.q, 3) + " & " + c.remark + " & " + seen + " & " +
                 (ok ? "yes" : "no") + "\\\\\n";
          // one time history per case, from the first start
          SimulationOptions so;
          const double span = std::min(periods, 12.0) * two_pi;
          so.sample_dt = span / (o.fast ? 200 : 2000);
          const Simulation sim = simulate(p, 0.0, 0.0, starts[0].first, starts[0].second, starts[0].second + span, so);
          Table h({"t", "x", "y", "v", "regime"});
          for (const auto& s : sim.samples) h.row({s.t, s.x, s.y, s.v, regime_number(s.regime)});
          out.table("history-" + c.name, h, "time history, case " + c.name + " (a=1, b=" + format_double(c.b) + ", q=" + format_double(c.q) + ")");
        }
        tex += "\\bottomrule\n\\end{tabular}\n";
        out.table("", t, "eventual behaviour over the last quarter of the simulation, per case and initial state (x = y = 0)");
        out.latex("sec9_regimes", tex);
        out.macro("SecNinePeriods", periods, 3);

        Claim remark{"sec9.remark", "Section 9, Remark",
                     "Outside b < a/2 the motion eventually has no free flight, and its eventual behaviour is the one the Remark names "
                     "for its range of q (permanent stop, everlasting progression, or one of the two in between); with b < a/2 free "
                     "flights go on."};
        remark.parameters.set("periods", periods).set("initial_states", static_cast<long long>(starts.size()));
        remark.evidence = evidence;
        remark.evidence.set("cases_disagreeing", disagreements);
        remark.holds = disagreements == 0;
        out.claim(remark);
        Claim indep{"sec9.independent_of_start", "Section 9, Remark",
                    "The eventual behaviour depends on the parameters but not on the initial state."};
        indep.evidence.set("cases", static_cast<long long>(cases.size())).set("cases_with_one_behaviour", independent_of_start);
        indep.holds = independent_of_start == static_cast<int>(cases.size());
        out.claim(indep);
      });
}
