#include "dfchaos/return_map.hpp"

#include <cmath>
#include <stdexcept>

#include "dfchaos/errors.hpp"
#include "dfchaos/regime_chain.hpp"

namespace dfchaos {

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
Scenario scenario_of(const std::string& chain) {
  if (chain == "f>p>f") return Scenario::A;
  if (chain == "f>p>s>f") return Scenario::B;
  if (chain == "f>p>s>p>s>f") return Scenario::C;
  if (chain == "f>p>s>p>f") return Scenario::D;
  if (chain == "f>s>p>s>f") return Scenario::Cprime;
  if (chain == "f>s>p>f") return Scenario::Dprime;
  if (chain == "f>f") return Scenario::Grazing;
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
  int restarts_from_t0 = 0;
  // A chain has at most 5 transitions (scenario C); anything longer repeats for ever.
  for (int n = 0; n < 8; ++n) {
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
    if (tr->to == Regime::Progression) ++step.progressions;
    s = tr->after();
    if (s.regime == Regime::Free) {
      step.end = s.t;
      step.T = s.t.phase;
      step.elapsed = static_cast<double>(elapsed(Instant::at_phase(theta), s.t));
      step.scenario = scenario_of(step.chain);
      return step;
    }
  }
  throw GaveUp("return map at theta=" + format_double(theta) + ": no return to free flight within 8 regime changes");
}

long long t1_branch(const Parameters& p, const MapStep& step) { return maxima_between(p, step.theta, step.hit.t1); }

double T(const Parameters& p, double theta) { return return_map_step(p, theta).T; }

double G2(const Parameters& p, double theta, const Instant& theta1, const Instant& theta2) {
  const Instant start = Instant::at_phase(theta);
  const long double s1 = elapsed(start, theta1), s21 = elapsed(theta1, theta2);
  return static_cast<double>(2.0L * p.b() * s1 + p.a() * std::cos(theta) + 2.0L * p.c() * s21 - p.a() * std::cos(theta2.phase));
}

}  // namespace dfchaos
