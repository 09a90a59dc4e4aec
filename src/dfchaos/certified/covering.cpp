#include "dfchaos/certified/covering.hpp"

#include <chrono>
#include <cmath>
#include <exception>

#include "dfchaos/covering.hpp"
#include "dfchaos/phase.hpp"

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
      double good = x, bad = y;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (good + bad);
        const LabelledStep lm = continuity_label(p, mid);
        if (lm.label == label && !reached(lm.step)) good = mid; else bad = mid;
      }
      const LabelledStep lb = continuity_label(p, bad);
      if (lb.label == label && reached(lb.step)) return bad;  // reached before the run ends
      return from + 0.5 * (good - from);
    }
    if (reached(l.step)) {
      double lo = x, hi = y;
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (reached(continuity_label(p, mid).step)) hi = mid; else lo = mid;
      }
      return hi;
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

/// Moves the t2 end away from the top end, inside the label, to where the phase of theta2 is
/// t2 - margin (inside [t1, t2): the mass stops until t2).
double move_t2(const Parameters& p, const dfchaos::CoveringSegment& s, double margin) {
  const double dir = s.theta_at_t2 < s.theta_at_top ? -1.0 : 1.0;
  const double scale = std::fabs(s.theta_at_t2 - s.theta_at_top);
  const double t1 = *p.t1(), t2 = *p.t2();
  const double target = t2 - margin > t1 ? t2 - margin : 0.5 * (t1 + t2);
  const long double base = return_map_step(p, s.theta_at_t2).theta2.value();
  const long long k = static_cast<long long>(std::floor((base - t1) / two_pi_l));
  return walk(p, s.label, s.theta_at_t2, dir, scale,
              [&](const MapStep& st) { return static_cast<double>(st.theta2.value() - k * two_pi_l) <= target; });
}

}  // namespace

std::vector<Candidate> covering_candidates(double a, double b, double q, const CoveringOptions& opt) {
  std::vector<Candidate> out;
  try {
    const Parameters p(a, b, q);
    p.require_return_map();
    const double lo = std::isnan(opt.lo) ? *p.t2() : std::max(opt.lo, *p.t2());
    const double hi = std::isnan(opt.hi) ? kThreeHalvesPi : std::min(opt.hi, kThreeHalvesPi);
    if (!(lo < hi)) return out;
    CoveringSearch search;
    search.max_segments = opt.candidates;
    const auto segs = covering_segments(p, lo, hi, kThreeHalvesPi, search);
    for (const auto& s : segs) {
      Candidate c;
      c.theta_top = move_top(p, s, kThreeHalvesPi + opt.margin_top);
      c.theta_t2 = move_t2(p, s, opt.margin_t2);
      if (c.lo() < lo) continue;
      if (c.hi() > hi) continue;
      if (!out.empty() && !(out.back().hi() < c.lo())) continue;  // keep them disjoint
      out.push_back(c);
    }
  } catch (const std::exception&) {
    // The floating layer refused (parameters outside its domain, or it gave up): no candidates.
  }
  return out;
}

SegmentProof prove_segment(const Model& m, const Candidate& c, const CoveringOptions& opt) {
  SegmentProof r;
  r.lo = c.lo();
  r.hi = c.hi();
  r.theta_top = c.theta_top;
  r.theta_t2 = c.theta_t2;
  r.min_width = r.hi - r.lo;
  if (Verdict v = m.admissible(); !v) {
    r.verdict = v;
    return r;
  }
  // J inside [t2, 3 pi / 2] for every parameter of the box.
  const Ball three_halves_pi = 1.5 * m.pi;
  if (!le(m.t2_at_b_hi, Ball(r.lo)) || !le(Ball(r.hi), three_halves_pi)) {
    r.verdict = Verdict::fail("covering: J inside [t2, 3pi/2]", "J = [" + fmt17(r.lo) + ", " + fmt17(r.hi) + "]");
    return r;
  }
  Budget budget;
  budget.max_tests = opt.max_tests;
  // The two ends.
  {
    TProof top = certify_T(m, StartSet::point(c.theta_top), budget);
    r.tests += top.tests;
    if (!top.verdict) {
      r.verdict = Verdict::fail("covering: T at the top end", top.verdict.describe());
      return r;
    }
    r.T_top = top.T;
    if (!le(three_halves_pi, top.T)) {
      r.verdict = Verdict::fail("covering: T >= 3pi/2 at the top end", "T = " + top.T.str(12) + " at theta = " + fmt17(c.theta_top));
      return r;
    }
    TProof bot = certify_T(m, StartSet::point(c.theta_t2), budget);
    r.tests += bot.tests;
    if (!bot.verdict) {
      r.verdict = Verdict::fail("covering: T at the t2 end", bot.verdict.describe());
      return r;
    }
    r.theta2_t2end = bot.theta2_phase;
    if (!bot.constant_t2) {
      r.verdict = Verdict::fail("covering: T = t2 at the t2 end", "T = " + bot.T.str(12) + " at theta = " + fmt17(c.theta_t2));
      return r;
    }
    r.used_lemma1 = r.used_lemma1 || bot.used_lemma1;
  }
  // Continuity on J: adaptive cover by closed balls.
  struct Item { double x, y; int depth; };
  std::vector<Item> stack{{r.lo, r.hi, 0}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    TProof t = certify_T(m, StartSet::interval(it.x, it.y), budget);
    r.tests += t.tests;
    if (t.verdict) {
      ++r.balls;
      r.depth = std::max(r.depth, it.depth);
      r.min_width = std::min(r.min_width, it.y - it.x);
      r.used_lemma1 = r.used_lemma1 || t.used_lemma1;
      if (r.balls > opt.max_balls) {
        r.verdict = Verdict::fail("covering: continuity on J", "more than " + std::to_string(opt.max_balls) + " balls");
        return r;
      }
      continue;
    }
    const double mid = 0.5 * (it.x + it.y);
    if (t.verdict.refuted && it.x == it.y) {
      r.verdict = Verdict::fail("covering: continuity on J", t.verdict.describe());
      return r;
    }
    if (it.depth >= opt.max_depth || !(mid > it.x && mid < it.y) || budget.exhausted()) {
      r.verdict = Verdict::fail("covering: continuity on J", "at theta in [" + fmt17(it.x) + ", " + fmt17(it.y) + "]: " + t.verdict.describe());
      return r;
    }
    stack.push_back({mid, it.y, it.depth + 1});
    stack.push_back({it.x, mid, it.depth + 1});
  }
  r.verdict = Verdict::ok();
  return r;
}

CoveringProof prove_covering(const ParamBox& box, const std::vector<Candidate>& candidates, const CoveringOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  CoveringProof r;
  r.box = box;
  const Model m(box);
  std::vector<SegmentProof> proved;
  SegmentProof last_failure;
  for (const Candidate& c : candidates) {
    if (proved.size() == 2) break;
    if (!proved.empty() && !(proved.back().hi < c.lo())) continue;
    ++r.candidates_tried;
    SegmentProof s = prove_segment(m, c, opt);
    if (s.verdict) proved.push_back(s);
    else last_failure = s;
  }
  if (proved.size() == 2) {
    r.J0 = proved[0];
    r.J1 = proved[1];
    r.verdict = Verdict::ok();
  } else if (candidates.empty()) {
    r.verdict = Verdict::fail("covering: candidates", "the floating-point search proposed no covering segment");
  } else if (!last_failure.verdict.proved && !last_failure.verdict.step.empty()) {
    r.verdict = last_failure.verdict;
    if (!proved.empty()) r.J0 = proved[0];
  } else {
    r.verdict = Verdict::fail("covering: candidates", "fewer than two disjoint candidates were proved");
    if (!proved.empty()) r.J0 = proved[0];
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

CoveringProof prove_covering(const ParamBox& box, const CoveringOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  const double b = 0.5 * (box.b_lo + box.b_hi), q = 0.5 * (box.q_lo + box.q_hi);
  const std::vector<Candidate> c = covering_candidates(box.a, b, q, opt);
  CoveringProof r = prove_covering(box, c, opt);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace dfchaos::certified
