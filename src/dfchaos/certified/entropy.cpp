// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/entropy.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/graph.hpp"
#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

namespace {

/// A vertex proposed by the floating grid.
struct Proposal {
  double lo, hi;      // the segment
  double T_lo, T_hi;  // floating T at its ends
};

/// Whether T(I_j) contains I_k by the floating values (a margin of 1e-9 on each side).
bool covers_float(const Proposal& j, const Proposal& k) {
  const double lo = std::min(j.T_lo, j.T_hi), hi = std::max(j.T_lo, j.T_hi);
  return lo + 1e-9 < k.lo && k.hi < hi - 1e-9;
}

/// The strongly connected part of the graph on `vertices` (indices into `all`) with the largest
/// floating Perron root: its vertices (ascending), Perron vector and root. Empty if no cycle.
struct Part {
  std::vector<int> vertices;
  std::vector<double> v;
  double rho = 0;
};

Part best_part(const std::vector<Proposal>& all, const std::vector<int>& vertices) {
  const int n = static_cast<int>(vertices.size());
  std::vector<std::vector<int>> succ(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k)
      if (covers_float(all[vertices[i]], all[vertices[k]])) succ[i].push_back(k);
  const PerronPart part = perron_part(succ);
  Part best;
  best.rho = part.rho;
  best.v = part.v;
  for (int m : part.vertices) best.vertices.push_back(vertices[m]);
  return best;
}

/// T at the single phase x, proved in case AB with the phase of theta2 above t2 (so T is that phase).
bool T_at(const ParameterBalls& m, double x, bool record, Ball& T, BallProof& kept) {
  Budget budget;
  MapStepProof t = certify_T(m, StartSet::point(x), budget, nullptr, record);
  if (!t.verdict || t.t_case != TCase::ScenarioAB || !lt(m.t2, t.theta2_phase)) return false;
  T = t.theta2_phase;
  if (record) kept = BallProof::of(StartSet::point(x), m.box(), std::move(t));
  return true;
}

/// T continuous on [lo, hi]: a cover by closed balls (bisection in theta).
bool continuous_on(const ParameterBalls& m, double lo, double hi, const EntropyOptions& opt, GraphSegment& g, bool& used_lemma1) {
  int balls = 0;
  auto check = [&](const Span& c, int) {
    Budget budget;
    MapStepProof t = certify_T(m, StartSet::interval(c.first, c.second), budget, nullptr, opt.record);
    if (!t.verdict) return CellVerdict::split(Outcome::fail("entropy: T continuous", t.verdict.describe()));
    if (++balls > opt.max_balls) return CellVerdict::stop(Outcome::fail("entropy: T continuous", "too many balls"));
    used_lemma1 = used_lemma1 || t.used_lemma1;
    if (opt.record) g.cover.push_back(BallProof::of(StartSet::interval(c.first, c.second), m.box(), std::move(t)));
    return CellVerdict::proved();
  };
  if (!cover(Span(lo, hi), check, halve, std::numeric_limits<int>::max())) return false;
  std::sort(g.cover.begin(), g.cover.end(), [](const BallProof& u, const BallProof& w) { return u.theta_lo.mid() < w.theta_lo.mid(); });
  return true;
}

}  // namespace

EntropyProof prove_entropy_bound(double a, double b, double q, const EntropyOptions& opt) {
  EntropyProof r;
  r.a = a, r.b = b, r.q = q;
  const ParameterBalls m(ParameterBox::point(a, b, q));
  if (Outcome v = m.admissible(); !v) {
    r.verdict = v;
    return r;
  }
  // 1. Floating proposals: per run of one continuity label on the grid, the segment between the
  //    samples where T is least and largest (both above t2).
  const Parameters p(a, b, q);
  const double t2 = *p.t2(), t3 = *p.t3();
  std::vector<Proposal> all;
  {
    int first = 0;
    std::vector<LabelledStep> s;
    std::vector<double> x;
    for (int i = 0; i < opt.grid; ++i) {
      poll_stop();  // stop.hpp: a caller may end the proof here
      x.push_back(t2 + (t3 - t2) * (i + 0.5) / opt.grid);
      s.push_back(continuity_label(p, x.back()));
    }
    for (int i = 1; i <= opt.grid; ++i) {
      if (i < opt.grid && s[i].label == s[first].label) continue;
      int lo = -1, hi = -1;
      for (int j = first; j < i; ++j) {
        if (!(s[j].step.T > t2)) continue;
        if (lo < 0 || s[j].step.T < s[lo].step.T) lo = j;
        if (hi < 0 || s[j].step.T > s[hi].step.T) hi = j;
      }
      if (lo >= 0 && lo != hi && s[hi].step.T - s[lo].step.T > 1e-9) {
        const int l = std::min(lo, hi), h = std::max(lo, hi);
        all.push_back({x[l], x[h], s[l].step.T, s[h].step.T});
      }
      first = i;
    }
  }
  r.candidates = static_cast<int>(all.size());
  std::vector<int> every(all.size());
  std::iota(every.begin(), every.end(), 0);
  Part part = best_part(all, every);
  if (static_cast<int>(part.vertices.size()) > opt.max_segments) {
    // Keep the segments of largest weight and choose again among them.
    std::vector<int> order(part.vertices.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int i, int k) { return part.v[i] > part.v[k]; });
    std::vector<int> kept;
    kept.reserve(static_cast<std::size_t>(std::max(opt.max_segments, 0)));
    for (int i = 0; i < opt.max_segments; ++i) kept.push_back(part.vertices[order[i]]);
    std::sort(kept.begin(), kept.end());
    part = best_part(all, kept);
  }
  r.rho_float = part.rho;
  if (part.vertices.empty() || part.rho <= 1) {
    r.verdict = Outcome::fail("entropy: graph", "the floating grid gives no part of the covering graph with Perron root above 1");
    return r;
  }
  // 2. The proofs: continuity on each segment and T at its ends; a segment that fails is dropped.
  for (std::size_t i = 0; i < part.vertices.size(); ++i) {
    const Proposal& pr = all[part.vertices[i]];
    GraphSegment g;
    g.lo = pr.lo, g.hi = pr.hi, g.weight = part.v[i];
    bool lemma1 = false;
    if (!T_at(m, pr.lo, opt.record, g.T_lo, g.at_lo) || !T_at(m, pr.hi, opt.record, g.T_hi, g.at_hi)) continue;
    if (!continuous_on(m, pr.lo, pr.hi, opt, g, lemma1)) continue;
    r.used_lemma1 = r.used_lemma1 || lemma1;
    r.segments.push_back(std::move(g));
  }
  // 3. The edges, proved with the enclosures, and the Collatz-Wielandt bound over them.
  const std::size_t n = r.segments.size();
  for (std::size_t j = 0; j < n; ++j) {
    GraphSegment& g = r.segments[j];
    for (std::size_t k = 0; k < n; ++k) {
      const Ball lo(r.segments[k].lo), hi(r.segments[k].hi);
      if ((lt(g.T_lo, lo) && lt(hi, g.T_hi)) || (lt(g.T_hi, lo) && lt(hi, g.T_lo))) g.successors.push_back(static_cast<int>(k));
    }
  }
  // The Collatz-Wielandt bound of a subgraph S: min over j in S of sum_{k in S, j -> k} v_k / v_j.
  std::vector<bool> best_set;
  double rho = 0;
  {
    std::vector<std::vector<int>> succ(n);
    std::vector<double> w(n);
    for (std::size_t j = 0; j < n; ++j) succ[j] = r.segments[j].successors, w[j] = r.segments[j].weight;
    rho = greedy_collatz_wielandt(succ, w, best_set);
  }
  // Keep the chosen subgraph, successors renumbered.
  {
    std::vector<int> number(n, -1);
    std::vector<GraphSegment> kept;
    for (std::size_t j = 0; j < n; ++j)
      if (best_set[j]) number[j] = static_cast<int>(kept.size()), kept.push_back(std::move(r.segments[j]));
    for (GraphSegment& g : kept) {
      std::vector<int> succ;
      for (int k : g.successors)
        if (number[k] >= 0) succ.push_back(number[k]);
      g.successors = succ;
    }
    r.segments = std::move(kept);
  }
  rho *= 1 - 1e-12;  // below the rounding of the floating sums; checked exactly next
  for (const GraphSegment& g : r.segments) {
    Ball sum(0.0);
    for (int k : g.successors) sum = sum + Ball(r.segments[k].weight);
    if (!le(Ball(rho) * g.weight, sum)) {
      r.verdict =
          Outcome::fail("entropy: bound", "sum of successors' weights < rho * weight at [" + format_double(g.lo) + ", " + format_double(g.hi) + "]");
      return r;
    }
  }
  r.rho_lower = rho;
  if (!(rho > 1)) {
    r.verdict = Outcome::fail("entropy: bound", "the proved graph (" + std::to_string(n) + " segments) gives a bound rho <= 1");
    return r;
  }
  r.log_rho_lower = log(Ball(rho));
  if (r.used_lemma1 && opt.record) r.lemma1 = certify_lemma1(m);
  r.verdict = Outcome::ok();
  return r;
}

}  // namespace dfchaos::certified
