// SPDX-License-Identifier: GPL-3.0-or-later
/// @file continuation.cpp
/// @brief A periodic orbit of T followed in b (continuation.hpp).
#include "dfchaos/continuation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "dfchaos/errors.hpp"
#include "dfchaos/map_derivative.hpp"

namespace dfchaos {

void ContinuationSettings::validate() const {
  if (!(step > 0 && step <= 0.1)) throw InvalidParameter("step", "0 < step <= 0.1 (relative to b)", step);
  if (!(min_step >= 1e-15 && min_step <= step)) throw InvalidParameter("min-step", "1e-15 <= min-step <= step", min_step);
  if (max_steps < 1 || max_steps > 1'000'000) throw InvalidParameter("max-steps", "1 <= max-steps <= 1e6", static_cast<double>(max_steps));
}

const char* branch_end_name(BranchEnd e) {
  switch (e) {
    case BranchEnd::RangeEnd: return "range_end";
    case BranchEnd::Plateau: return "plateau";
    case BranchEnd::ReachesT2: return "reaches_t2";
    case BranchEnd::ReachesT3: return "reaches_t3";
    case BranchEnd::Grazing: return "grazing";
    case BranchEnd::Fold: return "fold";
    case BranchEnd::NoConvergence: return "no_convergence";
    case BranchEnd::StepBudget: return "step_budget";
  }
  return "?";
}

namespace {

constexpr int kNewtonIterations = 12;
constexpr double kNewtonTolerance = 1e-12;  ///< largest last Newton correction accepted (radians)

/// The outcome of correcting a predicted cycle at one b.
struct Corrected {
  bool ok = false;
  BranchPoint point;
  BranchEnd failure = BranchEnd::NoConvergence;  ///< when !ok
  long long bad_point = -1;                      ///< the j at fault (plateau, grazing), else -1
  std::string detail;
};

/// The cycle through the steps from x, with T', the branch labels and F_j = T(x_j) - x_{j+1}; or the
/// failure (a point outside [t2, t3), a step not in scenario A, a branch changed).
struct Evaluation {
  std::vector<double> F, dT;
  std::vector<long long> branches;
  Corrected failure;  ///< failure.detail non-empty: failed
};

Evaluation evaluate(const Parameters& p, const std::vector<double>& x, const std::vector<long long>* want) {
  const std::size_t m = x.size();
  const double t2 = p.t2_required(), t3 = p.t3_required();
  Evaluation e;
  e.F.resize(m);
  e.dT.resize(m);
  e.branches.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    auto fail = [&](BranchEnd kind, std::string why) {
      e.failure.failure = kind;
      e.failure.bad_point = static_cast<long long>(j);
      e.failure.detail = "x_" + std::to_string(j) + " = " + format_double(x[j]) + ": " + std::move(why);
      return e;
    };
    // Below t2 lies the stop arc (t1, t2), sent to t2; a point reaching an end of [t2, t3) meets a plateau edge.
    if (!(x[j] >= t2)) return fail(BranchEnd::ReachesT2, "reaches t2, the end of the stop arc (t1, t2) (T' = 0 at t2)");
    if (!(x[j] < t3)) return fail(BranchEnd::ReachesT3, "reaches t3, the end of [t2, t3)");
    MapStep step;
    try {
      step = return_map_step(p, x[j]);
    } catch (const std::exception& ex) {
      return fail(BranchEnd::NoConvergence, std::string("T not computed: ") + ex.what());
    }
    const MapDerivative d = map_derivative(p, step);
    if (step.scenario != Scenario::A || d.flat || !std::isfinite(d.dT) || d.dT == 0)
      return fail(step.scenario == Scenario::Grazing ? BranchEnd::Grazing : BranchEnd::Plateau,
                  std::string("its step follows scenario ") + scenario_name(step.scenario) + " (" + step.chain + "), not A");
    e.branches[j] = t1_branch(p, step);
    if (want && e.branches[j] != (*want)[j])
      return fail(BranchEnd::Grazing, "its first flight moved from branch " + std::to_string((*want)[j]) + " to " + std::to_string(e.branches[j]) +
                                          " of T1 (it grazes the delimiter in between)");
    e.F[j] = step.T - x[(j + 1) % m];
    e.dT[j] = d.dT;
  }
  return e;
}

/// Newton's method on the cycle at p from x (see the file comment of continuation.hpp).
Corrected correct(const Parameters& p, std::vector<double> x, const std::vector<long long>* want) {
  const std::size_t m = x.size();
  for (int it = 0; it <= kNewtonIterations; ++it) {
    Evaluation e = evaluate(p, x, want);
    if (!e.failure.detail.empty()) return e.failure;
    // delta_0 = S / (1 - P), S = sum_j F_j prod_{i > j} T'_i, P = prod_j T'_i
    double S = 0, P = 1;
    for (std::size_t j = 0; j < m; ++j) {
      S = S * e.dT[j] + e.F[j];
      P *= e.dT[j];
    }
    if (!std::isfinite(S) || !std::isfinite(P) || P == 1) {
      Corrected c;
      c.detail = "Newton's system is singular or overflows (product of T' = " + format_double(P) + ")";
      return c;
    }
    // x_j - d_j solves F_j - T'_j d_j + d_{j+1} = 0: d_{j+1} = T'_j d_j - F_j around the cycle, so
    // d_0 = P d_0 - S, and backwards d_j = (d_{j+1} + F_j) / T'_j.
    std::vector<double> delta(m);
    delta[0] = S / (P - 1);
    for (std::size_t k = m - 1; k >= 1; --k) delta[k] = (delta[(k + 1) % m] + e.F[k]) / e.dT[k];
    double biggest = 0;
    for (std::size_t j = 0; j < m; ++j) {
      x[j] -= delta[j];
      biggest = std::max(biggest, std::fabs(delta[j]));
    }
    if (biggest <= kNewtonTolerance) {
      Evaluation f = evaluate(p, x, want);
      if (!f.failure.detail.empty()) return f.failure;
      Corrected c;
      c.ok = true;
      c.point.b = p.b();
      c.point.x = x;
      c.point.branches = f.branches;
      for (std::size_t j = 0; j < m; ++j) {
        c.point.log_multiplier += std::log(std::fabs(f.dT[j]));
        c.point.residual = std::max(c.point.residual, std::fabs(f.F[j]));
      }
      return c;
    }
  }
  Corrected c;
  c.detail = "Newton's method did not converge in " + std::to_string(kNewtonIterations) + " iterations";
  return c;
}

}  // namespace

OrbitBranch follow_periodic_orbit(double a, double q, double b0, const std::vector<double>& x0, double b_end, const ContinuationSettings& s) {
  s.validate();
  if (x0.empty() || x0.size() > kMaxContinuedPeriod)
    throw InvalidParameter("x0", "a cycle of 1 to " + std::to_string(kMaxContinuedPeriod) + " points", static_cast<double>(x0.size()));
  const Parameters p0(a, b0, q);
  p0.require_return_map();
  Parameters(a, b_end, q).require_return_map();
  for (double x : x0)
    if (!(x >= p0.t2_required() && x < p0.t3_required())) throw InvalidParameter("x0", "every point in [t2, t3)", x);
  const Corrected start = correct(p0, x0, nullptr);
  if (!start.ok) throw InvalidParameter("x0", "a cycle of T at b0 with every step in scenario A (" + start.detail + ")");

  OrbitBranch branch;
  branch.points.push_back(start.point);
  const double direction = b_end >= b0 ? 1 : -1;
  double h = s.step;
  branch.b_lost = std::numeric_limits<double>::quiet_NaN();
  for (long long accepted = 0;;) {
    const BranchPoint& last = branch.points.back();
    if (last.b == b_end) {
      branch.end = BranchEnd::RangeEnd;
      branch.detail = "reached b_end = " + format_double(b_end);
      return branch;
    }
    if (accepted >= s.max_steps) {
      branch.end = BranchEnd::StepBudget;
      branch.detail = "max-steps = " + std::to_string(s.max_steps) + " steps taken before b_end";
      return branch;
    }
    double b = last.b * (1 + direction * h);
    if ((b - b_end) * direction > 0) b = b_end;
    // secant predictor through the last two points (constant at the first step)
    std::vector<double> guess = last.x;
    if (branch.points.size() >= 2) {
      const BranchPoint& before = branch.points[branch.points.size() - 2];
      const double r = (b - last.b) / (last.b - before.b);
      for (std::size_t j = 0; j < guess.size(); ++j) guess[j] += r * (last.x[j] - before.x[j]);
    }
    const Corrected c = correct(Parameters(a, b, q), guess, &last.branches);
    if (c.ok) {
      branch.points.push_back(c.point);
      ++accepted;
      h = std::min(s.step, 2 * h);
      continue;
    }
    if (std::fabs(b - last.b) <= s.min_step * last.b) {
      branch.end = c.failure;
      branch.end_point = c.bad_point;
      branch.b_lost = b;
      branch.detail = c.detail;
      if (c.failure == BranchEnd::NoConvergence && std::fabs(last.log_multiplier) < kFoldLogMultiplier) {
        branch.end = BranchEnd::Fold;
        branch.detail += "; ln|(T^m)'| = " + format_double(last.log_multiplier) + " at the last point: the multiplier tends to 1";
      }
      return branch;
    }
    h = std::min(h, std::fabs(b - last.b) / last.b) / 2;
  }
}

}  // namespace dfchaos
