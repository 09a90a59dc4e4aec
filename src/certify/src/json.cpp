// SPDX-License-Identifier: GPL-3.0-or-later
#include "certify/json.hpp"

#include <cmath>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "dfchaos/errors.hpp"
#include "kit/format.hpp"

namespace dfchaos::certify {

using namespace dfchaos::certified;

namespace {
std::string params_text(const ParameterBox& box) {
  return box.is_point() ? "at the double values " + box.describe() : "for every parameter of the box " + box.describe();
}
Json box_json(const ParameterBox& box) {
  Json j = Json::object();
  j.set("a", box.a);
  if (box.b_lo == box.b_hi)
    j.set("b", box.b_lo);
  else
    j.set("b", Json::array().push(box.b_lo).push(box.b_hi));
  if (box.q_lo == box.q_hi)
    j.set("q", box.q_lo);
  else
    j.set("q", Json::array().push(box.q_lo).push(box.q_hi));
  return j;
}
}  // namespace

std::string shortest_double(double x) {
  char buf[40];
  for (int d = 1; d <= 17; ++d) {
    std::snprintf(buf, sizeof buf, "%.*g", d, x);
    if (std::strtod(buf, nullptr) == x) return buf;
  }
  return format_double(x);
}

Json ball_json(const Ball& x, long digits) {
  Json j = Json::object();
  const Ball::Printed p = x.printed(digits);  // a decimal ball that encloses x
  j.set("mid", p.mid).set("rad", p.rad);
  return j;
}

void add_verdict(Json& j, const Outcome& v) {
  j.set("proved", v.proved);
  if (!v.proved) {
    j.set("failed_step", v.step).set("detail", v.detail).set("refuted", v.refuted);
  }
}

std::string statement_vartheta0() {
  return "The equation pi - x = cot(x/2) has exactly one solution vartheta0 on (0, pi/2] (the left side minus the right increases "
         "strictly there), and vartheta0 and sin(vartheta0) lie in the printed balls; the printed doubles are their correctly "
         "rounded values.";
}
std::string statement_lemma1(const ParameterBox& box) {
  return "Lemma 1 " + params_text(box) +
         ": the progression that starts from rest at t0 has velocity u > 0 on (t0, t1] (u' = F - q > 0 there), u(t2) < 0 "
         "(Eq. 8, enclosed) and u' < 0 on (t1, t2], so it stops exactly once, at t4 in (t1, t2), where the mass waits for t2.";
}
std::string statement_b0(double a, double q, double b_low) {
  return "Lemma 1 holds for every b in (0, " + format_double(b_low) + "] at a = " + format_double(a) + ", q = " + format_double(q) +
         " (u(t2) < 0 proved over b-balls covering [0, b_low]): b0(q) >= " + format_double(b_low) + ".";
}
std::string statement_arc_l1(const ArcL1Proof& p) {
  const std::string arc = p.paper_arc ? "The arc L1 = [197pi/100, t3) of Lemma 4's proof"
                                      : "The arc [2pi - Delta, t3), Delta = " + format_double(p.delta_max) + " (L1 widened)";
  // For people: the bound of b/a rounded down (the exact double is the parameter b_over_a_max), the
  // ends of the box of q/a as the shortest decimals of their doubles.
  return arc + ", for every b/a <= " + kit::format_significant_down(p.eps_max, 3) + " and q/a in [" + format_shortest(p.kappa_lo) + ", " +
         format_shortest(p.kappa_hi) +
         "] (doubles) at once: from rest on it the first contact (Eq. 11) is simple and after t3, and the progression stops in " +
         (p.stop_arc ? std::string("(t3, 3pi), inside the stop arc (Eq. 17)") : std::string("(t3, t0 + 2pi) (Eq. 17)")) +
         ", so T = t2 there wherever Lemma 1 holds.";
}
std::string statement_lemma4_uniform(const Lemma4UniformProof& p) {
  const std::string segment =
      p.paper_L2 ? "L2 = [101pi/100, 51pi/50]"
                 : "[pi + w_lo, pi + w_hi], w_lo = " + format_double(p.w_a) + ", w_hi = " + format_double(p.w_b) + " (wider than L2)";
  // Rounded as in statement_arc_l1; the exact values are the certificate's parameters.
  return "Lemma 4 (hence Theorem 1) for every b/a <= " + kit::format_significant_down(p.eps_star, 3) + " and q/a in [" + format_shortest(p.kappa_lo) +
         ", " + format_shortest(p.kappa_hi) + "] (doubles), by the paper's construction on " + segment +
         ": the inequalities (I1)-(I9) of docs/certified.md are proved in ball arithmetic for all these b/a at once; the argument "
         "from them to Lemma 4 (written there) is a proof on paper.";
}
std::string statement_discontinuities(const std::string& segment, std::size_t n) {
  return "At the double values of a, b, T1 has exactly " + std::to_string(n) + " discontinuities on " + segment +
         ": the z_k with 2z - (a/b) cos z = (2k+1) pi (enclosed), each a first-contact tangency "
         "T1(z_k) = z_k - (a/b) cos z_k at which T1 is continuous from the right and jumps down as theta increases: the left limit "
         "T1(z_k - 0) exceeds T1(z_k) by at least the certified lower bound of the jump recorded for that z_k; T1 is continuous and "
         "decreasing on each interval between them.";
}
std::string statement_covering(const ParameterBox& box) {
  return "Lemma 4 (and the covering of Theorem 1) " + params_text(box) +
         ": J0 and J1 are disjoint closed segments of [t2, 3pi/2]; T is continuous on each (closed balls on which T1 and theta2 "
         "are proved simple and the chain fixed), T = t2 exactly at one end and T >= 3pi/2 at the other, so T(Ji) contains "
         "[t2, 3pi/2] (which contains J0 and J1).";
}
std::string statement_periodic(const std::string& w) {
  return "Sections 6-7 from the certified covering: T has a point of minimal period " + std::to_string(w.size()) + " with itinerary (" + w +
         ")^infinity through J0, J1 (nested segments and the intermediate value theorem, applied to the certified hypotheses); "
         "the Krawczyk operator proves that the printed boxes contain exactly one such orbit of the cycle equations "
         "T(x_j) = x_{j+1}; and h_top(T restricted to its invariant set in J0 u J1) >= ln 2 (semi-conjugacy onto the 2-shift).";
}
std::string statement_superstable() {
  return "Theorem 2's conclusion at the double values of a, b, q: T1(t2) and theta2(t2) are enclosed, theta2(t2) mod 2pi satisfies "
         "the printed condition ((21): in (t1, t2); (22): in (t3, 2pi) u [0, t0)) with certified margins, and T = t2 on the whole "
         "of [t2, t2 + eps] (closed balls on which the chain is proved to stop before t2): T sends [t2, t2 + eps] to t2, so t2 is "
         "a superstable fixed point. This is Theorem 2 only where its hypotheses hold as well, (2) with (22) or (21) with (23): "
         "'theorem2' is true when the conclusion and one of those pairs are proved, false otherwise.";
}
std::string statement_window() {
  return "Superstability window in b at fixed a, q: for every b of an inner interval, T sends [t2(b), t2(b) + eps_b] to t2 "
         "with eps_b > 0 (proved over b-boxes, with a lower bound of eps_b recorded), so t2 is superstable at each such b; and "
         "T(t2) != t2 at one b below that interval and one above it; so the maximal interval of b containing the window's middle "
         "on which T(t2) = t2 has each edge between an end of the inner interval and the outer b next to it (all four recorded). "
         "At the middle, Theorem 2 holds with a certified eps.";
}

std::string statement_entropy(const ParameterBox& box) {
  return "At " + box.describe() +
         " (double values), disjoint segments of [t2, t3) on each of which T is continuous, with "
         "T(I_j) containing I_k along each edge of their graph, give h_top(T) >= ln rho(A) > ln 2 for the graph's 0-1 matrix A, "
         "rho(A) bounded below from a positive vector (Collatz-Wielandt).";
}

Json to_json(const Vartheta0& v) {
  Json j = Json::object();
  j.set("statement", statement_vartheta0());
  add_verdict(j, v.verdict);
  j.set("vartheta0", ball_json(v.value, 40)).set("sin_vartheta0", ball_json(v.sine, 40));
  if (v.rounding_certified) {
    j.set("vartheta0_double", shortest_double(v.value_double)).set("sin_vartheta0_double", shortest_double(v.sine_double));
  }
  j.set("rounding_certified", v.rounding_certified).set("bits", static_cast<long long>(v.bits));
  return j;
}

Json to_json(const ParameterBox& box, const Lemma1Proof& p) {
  Json j = Json::object();
  j.set("statement", statement_lemma1(box)).set("parameters", box_json(box));
  add_verdict(j, p.verdict);
  j.set("u_at_t2", ball_json(p.u_at_t2, 20)).set("t4", ball_json(p.t4, 20)).set("pieces", p.pieces);
  return j;
}

Json to_json(double a, double q, const Lemma1Bound& p) {
  Json j = Json::object();
  j.set("statement", statement_b0(a, q, p.b_low));
  j.set("parameters", Json::object().set("a", a).set("q", q));
  add_verdict(j, p.verdict);
  j.set("b0_lower_bound", p.b_low).set("b0_float_estimate", p.b_float).set("pieces", p.pieces);
  return j;
}

Json to_json(double a, double b, const DiscontinuityProof& p, const std::string& segment) {
  Json j = Json::object();
  j.set("statement", statement_discontinuities(segment, p.z.size()));
  j.set("parameters", Json::object().set("a", a).set("b", b));
  add_verdict(j, p.verdict);
  j.set("segment", segment).set("covered", Json::array().push(p.lo).push(p.hi)).set("n", static_cast<long long>(p.z.size()));
  Json zs = Json::array();
  for (const auto& t : p.z) {
    Json z = Json::object();
    z.set("k", t.k).set("z", ball_json(t.z, 20)).set("T1", ball_json(t.t_star, 20));
    if (t.verdict) z.set("jump_at_least", t.jump.lower());
    zs.push(z);
  }
  j.set("discontinuities", zs).set("balls", p.balls).set("seconds", p.seconds);
  return j;
}

Json to_json(const CoveringProof& p) {
  Json j = Json::object();
  j.set("statement", statement_covering(p.box)).set("parameters", box_json(p.box));
  add_verdict(j, p.verdict);
  auto seg = [](const SegmentProof& s) {
    Json x = Json::object();
    x.set("proved", s.verdict.proved);
    x.set("interval", Json::array().push(s.lo).push(s.hi));
    x.set("theta_T_ge_3pi_2", s.theta_top).set("T_there", ball_json(s.T_top, 20));
    x.set("theta_T_eq_t2", s.theta_t2).set("theta2_phase_there", ball_json(s.theta2_t2end, 12));
    x.set("balls", s.balls).set("depth", s.depth).set("interval_tests", s.tests).set("used_lemma1", s.used_lemma1);
    if (!s.verdict.proved && !s.verdict.step.empty()) x.set("failed_step", s.verdict.step).set("detail", s.verdict.detail);
    return x;
  };
  if (p.J0.verdict.proved || p.J0.balls > 0) j.set("J0", Json::array().push(p.J0.lo).push(p.J0.hi));
  if (p.J1.verdict.proved || p.J1.balls > 0) j.set("J1", Json::array().push(p.J1.lo).push(p.J1.hi));
  j.set("segments", Json::array().push(seg(p.J0)).push(seg(p.J1)));
  j.set("candidates_tried", p.candidates_tried).set("seconds", p.seconds);
  return j;
}

Json to_json(const CoveringProof& c, const PeriodicProof& p) {
  Json j = Json::object();
  j.set("statement", statement_periodic(p.word)).set("parameters", box_json(c.box));
  add_verdict(j, p.verdict);
  j.set("period", p.period).set("itinerary", p.word).set("existence_from_covering", p.existence);
  j.set("J0", Json::array().push(c.J0.lo).push(c.J0.hi)).set("J1", Json::array().push(c.J1.lo).push(c.J1.hi));
  Json orbit = Json::array();
  for (const auto& x : p.orbit) orbit.push(ball_json(x, 25));
  j.set("orbit", orbit).set("log_multiplier", ball_json(p.log_multiplier, 10));
  j.set("h_top_lower_bound", p.existence ? "ln 2" : "not proved").set("seconds", p.seconds);
  return j;
}

Json to_json(double a, double b, double q, const SuperstableProof& p) {
  Json j = Json::object();
  j.set("statement", statement_superstable()).set("parameters", Json::object().set("a", a).set("b", b).set("q", q));
  add_verdict(j, p.verdict);
  j.set("condition", p.condition).set("T1_at_t2", ball_json(p.T1, 20)).set("theta2_at_t2", ball_json(p.theta2, 20));
  j.set("theta2_phase", ball_json(p.theta2_phase, 15)).set("epsilon", p.eps).set("balls", p.balls);
  j.set("used_lemma1", p.used_lemma1).set("assumptions_2", p.eq2).set("assumptions_23", p.eq23);
  // Theorem 2's hypotheses: (2) and (22), or (21) and (23).
  const bool hypotheses = (p.eq2 && p.condition == 22) || (p.eq23 && p.condition == 21);
  j.set("theorem2", p.verdict.proved && hypotheses).set("seconds", p.seconds);
  return j;
}

Json to_json(double a, double q, const WindowProof& w) {
  Json j = Json::object();
  j.set("statement", statement_window()).set("parameters", Json::object().set("a", a).set("q", q));
  add_verdict(j, w.verdict);
  j.set("float_estimate", Json::array().push(w.b_lo_float).push(w.b_hi_float));
  j.set("left_edge", Json::array().push(w.left_out).push(w.left_in));
  j.set("min_eps_boxes", w.min_eps);
  j.set("right_edge", Json::array().push(w.right_in).push(w.right_out));
  j.set("boxes", w.boxes).set("T_at_left_out", ball_json(w.T_left_out, 12)).set("T_at_right_out", ball_json(w.T_right_out, 12));
  j.set("inside", to_json(a, 0.5 * (w.b_lo_float + w.b_hi_float), q, w.inside)).set("seconds", w.seconds);
  return j;
}

Json to_json(double a, const ArcL1Proof& p) {
  Json j = Json::object();
  j.set("statement", statement_arc_l1(p));
  j.set("parameters", Json::object().set("a", a).set("q_over_a", Json::array().push(p.kappa_lo).push(p.kappa_hi)));
  add_verdict(j, p.verdict);
  j.set("b_over_a_max", p.eps_max).set("delta_max", p.delta_max).set("conclusion", p.stop_arc ? "stop_arc" : "before_t0");
  j.set("S", p.S).set("W", p.W);
  j.set("g", Json::array().push(p.g_lo).push(p.g_hi)).set("dH", Json::array().push(p.h_lo).push(p.h_hi));
  if (p.verdict.proved) j.set("x1_max", ball_json(p.x1_max, 8)).set("gamma", ball_json(p.gamma, 8)).set("t0_min", ball_json(p.t0_min, 8));
  j.set("pieces", static_cast<long long>(p.pieces.size()));
  return j;
}

Json to_json(double a, const Lemma4UniformProof& p) {
  Json j = Json::object();
  j.set("statement", statement_lemma4_uniform(p));
  j.set("segment", Json::array().push(p.w_a).push(p.w_b));
  j.set("parameters", Json::object().set("a", a).set("q_over_a", Json::array().push(p.kappa_lo).push(p.kappa_hi)));
  add_verdict(j, p.verdict);
  j.set("b_over_a_max", p.eps_star);
  j.set("departure_g_max", p.departure_g_max).set("middle_max", p.middle_max).set("end_bracket_max", p.end_bracket_max);
  if (p.verdict.proved) j.set("count_length", ball_json(p.count_length, 8)).set("s_min", ball_json(p.s_min, 8));
  j.set("arc_l1", to_json(a, p.arc_l1));
  return j;
}

Json to_json(const EntropyProof& p) {
  Json j = Json::object();
  j.set("statement", statement_entropy(ParameterBox::point(p.a, p.b, p.q)))
      .set("parameters", Json::object().set("a", p.a).set("b", p.b).set("q", p.q));
  add_verdict(j, p.verdict);
  long long edges = 0;
  for (const GraphSegment& g : p.segments) edges += static_cast<long long>(g.successors.size());
  j.set("segments", static_cast<long long>(p.segments.size())).set("edges", edges).set("rho_lower", p.rho_lower);
  if (p.verdict.proved) j.set("h_lower", ball_json(p.log_rho_lower, 20));
  j.set("rho_float", p.rho_float).set("candidates", static_cast<long long>(p.candidates)).set("used_lemma1", p.used_lemma1);
  return j;
}

}  // namespace dfchaos::certify
