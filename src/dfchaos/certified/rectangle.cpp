// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/rectangle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dfchaos::certified {

double RectangleProof::proved_fraction() const { return std::clamp((uniform_length + box_length) / (b_hi - b_lo), 0.0, 1.0); }

RectangleProof prove_rectangle(double a, double b_lo, double b_hi, double q_lo, double q_hi, const Lemma4UniformProof& uniform,
                               const RectangleOptions& opt) {
  if (!(std::isfinite(a) && a > 0)) throw std::invalid_argument("prove_rectangle: a must be finite and positive");
  if (!(std::isfinite(b_lo) && std::isfinite(b_hi) && b_lo > 0 && b_lo < b_hi))
    throw std::invalid_argument("prove_rectangle: 0 < b_lo < b_hi, both finite");
  if (!(std::isfinite(q_lo) && std::isfinite(q_hi) && q_lo > 0 && q_lo <= q_hi))
    throw std::invalid_argument("prove_rectangle: 0 < q_lo <= q_hi, both finite");
  if (opt.max_boxes < 1 || opt.max_failed_run < 0) throw std::invalid_argument("prove_rectangle: max_boxes >= 1 and max_failed_run >= 0");
  RectangleProof r{.a = a, .b_lo = b_lo, .b_hi = b_hi, .q_lo = q_lo, .q_hi = q_hi};
  // The uniform route: b/a in (0, eps*] for q/a in [kappa_lo, kappa_hi]. The comparisons of the
  // rectangle (in b and q) with the proof (in b/a and q/a) are exact: x <= y a holds exactly when
  // fma(y, a, -x) >= 0 (one rounding of the exact difference keeps its sign).
  const auto at_most = [a](double x, double y_ratio) { return std::fma(y_ratio, a, -x) >= 0; };  // x <= y_ratio a
  const bool applies =
      uniform.verdict.proved && std::fma(uniform.kappa_lo, a, -q_lo) <= 0 /* q_lo >= kappa_lo a */ && at_most(q_hi, uniform.kappa_hi);
  double b = b_lo;
  if (applies) {
    r.uniform_bound = uniform.eps_star;
    // The largest b <= min(b_hi, eps* a): the rounded product, stepped down while it exceeds it.
    double top = std::min(b_hi, uniform.eps_star * a);
    for (int k = 0; k < 64 && top > 0 && !at_most(top, uniform.eps_star); ++k) top = std::nextafter(top, 0.0);
    if (top > b_lo && at_most(top, uniform.eps_star)) {
      r.uniform_length = top - b_lo;
      b = top;
    }
  }
  r.b_reached = b;
  if (b >= b_hi) return r;
  // The rest as one column of boxes; 64 bits suffice for b/a >= 1e-5 (region.hpp), below more.
  RegionOptions ro{.a = a, .b_lo = b, .b_hi = b_hi, .q_lo = q_lo, .q_hi = q_hi, .q_columns = 1};
  ro.max_boxes = opt.max_boxes;
  ro.max_failed_run = opt.max_failed_run;
  ro.precision = b / a >= 1e-5 ? 64 : 128;
  const RegionResult g = certify_region(ro);
  const RegionColumn& col = g.columns.front();
  r.box_length = col.proved_length;
  r.boxes_proved = g.boxes_proved;
  r.boxes_failed = g.boxes_failed;
  r.attempts = col.attempts;
  r.b_reached = col.b_reached;
  if (col.gave_up)
    r.stop = RectangleStop::FailedRun;
  else if (!(col.b_reached >= b_hi))
    r.stop = RectangleStop::BoxBudget;
  return r;
}

}  // namespace dfchaos::certified
