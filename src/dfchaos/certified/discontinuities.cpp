// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/discontinuities.hpp"

#include <chrono>
#include <cmath>

#include "dfchaos/certified/bisect.hpp"
#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/oracle.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/model.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

Ball L_101pi_100() { return Ball::pi() * 101.0 / 100.0; }
Ball L_51pi_50() { return Ball::pi() * 51.0 / 50.0; }
Ball L_3pi_2() { return Ball::pi() * 1.5; }

namespace {

/// Covers [x, y] by closed balls on which certify_T1 proves a simple first root; with `record`, keeps
/// each ball's proof there.
Outcome cover_simple(const ParameterBalls& m, double x, double y, Budget& budget, int& balls, std::vector<T1Piece>* record) {
  if (!(x < y)) return Outcome::ok();
  auto check = [&](const Span& c, int) {
    FirstHitOptions opt;
    opt.record = record != nullptr;
    FirstHitProof p = certify_T1(m, StartSet::interval(c.first, c.second), budget, opt);
    if (p.verdict) {
      ++balls;
      if (record) record->push_back({Ball(c.first), Ball(c.second), std::move(p)});
      return CellVerdict::proved();
    }
    Outcome why = Outcome::fail("Lemma 2: T1 continuous between the tangencies",
                                "at theta in [" + format_double(c.first) + ", " + format_double(c.second) + "]: " + p.verdict.describe());
    return budget.exhausted() ? CellVerdict::stop(std::move(why)) : CellVerdict::split(std::move(why));
  };
  return cover(Span(x, y), check, halve, 50);
}

}  // namespace

DiscontinuityProof prove_discontinuities(double a, double b, const Ball& lo, const Ball& hi, int max_tangencies, bool record) {
  const auto start = std::chrono::steady_clock::now();
  DiscontinuityProof r;
  auto finish = [&](Outcome v) {
    r.verdict = std::move(v);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  };
  const ParameterBalls m(ParameterBox::point(a, b, 0.5 * a + 2 * b));  // q plays no role in T1
  r.lo = lo.lower();
  r.hi = hi.upper();
  if (!lt(m.t2, Ball(r.lo)) || !lt(Ball(r.hi), m.t3)) return finish(Outcome::fail("Lemma 2: L inside (t2, t3)", "b/a too large for this segment"));
  const Ball ab = m.a / m.b;
  auto h = [&](const Ball& z) { return model::symmetric_tangency_h(ab, z); };
  // Odd multiples of pi in h(L): h decreases.
  const Ball h_lo = h(Ball(r.hi)), h_hi = h(Ball(r.lo));
  const Ball pi = m.pi;
  const long long k_first = std::max(2LL, static_cast<long long>(std::floor((h_lo.lower() / M_PI - 1) / 2)));
  const long long k_last = static_cast<long long>(std::ceil((h_hi.upper() / M_PI - 1) / 2));
  std::vector<long long> ks;
  for (long long k = k_first; k <= k_last; ++k) {
    poll_stop();  // stop.hpp: a caller may end the proof here
    const Ball target = Ball(static_cast<double>(2 * k + 1)) * pi;
    if (lt(target, h_lo) || lt(h_hi, target)) continue;  // outside h(L)
    if (!(lt(h_lo, target) && lt(target, h_hi)))
      return finish(Outcome::fail("Lemma 2: count", "h at an end of L is too close to (2k+1) pi, k = " + std::to_string(k)));
    ks.push_back(k);
  }
  r.k_above = k_first;
  while (!lt(h_lo, Ball(static_cast<double>(2 * r.k_above + 1)) * pi) && r.k_above <= k_last) ++r.k_above;
  if (static_cast<int>(ks.size()) > max_tangencies)
    return finish(Outcome::fail("Lemma 2: count", std::to_string(ks.size()) + " tangencies exceed the bound " + std::to_string(max_tangencies)));
  // Enclose each z_k (ascending z = descending k).
  for (auto it = ks.rbegin(); it != ks.rend(); ++it) {
    const long long k = *it;
    const Ball target = Ball(static_cast<double>(2 * k + 1)) * pi;
    Tangency t;
    t.k = k;
    t.z = enclose_sign_change([&](const Ball& z) { return h(z) - target; }, Ball(r.lo), Ball(r.hi), 400);
    t.flight = model::symmetric_tangency_flight(ab, t.z);
    t.t_star = t.z + t.flight;
    if (!t.flight.is_positive()) return finish(Outcome::fail("Lemma 2: tangency", "flight not positive at k = " + std::to_string(k)));
    r.z.push_back(t);
  }
  Budget budget;
  budget.max_tests = 200'000'000;
  double cursor = r.lo;  // everything left of it is covered
  for (std::size_t i = 0; i < r.z.size(); ++i) {
    poll_stop();  // stop.hpp: a caller may end the proof here
    Tangency& t = r.z[i];
    const double z_lo = t.z.lower(), z_hi = t.z.upper();
    const double next = i + 1 < r.z.size() ? r.z[i + 1].z.lower() : r.hi;
    const double gap_left = z_lo - cursor, gap_right = next - z_hi;
    // Window where F < 0 around t*.
    Ball delta(0.25), wl, wh;
    bool window = false;
    for (int j = 0; j < 30 && !window; ++j, delta = delta * 0.5) {
      wl = (t.t_star - delta).lower_ball();
      wh = (t.t_star + delta).upper_ball();
      window = m.F(Ball::hull(wl, wh)).is_negative();
    }
    if (!window) return finish(Outcome::fail("Lemma 2: tangency window", "F < 0 near t* not proved at z = " + t.z.mid_str(20)));
    t.window_lo = wl;
    t.window_hi = wh;
    // Left piece [z - eta', z): skip W, the later root.
    const double eta_l = std::max(gap_left / 8, 0.0);
    const double left_start = z_lo - eta_l;
    FirstHitOptions opt;
    opt.skip = {{wl, wh}};
    opt.guess_at_max = oracle::T1(a, b, z_lo - std::max(1e-9, 1e-6 * eta_l));
    opt.guess_at_min = oracle::T1(a, b, left_start);
    opt.record = record;
    FirstHitProof left = certify_T1(m, StartSet::balls(Ball(left_start), t.z.upper_ball()), budget, opt);
    if (!left.verdict) return finish(Outcome::fail("Lemma 2: left of a tangency", "z = " + t.z.mid_str(20) + ": " + left.verdict.describe()));
    if (!lt(wh, left.t_lo)) return finish(Outcome::fail("Lemma 2: left of a tangency", "the later root is not after the window"));
    ++r.balls;
    t.left_limit = left.enclosure;
    t.jump = left.t_lo - t.t_star.upper_ball();
    if (record) t.left = {Ball(left_start), t.z.upper_ball(), std::move(left)};
    // Right piece [z, z + eta]: concavity on W.
    double eta = std::min(gap_right / 8, (delta * delta).mid() / (8 * t.flight.mid()));
    Outcome right = Outcome::fail("Lemma 2: right of a tangency", "not tried");
    for (int j = 0; j < 8; ++j, eta /= 4) {
      t.right_no_contact.clear();
      right = certify_no_contact(m, StartSet::balls(t.z.lower_ball(), Ball(z_hi + eta)), wl, budget, {}, nullptr, &t.right_s0,
                                 record ? &t.right_no_contact : nullptr);
      if (right) break;
    }
    if (!right) return finish(Outcome::fail("Lemma 2: right of a tangency", "z = " + t.z.mid_str(20) + ": " + right.describe()));
    ++r.balls;
    t.right_lo = t.z.lower_ball();
    t.right_hi = Ball(z_hi + eta);
    // The stretch between the previous piece and this tangency's left piece.
    if (Outcome v = cover_simple(m, cursor, left_start, budget, r.balls, record ? &r.cover : nullptr); !v) return finish(v);
    t.verdict = Outcome::ok();
    cursor = z_hi + eta;
  }
  if (Outcome v = cover_simple(m, cursor, r.hi, budget, r.balls, record ? &r.cover : nullptr); !v) return finish(v);
  return finish(Outcome::ok());
}

}  // namespace dfchaos::certified
