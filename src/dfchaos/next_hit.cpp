// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/next_hit.hpp"

#include <Eigen/Dense>
#include <cfloat>
#include <cmath>

#include "dfchaos/bisect.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/motion.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos {

QuadraticPlusHarmonic G1_function(const Parameters& p, double theta) { return FreeMotion(p, Instant::at_phase(theta), 0.0, 0.0).gap(0.0); }

double G1(const Parameters& p, double theta, const Instant& t) { return static_cast<double>(G1_function(p, theta).value(t)); }
double dG1_dt(const Parameters& p, double theta, const Instant& t) { return static_cast<double>(G1_function(p, theta).slope(t)); }
double dG1_dtheta(const Parameters& p, double theta, const Instant& t) {
  return static_cast<double>(-p.F(theta) * elapsed(Instant::at_phase(theta), t));
}

long long maxima_between(const Parameters& p, double theta, const Instant& t) {
  const double a = p.a(), b = p.b();
  const double t2 = p.t2_required(), t3 = p.t3_required();
  const Instant start = Instant::at_phase(theta);
  // Last F<0 piece [t2 + 2 pi k, t3 + 2 pi k] (turn k relative to theta) that ends before t.
  const long long rel_turn = t.turn - start.turn;
  const long long k_last = (t.phase >= t3) ? rel_turn : rel_turn - 1;
  if (k_last < 1) return 0;
  const double kappa = std::sqrt(1.0 - (2 * b / a) * (2 * b / a));  // cos t3 = -cos t2
  const long double offset = static_cast<long double>(t2) - theta;  // s_k = 2 pi k + offset
  // The velocity dG1/dt (model::dG1_dt_from_start) at the ends of the piece, with cos t2 = -kappa and
  // cos t3 = kappa, solved for the elapsed time s_k (hence written out here, not evaluated).
  // Velocity at the piece start positive:  2b s_k + a cos(theta) + a kappa > 0.
  const long double lower = -(a * (std::cos(theta) + kappa)) / (2.0L * b);
  // Velocity at the piece end negative:   2b (s_k + t3 - t2) + a cos(theta) - a kappa < 0.
  const long double upper = (a * (kappa - std::cos(theta))) / (2.0L * b) - (static_cast<long double>(t3) - t2);
  const long double kmin_real = (lower - offset) / two_pi_l, kmax_real = (upper - offset) / two_pi_l;
  long long kmin = static_cast<long long>(std::floor(kmin_real)) + 1;
  long long kmax = static_cast<long long>(std::ceil(kmax_real)) - 1;
  if (kmin < 1) kmin = 1;
  if (kmax > k_last) kmax = k_last;
  return kmax >= kmin ? kmax - kmin + 1 : 0;
}

NextHit next_hit(const Parameters& p, double theta) {
  p.require_in_map_domain(theta);
  const QuadraticPlusHarmonic g = G1_function(p, theta);
  const auto root = first_upcrossing(g);
  if (!root) throw std::logic_error("next_hit: a free flight with b > 0 always returns (a bug)");
  NextHit h;
  h.t1 = root->t;
  h.theta1 = root->t.value();
  h.hit_velocity = std::max(root->slope, 0.0);
  h.maxima_before = maxima_between(p, theta, root->t);
  h.pieces = root->pieces;
  return h;
}

std::vector<GrazingPoint> grazing_points(const Parameters& p, double lo, double hi, int scan) {
  p.require_in_map_domain(lo, "lo");
  p.require_in_map_domain(hi, "hi");
  if (!(lo < hi)) throw InvalidParameter("hi", "lo < hi", hi);
  if (scan < 2) throw InvalidParameter("scan", "scan >= 2", scan);

  auto label = [&](double th) { return next_hit(p, th).maxima_before; };
  std::vector<std::pair<double, double>> brackets;  // (lo, hi) with labels differing by exactly 1

  // Bisection on the label. Labels decrease with theta; isolate each unit change.
  auto isolate = [&](auto&& self, double l, double h, long long ll, long long lh) -> void {
    if (ll == lh) return;
    for (int it = 0; it < 200 && h - l > 2 * DBL_EPSILON * std::fabs(h); ++it) {
      const double m = 0.5 * (l + h);
      if (m <= l || m >= h) break;
      poll_stop();  // stop.hpp: each evaluation of T1 is a poll
      const long long lm = label(m);
      if (lm != ll && lm != lh) {  // two or more changes inside: split
        self(self, l, m, ll, lm);
        self(self, m, h, lm, lh);
        return;
      }
      if (lm == ll)
        l = m;
      else
        h = m;
    }
    for (long long k = 0; k < std::llabs(ll - lh); ++k) brackets.emplace_back(l, h);
  };

  double prev = lo;
  long long lprev = label(lo);
  for (int i = 1; i < scan; ++i) {
    poll_stop();  // stop.hpp
    const double th = (i == scan - 1) ? hi : lo + (hi - lo) * i / (scan - 1);
    const long long l = label(th);
    isolate(isolate, prev, th, lprev, l);
    prev = th;
    lprev = l;
  }

  std::vector<GrazingPoint> out;
  for (const auto& [bl, bh] : brackets) {
    poll_stop();  // stop.hpp
    GrazingPoint g;
    g.bracket_lo = bl;
    g.bracket_hi = bh;
    const NextHit left = next_hit(p, bl), right = next_hit(p, bh);
    g.maxima_left = left.maxima_before;
    g.maxima_right = right.maxima_before;
    g.t1_left = left.theta1;
    // 2D Newton on (theta, t): G1 = 0, dG1/dt = 0, from the hit side of the bracket.
    double z = bh;
    Instant t = right.t1;
    bool ok = false;
    for (int it = 0; it < 30; ++it) {
      const QuadraticPlusHarmonic f = G1_function(p, z);
      const double r1 = static_cast<double>(f.value(t)), r2 = static_cast<double>(f.slope(t));
      const double s = static_cast<double>(elapsed(Instant::at_phase(z), t));
      Eigen::Matrix2d J;
      J << -p.F(z) * s, r2, -p.F(z), p.F(t.phase);
      const Eigen::Vector2d d = J.fullPivLu().solve(Eigen::Vector2d(-r1, -r2));
      if (!d.allFinite()) break;
      z += d(0);
      t = advance(t, d(1));  // d(1) may be negative; advance handles any sign
      if (std::fabs(d(0)) <= 4 * DBL_EPSILON * std::fabs(z) && std::fabs(d(1)) <= 1e-12) {
        ok = true;
        break;
      }
    }
    const double tol = 1e-9;
    if (!ok || !std::isfinite(z) || z < bl - tol || z > bh + tol) {
      ok = false;
      z = bh;
      t = right.t1;
    }
    g.z = z;
    g.newton_converged = ok;
    g.tangency = t;
    g.t1_right = t.value();
    g.jump = g.t1_left - g.t1_right;
    g.residual_G1 = G1(p, z, t);
    g.residual_dG1 = dG1_dt(p, z, t);
    out.push_back(g);
  }
  return out;
}

namespace {
/// The k with (2k + 1) pi in h([lo, hi]), h(z) = 2z - (a/b) cos z, after hi is clipped to 3 pi/2:
/// k_lo..k_hi (empty when k_lo > k_hi). One formula for symmetric_tangencies and its count.
struct TangencyRange {
  double lo, hi, r;
  long long k_lo = 0, k_hi = -1;
  double h(double th) const { return model::symmetric_tangency_h(r, th); }
};
TangencyRange tangency_range(const Parameters& p, double lo, double hi) {
  p.require_in_map_domain(lo, "lo");
  p.require_in_map_domain(hi, "hi");
  TangencyRange t{lo, std::min(hi, 1.5 * pi), p.a() / p.b()};  // s = -(a/b) cos z > 0 needs cos z < 0
  if (!(t.lo < t.hi)) return t;
  // h decreases on (t2, t3): odd multiples of pi between h(hi) and h(lo).
  t.k_lo = static_cast<long long>(std::ceil((t.h(t.hi) / pi - 1) / 2));
  t.k_hi = static_cast<long long>(std::floor((t.h(t.lo) / pi - 1) / 2));
  return t;
}
}  // namespace

long long symmetric_tangency_count(const Parameters& p, double lo, double hi) {
  const TangencyRange t = tangency_range(p, lo, hi);
  return std::max(0LL, t.k_hi - t.k_lo + 1);
}

std::vector<SymmetricTangency> symmetric_tangencies(const Parameters& p, double lo, double hi) {
  const TangencyRange t = tangency_range(p, lo, hi);
  std::vector<SymmetricTangency> out;
  for (long long k = t.k_hi; k >= t.k_lo; --k) {
    poll_stop();  // stop.hpp: up to max_branches bisections
    const double target = (2 * k + 1) * pi;
    // h(lo) >= target > h(hi)
    const auto [a, b] = bisect([&](double m) { return t.h(m) >= target; }, t.lo, t.hi, {.max_iterations = 200, .rel_tol = 2 * DBL_EPSILON});
    const double z = 0.5 * (a + b);
    if (z < t.lo || z > t.hi) continue;
    out.push_back(SymmetricTangency{z, model::symmetric_tangency_flight(t.r, z), k});
  }
  return out;
}

}  // namespace dfchaos
