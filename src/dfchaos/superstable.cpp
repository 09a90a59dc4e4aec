// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/superstable.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

#include "dfchaos/bisect.hpp"
#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/map_derivative.hpp"
#include "dfchaos/orbit.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos {

SuperstableCheck superstable_check(const Parameters& p, int scan) {
  p.require_return_map();
  if (scan < 2) throw InvalidParameter("scan", "scan >= 2", scan);
  const double t2 = *p.t2(), t3 = *p.t3();
  SuperstableCheck r;
  r.step = return_map_step(p, t2);
  r.theta2_phase = r.step.theta2.phase;
  const bool has_t0 = p.t0().has_value();
  r.eq21 = has_t0 && r.theta2_phase > *p.t1() && r.theta2_phase < t2;
  r.eq22 = r.theta2_phase > t3 || (has_t0 && r.theta2_phase < *p.t0());
  r.impact_velocity = r.step.hit.hit_velocity;
  r.dG2 = p.F(r.theta2_phase) - p.q();
  r.nondegenerate = std::fabs(r.impact_velocity) > 1e-9 && std::fabs(r.dG2) > 1e-9;
  const Assumptions as = p.assumptions();
  r.hypotheses = (as.eq2 && r.eq22) || (as.eq23 && r.eq21);
  r.fixed = r.step.T == t2;
  if (!r.fixed) return r;
  // Width of the component of {T = t2} that starts at t2.
  const double h = (t3 - t2) / scan;
  double lo = t2, hi = NAN;
  for (int i = 1; i < scan; ++i) {
    poll_stop();  // stop.hpp: up to 10^6 evaluations of T
    const double th = t2 + h * i;
    if (T(p, th) != t2) {
      hi = th;
      break;
    }
    lo = th;
  }
  if (std::isnan(hi)) {
    r.epsilon = t3 - t2;
    return r;
  }
  lo = bisect([&](double m) { return T(p, m) == t2; }, lo, hi, {.max_iterations = 100, .rel_tol = 4e-16}).first;
  r.epsilon = lo - t2;
  return r;
}

namespace {

struct Sample {
  double r = 0;
  long long branch = 0;
  long double w = 0;     // theta2(t2) as an instant, turn 0 = t2's period
  double bound[4] = {};  // t1, t2, t3, t0 + 2 pi
};

Sample sample_at(double a, double q, double r) {
  const Parameters p(a, a / r, q);
  const MapStep s = return_map_step(p, *p.t2());
  Sample x;
  x.r = r;
  x.branch = t1_branch(p, s);
  x.w = static_cast<long double>(*p.t2()) + elapsed(Instant::at_phase(*p.t2()), s.theta2);
  x.bound[0] = *p.t1();
  x.bound[1] = *p.t2();
  x.bound[2] = *p.t3();
  x.bound[3] = *p.t0() + two_pi;
  return x;
}

/// Number of whole turns of (w - boundary) / 2 pi, i.e. which copy of the boundary w is past.
long long turns_past(const Sample& x, int k) { return static_cast<long long>(std::floor((x.w - x.bound[k]) / two_pi_l)); }

int condition_at(double a, double q, double r) {
  const Parameters p(a, a / r, q);
  const SuperstableCheck c = superstable_check(p, 2);
  return c.eq21 ? 21 : (c.eq22 ? 22 : 0);
}

void events_between(double a, double q, const Sample& x, const Sample& y, int depth, std::vector<double>& events) {
  const bool jump = x.branch != y.branch || std::fabs(static_cast<double>(y.w - x.w)) > 1.0;
  if (jump) {
    if (depth > 60 || (y.r - x.r) <= 1e-12 * y.r) {
      events.push_back(0.5 * (x.r + y.r));
      return;
    }
    const Sample m = sample_at(a, q, 0.5 * (x.r + y.r));
    events_between(a, q, x, m, depth + 1, events);
    events_between(a, q, m, y, depth + 1, events);
    return;
  }
  for (int k = 0; k < 4; ++k) {
    if (turns_past(x, k) == turns_past(y, k)) continue;
    // One crossing of this boundary (w moves by less than 1 here): bisect on the turn count.
    Sample lo = x, hi = y;
    for (int it = 0; it < 80 && (hi.r - lo.r) > 1e-13 * hi.r; ++it) {
      const Sample m = sample_at(a, q, 0.5 * (lo.r + hi.r));
      if (m.branch != lo.branch && m.branch != hi.branch) break;
      if (turns_past(m, k) == turns_past(lo, k))
        lo = m;
      else
        hi = m;
    }
    events.push_back(0.5 * (lo.r + hi.r));
  }
}

}  // namespace

std::vector<SuperstableWindow> superstable_windows(double a, double q, double b_lo, double b_hi, int samples) {
  if (!(b_lo > 0 && b_lo < b_hi)) throw InvalidParameter("b_lo", "0 < b_lo < b_hi", b_lo);
  if (samples < 2) throw InvalidParameter("samples", "samples >= 2", samples);
  Parameters(a, b_hi, q).require_return_map();
  const double r_lo = a / b_hi, r_hi = a / b_lo;
  std::vector<double> events{r_lo, r_hi};
  Sample prev = sample_at(a, q, r_lo);
  for (int i = 1; i < samples; ++i) {
    const double r = r_lo + (r_hi - r_lo) * i / (samples - 1);
    const Sample cur = sample_at(a, q, r);
    events_between(a, q, prev, cur, 0, events);
    prev = cur;
  }
  std::sort(events.begin(), events.end());
  // Intervals between events, classified at their midpoints, merged when adjacent and alike.
  std::vector<SuperstableWindow> out;
  for (std::size_t i = 0; i + 1 < events.size(); ++i) {
    if (!(events[i + 1] > events[i])) continue;
    const int cond = condition_at(a, q, 0.5 * (events[i] + events[i + 1]));
    if (cond == 0) continue;
    const double b1 = a / events[i + 1], b2 = a / events[i];
    if (!out.empty() && out.back().condition == cond && out.back().b_lo == b2) {
      out.back().b_lo = b1;
      continue;
    }
    out.push_back(SuperstableWindow{b1, b2, cond});
  }
  std::sort(out.begin(), out.end(), [](const SuperstableWindow& x, const SuperstableWindow& y) { return x.b_lo < y.b_lo; });
  return out;
}

namespace {

/// The largest radius r of 1e-14, 1e-13, ..., 1e-2 such that T stops with image `image` at
/// theta +- r for it and every smaller one (0 if already 1e-14 fails). Probes outside [t2, t3) are
/// skipped (theta = t2 is the left end of the domain); a probe that throws ends the arc.
double stop_arc_radius(const Parameters& p, double theta, double image) {
  double radius = 0;
  for (int j = -14; j <= -2; ++j) {
    const double r = std::pow(10.0, j);
    for (const double x : {theta - r, theta + r}) {
      if (!p.in_map_domain(x)) continue;
      try {
        const MapStep s = return_map_step(p, x);
        if (!map_derivative(p, s).flat || s.T != image) return radius;
      } catch (const std::bad_alloc&) {
        throw;  // memory ran out: not an answer of the search
      } catch (const std::exception&) {
        return radius;
      }
    }
    radius = r;
  }
  return radius;
}

/// Whether T keeps the continuity label and the scenario of theta at theta +- r (points outside
/// [t2, t3) skipped; a throw counts as a change).
bool same_branch_around(const Parameters& p, double theta, double r) {
  try {
    const LabelledStep at = continuity_label(p, theta);
    for (const double x : {theta - r, theta + r}) {
      if (!p.in_map_domain(x)) continue;
      const LabelledStep there = continuity_label(p, x);
      if (!(there.label == at.label) || there.step.scenario != at.step.scenario) return false;
    }
  } catch (const std::bad_alloc&) {
    throw;  // memory ran out: not an answer of the search
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

/// Largest error a step without a stop may carry: below it the step's branch is checked; at or above
/// it the error counts as infinite until the next stop (a later contraction, e.g. near t2 where
/// T' = 0, must not bring back a verdict that was lost).
constexpr double kLostAt = kStopCycleLostAt;

}  // namespace

long long first_visit(const Parameters& p, double theta, double target, long long max_steps) {
  p.require_return_map();
  if (max_steps < 1 || max_steps > 10'000'000) throw InvalidParameter("max_steps", "1 <= max_steps <= 10^7", static_cast<double>(max_steps));
  const Orbit orbit(p, theta, max_steps);
  for (auto it = orbit.begin(); it != orbit.end(); ++it)
    if (it->T == target) return it.n() + 1;  // it->T is theta_{n+1}
  return 0;
}

bool stop_cycle_survives_shift(const Parameters& p, const StopCycle& c, double h) {
  p.require_return_map();
  if (c.period < 1 || c.period > 10'000'000) throw InvalidParameter("period", "1 <= period <= 10^7", static_cast<double>(c.period));
  if (!(h > 0 && h < 1e-3)) throw InvalidParameter("h", "0 < h < 1e-3", h);
  const double t3 = p.t3_required();
  const double base = c.period == 1 ? c.image : T(p, c.image);
  const double start = base + h < t3 ? base + h : base - h;  // shifted to the side inside [t2, t3)
  if (!p.in_map_domain(start)) return false;                 // no room on either side: not passed
  const long long rest = c.period == 1 ? 1 : c.period - 1;
  return first_visit(p, start, c.image, rest) == rest;
}

StopCycle stop_cycle(const Parameters& p, double image, long long max_steps, double step_error) {
  p.require_return_map();
  if (!p.in_map_domain(image)) throw InvalidParameter("image", "t2 <= image < t3", image);
  if (max_steps < 1 || max_steps > 10'000'000) throw InvalidParameter("max_steps", "1 <= max_steps <= 10^7", static_cast<double>(max_steps));
  if (!(step_error > 0 && step_error < 1e-3)) throw InvalidParameter("step_error", "0 < step_error < 1e-3", step_error);
  constexpr double inf = std::numeric_limits<double>::infinity();
  // The stop images met so far (a handful: t2 and the images of D, D'), with the step of their visit.
  std::vector<std::pair<double, long long>> images{{image, 0}};
  StopCycle c;
  double margin = inf;
  double error = step_error;
  const Orbit orbit(p, image, max_steps);
  for (auto it = orbit.begin(); it != orbit.end(); ++it) {
    const MapStep& s = *it;
    const double theta = s.theta;
    const long long k = it.n() + 1;
    const MapDerivative d = map_derivative(p, s);
    if (d.flat) {
      ++c.stops;
      if (error < kLostAt) {
        margin = std::min(margin, stop_arc_radius(p, theta, s.T) / error);
      } else {
        margin = 0;
        c.lost = true;
      }
      error = step_error;  // the image of a stop is a fixed phase
      const auto seen = std::find_if(images.begin(), images.end(), [&](const auto& e) { return e.first == s.T; });
      if (seen != images.end()) {
        c.image = seen->first;
        c.entry = seen->second;
        c.period = k - seen->second;
        break;
      }
      images.emplace_back(s.T, k);
    } else {
      if (error < kLostAt && !same_branch_around(p, theta, kStopCycleSafety * error)) {
        margin = 0;
        c.lost = true;
      }
      error = std::isfinite(d.dT) && error < kLostAt ? std::fabs(d.dT) * error + step_error : inf;
    }
  }
  // No stop image repeated, and the orbit's error ended beyond every arc: that the computed orbit did
  // not close says nothing about the true one.
  if (c.period == 0 && !(error < kLostAt)) c.lost = true;
  c.margin = c.period > 0 ? margin : 0.0;
  c.resolved = c.period > 0 && c.margin >= kStopCycleSafety;
  return c;
}

StopCycle t2_cycle(const Parameters& p, long long max_steps, double step_error) { return stop_cycle(p, p.t2_required(), max_steps, step_error); }

std::vector<SuperstableInterval> join_windows(const std::vector<SuperstableWindow>& windows) {
  std::vector<SuperstableInterval> out;
  for (std::size_t i = 0; i < windows.size(); ++i) {
    const SuperstableWindow& w = windows[i];
    if (out.empty() || out.back().b_hi != w.b_lo) out.push_back({.b_lo = w.b_lo, .b_hi = w.b_hi, .first = i, .last = i});
    SuperstableInterval& j = out.back();
    j.b_hi = w.b_hi;
    j.last = i + 1;
    (w.condition == 21 ? j.has21 : j.has22) = true;
  }
  return out;
}

double sharpen_interval_end(double a, double q, double edge, bool lower) {
  const auto fixed = [&](double b) {
    const Parameters p(a, b, q);
    return T(p, p.t2_required()) == p.t2_required();
  };
  double in = lower ? edge * (1 + 1e-10) : edge * (1 - 1e-10), out = lower ? edge * (1 - 1e-10) : edge * (1 + 1e-10);
  if (!fixed(in) || fixed(out)) return edge;
  for (int i = 0; i < 64; ++i) {  // each halving removes at least one bit of the bracket
    const double mid = 0.5 * (in + out);
    if (mid == in || mid == out) break;
    (fixed(mid) ? in : out) = mid;
  }
  return in;
}

}  // namespace dfchaos
