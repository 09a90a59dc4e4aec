#include "dfchaos/certified/region.hpp"

#include <chrono>
#include <cmath>

namespace dfchaos::certified {

CoveringProof prove_covering_split(const ParamBox& box, const std::vector<Candidate>& c, int depth, int& sub_boxes,
                                   const CoveringOptions& opt) {
  CoveringProof p = prove_covering(box, c, opt);
  if (p.verdict) {
    ++sub_boxes;
    return p;
  }
  const double mid = 0.5 * (box.b_lo + box.b_hi);
  if (depth <= 0 || !(mid > box.b_lo && mid < box.b_hi)) return p;
  ParamBox left = box, right = box;
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

RegionColumn tile_column(const RegionOptions& opt, double q_lo, double q_hi, long budget) {
  const auto start = std::chrono::steady_clock::now();
  RegionColumn col;
  col.q_lo = q_lo;
  col.q_hi = q_hi;
  double b = opt.b_lo, c = opt.c_start;
  std::vector<Candidate> cand;
  while (b < opt.b_hi && col.attempts < budget) {
    const double w = std::min(c * b * b / opt.a, opt.b_hi - b);
    ParamBox box{opt.a, b, b + w, q_lo, q_hi};
    if (box.b_hi == box.b_lo) break;
    ++col.attempts;
    // Candidates are kept from box to box while they prove; recomputed at this box's centre otherwise.
    int sub = 0;
    CoveringProof p;
    const double bc = 0.5 * (box.b_lo + box.b_hi), qc = 0.5 * (q_lo + q_hi);
    if (!cand.empty()) cand = track_candidates(opt.a, bc, qc, cand);
    bool fresh = cand.empty();
    if (fresh) cand = covering_candidates(opt.a, bc, qc);
    CoveringOptions copt;
    copt.end_depth = 2;
    copt.max_depth = 12;
    p = prove_covering_split(box, cand, opt.split_depth, sub, copt);
    if (!p.verdict && !fresh && c <= opt.c_min) {
      cand = covering_candidates(opt.a, 0.5 * (box.b_lo + box.b_hi), 0.5 * (q_lo + q_hi));
      sub = 0;
      p = prove_covering_split(box, cand, opt.split_depth, sub, copt);
    }
    if (p.verdict) {
      col.boxes.push_back(RegionBox{box.b_lo, box.b_hi, q_lo, q_hi, true, sub, ""});
      col.proved_length += box.b_hi - box.b_lo;
      b = box.b_hi;
      c = std::min(opt.c_max, c * 1.25);
      continue;
    }
    if (c > opt.c_min) {
      c = std::max(opt.c_min, c / 1.6);
      continue;
    }
    col.boxes.push_back(RegionBox{box.b_lo, box.b_hi, q_lo, q_hi, false, 0, p.verdict.step});
    b = box.b_hi;
    cand.clear();
  }
  col.b_reached = b;
  col.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return col;
}

}  // namespace

RegionResult certify_region(const RegionOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  RegionResult r;
  r.options = opt;
  const int n = std::max(1, opt.q_columns);
  r.columns.resize(static_cast<std::size_t>(n));
  const long per_column = std::max(1L, opt.max_boxes / n);
#pragma omp parallel for schedule(dynamic, 1)
  for (int i = 0; i < n; ++i) {
    const double q0 = opt.q_lo + (opt.q_hi - opt.q_lo) * i / n;
    const double q1 = i + 1 == n ? opt.q_hi : opt.q_lo + (opt.q_hi - opt.q_lo) * (i + 1) / n;
    r.columns[static_cast<std::size_t>(i)] = tile_column(opt, q0, q1, per_column);
  }
  r.complete = true;
  for (const auto& col : r.columns) {
    for (const auto& bx : col.boxes) (bx.proved ? r.boxes_proved : r.boxes_failed)++;
    if (col.b_reached < opt.b_hi) r.complete = false;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace dfchaos::certified
