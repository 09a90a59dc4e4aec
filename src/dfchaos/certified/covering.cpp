// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/covering.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/oracle.hpp"
#include "dfchaos/errors.hpp"

namespace dfchaos::certified {

namespace {

/// Which of theta and b moves T1 more over a ball x box (floating estimate): true to split b.
bool split_b_first(const ParameterBox& box, double th_lo, double th_hi) {
  if (box.b_lo == box.b_hi) return false;
  if (th_lo == th_hi) return true;
  const double bm = 0.5 * (box.b_lo + box.b_hi), tm = 0.5 * (th_lo + th_hi);
  const double by_b = std::fabs(oracle::T1(box.a, box.b_lo, tm) - oracle::T1(box.a, box.b_hi, tm));
  const double by_t = std::fabs(oracle::T1(box.a, bm, th_lo) - oracle::T1(box.a, bm, th_hi));
  if (std::isnan(by_b) || std::isnan(by_t)) return box.b_hi - box.b_lo > 0;
  return by_b > by_t;
}

/// Proves `check` on [th_lo, th_hi] x box by an adaptive cover that splits theta or b.
template <class Check>
Outcome cover_2d(const ParameterBox& box, double th_lo, double th_hi, const CoveringOptions& opt, int max_depth, Budget& budget, SegmentProof& r,
                 const std::string& step, Check&& check) {
  struct Cell {
    double t0, t1;
    ParameterBox box;
  };
  auto check_cell = [&](const Cell& c, int depth) {
    const ParameterBalls m(c.box);
    Outcome why;
    if (check(m, c.t0, c.t1, why)) {
      ++r.balls;
      r.depth = std::max(r.depth, depth);
      if (c.t1 > c.t0) r.min_width = std::min(r.min_width, c.t1 - c.t0);
      if (r.balls > opt.max_balls) return CellVerdict::stop(Outcome::fail(step, "more than " + std::to_string(opt.max_balls) + " balls"));
      return CellVerdict::proved();
    }
    Outcome fail =
        Outcome::fail(step, "at theta in [" + format_double(c.t0) + ", " + format_double(c.t1) + "], " + c.box.describe() + ": " + why.describe());
    return budget.exhausted() ? CellVerdict::stop(std::move(fail)) : CellVerdict::split(std::move(fail));
  };
  // Halves theta, b or q: b where it moves T1 more than theta (or theta cannot be halved), q only when
  // neither can. Splitting stops at relative widths where ball arithmetic gains nothing more.
  auto split = [](const Cell& c, int) -> std::optional<std::pair<Cell, Cell>> {
    const double tm = 0.5 * (c.t0 + c.t1), bm = 0.5 * (c.box.b_lo + c.box.b_hi), qm = 0.5 * (c.box.q_lo + c.box.q_hi);
    const bool can_t = tm > c.t0 && tm < c.t1;
    const bool can_b = c.box.b_hi - c.box.b_lo > 1e-9 * c.box.b_hi && bm > c.box.b_lo && bm < c.box.b_hi;
    const bool can_q = c.box.q_hi - c.box.q_lo > 1e-7 && qm > c.box.q_lo && qm < c.box.q_hi;
    if (!can_t && !can_b && !can_q) return std::nullopt;
    ParameterBox lo = c.box, hi = c.box;
    if (can_b && (!can_t || split_b_first(c.box, c.t0, c.t1))) {
      lo.b_hi = bm;
      hi.b_lo = bm;
    } else if (!can_t) {
      lo.q_hi = qm;
      hi.q_lo = qm;
    } else {
      return std::make_pair(Cell{c.t0, tm, c.box}, Cell{tm, c.t1, c.box});
    }
    return std::make_pair(Cell{c.t0, c.t1, lo}, Cell{c.t0, c.t1, hi});
  };
  return cover(Cell{th_lo, th_hi, box}, check_cell, split, max_depth);
}

}  // namespace

SegmentProof prove_segment(const ParameterBalls& m, const Candidate& c, const CoveringOptions& opt) {
  SegmentProof r;
  r.lo = c.lo();
  r.hi = c.hi();
  r.theta_top = c.theta_top;
  r.theta_t2 = c.theta_t2;
  r.min_width = r.hi - r.lo;
  if (Outcome v = m.admissible(); !v) {
    r.verdict = v;
    return r;
  }
  // J inside [t2, 3 pi / 2] for every parameter of the box.
  const Ball three_halves_pi = 1.5 * m.pi;
  if (!le(m.t2_at_b_hi, Ball(r.lo)) || !le(Ball(r.hi), three_halves_pi)) {
    r.verdict = Outcome::fail("covering: J inside [t2, 3pi/2]", "J = [" + format_double(r.lo) + ", " + format_double(r.hi) + "]");
    return r;
  }
  Budget budget;
  budget.max_tests = opt.max_tests;
  bool first_top = true, first_bot = true;
  // The two ends (over sub-boxes of b if needed).
  Outcome v = cover_2d(m.box(), c.theta_top, c.theta_top, opt, opt.end_depth, budget, r, "covering: T >= 3pi/2 at the top end",
                       [&](const ParameterBalls& mm, double t0, double t1, Outcome& why) {
                         MapStepProof top = certify_T(mm, StartSet::interval(t0, t1), budget, nullptr, opt.record);
                         r.tests += top.tests;
                         if (!top.verdict) {
                           why = top.verdict;
                           return false;
                         }
                         if (!le(1.5 * mm.pi, top.T)) {
                           why = Outcome::fail("T >= 3pi/2", "T = " + top.T.str(12));
                           return false;
                         }
                         r.T_top = first_top ? top.T : Ball::hull(r.T_top, top.T);
                         first_top = false;
                         if (opt.record) r.top_balls.push_back(BallProof::of(StartSet::interval(t0, t1), mm.box(), std::move(top)));
                         return true;
                       });
  if (!v) {
    r.verdict = v;
    return r;
  }
  v = cover_2d(m.box(), c.theta_t2, c.theta_t2, opt, opt.end_depth, budget, r, "covering: T = t2 at the t2 end",
               [&](const ParameterBalls& mm, double t0, double t1, Outcome& why) {
                 MapStepProof bot = certify_T(mm, StartSet::interval(t0, t1), budget, nullptr, opt.record);
                 r.tests += bot.tests;
                 if (!bot.verdict) {
                   why = bot.verdict;
                   return false;
                 }
                 if (!bot.constant_t2) {
                   why = Outcome::fail("T = t2", "T = " + bot.T.str(12));
                   return false;
                 }
                 r.theta2_t2end = first_bot ? bot.theta2_phase : Ball::hull(r.theta2_t2end, bot.theta2_phase);
                 first_bot = false;
                 r.used_lemma1 = r.used_lemma1 || bot.used_lemma1;
                 if (opt.record) r.t2_balls.push_back(BallProof::of(StartSet::interval(t0, t1), mm.box(), std::move(bot)));
                 return true;
               });
  if (!v) {
    r.verdict = v;
    return r;
  }
  const int end_balls = r.balls;
  // Continuity on J.
  v = cover_2d(m.box(), r.lo, r.hi, opt, opt.max_depth, budget, r, "covering: continuity on J",
               [&](const ParameterBalls& mm, double t0, double t1, Outcome& why) {
                 MapStepProof t = certify_T(mm, StartSet::interval(t0, t1), budget, nullptr, opt.record);
                 r.tests += t.tests;
                 if (!t.verdict) {
                   why = t.verdict;
                   return false;
                 }
                 r.used_lemma1 = r.used_lemma1 || t.used_lemma1;
                 if (opt.record) r.cover_balls.push_back(BallProof::of(StartSet::interval(t0, t1), mm.box(), std::move(t)));
                 return true;
               });
  r.balls -= end_balls;
  r.verdict = v;
  return r;
}

namespace {

/// Lemma 4 over a box from candidates offered one by one (in ascending order): each disjoint from the
/// segments proved so far is proved, until two are.
class CoveringAttempt {
 public:
  CoveringAttempt(const ParameterBox& box, const CoveringOptions& opt) : m_(box), opt_(opt) { r_.box = box; }
  /// Tries `c`; true when two segments are proved (offer no more).
  bool offer(const Candidate& c) {
    if (proved_.size() == 2) return true;
    if (!proved_.empty() && !(proved_.back().hi < c.lo())) return false;
    ++r_.candidates_tried;
    SegmentProof s = prove_segment(m_, c, opt_);
    if (s.verdict)
      proved_.push_back(s);
    else
      last_failure_ = s;
    return proved_.size() == 2;
  }
  /// The verdict after the last offer; `searched` (if not empty) says where the candidates were sought.
  CoveringProof finish(const std::string& searched = {}) {
    if (proved_.size() == 2) {
      r_.J0 = proved_[0];
      r_.J1 = proved_[1];
      r_.verdict = Outcome::ok();
      if (opt_.record && (r_.J0.used_lemma1 || r_.J1.used_lemma1)) r_.lemma1 = certify_lemma1(m_);
    } else if (r_.candidates_tried == 0) {
      r_.verdict = Outcome::fail("covering: candidates", "the floating-point search proposed no covering segment" + searched);
    } else if (!last_failure_.verdict.proved && !last_failure_.verdict.step.empty()) {
      r_.verdict = last_failure_.verdict;
      if (!proved_.empty()) r_.J0 = proved_[0];
    } else {
      r_.verdict = Outcome::fail("covering: candidates", "fewer than two disjoint candidates were proved" + searched);
      if (!proved_.empty()) r_.J0 = proved_[0];
    }
    return r_;
  }

 private:
  const ParameterBalls m_;
  const CoveringOptions& opt_;
  CoveringProof r_;
  std::vector<SegmentProof> proved_;
  SegmentProof last_failure_;
};

}  // namespace

CoveringProof prove_covering(const ParameterBox& box, const std::vector<Candidate>& candidates, const CoveringOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  CoveringAttempt attempt(box, opt);
  for (const Candidate& c : candidates)
    if (attempt.offer(c)) break;
  CoveringProof r = attempt.finish();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

CoveringProof prove_covering(const ParameterBox& box, const CoveringOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  const double b = 0.5 * (box.b_lo + box.b_hi), q = 0.5 * (box.q_lo + box.q_hi);
  // Candidates are moved and proved one at a time: the walks that move the ends of a candidate are
  // most of the search's cost, and the first two usually prove.
  CoveringAttempt attempt(box, opt);
  const std::string searched = for_each_candidate(box.a, b, q, opt, [&](const Candidate& c) { return attempt.offer(c); });
  CoveringProof r = attempt.finish(searched);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace dfchaos::certified
