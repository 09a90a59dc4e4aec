// SPDX-License-Identifier: GPL-3.0-or-later
/// @file phase.cpp
/// @brief Instants as whole periods plus a phase (phase.hpp).
#include "dfchaos/phase.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dfchaos/double_double.hpp"
#include "dfchaos/errors.hpp"

namespace dfchaos {

double circle_distance(double x, double y) {
  const double d = std::fabs(std::fmod(x - y, two_pi));
  return std::min(d, two_pi - d);
}

double wrap_phase(double t) {
  // fmod is exact and returns t itself when |t| < 2 pi: skip the (slow) long double fmod then.
  long double r = std::fabs(t) < two_pi ? static_cast<long double>(t) : std::fmod(static_cast<long double>(t), two_pi_l);
  if (r < 0) r += two_pi_l;
  double d = static_cast<double>(r);
  if (d >= two_pi) d = 0.0;
  return d;
}

Instant Instant::from_time(double t) {
  // Fast path (no division): a time already inside [0, 2 pi) is its own phase.
  if (t >= 0 && t < two_pi) return Instant{0, t};
  if (!(std::fabs(t) <= kMaxInstantTime))
    throw std::domain_error("Instant::from_time: |t| = " + format_double(t) + " exceeds 1e15 (callers must refuse such times)");
  // t - 2 pi k in double-double: k 2 pi = k hi + k lo with k hi exact (TwoProd) and 2 pi to 107
  // bits, so the phase is right to the last bit for every |t| <= 1e15 (a long-double 2 pi would be
  // off by 2e-19 k, 3.5e-8 at t = 1e12).
  double k = std::floor(t / two_pi);
  auto reduce = [&](double kk) {
    return dd::add(dd::two_sum(t, 0.0), dd::neg(dd::add(dd::two_prod(kk, dd::kTwoPi.hi), dd::DD{kk * dd::kTwoPi.lo, 0.0})));
  };
  dd::DD r = reduce(k);
  if (r.hi < 0 || (r.hi == 0 && r.lo < 0))
    r = reduce(--k);
  else if (r.hi >= two_pi)
    r = reduce(++k);
  double ph = r.hi;
  std::int64_t turn = static_cast<std::int64_t>(k);
  if (ph < 0) ph = 0.0;
  if (ph >= two_pi) {
    ph = 0.0;
    ++turn;
  }
  return Instant{turn, ph};
}

long double elapsed(const Instant& from, const Instant& to) {
  return static_cast<long double>(to.turn - from.turn) * two_pi_l + (static_cast<long double>(to.phase) - static_cast<long double>(from.phase));
}

bool before(const Instant& x, const Instant& y) { return x.turn < y.turn || (x.turn == y.turn && x.phase < y.phase); }

Instant advance(const Instant& t, long double delta) {
  const long double total = static_cast<long double>(t.phase) + delta;
  // Fast path, bit-identical to the general formula: the sum stays inside the same turn.
  if (total >= 0 && total < two_pi_l) {
    const double ph = static_cast<double>(total);
    if (ph < two_pi) return Instant{t.turn, ph};
  }
  // Fast path into the next turn (a piece of a root search that runs across the phase 0): the
  // general formula with k = 1, without its long-double division and floor.
  if (total >= two_pi_l && total < 2 * two_pi_l) {
    const double ph = static_cast<double>(total - two_pi_l);
    if (ph < two_pi) return Instant{t.turn + 1, ph};
  }
  const long double k = std::floor(total / two_pi_l);
  long double r = total - k * two_pi_l;
  std::int64_t turn = t.turn + static_cast<std::int64_t>(k);
  if (r < 0) {
    r += two_pi_l;
    --turn;
  }
  double ph = static_cast<double>(r);
  if (ph >= two_pi) {
    ph = 0.0;
    ++turn;
  }
  return Instant{turn, ph};
}

Instant next_at_phase(const Instant& t, double phi) {
  if (phi > t.phase) return Instant{t.turn, phi};
  return Instant{t.turn + 1, phi};
}

bool phase_in_arc(double phi, double lo, double hi) {
  if (lo <= hi) return phi >= lo && phi < hi;
  return phi >= lo || phi < hi;
}

}  // namespace dfchaos
