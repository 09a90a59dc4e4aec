// SPDX-License-Identifier: GPL-3.0-or-later
/// @file perturbed.cpp
/// @brief Section 10's perturbed return map and the persistence of the covering (perturbed.hpp).
#include "dfchaos/perturbed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dfchaos/bisect.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/phase.hpp"

namespace dfchaos {

double perturbation_G(double eps, double t, double /*x*/, double v) { return eps * (std::cos(2 * t + 1) + v / (1 + v * v)); }

double perturbed_stop_release(const Parameters& p, double eps) {
  auto force = [&](double t) { return p.a() * std::sin(t) + 2 * p.b() + perturbation_G(eps, t, 0, 0); };
  const double lo = pi - 0.5, hi = 1.5 * pi;
  if (!(force(lo) > 0 && force(hi) < 0)) throw InvalidParameter("eps", "a perturbation small enough that the stop-release phase stays near t2", eps);
  const auto [l, h] = bisect([&](double t) { return force(t) > 0; }, lo, hi, BisectStop{.max_iterations = 200, .abs_tol = 1e-15});
  return 0.5 * (l + h);
}

double perturbed_T(const Parameters& p, double eps, double theta, long max_steps) {
  OdeMapOptions opt;
  opt.max_steps = max_steps;
  opt.perturbation = [eps](double t, double x, double v) { return perturbation_G(eps, t, x, v); };
  return ode_return_map_step(p, theta, opt).T;
}

bool perturbed_continuous_between(const Parameters& p, double eps, double x0, double x1, const PerturbedCoveringSearch& s,
                                  std::vector<PerturbedSample>* graph, int segment) {
  if (s.grid < 2) throw InvalidParameter("grid", "at least 2 points for the continuity check", s.grid);
  double prev_x = x0, prev_T = perturbed_T(p, eps, x0);
  for (int i = 1; i < s.grid; ++i) {
    const double x = x0 + (x1 - x0) * i / (s.grid - 1), Tx = perturbed_T(p, eps, x);
    if (graph) graph->push_back({segment, x, Tx});
    if (std::fabs(Tx - prev_T) > s.suspect_jump) {
      // Localise the change: the predicate "the larger part of the change lies right of m" moves
      // the bracket towards it; T at the bracket ends is carried along.
      double Tlo = prev_T, Thi = Tx;
      bisect(
          [&](double m) {
            const double Tm = perturbed_T(p, eps, m);
            if (std::fabs(Tm - Tlo) >= std::fabs(Thi - Tm)) {
              Thi = Tm;
              return false;
            }
            Tlo = Tm;
            return true;
          },
          prev_x, x, BisectStop{.max_iterations = s.jump_halvings, .abs_tol = s.jump_width});
      if (std::fabs(Thi - Tlo) > s.jump) return false;
    }
    prev_x = x;
    prev_T = Tx;
  }
  return true;
}

PerturbedCovering perturbed_covering(const Parameters& p, const Lemma4Covering& c, double eps, const PerturbedCoveringSearch& s,
                                     std::vector<PerturbedSample>* graph) {
  PerturbedCovering r;
  r.t2_eps = perturbed_stop_release(p, eps);
  const CoveringSegment* J[2] = {&c.J0, &c.J1};
  const double top = 1.5 * pi, t2 = p.t2_required();
  // The phase nearest to x0 (outwards on a ladder, right before left) where `accept` holds.
  auto nearest = [&](double x0, double reach, auto&& accept) {
    for (int k = 0; k <= s.ladder; ++k)
      for (int sign : {1, -1}) {
        if (k == 0 && sign < 0) continue;  // the same point
        const double x = x0 + sign * reach * k / s.ladder;
        if (x >= t2 && x < top && accept(perturbed_T(p, eps, x))) return x;
      }
    return PerturbedCovering::nan;
  };
  // From a phase x on a stop arc (T_eps = t2_eps), the edge of that arc on the side of `target`:
  // step towards target (ladder steps of the search) while T_eps = t2_eps holds, then bisect
  // between the last such phase and the first where it does not. Without this, a stop arc that
  // has grown over the end of J_i would give u = that end itself, not where the arc ends.
  auto edge_towards = [&](double x, double target, double step, auto&& on_arc) {
    if (!std::isfinite(x) || !std::isfinite(target) || x == target) return x;
    const double dir = target > x ? 1.0 : -1.0;
    double in = x, out = target;  // target = w: T_eps >= 3pi/2 there, not on the arc
    for (int k = 1; k <= s.ladder; ++k) {
      const double y = x + dir * step * k;
      if ((target - y) * dir <= 0) break;
      if (!on_arc(perturbed_T(p, eps, y))) {
        out = y;
        break;
      }
      in = y;
    }
    return bisect([&](double m) { return on_arc(perturbed_T(p, eps, m)); }, in, out,
                  BisectStop{.max_iterations = s.jump_halvings, .abs_tol = s.jump_width})
        .first;
  };
  for (int i = 0; i < 2; ++i) {
    const double reach = s.margin * (J[i]->hi - J[i]->lo);
    auto on_arc = [&](double Tx) { return std::fabs(Tx - r.t2_eps) < s.release_match; };
    const double w = nearest(J[i]->theta_at_top, reach, [&](double Tx) { return Tx >= top; });
    const double u = edge_towards(nearest(J[i]->theta_at_t2, reach, on_arc), w, reach / s.ladder, on_arc);
    r.u[i] = u;
    r.w[i] = w;
    r.covers[i] = std::isfinite(u) && std::isfinite(w) && perturbed_continuous_between(p, eps, std::min(u, w), std::max(u, w), s, graph, i);
  }
  return r;
}

PerturbedGlobalCovering perturbed_covering_global(const Parameters& p, double eps, int grid, const PerturbedCoveringSearch& s, int max_gave_up) {
  if (grid < 2) throw InvalidParameter("grid", "at least 2 points for the global search", grid);
  PerturbedGlobalCovering r;
  r.t2_eps = perturbed_stop_release(p, eps);
  const double t2 = p.t2_required(), top = 1.5 * pi;
  // A sample: its phase, value, and whether the integration gave up there.
  struct S {
    double x, T;
    bool ok;
  };
  std::vector<S> v;
  for (int k = 0; k < grid && r.gave_up < max_gave_up; ++k) {
    const double x = t2 + (top - t2) * (k + 0.5) / grid;
    try {
      v.push_back({x, perturbed_T(p, eps, x), true});
    } catch (const GaveUp&) {
      v.push_back({x, PerturbedCovering::nan, false});
      ++r.gave_up;
    }
  }
  r.samples = static_cast<int>(v.size());
  // Runs: maximal stretches of samples with no jump between neighbours (and no give-up).
  PerturbedCoveringSearch pair = s;
  pair.grid = 2;
  double last_stop = PerturbedCovering::nan, last_top = PerturbedCovering::nan;
  double segment_floor = -std::numeric_limits<double>::infinity();  // segments must start right of the last one taken
  for (std::size_t k = 0; k < v.size(); ++k) {
    bool joined = k > 0 && v[k].ok && v[k - 1].ok;
    if (joined && std::fabs(v[k].T - v[k - 1].T) > s.suspect_jump) {
      try {
        joined = perturbed_continuous_between(p, eps, v[k - 1].x, v[k].x, pair);
      } catch (const GaveUp&) {
        joined = false;
      }
    }
    if (!joined) last_stop = last_top = PerturbedCovering::nan;  // a new run
    if (!v[k].ok) continue;
    const bool is_stop = std::fabs(v[k].T - r.t2_eps) < s.release_match, is_top = v[k].T >= top;
    if (is_stop) {
      if (std::isfinite(last_top) && last_top > segment_floor) {
        r.segments.emplace_back(last_top, v[k].x);
        segment_floor = v[k].x;
        last_top = PerturbedCovering::nan;
      }
      last_stop = v[k].x;
    }
    if (is_top) {
      if (std::isfinite(last_stop) && last_stop > segment_floor) {
        r.segments.emplace_back(last_stop, v[k].x);
        segment_floor = v[k].x;
        last_stop = PerturbedCovering::nan;
      }
      last_top = v[k].x;
    }
  }
  return r;
}

}  // namespace dfchaos
