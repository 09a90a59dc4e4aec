// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/cell.hpp"

#include <algorithm>
#include <exception>
#include <map>
#include <mutex>
#include <new>
#include <optional>
#include <stdexcept>
#include <utility>

#include "dfchaos/certified/covering.hpp"
#include "dfchaos/certified/laps.hpp"
#include "dfchaos/certified/rectangle.hpp"
#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/map_derivative.hpp"
#include "dfchaos/next_hit.hpp"
#include "dfchaos/orbit.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/stop.hpp"
#include "dfchaos/superstable.hpp"

namespace dfchaos::sweep {

const char* status_name(CellStatus s) {
  switch (s) {
    case CellStatus::Ok: return "ok";
    case CellStatus::Inadmissible: return "inadmissible";
    case CellStatus::Error: return "error";
  }
  return "?";
}

namespace {

/// Runs one group of observables; an exception is recorded under `name`.
template <class F>
void guarded(CellValues& v, const char* name, F&& f) {
  try {
    f();
  } catch (const std::bad_alloc&) {
    throw;  // memory ran out: not a property of the cell (compute_rows ends the run)
  } catch (const Stopped&) {
    throw;  // a stop request (dfchaos/stop.hpp): not a property of the cell either
  } catch (const std::exception& e) {
    v.status = CellStatus::Error;
    v.error += (v.error.empty() ? "" : "; ") + std::string(name) + ": " + e.what();
  }
}

/// The smallest k in 1..max with |T^k(e) - e| <= tol on the circle, 0 if none.
long long cycle_period(const Parameters& p, double e, const PeriodSettings& s) {
  const Orbit orbit(p, e, s.max);
  for (auto it = orbit.begin(); it != orbit.end(); ++it)
    if (circle_distance(it->T, e) <= s.tol) return it.n() + 1;  // it->T is T^(n+1)(e)
  return 0;
}

/// A message made safe for one TSV field: no tab, no line break.
std::string one_field(std::string text) {
  for (auto& ch : text)
    if (ch == '\t' || ch == '\n' || ch == '\r') ch = ' ';
  return text.empty() ? "-" : text;
}

}  // namespace

const char* certified_step_name(CertifiedStep s) {
  switch (s) {
    case CertifiedStep::Proved: return "proved";
    case CertifiedStep::Admissibility: return "admissibility";
    case CertifiedStep::Candidates: return "covering: candidates";
    case CertifiedStep::Inside: return "covering: J inside [t2, 3pi/2]";
    case CertifiedStep::TopEnd: return "covering: T >= 3pi/2 at the top end";
    case CertifiedStep::T2End: return "covering: T = t2 at the t2 end";
    case CertifiedStep::Continuity: return "covering: continuity on J";
  }
  return "?";
}

std::optional<CertifiedStep> certified_step_of(const std::string& step) {
  for (CertifiedStep s : kAllCertifiedSteps)
    if (s != CertifiedStep::Proved && step == certified_step_name(s)) return s;
  return std::nullopt;
}

std::string certified_step_legend() {
  std::string s;
  for (CertifiedStep c : kAllCertifiedSteps) s += (s.empty() ? "" : " | ") + std::to_string(static_cast<int>(c)) + " " + certified_step_name(c);
  return s;
}

PlaneCertified plane_certified(const Parameters& p, long long max_branches) {
  p.require_return_map();
  certified::CoveringOptions opt;
  opt.max_branches = std::max(1LL, max_branches / kDenseCostFactor);  // its candidate search is a Dense one
  const certified::CoveringProof proof = certified::prove_covering(certified::ParameterBox::point(p.a(), p.b(), p.q()), opt);
  if (proof.verdict.proved) return {.proved = true, .step = CertifiedStep::Proved};
  const std::optional<CertifiedStep> step = certified_step_of(proof.verdict.step);
  if (!step) throw std::logic_error("not proved at a step with no code in this sweep: '" + proof.verdict.step + "'");
  return {.proved = false, .step = *step};
}

std::string region_stop_legend() {
  return "0 decided to the top | 1 gave up after " + std::to_string(kRegionFailedRun) + " unproved boxes in a row | 2 box budget";
}

namespace {
/// best_lemma4_uniform for a q/a range, computed once per range and process (it is a pure function
/// of the range, so the memo cannot change a result; two threads may compute the same range once each).
certified::Lemma4UniformProof uniform_for(double kappa_lo, double kappa_hi) {
  static std::mutex lock;
  static std::map<std::pair<double, double>, certified::Lemma4UniformProof> memo;
  const std::pair<double, double> key{kappa_lo, kappa_hi};
  {
    const std::lock_guard<std::mutex> g(lock);
    if (auto it = memo.find(key); it != memo.end()) return it->second;
  }
  certified::Lemma4UniformProof proof = certified::best_lemma4_uniform(kappa_lo, kappa_hi);
  poll_stop();  // a proof cut short by a stop request (dfchaos/stop.hpp) is never remembered
  const std::lock_guard<std::mutex> g(lock);
  return memo.emplace(key, std::move(proof)).first->second;
}
}  // namespace

PlaneRegion plane_region(const Spec& spec, long long index, long max_boxes) {
  const auto [k_lo, k_hi] = spec.q_over_a.extent(index / spec.b_over_a.size());
  const auto [e_lo, e_hi] = spec.b_over_a.extent(index % spec.b_over_a.size());
  certified::RectangleOptions opt;
  opt.max_boxes = max_boxes;
  opt.max_failed_run = kRegionFailedRun;
  // The uniform route is tried only where it can hold: q/a at most 1 (its proof needs q/a <= 1).
  const certified::Lemma4UniformProof uniform = k_hi <= 1 ? uniform_for(k_lo, k_hi) : certified::Lemma4UniformProof{};
  // Only q/a and b/a matter: the rectangle of ratios is proved at a = 1, exactly (products with the
  // spec's a would be rounded, and a rounded end can fall outside the uniform proof's box).
  const certified::RectangleProof r = certified::prove_rectangle(1.0, e_lo, e_hi, k_lo, k_hi, uniform, opt);
  PlaneRegion out;
  out.proved_fraction = r.proved_fraction();
  out.uniform_bound = r.uniform_bound;
  out.boxes = r.attempts;
  out.stop = r.stop;
  return out;
}

PlaneEntropy plane_entropy(double q_over_a, double b_over_a) {
  const certified::EntropyBracket e = certified::prove_entropy_bracket(1.0, b_over_a, q_over_a);
  poll_stop();  // a bracket cut short by a stop request (dfchaos/stop.hpp) is never written
  PlaneEntropy out;
  if (!e.verdict.proved) return out;
  out.lower = e.h_lower();
  out.upper = e.h_upper();
  out.laps = static_cast<double>(e.partition.laps.size());
  return out;
}

Lemma4Covering plane_covering(const Parameters& p, long long max_branches, CoveringSearchStats* stats) {
  CoveringSearch search = CoveringSearch::branchwise();
  search.max_branches = max_branches;
  return lemma4_covering(p, search, stats);
}

PlaneSuperstable plane_superstable(const Parameters& p, int scan) {
  const SuperstableCheck s = superstable_check(p, scan);
  return {.superstable = s.fixed && s.epsilon > 0, .epsilon = s.epsilon};
}

double orbit_start(const Parameters& p, double fraction) {
  const double t2 = p.t2_required(), t3 = p.t3_required();
  return t2 + fraction * (t3 - t2);
}

PlaneOrbit plane_orbit(const Parameters& p, double theta0, const OrbitSettings& orbit, const PeriodSettings& period, bool statistics,
                       bool with_period) {
  PlaneOrbit o;
  const long long total = orbit.transient + orbit.steps;
  double end = theta0;  // T^(transient + steps)(theta0), needed by the period only
  if (statistics) {
    const OrbitStatistics st = orbit_statistics(p, theta0, orbit.transient, orbit.steps, 1);
    o.lyapunov = st.lyapunov;
    o.rate = st.penetration_rate;
    o.stop_image = st.last_stop_image;
    if (with_period) end = T(p, st.tail.back());  // the tail holds T^(total - 1)(theta0)
  } else if (with_period) {
    end = T_power(p, theta0, total);
  }
  if (with_period) o.period = static_cast<double>(cycle_period(p, end, period));
  return o;
}

CellValues evaluate_cell(const Spec& spec, long long index) {
  CellValues v;
  v.index = index;
  v.q_over_a = spec.q_at(index);
  v.b_over_a = spec.b_at(index);
  const ObservableSet& obs = spec.observables;
  std::optional<Parameters> made;
  guarded(v, "parameters", [&] { made.emplace(spec.a, v.b_over_a * spec.a, v.q_over_a * spec.a); });  // Spec::validate makes it succeed
  if (!made) return v;
  const Parameters& p = *made;
  if (!(p.q() > 2 * p.b())) {  // exactly the condition of Parameters::require_return_map
    v.status = CellStatus::Inadmissible;
    return v;
  }
  if (obs.has(Observable::Covering)) guarded(v, "covering", [&] { v.covering = plane_covering(p, spec.covering_max_branches).holds ? 1 : 0; });
  if (obs.has(Observable::Superstable))
    guarded(v, "superstable", [&] {
      const PlaneSuperstable s = plane_superstable(p, static_cast<int>(spec.superstable_scan));
      v.superstable = s.superstable ? 1 : 0;
      v.epsilon = s.epsilon;
    });
  if (obs.needs_orbit())
    guarded(v, "orbit", [&] {
      const PlaneOrbit o = plane_orbit(p, orbit_start(p, spec.orbit.theta0_fraction), spec.orbit, spec.period,
                                       obs.has(Observable::Lyapunov) || obs.has(Observable::Rate), obs.has(Observable::Period));
      v.lyapunov = o.lyapunov;
      v.rate = o.rate;
      v.stop_image = o.stop_image;
      v.period = o.period;
    });
  if (obs.has(Observable::Certified))
    guarded(v, "certified", [&] {
      const PlaneCertified c = plane_certified(p, spec.covering_max_branches);
      v.certified = c.proved ? 1 : 0;
      v.certified_step = static_cast<double>(static_cast<int>(c.step));
    });
  if (obs.has(Observable::Region))
    guarded(v, "region", [&] {
      const PlaneRegion r = plane_region(spec, index, spec.region_max_boxes);
      v.region = r.proved_fraction;
      v.region_uniform = r.uniform_bound;
      v.region_boxes = static_cast<double>(r.boxes);
      v.region_stop = static_cast<double>(static_cast<int>(r.stop));
    });
  if (obs.has(Observable::Entropy))
    guarded(v, "entropy", [&] {
      const PlaneEntropy e = plane_entropy(v.q_over_a, v.b_over_a);
      v.entropy_lower = e.lower;
      v.entropy_upper = e.upper;
      v.entropy_laps = e.laps;
    });
  return v;
}

std::string error_field(const CellValues& v) { return one_field(v.error); }

std::vector<double> observable_values(const Spec& spec, const CellValues& v) {
  std::vector<double> x;
  for (Observable o : kAllObservables) {
    if (!spec.observables.has(o)) continue;
    switch (o) {
      case Observable::Covering: x.push_back(v.covering); break;
      case Observable::Superstable: x.insert(x.end(), {v.superstable, v.epsilon}); break;
      case Observable::Lyapunov: x.push_back(v.lyapunov); break;
      case Observable::Rate: x.push_back(spec.physical.given() ? spec.physical.metres_per_second(v.rate) : v.rate); break;
      case Observable::Period: x.push_back(v.period); break;
      case Observable::Certified: x.insert(x.end(), {v.certified, v.certified_step}); break;
      case Observable::Region: x.insert(x.end(), {v.region, v.region_uniform, v.region_boxes, v.region_stop}); break;
      case Observable::Entropy: x.insert(x.end(), {v.entropy_lower, v.entropy_upper, v.entropy_laps}); break;
    }
  }
  if (spec.physical.given()) x.insert(x.end(), {spec.physical.friction(v.q_over_a), spec.physical.static_force(v.b_over_a)});
  return x;
}

std::string format_row(const Spec& spec, const CellValues& v) {
  std::string row = std::to_string(v.index) + '\t' + format_double(v.q_over_a) + '\t' + format_double(v.b_over_a) + '\t' + status_name(v.status);
  for (double x : observable_values(spec, v)) row += '\t' + format_double(x);
  row += '\t' + error_field(v) + '\n';
  return row;
}

}  // namespace dfchaos::sweep
