// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/region.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

CoveringProof prove_covering_split(const ParameterBox& box, const std::vector<Candidate>& c, int depth, int& sub_boxes, const CoveringOptions& opt) {
  CoveringProof p = prove_covering(box, c, opt);
  if (p.verdict) {
    ++sub_boxes;
    return p;
  }
  const double mid = 0.5 * (box.b_lo + box.b_hi);
  if (depth <= 0 || !(mid > box.b_lo && mid < box.b_hi)) return p;
  ParameterBox left = box, right = box;
  left.b_hi = mid;
  right.b_lo = mid;
  const int before = sub_boxes;
  CoveringProof l = prove_covering_split(left, c, depth - 1, sub_boxes, opt);
  if (!l.verdict) {
    sub_boxes = before;
    return l;
  }
  CoveringProof r = prove_covering_split(right, c, depth - 1, sub_boxes, opt);
  if (!r.verdict) {
    sub_boxes = before;
    return r;
  }
  r.box = box;
  return r;
}

namespace {

/// The two candidates whose plateau T = t2 is widest (they survive the widest boxes), ascending.
std::vector<Candidate> widest_two(std::vector<Candidate> c) {
  if (c.size() <= 2) return c;
  std::vector<std::size_t> idx(c.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t x, std::size_t y) { return c[x].plateau > c[y].plateau; });
  const std::size_t i = std::min(idx[0], idx[1]), j = std::max(idx[0], idx[1]);
  return {c[i], c[j]};
}

/// The state of a column between passes (so that a later pass resumes where the last stopped).
struct ColumnState {
  std::size_t index = 0;
  RegionColumn col;
  double b = 0, c = 0;
  std::vector<Candidate> cand;
  bool done = false;
};

void tile_column(const RegionOptions& opt, const ProvedBoxSink& sink, ColumnState& st, long budget) {
  const auto start = std::chrono::steady_clock::now();
  const PrecisionScope precision_of_this_thread(opt.precision);
  RegionColumn& col = st.col;
  const double q_lo = col.q_lo, q_hi = col.q_hi;
  double& b = st.b;
  double& c = st.c;
  std::vector<Candidate>& cand = st.cand;
  long used = 0;
  while (b < opt.b_hi && used < budget && !col.gave_up) {
    poll_stop();  // stop.hpp: a caller may end the proof here
    const double w = std::min(c * b * b / opt.a, opt.b_hi - b);
    ParameterBox box{opt.a, b, b + w, q_lo, q_hi};
    if (box.b_hi == box.b_lo) break;
    ++used;
    ++col.attempts;
    // Candidates are followed from box to box (track_candidates); searched afresh when lost.
    int sub = 0;
    const double bc = 0.5 * (box.b_lo + box.b_hi), qc = 0.5 * (q_lo + q_hi);
    if (!cand.empty()) cand = track_candidates(opt.a, bc, qc, cand);
    const bool fresh = cand.empty();
    if (fresh) cand = widest_two(covering_candidates(opt.a, bc, qc));
    // A box too wide fails at its ends: no splitting there (the width is adapted instead).
    CoveringOptions copt;
    copt.end_depth = 0;
    copt.max_depth = 12;
    copt.record = static_cast<bool>(sink);
    CoveringProof p = prove_covering_split(box, cand, opt.split_depth, sub, copt);
    if (!p.verdict && !fresh && c <= opt.c_min) {
      cand = widest_two(covering_candidates(opt.a, bc, qc));
      sub = 0;
      p = prove_covering_split(box, cand, opt.split_depth, sub, copt);
    }
    if (p.verdict) {
      const Candidate J0{p.J0.theta_top, p.J0.theta_t2}, J1{p.J1.theta_top, p.J1.theta_t2};
      col.boxes.push_back(RegionBox{box.b_lo, box.b_hi, q_lo, q_hi, true, sub, "", J0, J1});
      if (sink) sink(st.index, col.boxes.back(), p);
      col.proved_length += box.b_hi - box.b_lo;
      col.failed_run = 0;
      b = box.b_hi;
      c = std::min(opt.c_max, c * 1.25);
      continue;
    }
    if (c > opt.c_min) {
      c = std::max(opt.c_min, c / 1.6);
      continue;
    }
    col.boxes.push_back(RegionBox{box.b_lo, box.b_hi, q_lo, q_hi, false, 0, p.verdict.step, {}, {}});
    b = box.b_hi;
    cand.clear();
    if (++col.failed_run == opt.max_failed_run) col.gave_up = true;
  }
  st.done = !(b < opt.b_hi) || col.gave_up;
  col.b_reached = b;
  col.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RegionResult certify_region(const RegionOptions& opt, const ProvedBoxSink& sink) {
  if (sink && opt.split_depth > 0)
    throw std::invalid_argument("certify_region: recording needs split_depth = 0 (the proof of a split box keeps only its last half)");
  const auto start = std::chrono::steady_clock::now();
  RegionResult r;
  r.options = opt;
  const int n = std::max(1, opt.q_columns);
  std::vector<ColumnState> st(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    ColumnState& s = st[static_cast<std::size_t>(i)];
    s.index = static_cast<std::size_t>(i);
    s.col.q_lo = opt.q_lo + (opt.q_hi - opt.q_lo) * i / n;
    s.col.q_hi = i + 1 == n ? opt.q_hi : opt.q_lo + (opt.q_hi - opt.q_lo) * (i + 1) / n;
    s.b = opt.b_lo;
    s.c = opt.c_start;
  }
  // Passes: the box budget left is shared equally among the unfinished columns; a column that
  // finishes early leaves its share to the others. Each pass's shares are fixed before it starts,
  // so the result does not depend on the number of threads.
  long left = opt.max_boxes;
  const StopToken* token = current_stop_token();  // installed in each thread; Stopped cannot leave a parallel region
  for (int pass = 0; pass < 64 && left > 0; ++pass) {
    std::vector<int> open;
    for (int i = 0; i < n; ++i)
      if (!st[static_cast<std::size_t>(i)].done) open.push_back(i);
    if (open.empty()) break;
    const long share = std::max(1L, left / static_cast<long>(open.size()));
    const int m = static_cast<int>(open.size());
    int finished = 0;
#pragma omp parallel for schedule(dynamic, 1)
    for (int j = 0; j < m; ++j) {
      ColumnState& s = st[static_cast<std::size_t>(open[static_cast<std::size_t>(j)])];
      const StopScope scope(token);
      try {
        tile_column(opt, sink, s, share);
      } catch (const Stopped&) {
        continue;  // thrown again after the region
      }
      if (opt.progress) {
#pragma omp critical
        std::fprintf(stderr, "\rcertified_region: pass %d, column %d/%d done (q/a in [%.4f, %.4f] reached b/a = %.6g)   ", pass + 1, ++finished, m,
                     s.col.q_lo, s.col.q_hi, s.col.b_reached);
      }
    }
    poll_stop();
    long used = 0;
    for (int i : open) used += st[static_cast<std::size_t>(i)].col.attempts;
    left = opt.max_boxes;
    for (const auto& s : st) left -= s.col.attempts;
    if (used == 0) break;
  }
  if (opt.progress) std::fprintf(stderr, "\n");
  r.complete = true;
  for (auto& s : st) {
    for (const auto& bx : s.col.boxes) (bx.proved ? r.boxes_proved : r.boxes_failed)++;
    if (!s.done || s.col.gave_up) r.complete = false;
    r.columns.push_back(std::move(s.col));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace dfchaos::certified
