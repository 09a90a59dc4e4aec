/// @file sec9_regimes.cpp
/// @brief The Remark of Section 9, by the full event-driven simulator: outside b < a/2 free flights
/// die out; then q >= a + 2b leads to a permanent stop, q <= 2b to an everlasting progression, and
/// q in between to either an everlasting progression or a periodic stick-slip (progression from
/// rest at t0, stop in [t1, t0 + 2pi)), whatever the initial state. Each case is simulated from
/// several initial states; the eventual behaviour is read off the final window of the simulation.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dfchaos/eventual_regime.hpp"
#include "dfchaos/simulator.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {

using EB = EventualBehaviour;

struct Case {
  std::string name;     ///< part name of the time-history table
  double b, q;          ///< with a = 1
  std::string remark;   ///< what the Remark predicts (LaTeX: the relations in math mode)
  std::vector<EB> allowed;  ///< the behaviours that agree with it
};

const std::vector<Case> cases = {
    {"stop", 0.6, 2.5, "$q\\ge a+2b$: eventually stopped for ever", {EB::StaysStopped}},
    {"progression", 0.6, 1.0, "$q\\le 2b$: an everlasting progression starts", {EB::EternalProgression}},
    {"between-high", 0.6, 1.9, "$2b<q<a+2b$: everlasting progression or periodic stick-slip", {EB::EternalProgression, EB::PeriodicStickSlip}},
    {"between-low", 0.6, 1.3, "$2b<q<a+2b$: everlasting progression or periodic stick-slip", {EB::EternalProgression, EB::PeriodicStickSlip}},
    {"b-large-q-small", 1.5, 1.0, "$q\\le 2b$ ($b\\ge a/2$): an everlasting progression starts", {EB::EternalProgression}},
    {"reference", 0.01, 0.85, "$b<a/2$ (the paper's case): free flights go on (contrast)", {EB::FreeFlights}},
};
const std::vector<std::pair<double, double>> starts = {{0.0, 0.0}, {0.0, 2.0}, {1.5, 4.0}, {-1.0, 5.5}};  // (v0, t0)

long long regime_number(Regime r) { return r == Regime::Free ? 0 : (r == Regime::Progression ? 1 : 2); }

/// Time history from the first initial state, sampled n times over min(periods, 12) periods.
Table history(const Parameters& p, double periods, int n) {
  SimulationOptions so;
  const double span = std::min(periods, 12.0) * two_pi;
  so.sample_dt = span / n;
  const Simulation sim = simulate(p, 0.0, 0.0, starts[0].first, starts[0].second, starts[0].second + span, so);
  Table h({"t", "x", "y", "v", "regime"});
  for (const auto& s : sim.samples) h.row({s.t, s.x, s.y, s.v, regime_number(s.regime)});
  return h;
}

}  // namespace

const Experiment experiment{
    .title = "Remark of Section 9: eventual regimes outside b < a/2, by the full simulator",
    .paper = {"Section 9, Remark"},
    .tests = {"test_beyond"},
    .options = {real("periods", 60, "forcing periods simulated per initial state").range(10, 1e5).fast_value(20)},
    .outputs = {data("", "eventual behaviour over the last quarter of the simulation, per case and initial state (x = y = 0)"),
                data("history-*", "time history per case, from the first initial state"),
                latex("sec9_regimes", "per case: what the Remark predicts, what is observed, agreement")},
    .body = [](Run& run) {
      const double periods = run.real("periods"), window = periods / 4;
      Table t({"case", "b_over_a", "q_over_a", "v0", "t0", "behaviour", "fraction_free", "fraction_progression", "fraction_stop",
               "events_in_window", "last_free_time", "stick_stop_from_t1_min", "stick_stop_from_t1_max"});
      // Paragraph columns for the two texts, so that the table fits the text width.
      LatexTable tex("lrr>{\\raggedright\\arraybackslash}p{5.6cm}>{\\raggedright\\arraybackslash}p{3.2cm}l",
                     {"case", "$b/a$", "$q/a$", "the Remark predicts", "observed (all starts)", "agrees"});
      int disagreements = 0, independent_of_start = 0;
      std::vector<std::pair<std::string, std::string>> observed;  // per case: the behaviours seen
      for (const auto& c : cases) {
        const Parameters p(1.0, c.b, c.q);
        std::string seen;
        bool ok = true, same = true;
        EB first = EB::Undetermined;
        for (std::size_t k = 0; k < starts.size(); ++k) {
          const auto [v0, t0] = starts[k];
          const EventualRegime r = eventual_regime(p, v0, t0, periods, window);
          const std::string name = eventual_behaviour_name(r.behaviour);
          t.row({c.name, c.b, c.q, v0, t0, name, r.fraction_free, r.fraction_progression, r.fraction_stop,
                 static_cast<long long>(r.events_in_window), r.last_free_time, r.stick_stop_phase_min, r.stick_stop_phase_max});
          if (std::find(c.allowed.begin(), c.allowed.end(), r.behaviour) == c.allowed.end()) ok = false;
          if (k == 0) first = r.behaviour;
          else if (r.behaviour != first) same = false;
          if (seen.find(name) == std::string::npos) seen += (seen.empty() ? "" : ", ") + name;
        }
        if (!ok) ++disagreements;
        if (same) ++independent_of_start;
        observed.emplace_back(c.name, seen);
        tex.row({c.name, format_significant(c.b, 3), format_significant(c.q, 3), c.remark, seen, ok ? "yes" : "no"});
        run.out.table("history-" + c.name, history(p, periods, run.fast() ? 200 : 2000),
                      "time history, case " + c.name + " (a=1, b=" + format_double(c.b) + ", q=" + format_double(c.q) + ")");
      }
      run.table("", t);
      run.latex("sec9_regimes", tex.render());
      run.out.macro("SecNinePeriods", periods, 3);

      Claim& remark = run.out.claim("sec9.remark", "Section 9, Remark", EvidenceKind::Sampled,
                                    "Outside b < a/2 the motion eventually has no free flight, and its eventual behaviour is the one the "
                                    "Remark names for its range of q (permanent stop, everlasting progression, or one of the two in "
                                    "between); with b < a/2 free flights go on.");
      remark.parameter("periods", periods).parameter("initial_states", static_cast<long long>(starts.size()));
      for (const auto& [name, seen] : observed) remark.evidence(name, seen);
      remark.evidence("cases_disagreeing", disagreements).holds(disagreements == 0);
      run.out.claim("sec9.independent_of_start", "Section 9, Remark", EvidenceKind::Sampled,
                    "The eventual behaviour depends on the parameters but not on the initial state.")
          .evidence("cases", static_cast<long long>(cases.size())).evidence("cases_with_one_behaviour", independent_of_start)
          .holds(independent_of_start == static_cast<int>(cases.size()));
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
