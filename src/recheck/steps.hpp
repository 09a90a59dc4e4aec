// SPDX-License-Identifier: GPL-3.0-or-later
/// @file steps.hpp
/// @brief The counted steps of a check, parameter boxes and balls of start phases, the exact test
/// that closed balls cover a box, the standing conditions of Section 2, and Lemma 1 on sub-boxes.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "interval.hpp"
#include "reading.hpp"

namespace recheck {

/// Counts the steps re-verified; the first that fails ends the check.
struct Steps {
  long n = 0;
  void require(bool ok, const std::string& step) {
    if (!ok) throw Failed(step);
    ++n;
  }
};
/// A sub-box [b_lo, b_hi] x [q_lo, q_hi].
struct Box {
  double b_lo, b_hi, q_lo, q_hi;
};
/// How a ball's start phases are given: [th_lo, th_hi] (doubles), or ["t2", th_hi], the phases
/// [t2(b), th_hi] from t2 exactly, for each b of the box.
enum class Start { Interval, FromT2 };
/// A closed set [th_lo, th_hi] x [b_lo, b_hi] x [q_lo, q_hi] (a ball of a covering certificate; a
/// Lemma 1 sub-box has th_lo = th_hi = 0).
struct Ball {
  double th_lo, th_hi;
  Box box;
  Start start = Start::Interval;
};

/// Whether the closed intervals cover [lo, hi] (lo == hi: contain the point).
bool covers(std::vector<std::pair<double, double>> v, double lo, double hi);
/// The box in hexadecimal (for the step that failed).
std::string describe(const Box& s);
/// The parameters {a} x B x Q in decimal, as the verdict line states them.
std::string box_text(double a, const Box& s);
/// The sorted distinct values of `ends` clipped to [lo, hi], with lo and hi.
std::vector<double> edges(double lo, double hi, std::vector<double> ends);
/// Requires that the closed balls cover [th_lo, th_hi] x box, exactly in double comparisons: for each
/// open cell between consecutive theta edges (the point when th_lo == th_hi) and consecutive b edges
/// (likewise), the q ranges of the balls whose closed theta and b ranges contain the cell cover
/// [q_lo, q_hi]. Closed balls then cover the cells' edges too.
void require_cover(Steps& st, const std::vector<Ball>& balls, double th_lo, double th_hi, const Box& box, const std::string& step);
/// Eq. (1): f(lo) < 0 < f(hi) with 0 < lo < hi < pi/2 (f' > 0 on (0, pi/2): analytic, README.md);
/// then the correctly rounded doubles of vartheta0 and sin vartheta0, when given.
void vartheta0_steps(Steps& st, const Num& lo, const Num& hi);
/// The standing conditions of Section 2 on {a} x B x Q: 2b < a, q > 2b, q - 2b < a, and b > 0
/// unless B starts at 0 (b0's [0, b_low], whose statement is about (0, b_low]).
void standing(Steps& st, const Iv& A, const Iv& B, const Iv& Q, bool b_positive);
/// The parameters {a} x [b_lo, b_hi] x [q_lo, q_hi] of a certificate.
std::pair<double, Box> read_box(const json& c);
/// The box is not empty and the standing conditions hold on it; returns {a}.
Iv standing_box(Steps& st, double a, const Box& box);
/// Lemma 1's witness {"sub_boxes": [[b_lo, b_hi, q_lo, q_hi], ...]}.
std::vector<Ball> read_sub_boxes(const json& w, const std::string& where);
/// Lemma 1 over the box (its standing conditions already required): the sub-boxes inside the box
/// and covering it, Eq. (8) u(t2) < 0 on each.
void lemma1(Steps& st, const Iv& A, const Box& box, const std::vector<Ball>& subs);

}  // namespace recheck
