// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/return_map.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "dfchaos/errors.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/regime_chain.hpp"

namespace dfchaos {

namespace {
constexpr int kMaxTransitions = 8;  ///< regime changes of one step of T before it gives up
}  // namespace

const char* scenario_name(Scenario s) {
  switch (s) {
    case Scenario::A: return "A";
    case Scenario::B: return "B";
    case Scenario::C: return "C";
    case Scenario::D: return "D";
    case Scenario::Cprime: return "C'";
    case Scenario::Dprime: return "D'";
    case Scenario::Grazing: return "G";
    case Scenario::Other: return "other";
  }
  return "other";
}

namespace {
/// The scenario of Section 3 whose chain of regimes entered after the first flight is
/// `after_flight[0..n)`.
Scenario scenario_of(const Regime* after_flight, int n) {
  using R = Regime;
  struct Row {
    Scenario scenario;
    std::initializer_list<Regime> chain;
  };
  static const Row rows[] = {
      {Scenario::A, {R::Progression, R::Free}},
      {Scenario::B, {R::Progression, R::Stop, R::Free}},
      {Scenario::C, {R::Progression, R::Stop, R::Progression, R::Stop, R::Free}},
      {Scenario::D, {R::Progression, R::Stop, R::Progression, R::Free}},
      {Scenario::Cprime, {R::Stop, R::Progression, R::Stop, R::Free}},
      {Scenario::Dprime, {R::Stop, R::Progression, R::Free}},
      {Scenario::Grazing, {R::Free}},
  };
  for (const Row& row : rows)
    if (std::equal(row.chain.begin(), row.chain.end(), after_flight, after_flight + n)) return row.scenario;
  return Scenario::Other;
}
}  // namespace

MapStep return_map_step(const Parameters& p, double theta) {
  p.require_return_map();
  MapStep step;
  step.theta = theta;
  p.require_in_map_domain(theta);

  MechanicalState s{Instant::at_phase(theta), Regime::Free, 0.0, 0.0, 0.0};
  step.chain = "f";
  Regime after_flight[kMaxTransitions];  // the regimes entered after the first flight
  int restarts_from_t0 = 0;
  // A chain has at most 5 transitions (scenario C); anything longer repeats for ever.
  for (int n = 0; n < kMaxTransitions; ++n) {
    const auto tr = next_transition(p, s);
    if (!tr) throw std::logic_error("return_map_step: a regime of the map never ends (a bug)");
    step.pieces += tr->pieces;
    if (tr->from == Regime::Progression) step.penetration += tr->y - s.y;
    if (n == 0) {  // the first contact is T1 (Eq. 11): the same root search as next_hit()
      step.theta2 = tr->t;
      step.hit.t1 = tr->t;
      step.hit.theta1 = tr->t.value();
      step.hit.hit_velocity = tr->v_before;
      step.hit.pieces = tr->pieces;
    }
    if (n == 1 && tr->from == Regime::Progression && step.progressions == 1) step.theta2 = tr->t;
    if (tr->from == Regime::Stop && tr->to == Regime::Progression && ++restarts_from_t0 >= 2)
      throw GaveUp("return map at theta=" + format_double(theta) + ": no return to free flight (" + p.describe() +
                   "): the progression from rest at t0 stops again before t2, so it repeats every period");
    step.chain += '>';
    step.chain += regime_code(tr->to);
    after_flight[n] = tr->to;
    if (tr->to == Regime::Progression) ++step.progressions;
    s = tr->after();
    if (s.regime == Regime::Free) {
      step.end = s.t;
      step.T = s.t.phase;
      step.elapsed = static_cast<double>(elapsed(Instant::at_phase(theta), s.t));
      step.scenario = scenario_of(after_flight, n + 1);
      return step;
    }
  }
  throw GaveUp("return map at theta=" + format_double(theta) + ": no return to free flight within " + std::to_string(kMaxTransitions) +
               " regime changes");
}

long long t1_branch(const Parameters& p, const MapStep& step) { return maxima_between(p, step.theta, step.hit.t1); }

double T(const Parameters& p, double theta) { return return_map_step(p, theta).T; }

double G2(const Parameters& p, double theta, const Instant& theta1, const Instant& theta2) {
  const Instant start = Instant::at_phase(theta);
  // In long double, with the elapsed times of the instants and the cosines at their phases.
  const long double a = p.a(), b = p.b(), q = p.q();
  return static_cast<double>(model::G2_from_start(a, b, model::two_c(b, q), std::cos(static_cast<long double>(theta)), elapsed(start, theta1),
                                                  elapsed(theta1, theta2), static_cast<long double>(theta2.phase)));
}

}  // namespace dfchaos
