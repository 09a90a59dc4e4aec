// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/periodic.hpp"

#include "dfchaos/symbolic.hpp"

#include <arb_mat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "dfchaos/bisect.hpp"
#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/oracle.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

namespace {

/// An m x m arb matrix, RAII.
struct Mat {
  arb_mat_t a;
  explicit Mat(long n) { arb_mat_init(a, n, n); }
  ~Mat() { arb_mat_clear(a); }
  Mat(const Mat&) = delete;
  Mat& operator=(const Mat&) = delete;
  arb_ptr at(long i, long j) { return arb_mat_entry(a, i, j); }
};

/// Floating inverse branch of T on a certified segment: the x between the ends with T(x) = y.
double inverse_branch(const ParameterBox& box, const SegmentProof& J, double y) {
  // T(theta_top) >= 3pi/2 >= y >= t2 = T(theta_t2); a step the oracle cannot take ends the search
  const auto [a, c] = bisect(
      [&](double mid) -> std::optional<bool> {
        const auto s = oracle::step(box.a, box.b_lo, box.q_lo, mid);
        if (!s) return std::nullopt;
        return s->T >= y;
      },
      J.theta_top, J.theta_t2);
  return 0.5 * (a + c);
}

struct PointEval {
  bool ok = false;
  Ball T, dT;
  std::string why;
};

PointEval eval_T(const ParameterBalls& m, const Ball& lo, const Ball& hi) {
  PointEval e;
  Budget budget;
  const StartSet set = StartSet::balls(lo, hi);
  const MapStepProof t = certify_T(m, set, budget);
  if (!t.verdict) {
    e.why = t.verdict.describe();
    return e;
  }
  if (!derivative_T(m, set, t, e.dT)) {
    e.why = "T not proved smooth (scenario A) on the box";
    return e;
  }
  e.T = t.T;
  e.ok = true;
  return e;
}

/// x rounded to `bits` bits, down or up (an exact ball).
Ball rounded(const Ball& x, long bits, bool up) {
  Ball r;
  arf_set_round(arb_midref(r.get()), arb_midref(x.get()), bits, up ? ARF_RND_CEIL : ARF_RND_FLOOR);
  return r;
}

/// T on `set` with its witnesses, in scenario A (case AB with a theta2 bracket above t2): the
/// bracket of T, \f$[u_{lo}, u_{hi}] - 2\pi k\f$, or nothing.
std::optional<Ball> recorded_T(const ParameterBalls& m, const StartSet& set, BallProof& proof) {
  Budget budget;
  MapStepProof t = certify_T(m, set, budget, nullptr, true);
  if (!t.verdict || t.t_case != TCase::ScenarioAB || !t.theta2.verdict) return std::nullopt;
  const Ball T = Ball::hull(t.theta2.u_lo, t.theta2.u_hi) - Ball::pi() * Ball(2 * static_cast<long>(t.turn));
  if (!lt(m.t2, T)) return std::nullopt;
  proof = BallProof::of(set, m.box(), std::move(t));
  return T;
}

/// The covering relations of the orbit boxes X (PeriodicProof::boxes), or a failure naming the box.
Outcome covering_relations(const ParameterBalls& m, const std::vector<Ball>& X, std::vector<OrbitBoxProof>& out) {
  const std::size_t n = X.size();
  std::vector<OrbitBoxProof> boxes(n);
  std::vector<Ball> T_lo(n), T_hi(n);
  constexpr long kBits = 128;  // the ends as exact numbers of 128 bits (the checker reads 256)
  for (std::size_t j = 0; j < n; ++j) {
    OrbitBoxProof& x = boxes[j];
    x.lo = rounded(X[j].lower_ball(), kBits, false);
    x.hi = rounded(X[j].upper_ball(), kBits, true);
    const std::string name = "X_" + std::to_string(j);
    if (!recorded_T(m, StartSet::balls(x.lo, x.hi), x.on))
      return Outcome::fail("periodic: certificate", name + ": T not proved in scenario A on the box");
    const auto lo = recorded_T(m, StartSet::balls(x.lo, x.lo), x.at_lo), hi = recorded_T(m, StartSet::balls(x.hi, x.hi), x.at_hi);
    if (!lo || !hi) return Outcome::fail("periodic: certificate", name + ": T not proved in scenario A at an end");
    T_lo[j] = *lo, T_hi[j] = *hi;
  }
  for (std::size_t j = 0; j < n; ++j) {
    const OrbitBoxProof& next = boxes[(j + 1) % n];
    const bool up = lt(T_lo[j], next.lo) && lt(next.hi, T_hi[j]), down = lt(next.hi, T_lo[j]) && lt(T_hi[j], next.lo);
    if (!up && !down)
      return Outcome::fail("periodic: certificate",
                           "T(X_" + std::to_string(j) + ") does not cover X_" + std::to_string((j + 1) % n) + " by its ends");
  }
  out = std::move(boxes);
  return Outcome::ok();
}

}  // namespace

PeriodicProof prove_periodic(const CoveringProof& cov, int period, const PeriodicOptions& opt) {
  if (period < 1 || period > 64) {
    PeriodicProof r;
    r.period = period;
    r.verdict = Outcome::fail("periodic: period", "1 <= m <= 64");
    return r;
  }
  return prove_periodic(cov, std::string(static_cast<std::size_t>(period - 1), '0') + "1", opt);
}

PeriodicProof prove_periodic(const CoveringProof& cov, const std::string& word, const PeriodicOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  PeriodicProof r;
  r.period = static_cast<int>(word.size());
  r.word = word;
  auto finish = [&](Outcome v) {
    r.verdict = std::move(v);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  };
  if (word.empty() || word.size() > 64 || word.find_first_not_of("01") != std::string::npos || !is_primitive_word(word))
    return finish(Outcome::fail("periodic: word", "a primitive word of 1 to 64 letters 0 and 1 (got '" + word.substr(0, 80) + "')"));
  const int period = r.period;
  if (!cov.verdict) return finish(Outcome::fail("periodic: needs the covering", cov.verdict.describe()));
  if (!cov.box.is_point()) return finish(Outcome::fail("periodic: point parameters", "orbits are enclosed at a parameter point"));
  r.existence = true;
  const ParameterBalls m(cov.box);
  const SegmentProof* J[2] = {&cov.J0, &cov.J1};
  const std::size_t n = static_cast<std::size_t>(period);
  auto seg = [&](std::size_t j) { return J[r.word[j] == '1' ? 1 : 0]; };

  // 1. Floating guess: the fixed point of g_{w_0} o ... o g_{w_{m-1}} (a contraction).
  std::vector<double> x(n);
  double y = 0.5 * (J[0]->lo + J[0]->hi);
  for (int sweep = 0; sweep < 4; ++sweep) {
    double z = y;
    for (std::size_t j = n; j-- > 0;) {
      z = inverse_branch(cov.box, *seg(j), z);
      x[j] = z;
    }
    y = x[0];
  }
  // 2. Newton on F_j = T(x_j) - x_{j+1} in ball midpoints (not a proof).
  std::vector<Ball> xh(n);
  for (std::size_t j = 0; j < n; ++j) xh[j] = Ball(x[j]);
  std::vector<PointEval> ev(n);
  for (int step = 0; step <= opt.newton_steps; ++step) {
    for (std::size_t j = 0; j < n; ++j) {
      ev[j] = eval_T(m, xh[j], xh[j]);
      if (!ev[j].ok)
        return finish(Outcome::fail("periodic: T at the orbit", "x_" + std::to_string(j) + " = " + xh[j].mid_str(20) + ": " + ev[j].why));
    }
    if (step == opt.newton_steps) break;
    // Solve d_j D_j - D_{j+1} = F_j: D_j = (F_j + D_{j+1}) / d_j, closing the cycle for D_0.
    std::vector<Ball> F(n), d(n);
    for (std::size_t j = 0; j < n; ++j) {
      F[j] = (ev[j].T - xh[(j + 1) % n]).mid_ball();
      d[j] = ev[j].dT.mid_ball();
    }
    Ball A(0.0), B(1.0);  // D_0 = A + B D_0 accumulated from the back
    for (std::size_t j = n; j-- > 0;) {
      A = (F[j] + A) / d[j];
      B = B / d[j];
    }
    std::vector<Ball> D(n);
    D[0] = (A / (Ball(1.0) - B)).mid_ball();
    for (std::size_t j = n; j-- > 1;) {
      // D_j from D_{j+1}: go backwards from D_0 = D_m.
      D[j] = ((F[j] + (j + 1 == n ? D[0] : D[j + 1])) / d[j]).mid_ball();
    }
    for (std::size_t j = 0; j < n; ++j) xh[j] = (xh[j] - D[j]).mid_ball();
  }
  // 3. Krawczyk on X_j = x_j +- rad.
  const Ball rad(opt.radius);
  std::vector<Ball> X(n), dX(n);
  for (std::size_t j = 0; j < n; ++j) {
    X[j] = Ball::hull(xh[j] - rad, xh[j] + rad);
    const PointEval e = eval_T(m, X[j].lower_ball(), X[j].upper_ball());
    if (!e.ok) return finish(Outcome::fail("periodic: T smooth on the box", "X_" + std::to_string(j) + ": " + e.why));
    dX[j] = e.dT;
    // Inside the right segment.
    if (!le(Ball(seg(j)->lo), X[j]) || !le(X[j], Ball(seg(j)->hi)))
      return finish(Outcome::fail("periodic: itinerary", "X_" + std::to_string(j) + " not inside J" + r.word[j]));
  }
  const long nn = static_cast<long>(n);
  const long prec = precision();
  Mat Jm(nn), C(nn), JX(nn), CJ(nn), Id(nn);
  for (long i = 0; i < nn; ++i) {
    arb_set(Jm.at(i, i), ev[static_cast<std::size_t>(i)].dT.mid_ball().get());
    arb_set(JX.at(i, i), dX[static_cast<std::size_t>(i)].get());
    if (nn > 1) {
      arb_set_si(Jm.at(i, (i + 1) % nn), -1);
      arb_set_si(JX.at(i, (i + 1) % nn), -1);
    }
  }
  if (nn == 1) {  // F(x) = T(x) - x: DF = T' - 1
    arb_sub_ui(Jm.at(0, 0), Jm.at(0, 0), 1, prec);
    arb_sub_ui(JX.at(0, 0), JX.at(0, 0), 1, prec);
  }
  if (!arb_mat_approx_inv(C.a, Jm.a, prec)) return finish(Outcome::fail("periodic: Krawczyk", "singular Jacobian"));
  arb_mat_get_mid(C.a, C.a);
  arb_mat_mul(CJ.a, C.a, JX.a, prec);
  arb_mat_one(Id.a);
  arb_mat_sub(CJ.a, Id.a, CJ.a, prec);  // I - C DF(X)
  std::vector<Ball> Fh(n), K(n);
  for (std::size_t j = 0; j < n; ++j) Fh[j] = ev[j].T - xh[(j + 1) % n];
  bool inside = true;
  for (std::size_t i = 0; i < n; ++i) {
    Ball k = xh[i];
    for (std::size_t j = 0; j < n; ++j) {
      Ball cij, mij;
      arb_set(cij.get(), C.at(static_cast<long>(i), static_cast<long>(j)));
      arb_set(mij.get(), CJ.at(static_cast<long>(i), static_cast<long>(j)));
      k = k - cij * Fh[j] + mij * (X[j] - xh[j]);
    }
    K[i] = k;
    if (!(lt(X[i].lower_ball(), k) && lt(k, X[i].upper_ball()))) inside = false;
  }
  if (!inside) return finish(Outcome::fail("periodic: Krawczyk", "K(X) not inside the interior of X"));
  r.orbit = K;
  Ball logm(0.0);
  for (std::size_t j = 0; j < n; ++j) {
    Ball l;
    arb_log(l.get(), abs(dX[j]).get(), prec);
    logm = logm + l;
  }
  r.log_multiplier = logm;
  if (opt.record) {  // the proof stands without them; a certificate is then not possible
    const Outcome rel = covering_relations(m, X, r.boxes);
    if (!rel) r.unrecorded = rel.describe();
  }
  return finish(Outcome::ok());
}

namespace {

/// One piece of prove_cycle_on_interval(): the boxes around the two cycles, radius grown until proved.
CycleIntervalProof prove_cycle_piece(double a, double q, double b_lo, double b_hi, const std::vector<double>& x_lo, const std::vector<double>& x_hi) {
  CycleIntervalProof r;
  const ParameterBalls m(ParameterBox{a, b_lo, b_hi, q, q});
  if (Outcome v = m.admissible(); !v) {
    r.verdict = v;
    return r;
  }
  double spread = 0;
  for (std::size_t j = 0; j < x_lo.size(); ++j) spread = std::max(spread, std::fabs(x_hi[j] - x_lo[j]));
  // T' is large on these orbits, so the ends of X_j need only be a little beyond the two points:
  // from 1% of the spread up (x4 each time, at most 10 times the spread).
  r.radius = 0.01 * spread + 1e-13;
  Outcome last;
  for (int attempt = 0; attempt < 6; ++attempt, r.radius *= 4) {
    poll_stop();
    r.X.clear();
    for (std::size_t j = 0; j < x_lo.size(); ++j)
      r.X.push_back(Ball::hull(Ball(std::min(x_lo[j], x_hi[j])) - Ball(r.radius), Ball(std::max(x_lo[j], x_hi[j])) + Ball(r.radius)));
    last = covering_relations(m, r.X, r.boxes);
    if (last) {
      r.verdict = Outcome::ok();
      return r;
    }
  }
  r.verdict = last;
  return r;
}

}  // namespace

CycleIntervalProof prove_cycle_on_interval(double a, double q, double b_lo, double b_hi, const std::vector<double>& x_lo,
                                           const std::vector<double>& x_hi) {
  if (x_lo.empty() || x_lo.size() != x_hi.size() || x_lo.size() > 64 || !(b_lo <= b_hi)) {
    CycleIntervalProof r;
    r.verdict = Outcome::fail("cycle: input", "two cycles of the same length 1..64 and b_lo <= b_hi");
    return r;
  }
  // Halves of the interval (at most kCyclePieceDepth times), the cycle at a cut interpolated
  // linearly: its distance to the true cycle (the curvature of x(b)) is covered by the radius.
  struct Piece {
    double lo, hi;
    std::vector<double> x_lo, x_hi;
  };
  CycleIntervalProof first, failed;
  int pieces = 0;
  auto check = [&](const Piece& pc, int) {
    CycleIntervalProof r = prove_cycle_piece(a, q, pc.lo, pc.hi, pc.x_lo, pc.x_hi);
    if (r.verdict) {
      if (pieces++ == 0) first = std::move(r);
      return CellVerdict::proved();
    }
    failed = std::move(r);
    return CellVerdict::split(failed.verdict);
  };
  auto split = [](const Piece& pc, int) -> std::optional<std::pair<Piece, Piece>> {
    const double mid = 0.5 * (pc.lo + pc.hi);
    if (!(mid > pc.lo && mid < pc.hi)) return std::nullopt;
    std::vector<double> x_mid(pc.x_lo.size());
    for (std::size_t j = 0; j < x_mid.size(); ++j) x_mid[j] = 0.5 * (pc.x_lo[j] + pc.x_hi[j]);
    return std::make_pair(Piece{pc.lo, mid, pc.x_lo, x_mid}, Piece{mid, pc.hi, x_mid, pc.x_hi});
  };
  if (!cover(Piece{b_lo, b_hi, x_lo, x_hi}, check, split, kCyclePieceDepth)) {
    failed.pieces = pieces;
    return failed;
  }
  first.pieces = pieces;
  return first;
}

std::vector<int> prove_branch_steps(double a, double q, const OrbitBranch& branch) {
  std::vector<int> proved(branch.points.size(), -1);
  for (std::size_t k = 1; k < branch.points.size(); ++k) {
    const BranchPoint &u = branch.points[k - 1], &v = branch.points[k];
    const bool up = u.b <= v.b;
    proved[k] = prove_cycle_on_interval(a, q, up ? u.b : v.b, up ? v.b : u.b, up ? u.x : v.x, up ? v.x : u.x).verdict.proved ? 1 : 0;
  }
  return proved;
}

}  // namespace dfchaos::certified
