// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/spec.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/units.hpp"
#include "sweep/cell.hpp"

namespace dfchaos::sweep {

namespace {
std::string count_text(long long v) { return format_shortest(static_cast<double>(v)); }
}  // namespace

void OrbitSettings::validate() const {
  if (!(theta0_fraction >= 0 && theta0_fraction < 1))
    throw InvalidParameter("theta0-fraction", "0 <= theta0-fraction < 1 (a fraction of [t2, t3))", theta0_fraction);
  if (transient < 0 || transient > kMaxTransient)
    throw InvalidParameter("transient", "0 <= transient <= " + count_text(kMaxTransient), static_cast<double>(transient));
  if (steps < 1 || steps > kMaxSteps) throw InvalidParameter("steps", "1 <= steps <= " + count_text(kMaxSteps), static_cast<double>(steps));
}

void PeriodSettings::validate() const {
  if (max < 1 || max > kMaxPeriod) throw InvalidParameter("period-max", "1 <= period-max <= " + count_text(kMaxPeriod), static_cast<double>(max));
  if (!(tol >= kMinPeriodTol && tol <= kMaxPeriodTol))
    throw InvalidParameter("period-tol", format_shortest(kMinPeriodTol) + " <= period-tol <= " + format_shortest(kMaxPeriodTol), tol);
}

void Spec::validate() const {
  if (physical.given() && !(a == length_scale(physical.mass, physical.omega, physical.amplitude)))
    throw InvalidParameter("a", "give --a or --physical MASS OMEGA AMPLITUDE, not both (physical: a = AMPLITUDE/(MASS OMEGA^2))", a);
  if (!(a >= kMinA && a <= kMaxA))
    throw InvalidParameter("a", format_shortest(kMinA) + " <= a <= " + format_shortest(kMaxA) + " (the model's range)", a);
  if (q_over_a.size() < 1 || b_over_a.size() < 1) throw InvalidParameter("q-range", "both ranges are required");
  q_over_a.require_within("q-range", 0, INFINITY, "every q/a must be positive and finite");
  for (double r : {q_over_a[0], q_over_a[q_over_a.size() - 1]})
    if (!std::isnormal(r)) throw InvalidParameter("q-range", "every q/a a normal number (not subnormal)", r);
  b_over_a.require_within("b-range", 0, 0.5, "every b/a must lie in (0, 1/2), where t2 and t3 exist");
  // The axes are monotone: the smallest b/a is at one end.
  const double b_least = std::min(b_over_a[0], b_over_a[b_over_a.size() - 1]);
  if (!(b_least >= kMinMapRatio))
    throw InvalidParameter("b-range", "every b/a >= " + format_shortest(kMinMapRatio) + " (the accuracy floor of T, docs/accuracy.md)", b_least);
  // The parameters themselves, a·(q/a) and a·(b/a), must be finite and positive (a huge or tiny a
  // would overflow or underflow them).
  for (double r : {q_over_a[0], q_over_a[q_over_a.size() - 1], b_over_a[0], b_over_a[b_over_a.size() - 1]})
    if (!(std::isnormal(a * r) && a * r > 0))
      throw InvalidParameter("a", "a * (q/a) and a * (b/a) must be finite, positive and normal for every cell", a);
  // ... and inside the model's range, so that an axis no cell of which could be computed is refused
  // here, not answered by a file of error rows.
  // The axes are monotone and the products a * r are monotone in r, so the ends decide.
  for (const auto& [axis, name, ratio] : {std::tuple{&q_over_a, "q-range", "q/a"}, std::tuple{&b_over_a, "b-range", "b/a"}})
    for (double r : {(*axis)[0], (*axis)[axis->size() - 1]})
      if (!(a * r >= kMinParameter && a * r <= kMaxParameter))
        throw InvalidParameter(name,
                               std::string("a * (") + ratio + ") within [" + format_shortest(kMinParameter) + ", " + format_shortest(kMaxParameter) +
                                   "] for every cell (the model's range: only b/a and q/a matter, rescale a)",
                               r);
  // The product is checked in floating point first: n_q and n_b are each at most 10^8.
  if (static_cast<double>(q_over_a.size()) * static_cast<double>(b_over_a.size()) > static_cast<double>(kMaxCells))
    throw InvalidParameter("q-range", "n_q * n_b <= " + count_text(kMaxCells) + " cells (got " + count_text(q_over_a.size()) + " * " +
                                          count_text(b_over_a.size()) + ")");
  if (superstable_scan < kMinSuperstableScan || superstable_scan > kMaxSuperstableScan)
    throw InvalidParameter("superstable-scan", count_text(kMinSuperstableScan) + " <= superstable-scan <= " + count_text(kMaxSuperstableScan),
                           static_cast<double>(superstable_scan));
  if (covering_max_branches < 1 || covering_max_branches > kMaxCoveringBranches)
    throw InvalidParameter("max-branches", "1 <= max-branches <= " + count_text(kMaxCoveringBranches), static_cast<double>(covering_max_branches));
  if (region_max_boxes < 1 || region_max_boxes > kMaxRegionBoxes)
    throw InvalidParameter("region-max-boxes", "1 <= region-max-boxes <= " + count_text(kMaxRegionBoxes), static_cast<double>(region_max_boxes));
  if (observables.has(Observable::Region)) {
    if (b_over_a.size() < 2 && b_over_a.spacing() != Spacing::Mid)
      throw InvalidParameter("b-range", "region proves over each cell's b/a interval, up to the next point: give two points or more, or lo:hi:n:mid");
    // The rectangles, not only the points, must have positive sides (a mid axis may start at 0).
    if (!(b_over_a.extent(0).first > 0)) throw InvalidParameter("b-range", "region needs every cell's b/a interval above 0 (a mid axis from lo > 0)");
    if (!(q_over_a.extent(0).first > 0)) throw InvalidParameter("q-range", "region needs every cell's q/a interval above 0 (a mid axis from lo > 0)");
  }
  if (max_proofs < 1 || max_proofs > kMaxMaxProofs)
    throw InvalidParameter("max-proofs", "1 <= max-proofs <= " + count_text(kMaxMaxProofs), static_cast<double>(max_proofs));
  const double per_cell = (observables.has(Observable::Certified) ? 1.0 : 0.0) +
                          (observables.has(Observable::Region) ? static_cast<double>(region_max_boxes) : 0.0) +
                          (observables.has(Observable::Entropy) ? 1.0 : 0.0);
  if (const double proofs = static_cast<double>(cells()) * per_cell; proofs > static_cast<double>(max_proofs))
    throw InvalidParameter("max-proofs",
                           "cells * proofs per cell (certified: 1, region: region-max-boxes, entropy: 1) <= max-proofs = " + count_text(max_proofs) +
                               " (got " + format_shortest(proofs) + "): a smaller grid, or --max-proofs to raise the cap");
  orbit.validate();
  period.validate();
  if (observables.needs_orbit()) {
    const double work =
        static_cast<double>(cells()) * static_cast<double>(orbit.transient + orbit.steps + (observables.has(Observable::Period) ? period.max : 0));
    if (work > kMaxOrbitEvaluations)
      throw InvalidParameter("steps", "cells * (transient + steps + period-max) <= 1e12 evaluations of T (got " + format_shortest(work) + ")");
  }
}

std::vector<std::string> Spec::header_lines() const {
  std::vector<std::string> h;
  h.push_back("a = " + format_shortest(a));
  if (physical.given()) {
    h.push_back("physical = " + format_shortest(physical.mass) + " " + format_shortest(physical.omega) + " " + format_shortest(physical.amplitude) +
                "  (mass kg, omega rad/s, amplitude N: a = amplitude/(mass omega^2) m; q_over_a = friction/amplitude, "
                "b_over_a = static force/(2 amplitude); docs/units.md)");
    h.emplace_back(
        "units = rate_m_per_s = omega rate (m/s); friction_N = q_over_a amplitude, static_N = 2 b_over_a amplitude (N); "
        "epsilon in radians of the forcing");
  }
  h.push_back("q_over_a = " + q_over_a.canonical());
  h.push_back("b_over_a = " + b_over_a.canonical());
  h.push_back("observables = " + observables.canonical());
  if (observables.has(Observable::Covering) || observables.has(Observable::Certified))
    h.push_back("max_branches = " + count_text(covering_max_branches) +
                "  (work budget per cell: most branches of T1 in [t2, 3pi/2] for covering, max_branches / " + count_text(kDenseCostFactor) +
                " for certified)");
  if (observables.has(Observable::Superstable)) h.push_back("superstable_scan = " + count_text(superstable_scan));
  if (observables.needs_orbit()) {
    h.push_back("theta0_fraction = " + format_shortest(orbit.theta0_fraction) + "  (theta_0 = t2 + theta0_fraction (t3 - t2))");
    h.push_back("transient = " + count_text(orbit.transient));
    h.push_back("steps = " + count_text(orbit.steps));
  }
  if (observables.has(Observable::Period)) {
    h.push_back("period_max = " + count_text(period.max));
    h.push_back("period_tol = " + format_shortest(period.tol) +
                "  (period: the smallest k <= period_max with |T^k(e) - e| <= period_tol on the circle, "
                "e = T^(transient+steps)(theta_0); 0 if none)");
  }
  if (observables.has(Observable::Certified))
    h.push_back("certified_step = " + certified_step_legend() +
                "  (certified: 1 when Lemma 4 is proved in ball arithmetic at the cell's double parameters, "
                "prove_covering with its default options; else 0 and the code of the step not proved; "
                "a proof at one point, not over the cell)");
  if (observables.has(Observable::Region)) {
    h.push_back("region_max_boxes = " + count_text(region_max_boxes) + "  (box proofs per cell above the uniform bound)");
    h.push_back("region_stop = " + region_stop_legend() +
                "  (region: the proved fraction of the b/a length of the cell's rectangle, from its point to the next one on each "
                "axis (mid: its part of the range); proved for every parameter in it, below region_uniform by Lemma 4 for every "
                "small b/a, above by parameter boxes)");
  }
  if (observables.has(Observable::Entropy))
    h.emplace_back(
        "entropy = entropy_lower <= h_top(T) <= entropy_upper, both proved in ball arithmetic at the cell's ratios (a = 1) from the "
        "entropy_laps laps of T (certified/laps.hpp, prove_entropy_bracket with its default options); lower 0 when no bound above "
        "ln 1 was proved, upper nan and laps 0 when the laps were not; a proof at one point, not over the cell");
  h.push_back("cells = " + count_text(cells()) + "  (index = i * " + count_text(b_over_a.size()) +
              " + j, i over q_over_a, j over b_over_a; a = A, q = q_over_a A, b = b_over_a A)");
  h.emplace_back(
      "status: ok | inadmissible (q/a <= 2 b/a: T undefined; values nan) | error (an observable threw: "
      "its values nan, the message in the error column)");
  return h;
}

std::vector<std::string> Spec::columns() const {
  std::vector<std::string> c = {"index", "q_over_a", "b_over_a", "status"};
  for (auto& name : observables.columns()) c.push_back(physical.given() && name == "rate" ? "rate_m_per_s" : name);
  if (physical.given()) c.insert(c.end(), {"friction_N", "static_N"});
  c.emplace_back("error");
  return c;
}

Spec report_plane(long long n, const std::string& observables) {
  Spec spec;
  spec.a = 1;
  spec.q_over_a = Range::parse("q-range", format_shortest(sin_vartheta0()) + ":1:" + std::to_string(n) + ":mid");
  spec.b_over_a = Range::parse("b-range", "1e-4:0.1:" + std::to_string(n) + ":log");
  spec.observables = ObservableSet::parse("observables", observables);
  spec.validate();
  return spec;
}

}  // namespace dfchaos::sweep
