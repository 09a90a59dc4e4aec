// SPDX-License-Identifier: GPL-3.0-or-later
/// @file sec9_regimes.cpp
/// @brief The Remark of Section 9, by the full event-driven simulator: outside b < a/2 free flights
/// die out; then q >= a + 2b leads to a permanent stop, q <= 2b to an everlasting progression, and
/// q in between to either an everlasting progression or a periodic stick-slip (progression from
/// rest at t0, stop in [t1, t0 + 2pi)), whatever the initial state. The Remark writes "in between" as
/// q in (2b - a, a + 2b), which overlaps q <= 2b; the cases read it as 2b < q < a + 2b, and the
/// overlap (2b - a, 2b] is checked on its own (claim sec9.overlap). Each case is simulated from
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

constexpr double kInstantStopShare = 1e-8;  // at q = 2b: largest share of time stopped that counts as instantaneous stops

struct Case {
  std::string name;         ///< identifier: column case of the tables, part name of the time-history table
  std::string label;        ///< the case in words (LaTeX), for the report's table and figure
  double b, q;              ///< with a = 1
  std::string remark;       ///< what the Remark predicts (LaTeX: the relations in math mode)
  std::vector<EB> allowed;  ///< the behaviours that agree with it
};

const std::vector<Case> cases = {
    {"stop", "high $q$", 0.6, 2.5, "$q\\ge a+2b$: eventually stopped for ever", {EB::StaysStopped}},
    {"progression", "low $q$", 0.6, 1.0, "$q\\le 2b$: an everlasting progression starts", {EB::EternalProgression}},
    {"between-high",
     "middle $q$, upper",
     0.6,
     1.9,
     "$2b<q<a+2b$: everlasting progression or periodic stick-slip",
     {EB::EternalProgression, EB::PeriodicStickSlip}},
    {"between-low",
     "middle $q$, lower",
     0.6,
     1.3,
     "$2b<q<a+2b$: everlasting progression or periodic stick-slip",
     {EB::EternalProgression, EB::PeriodicStickSlip}},
    {"b-large-q-small", "low $q$, large $b$", 1.5, 1.0, "$q\\le 2b$ ($b\\ge a/2$): an everlasting progression starts", {EB::EternalProgression}},
    {"reference", "the paper's case", 0.01, 0.85, "$b<a/2$ (the paper's case): free flights go on (contrast)", {EB::FreeFlights}},
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
      Table t({"case", "label", "b_over_a", "q_over_a", "v0", "t0", "behaviour", "fraction_free", "fraction_progression", "fraction_stop",
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
          t.row({c.name, c.label, c.b, c.q, v0, t0, name, r.fraction_free, r.fraction_progression, r.fraction_stop,
                 static_cast<long long>(r.events_in_window), r.last_free_time, r.stick_stop_phase_min, r.stick_stop_phase_max});
          if (std::find(c.allowed.begin(), c.allowed.end(), r.behaviour) == c.allowed.end()) ok = false;
          if (k == 0)
            first = r.behaviour;
          else if (r.behaviour != first)
            same = false;
          if (seen.find(name) == std::string::npos) seen += (seen.empty() ? "" : ", ") + name;
        }
        if (!ok) ++disagreements;
        if (same) ++independent_of_start;
        observed.emplace_back(c.name, seen);
        tex.row({c.label, format_significant(c.b, 3), format_significant(c.q, 3), c.remark, seen, ok ? "yes" : "no"});
        run.out.table("history-" + c.name, history(p, periods, run.fast() ? 200 : 2000),
                      "time history, case " + c.name + " (a=1, b=" + format_double(c.b) + ", q=" + format_double(c.q) + ")");
      }
      run.table("", t);
      run.latex("sec9_regimes", tex.render());
      run.out.macro("SecNinePeriods", periods, 3);
      run.out.macro("SecNineWindow", window, 3);  // the periods at the end of each run that are classified
      run.out.macro("SecNineStarts", std::to_string(starts.size()));

      Claim& remark = run.out.claim("sec9.remark", "Section 9, Remark", EvidenceKind::Sampled,
                                    "Outside b < a/2 the motion eventually has no free flight, and its eventual behaviour is the one the "
                                    "Remark names for its range of q (permanent stop, everlasting progression, or one of the two in "
                                    "between); with b < a/2 free flights go on.");
      remark.parameter("periods", periods).parameter("initial_states", static_cast<long long>(starts.size()));
      for (const auto& [name, seen] : observed) remark.evidence(name, seen);
      remark.evidence("cases_disagreeing", disagreements).holds(disagreements == 0);
      // The Remark's third range (2b - a, a + 2b) overlaps its second, q <= 2b, on (2b - a, 2b]; the
      // cases above read the third as 2b < q < a + 2b. On the overlap the two cases must agree for the
      // Remark to be consistent: an everlasting progression is the only behaviour both allow.
      // At q = 2b (c = 0) the velocity of a progression from rest at t0 is a (1 - cos t): it touches zero once
      // per period and the motion goes on (an instantaneous stop, which Section 3 omits); the simulator
      // records it as a stop of rounding length, so there the check is on the share of time stopped.
      long long overlap_runs = 0, overlap_other = 0, edge_runs = 0, edge_other = 0;
      double edge_stop_share = 0;
      std::string overlap_seen;
      const int n_overlap = run.fast() ? 2 : 6;
      for (const double b : {0.6, 1.5})
        for (int k = 1; k <= n_overlap; ++k) {
          const bool edge = k == n_overlap;
          const double q = edge ? 2 * b : (2 * b - 1.0) + 1.0 * k / n_overlap;
          const Parameters p(1.0, b, q);
          for (const auto& [v0, t0] : starts) {
            const EventualRegime r = eventual_regime(p, v0, t0, periods, window);
            bool ok = r.behaviour == EB::EternalProgression;
            if (edge) {
              ++edge_runs;
              edge_stop_share = std::max(edge_stop_share, r.fraction_stop);
              ok = (ok || r.behaviour == EB::PeriodicStickSlip) && r.fraction_stop <= kInstantStopShare && r.fraction_free == 0;
              if (!ok) ++edge_other;
            } else {
              ++overlap_runs;
              if (!ok) ++overlap_other;
            }
            if (!ok) {
              const std::string name = eventual_behaviour_name(r.behaviour);
              if (overlap_seen.find(name) == std::string::npos) overlap_seen += (overlap_seen.empty() ? "" : ", ") + name;
            }
          }
        }
      run.out
          .claim("sec9.overlap", "Section 9, Remark", EvidenceKind::Sampled,
                 "On (2b - a, 2b), where the Remark's ranges q <= 2b and (2b - a, a + 2b) overlap, the motion progresses for "
                 "ever from every initial state tried, the one behaviour both cases allow: the overlap is harmless. At "
                 "q = 2b it progresses for ever up to instantaneous stops (time stopped below a share {tol}).")
          .ours()
          .parameter("b_over_a", Json::array().push(0.6).push(1.5))
          .parameter("q_points_per_b", static_cast<long long>(n_overlap))
          .parameter("periods", periods)
          .evidence("runs_inside", overlap_runs)
          .evidence("runs_inside_not_eternal_progression", overlap_other)
          .evidence("runs_at_q_2b", edge_runs)
          .evidence("runs_at_q_2b_failing", edge_other)
          .evidence("largest_stop_share_at_q_2b", edge_stop_share)
          .evidence("behaviours_of_failing_runs", overlap_seen.empty() ? std::string("none") : overlap_seen)
          .tolerance(kInstantStopShare)
          .holds(overlap_runs > 0 && edge_runs > 0 && overlap_other == 0 && edge_other == 0);
      run.out.macro("SecNineOverlapRuns", std::to_string(overlap_runs + edge_runs));
      run.out
          .claim("sec9.independent_of_start", "Section 9, Remark", EvidenceKind::Sampled,
                 "The eventual behaviour depends on the parameters but not on the initial state.")
          .evidence("cases", static_cast<long long>(cases.size()))
          .evidence("cases_with_one_behaviour", independent_of_start)
          .holds(independent_of_start == static_cast<int>(cases.size()));
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
