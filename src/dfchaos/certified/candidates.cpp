// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/candidates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "dfchaos/bisect.hpp"
#include "dfchaos/certified/oracle.hpp"
#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

namespace {

constexpr double kThreeHalvesPi = 1.5 * 3.14159265358979323846;

/// Walks from `from` in direction `dir` with geometric steps while the continuity label stays
/// `label`, until `reached(step)`; returns the first such phase refined by bisection, or, if the label
/// changes first, a phase half-way between `from` and the end of the label run. Best effort (the
/// result is only a candidate; proofs decide).
template <class Reached>
double walk(const Parameters& p, const dfchaos::ContinuityLabel& label, double from, double dir, double scale, Reached&& reached) {
  const double t2 = *p.t2();
  double x = from, h = std::max(1e-13, scale * 1e-4);
  for (int i = 0; i < 200; ++i) {
    double y = x + dir * h;
    bool out = y <= t2 || y >= kThreeHalvesPi;
    if (out) y = dir > 0 ? std::nextafter(kThreeHalvesPi, 0.0) : std::nextafter(t2, 4.0);
    const LabelledStep l = continuity_label(p, y);
    if (!(l.label == label)) {
      const auto [good, bad] = bisect(
          [&](double mid) {
            const LabelledStep lm = continuity_label(p, mid);
            return lm.label == label && !reached(lm.step);
          },
          x, y, {.max_iterations = 60});
      const LabelledStep lb = continuity_label(p, bad);
      if (lb.label == label && reached(lb.step)) return bad;  // reached before the run ends
      return from + 0.5 * (good - from);
    }
    if (reached(l.step)) {
      return bisect([&](double mid) { return !reached(continuity_label(p, mid).step); }, x, y, {.max_iterations = 80}).second;
    }
    if (out) return x;
    x = y;
    h *= 1.5;
  }
  return x;
}

/// Moves the top end away from the t2 end, inside the continuity label, to where T reaches
/// 3pi/2 + margin (T is continuous and increasing that way on a label run).
double move_top(const Parameters& p, const dfchaos::CoveringSegment& s, double target) {
  const double dir = s.theta_at_top < s.theta_at_t2 ? -1.0 : 1.0;
  const double scale = std::fabs(s.theta_at_t2 - s.theta_at_top);
  return walk(p, s.label, s.theta_at_top, dir, scale, [&](const MapStep& st) { return st.T >= target; });
}

/// Moves the t2 end away from the top end to the middle of the plateau where T = t2: from the first
/// phase with T = t2 to where T leaves t2 or the branch of T1 ends (the progression may end in the
/// arc [t1, t2) or, after a jump of theta2, in [t3, t0]: T = t2 on both).
double move_t2(const Parameters& p, const dfchaos::CoveringSegment& s) {
  const double dir = s.theta_at_t2 < s.theta_at_top ? -1.0 : 1.0;
  const double scale = std::fabs(s.theta_at_t2 - s.theta_at_top);
  const double t2 = *p.t2();
  const long long branch = t1_branch(p, return_map_step(p, s.theta_at_t2));
  auto on_plateau = [&](double th) {
    if (th <= t2 || th >= kThreeHalvesPi) return false;
    const MapStep st = return_map_step(p, th);
    return t1_branch(p, st) == branch && st.T == t2;
  };
  if (!on_plateau(s.theta_at_t2)) return s.theta_at_t2;
  double x = s.theta_at_t2, h = std::max(1e-13, scale * 1e-4);
  double y = x + dir * h;
  for (int i = 0; i < 200 && on_plateau(y); ++i) {
    x = y;
    h *= 1.5;
    y = x + dir * h;
  }
  x = bisect(on_plateau, x, y, {.max_iterations = 60}).first;  // x on the plateau, y off it
  return s.theta_at_t2 + 0.5 * (x - s.theta_at_t2);
}

/// The plateau of T = t2 around `th` in the branch of T1 at `th`, and its middle; NaN if T(th) != t2.
/// `width` receives the plateau's width.
double plateau_middle(const Parameters& p, double th, double scale, double& width) {
  const double t2 = *p.t2();
  if (th <= t2 || th >= kThreeHalvesPi) return NAN;
  const MapStep s0 = return_map_step(p, th);
  if (s0.T != t2) return NAN;
  const long long branch = t1_branch(p, s0);
  auto on = [&](double x) {
    if (x <= t2 || x >= kThreeHalvesPi) return false;
    const MapStep st = return_map_step(p, x);
    return t1_branch(p, st) == branch && st.T == t2;
  };
  double ends[2];
  for (int side = 0; side < 2; ++side) {
    const double dir = side == 0 ? -1.0 : 1.0;
    double x = th, h = std::max(1e-13, scale * 1e-3), y = x + dir * h;
    for (int i = 0; i < 200 && on(y); ++i) {
      x = y;
      h *= 1.6;
      y = x + dir * h;
    }
    ends[side] = bisect(on, x, y, {.max_iterations = 12}).first;
  }
  width = ends[1] - ends[0];
  return 0.5 * (ends[0] + ends[1]);
}

/// The end w of the window [lo, w] of [lo, hi] that holds at most `branches` branches of T1
/// (symmetric_tangency_count, closed form), largest to 2e-16 relative; hi when [lo, hi] holds them.
double branch_window(const Parameters& p, double lo, double hi, long long branches) {
  if (symmetric_tangency_count(p, lo, hi) + 1 <= branches) return hi;
  return bisect([&](double w) { return symmetric_tangency_count(p, lo, w) + 1 <= branches; }, lo, hi, {.max_iterations = 200, .rel_tol = 2e-16})
      .first;
}

}  // namespace

std::vector<Candidate> track_candidates(double a, double b, double q, const std::vector<Candidate>& old, const CandidateOptions& opt) {
  std::vector<Candidate> out;
  const bool followed = oracle::attempt([&] {
    const Parameters p(a, b, q);
    p.require_return_map();
    const double lo_target = kThreeHalvesPi + 0.25 * opt.margin_top, hi_limit = *p.t3() - 0.25;
    for (const Candidate& c : old) {
      Candidate n = c;
      const double scale = std::fabs(c.theta_t2 - c.theta_top);
      // Keep the t2 end while the plateau still reaches a quarter of its width on both sides of it.
      bool keep = false;
      if (c.plateau > 0) {
        const double t2 = *p.t2();
        auto on = [&](double x) { return x > t2 && x < kThreeHalvesPi && return_map_step(p, x).T == t2; };
        const long long br = t1_branch(p, return_map_step(p, c.theta_t2));
        auto same = [&](double x) { return t1_branch(p, return_map_step(p, x)) == br; };
        const double d = 0.25 * c.plateau;
        keep = on(c.theta_t2) && on(c.theta_t2 - d) && on(c.theta_t2 + d) && same(c.theta_t2 - d) && same(c.theta_t2 + d);
      }
      if (!keep) {
        n.theta_t2 = plateau_middle(p, c.theta_t2, scale, n.plateau);
        // The plateau moved off the old end: look for it nearby (it moves by about its width per box).
        const double step = c.plateau > 0 ? 0.25 * c.plateau : 1e-3 * scale;
        for (int k = 1; k <= 12 && std::isnan(n.theta_t2); ++k) {
          const int steps_away = (k + 1) / 2;  // 1, 1, 2, 2, ...: right and left in turn
          const double x = c.theta_t2 + (k % 2 ? 1.0 : -1.0) * step * steps_away;
          if (return_map_step(p, x).T == *p.t2()) n.theta_t2 = plateau_middle(p, x, scale, n.plateau);
        }
        if (std::isnan(n.theta_t2)) continue;  // this one is lost
      }
      const double T_top = return_map_step(p, c.theta_top).T;
      if (!(T_top >= lo_target && T_top <= hi_limit)) {
        // Re-aim the top end at 3pi/2 + margin by bisection between it and the t2 end (T continuous and
        // decreasing there on a run of the chain; the proof checks).
        const double target = kThreeHalvesPi + opt.margin_top;
        double x = c.theta_top, y = n.theta_t2;  // T(x) should be >= target, T(y) = t2
        if (T_top < target) {
          // Move away from the t2 end until T >= target (bounded), else give up.
          const double dir = c.theta_top < c.theta_t2 ? -1.0 : 1.0;
          double h = scale * 1e-3;
          bool found = false;
          for (int i = 0; i < 60 && !found; ++i, h *= 1.5) {
            const double z = c.theta_top + dir * h;
            const double Tz = return_map_step(p, z).T;
            if (Tz > hi_limit) break;
            if (Tz >= target) {
              x = z;
              found = true;
            }
          }
          if (!found) continue;
        }
        n.theta_top = bisect([&](double mid) { return return_map_step(p, mid).T >= target; }, x, y, {.max_iterations = 30}).first;
      }
      if (!out.empty() && !(out.back().hi() < n.lo())) continue;
      if (n.lo() < *p.t2() || n.hi() > kThreeHalvesPi) continue;
      out.push_back(n);
    }
  });
  if (!followed || out.size() < 2) return {};
  return out;
}

std::string for_each_candidate(double a, double b, double q, const CandidateOptions& opt, const std::function<bool(const Candidate&)>& take) {
  std::string searched;
  std::optional<Parameters> p;
  double lo = 0, hi = 0;
  std::vector<dfchaos::CoveringSegment> segs;
  // The floating layer may refuse (parameters outside its domain, or it gave up): then no (more)
  // candidates. Only its calls are attempted (oracle::attempt); the proofs' exceptions (`take`) pass.
  const bool searched_ok = oracle::attempt([&] {
    p.emplace(a, b, q);
    p->require_return_map();
    lo = std::isnan(opt.lo) ? *p->t2() : std::max(opt.lo, *p->t2());
    hi = std::isnan(opt.hi) ? kThreeHalvesPi : std::min(opt.hi, kThreeHalvesPi);
    if (!(lo < hi)) return;
    CoveringSearch search;
    search.max_segments = opt.candidates;
    search.recheck = 32;
    const long long cap = std::max(1LL, opt.max_branches);
    for (long long branches = std::clamp(opt.first_branches, 1LL, cap);; branches = std::min(4 * branches, cap)) {
      poll_stop();  // stop.hpp: a caller may end the proof here
      const double w = branch_window(*p, lo, hi, branches);
      search.max_branches = branches + 1;
      segs = covering_segments(*p, lo, w, kThreeHalvesPi, search);
      searched = w < hi ? " (candidates sought in [" + format_double(lo) + ", " + format_double(w) + "]: " + std::to_string(branches) +
                              " branches of T1, CandidateOptions::max_branches " + std::to_string(cap) + ")"
                        : std::string();
      if (static_cast<int>(segs.size()) >= opt.candidates || w == hi || branches >= cap) break;
    }
  });
  if (!searched_ok) return searched;
  double last_hi = -std::numeric_limits<double>::infinity();  // keep them disjoint
  for (const auto& s : segs) {
    Candidate c;
    if (!oracle::attempt([&] {
          c.theta_top = move_top(*p, s, kThreeHalvesPi + opt.margin_top);
          c.theta_t2 = move_t2(*p, s);
          double w = 0;
          const double mid = plateau_middle(*p, c.theta_t2, std::fabs(c.theta_t2 - c.theta_top), w);
          if (!std::isnan(mid)) c.plateau = w;
        }))
      return searched;
    if (c.lo() < lo || c.hi() > hi || !(last_hi < c.lo())) continue;
    last_hi = c.hi();
    if (take(c)) return searched;
  }
  return searched;
}

std::vector<Candidate> covering_candidates(double a, double b, double q, const CandidateOptions& opt) {
  std::vector<Candidate> out;
  for_each_candidate(a, b, q, opt, [&](const Candidate& c) {
    out.push_back(c);
    return false;
  });
  return out;
}

}  // namespace dfchaos::certified
