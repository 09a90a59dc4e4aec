// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/symbolic.hpp"

#include <cfloat>
#include <cmath>

#include "dfchaos/bisect.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/return_map.hpp"

namespace dfchaos {

InverseBranch make_inverse_branch(const Parameters& p, const CoveringSegment& J, double top, int check) {
  const double t2 = *p.t2();
  InverseBranch g;
  g.J = J;
  g.top = top;
  // From the T = t2 end towards the T >= top end: the first point where T reaches top, and the
  // last point before it where T = t2. Between them T is continuous (J is a covering segment).
  const BisectStop to_4e16{.max_iterations = 200, .rel_tol = 4e-16};
  // T(theta_at_t2) < top <= T(theta_at_top)
  g.k_at_top = bisect([&](double m) { return T(p, m) < top; }, J.theta_at_t2, J.theta_at_top, to_4e16).second;
  // T = t2 at theta_at_t2, T > t2 at k_at_top
  g.k_at_t2 = bisect([&](double m) { return T(p, m) == t2; }, J.theta_at_t2, g.k_at_top, to_4e16).first;
  // Strict monotonicity on K, checked on a grid.
  const double sign = g.k_at_top > g.k_at_t2 ? 1.0 : -1.0;
  double prev = T(p, g.k_at_t2);
  g.monotone = true;
  for (int i = 1; i <= check; ++i) {
    const double v = T(p, g.k_at_t2 + (g.k_at_top - g.k_at_t2) * i / check);
    if (!(v > prev)) {
      g.monotone = false;
      break;
    }
    prev = v;
  }
  (void)sign;
  if (!g.monotone)
    throw GaveUp("make_inverse_branch: T is not monotone on K = [" + format_double(g.k_at_t2) + ", " + format_double(g.k_at_top) + "]");
  return g;
}

double inverse(const Parameters& p, const InverseBranch& g, double y) {
  const double t2 = *p.t2();
  if (!(y >= t2 && y <= g.top)) throw InvalidParameter("y", "t2 <= y <= top", y);
  // T(k_at_t2) = t2 <= y <= T(k_at_top), T increasing from k_at_t2 to k_at_top
  const auto [lo, hi] = bisect([&](double m) { return T(p, m) < y; }, g.k_at_t2, g.k_at_top, {.max_iterations = 200, .rel_tol = 2e-16});
  return std::fabs(T(p, lo) - y) < std::fabs(T(p, hi) - y) ? lo : hi;
}

namespace detail {
void check_itinerary_orbit(const Parameters& p, const InverseBranch (&g)[2], ItineraryOrbit& o, bool periodic) {
  const std::size_t n = o.x.size();
  o.itinerary_ok = true;
  o.max_step_residual = 0;
  o.log_expansion = 0;
  o.min_separation = INFINITY;
  o.precision_floor = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const InverseBranch& b = g[o.word[j] == '1' ? 1 : 0];
    const double lo = std::min(b.k_at_t2, b.k_at_top), hi = std::max(b.k_at_t2, b.k_at_top);
    if (o.x[j] < lo || o.x[j] > hi) o.itinerary_ok = false;
    if (j + 1 < n || periodic) o.max_step_residual = std::max(o.max_step_residual, circle_distance(T(p, o.x[j]), o.x[(j + 1) % n]));
    const double h = 1e-9 * (hi - lo);
    const double slope = std::fabs((T(p, o.x[j] + h) - T(p, o.x[j] - h)) / (2 * h));
    o.log_expansion += std::log(slope);
    if (j + 1 < n || periodic)
      o.precision_floor = std::max(o.precision_floor, 4 * (slope * 2 * DBL_EPSILON * std::fabs(o.x[j]) + DBL_EPSILON * std::fabs(o.x[(j + 1) % n])));
    for (std::size_t k = j + 1; k < n; ++k) o.min_separation = std::min(o.min_separation, std::fabs(o.x[j] - o.x[k]));
  }
}
}  // namespace detail

ItineraryOrbit periodic_orbit(const Parameters& p, const InverseBranch (&g)[2], const std::string& word) {
  if (word.empty() || word.find_first_not_of("01") != std::string::npos) throw InvalidParameter("word", "a non-empty word over {0, 1}");
  ItineraryOrbit o;
  o.word = word;
  o.x.assign(word.size(), 0.0);
  double y = 0.5 * (*p.t2() + g[0].top), prev = NAN;
  for (int sweep = 0; sweep < 200; ++sweep) {
    for (std::size_t j = word.size(); j-- > 0;) {
      y = inverse(p, g[word[j] == '1' ? 1 : 0], y);
      o.x[j] = y;
    }
    if (y == prev) break;
    prev = y;
    if (sweep == 199) throw GaveUp("periodic_orbit: no convergence in 200 sweeps for word " + word);
  }
  detail::check_itinerary_orbit(p, g, o, true);
  return o;
}

bool is_primitive_word(const std::string& word) {
  // w is a proper power iff it occurs in ww at a position strictly between 0 and |w|
  return !word.empty() && (word + word).find(word, 1) == word.size();
}

void require_itinerary_word(const std::string& name, const std::string& word, std::size_t max_length) {
  if (word.empty() || word.size() > max_length || word.find_first_not_of("01") != std::string::npos)
    throw InvalidParameter(name, "a word of 1 to " + std::to_string(max_length) + " letters 0 and 1 (got '" + word.substr(0, 80) + "')");
  if (!is_primitive_word(word)) {
    const std::size_t root = (word + word).find(word, 1);
    throw InvalidParameter(name, "a primitive word, not a power of a shorter one (" + word.substr(0, 80) + " repeats " + word.substr(0, root) +
                                     ": give that, whose orbit is the same)");
  }
}

ItineraryOrbit periodic_orbit(const Parameters& p, const std::string& word) {
  require_itinerary_word("word", word, kMaxItineraryLength);
  const Lemma4Covering c = require_lemma4_covering(p);
  const InverseBranch g[2] = {make_inverse_branch(p, c.J0), make_inverse_branch(p, c.J1)};
  return periodic_orbit(p, g, word);
}

}  // namespace dfchaos
