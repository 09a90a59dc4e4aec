// SPDX-License-Identifier: GPL-3.0-or-later
#include "certify/certificate.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <flint/fmpz.h>

#include "certify/json.hpp"
#include "kit/digest.hpp"
#include "kit/output.hpp"

namespace dfchaos::certify {

namespace {

/// The fields every certificate starts with.
kit::Json header(const std::string& statement, const std::string& claim) {
  kit::Json j = kit::Json::object();
  j.set("format", kCertificateFormat);
  j.set("version", kCertificateVersion);
  j.set("statement", statement);
  j.set("claim", claim);
  return j;
}

/// `{"lo": exact_number(r.lo), "hi": exact_number(r.hi)}`.
kit::Json exact_range(const Range& r) {
  kit::Json j = kit::Json::object();
  j.set("lo", exact_number(r.lo));
  j.set("hi", exact_number(r.hi));
  return j;
}

/// An array of hex_double strings.
kit::Json hex_array(std::initializer_list<double> xs) {
  kit::Json j = kit::Json::array();
  for (double x : xs) j.push(hex_double(x));
  return j;
}

/// `{"sub_boxes": [[b_lo, b_hi, q_lo, q_hi], ...]}`: the leaves of a Lemma 1 proof (the `lemma1`
/// witnesses, alone or inside a covering's or Theorem 2's certificate).
kit::Json lemma1_sub_boxes(const certified::Lemma1Proof& p) {
  kit::Json boxes = kit::Json::array();
  for (const certified::Lemma1SubBox& s : p.sub_boxes) boxes.push(hex_array({s.b_lo, s.b_hi, s.q_lo, s.q_hi}));
  kit::Json j = kit::Json::object();
  j.set("sub_boxes", boxes);
  return j;
}

}  // namespace

std::string hex_double(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

std::string hex_exact(const certified::Ball& x) {
  if (!x.is_exact() || !x.is_finite()) throw std::logic_error("hex_exact: not an exact finite ball: " + x.str(20));
  fmpz_t m, e, frac;
  fmpz_init(m);
  fmpz_init(e);
  fmpz_init(frac);
  arf_get_fmpz_2exp(m, e, arb_midref(x.get()));  // x = m 2^e, m odd (or 0)
  std::string s;
  if (fmpz_is_zero(m)) {
    s = "0x0p+0";
  } else {
    if (fmpz_sgn(m) < 0) {
      s = "-";
      fmpz_neg(m, m);
    }
    const slong n = static_cast<slong>(fmpz_bits(m));  // m = 1.f * 2^(n-1)
    const slong frac_bits = n - 1, pad = (4 - frac_bits % 4) % 4, digits = (frac_bits + pad) / 4;
    fmpz_one(frac);
    fmpz_mul_2exp(frac, frac, static_cast<ulong>(n - 1));
    fmpz_sub(frac, m, frac);
    fmpz_mul_2exp(frac, frac, static_cast<ulong>(pad));
    s += "0x1";
    if (digits > 0) {
      char* h = fmpz_get_str(nullptr, 16, frac);
      std::string hex(h);
      flint_free(h);
      hex.insert(0, static_cast<std::size_t>(digits) - hex.size(), '0');
      while (!hex.empty() && hex.back() == '0') hex.pop_back();
      if (!hex.empty()) s += "." + hex;
    }
    fmpz_add_si(e, e, n - 1);
    const slong exponent = fmpz_get_si(e);
    s += (exponent < 0 ? "p" : "p+") + std::to_string(exponent);
  }
  fmpz_clear(m);
  fmpz_clear(e);
  fmpz_clear(frac);
  return s;
}

kit::Json exact_number(double x) {
  kit::Json j = kit::Json::object();
  j.set("hex", hex_double(x));
  j.set("decimal", shortest_double(x));
  return j;
}

kit::Json certificate_vartheta0(const certified::Vartheta0& v, const std::string& claim, const std::vector<PrintedDecimal>& decimals) {
  if (!v.verdict.proved) throw std::logic_error("certificate_vartheta0: not proved");
  kit::Json j = header("vartheta0", claim);
  j.set("parameters", kit::Json::object());
  kit::Json w = kit::Json::object();
  kit::Json bracket = kit::Json::object();
  for (const auto& [name, ball] : {std::pair<const char*, const certified::Ball*>{"lo", &v.bracket_lo}, {"hi", &v.bracket_hi}}) {
    kit::Json end = kit::Json::object();
    end.set("hex", hex_exact(*ball));
    end.set("decimal", ball->mid_str(70));
    bracket.set(name, end);
  }
  w.set("bracket", bracket);
  if (v.rounding_certified) {
    w.set("value_double", exact_number(v.value_double));
    w.set("sine_double", exact_number(v.sine_double));
  }
  if (!decimals.empty()) {
    kit::Json list = kit::Json::array();
    for (const PrintedDecimal& d : decimals) {
      kit::Json e = kit::Json::object();
      e.set("of", d.of).set("value", d.value);
      list.push(e);
    }
    w.set("decimals", list);
  }
  j.set("witnesses", w);
  return j;
}

kit::Json certificate_lemma1(double a, const Range& b, const Range& q, const certified::Lemma1Proof& p, const std::string& claim) {
  if (!p.verdict.proved) throw std::logic_error("certificate_lemma1: not proved");
  kit::Json j = header("lemma1", claim);
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(a));
  par.set("b", exact_range(b));
  par.set("q", exact_range(q));
  j.set("parameters", par);
  j.set("witnesses", lemma1_sub_boxes(p));
  return j;
}

kit::Json certificate_arc_l1(double a, const certified::ArcL1Proof& p, const std::string& claim) {
  if (!p.verdict.proved || p.pieces.empty()) throw std::logic_error("certificate_arc_l1: not proved");
  kit::Json j = header("arc-l1", claim);
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(a));
  par.set("q_over_a", exact_range(Range{p.kappa_lo, p.kappa_hi}));
  par.set("b_over_a_max", exact_number(p.eps_max));
  par.set("delta_max", exact_number(p.delta_max));
  j.set("parameters", par);
  // The grid: the pieces run over delta cells, and over s cells inside each.
  std::vector<double> dc{p.pieces.front().delta_lo}, sc{p.pieces.front().s_lo};
  for (const certified::ArcL1Piece& x : p.pieces) {
    if (x.delta_hi > dc.back()) dc.push_back(x.delta_hi);
    if (x.s_hi > sc.back()) sc.push_back(x.s_hi);
  }
  kit::Json dj = kit::Json::array(), sj = kit::Json::array();
  for (double d : dc) dj.push(hex_double(d));
  for (double s : sc) sj.push(hex_double(s));
  kit::Json w = kit::Json::object();
  w.set("conclusion", p.stop_arc ? "stop_arc" : "before_t0");
  w.set("S", exact_number(p.S)).set("W", exact_number(p.W));
  w.set("g_lo", exact_number(p.g_lo)).set("g_hi", exact_number(p.g_hi));
  w.set("dH_lo", exact_number(p.h_lo)).set("dH_hi", exact_number(p.h_hi));
  w.set("delta_cuts", dj).set("s_cuts", sj);
  if (p.stop_arc) {
    kit::Json tj = kit::Json::array();
    for (double t : p.tau) tj.push(hex_double(t));
    w.set("tau", tj);
  }
  j.set("witnesses", w);
  return j;
}

kit::Json certificate_lemma4_uniform(double a, const certified::Lemma4UniformProof& p, const std::string& claim) {
  if (!p.verdict.proved) throw std::logic_error("certificate_lemma4_uniform: not proved");
  kit::Json j = header("lemma4-uniform", claim);
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(a));
  par.set("q_over_a", exact_range(Range{p.kappa_lo, p.kappa_hi}));
  par.set("b_over_a_max", exact_number(p.eps_star));
  par.set("w_lo", exact_number(p.w_a));
  par.set("w_hi", exact_number(p.w_b));
  j.set("parameters", par);
  kit::Json w = kit::Json::object();
  w.set("pieces", static_cast<long long>(p.w_pieces));
  kit::Json cells = kit::Json::array();
  for (const certified::Lemma1SubBox& c : p.lemma1_cells) cells.push(hex_array({c.b_lo, c.b_hi, c.q_lo, c.q_hi}));
  w.set("lemma1", kit::Json::object().set("sub_boxes", cells));
  w.set("arc_l1", certificate_arc_l1(a, p.arc_l1, statement_arc_l1(p.arc_l1)));
  j.set("witnesses", w);
  return j;
}

kit::Json certificate_b0(double a, double q, const certified::Lemma1Bound& p, const std::string& claim) {
  if (!p.verdict.proved) throw std::logic_error("certificate_b0: not proved");
  kit::Json j = header("b0", claim);
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(a));
  par.set("q", exact_number(q));
  j.set("parameters", par);
  kit::Json pieces = kit::Json::array();
  for (const certified::Lemma1SubBox& s : p.b_pieces) pieces.push(hex_array({s.b_lo, s.b_hi}));
  kit::Json w = kit::Json::object();
  w.set("b_low", exact_number(p.b_low));
  w.set("b_pieces", pieces);
  j.set("witnesses", w);
  return j;
}

namespace {

/// The pieces of one negativity proof: `[[lo, hi, test], ...]` (exact hex ends).
kit::Json pieces(const certified::NegativityRecord& r) {
  kit::Json j = kit::Json::array();
  for (const certified::NegativityPiece& p : r) {
    kit::Json e = kit::Json::array();
    e.push(hex_exact(p.lo)).push(hex_exact(p.hi)).push(certified::negativity_test_name(p.test));
    j.push(e);
  }
  return j;
}

/// `{"s0", "t_lo", "t_hi", "no_contact", "simple_root"}`: the T1 witnesses of a recorded proof.
kit::Json t1_witness(const certified::FirstHitProof& p) {
  if (!p.verdict.proved || (p.no_contact.empty() && p.simple_root.empty()))
    throw std::logic_error("certificate: a T1 proof is not proved or not recorded");
  kit::Json t1 = kit::Json::object();
  t1.set("s0", hex_exact(p.s0)).set("t_lo", hex_exact(p.t_lo)).set("t_hi", hex_exact(p.t_hi));
  t1.set("no_contact", pieces(p.no_contact)).set("simple_root", pieces(p.simple_root));
  return t1;
}

/// `[hex_exact(lo), hex_exact(hi)]`.
kit::Json exact_pair(const certified::Ball& lo, const certified::Ball& hi) {
  kit::Json j = kit::Json::array();
  j.push(hex_exact(lo)).push(hex_exact(hi));
  return j;
}

/// One ball of a covering proof: its set, the T1 witnesses, the case and the first progression's.
kit::Json ball(const certified::BallProof& b) {
  using certified::TCase;
  const certified::MapStepProof& T = b.T;
  if (!T.verdict.proved) throw std::logic_error("certificate: a ball is not proved");
  if (T.t1.no_contact.empty() && T.t1.simple_root.empty()) throw std::logic_error("certificate: the proof was not recorded");
  kit::Json j = kit::Json::object();
  if (b.at_t2) throw std::logic_error("certificate: the start set theta = t2(b) has no format");
  if (b.from_t2) {
    kit::Json th = kit::Json::array();
    th.push("t2").push(hex_exact(b.theta_hi));
    j.set("theta", th);
  } else {
    j.set("theta", exact_pair(b.theta_lo, b.theta_hi));
  }
  j.set("b", hex_array({b.box.b_lo, b.box.b_hi}));
  j.set("q", hex_array({b.box.q_lo, b.box.q_hi}));
  j.set("T1", t1_witness(T.t1));
  j.set("case", T.t_case == TCase::ScenarioAB ? "AB" : T.t_case == TCase::ScenarioBC ? "BC" : "none");
  j.set("k", static_cast<long long>(T.turn));
  if (T.stop_arc.verdict.proved) {
    kit::Json s = kit::Json::object();
    s.set("tau", hex_exact(T.stop_arc.tau));
    if (T.stop_arc.from_impact)
      s.set("from", "impact");
    else
      s.set("from", hex_exact(T.stop_arc.from_end));
    s.set("no_stop_before_t3", pieces(T.stop_arc.no_stop_before_t3));
    j.set("stop_arc", s);
  } else {
    kit::Json s = kit::Json::object();
    s.set("u_lo", hex_exact(T.theta2.u_lo)).set("u_hi", hex_exact(T.theta2.u_hi));
    s.set("no_earlier_stop", pieces(T.theta2.no_earlier_stop)).set("simple_zero", pieces(T.theta2.simple_zero));
    j.set("theta2", s);
  }
  return j;
}

kit::Json balls(const std::vector<certified::BallProof>& v) {
  kit::Json j = kit::Json::array();
  for (const certified::BallProof& b : v) j.push(ball(b));
  return j;
}

kit::Json segment(const certified::SegmentProof& s) {
  if (s.top_balls.empty() || s.t2_balls.empty() || s.cover_balls.empty())
    throw std::logic_error("certificate_covering: the proof was not recorded (CoveringOptions::record)");
  kit::Json j = kit::Json::object();
  j.set("lo", hex_double(s.lo)).set("hi", hex_double(s.hi)).set("theta_top", hex_double(s.theta_top)).set("theta_t2", hex_double(s.theta_t2));
  j.set("top", balls(s.top_balls)).set("t2_end", balls(s.t2_balls)).set("cover", balls(s.cover_balls));
  return j;
}

/// `{"lo", "hi"}` of the bracket of vartheta0 (exact hex), for the hypotheses (2) of Theorem 2.
kit::Json vartheta0_bracket() {
  static const certified::Vartheta0 v = certified::certify_vartheta0(128);
  if (!v.verdict.proved) throw std::logic_error("certificate: vartheta0 not certified");
  kit::Json j = kit::Json::object();
  j.set("lo", hex_exact(v.bracket_lo)).set("hi", hex_exact(v.bracket_hi));
  return j;
}

/// Lemma 1's witness of a proof that used it (`{"sub_boxes": [...]}`). @throws std::logic_error if not proved.
kit::Json lemma1_witness(const certified::Lemma1Proof& l) {
  if (!l.verdict.proved) throw std::logic_error("certificate: a ball needed Lemma 1, which is not proved over the whole range of b");
  return lemma1_sub_boxes(l);
}

/// The witnesses of Theorem 2's conclusion at a point (statement superstable; also a window's middle).
kit::Json superstable_witnesses(const certified::SuperstableProof& p) {
  if (!p.verdict.proved || p.at.size() != 1 || p.cover.empty()) throw std::logic_error("certificate_superstable: not proved, or not recorded");
  kit::Json w = kit::Json::object();
  if (p.used_lemma1) w.set("lemma1", lemma1_witness(p.lemma1));
  w.set("vartheta0", vartheta0_bracket());
  kit::Json hyp = kit::Json::array();
  if (p.eq2) hyp.push("(2)");
  if (p.eq23) hyp.push("(23)");
  w.set("hypotheses", hyp);
  w.set("at_t2", ball(p.at.front()));
  w.set("phase_turn", p.phase_turn);
  w.set("condition", static_cast<long long>(p.condition));
  double end = 0;
  for (const certified::BallProof& b : p.cover) end = std::max(end, b.theta_hi.mid());  // a double (the balls of the cover have double ends)
  w.set("theta_end", hex_double(end));
  w.set("cover", balls(p.cover));
  return w;
}

kit::Json point_parameters(double a, double b, double q) {
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(a)).set("b", exact_number(b)).set("q", exact_number(q));
  return par;
}

}  // namespace

kit::Json certificate_superstable(double a, double b, double q, const certified::SuperstableProof& p, const std::string& claim) {
  kit::Json j = header("superstable", claim);
  j.set("parameters", point_parameters(a, b, q));
  j.set("witnesses", superstable_witnesses(p));
  return j;
}

kit::Json certificate_not_superstable(double a, double b, double q, const certified::SuperstableProof& p, const std::string& claim) {
  if (!p.verdict.refuted || p.at.size() != 1) throw std::logic_error("certificate_not_superstable: not refuted, or not recorded");
  kit::Json j = header("not_superstable", claim);
  j.set("parameters", point_parameters(a, b, q));
  kit::Json w = kit::Json::object();
  w.set("at_t2", ball(p.at.front()));
  j.set("witnesses", w);
  return j;
}

kit::Json certificate_window(double a, double q, const certified::WindowProof& p, const std::string& claim) {
  if (!p.verdict.proved || p.outer.size() != 2 || p.box_proofs.empty()) throw std::logic_error("certificate_window: not proved, or not recorded");
  kit::Json j = header("window", claim);
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(a)).set("q", exact_number(q));
  j.set("parameters", par);
  kit::Json w = kit::Json::object();
  w.set("left_out", hex_double(p.left_out)).set("left_in", hex_double(p.left_in));
  w.set("right_in", hex_double(p.right_in)).set("right_out", hex_double(p.right_out));
  w.set("outer", balls(p.outer));
  w.set("boxes", balls(p.box_proofs));
  bool lemma1 = false;
  for (const certified::BallProof& b : p.box_proofs) lemma1 = lemma1 || b.T.used_lemma1;
  if (lemma1) w.set("lemma1", lemma1_witness(p.lemma1));
  const double b_mid = p.inside.at.front().box.b_lo;
  kit::Json inside = superstable_witnesses(p.inside);
  inside.set("b", hex_double(b_mid));
  w.set("inside", inside);
  j.set("witnesses", w);
  return j;
}

kit::Json certificate_theorem2_counterexample(double a, double b, double q, const certified::Theorem2Counterexample& p, const std::string& claim) {
  if (!p.verdict.proved || p.at.size() != 1) throw std::logic_error("certificate_theorem2_counterexample: not proved, or not recorded");
  kit::Json j = header("theorem2_counterexample", claim);
  j.set("parameters", point_parameters(a, b, q));
  kit::Json w = kit::Json::object();
  w.set("vartheta0", vartheta0_bracket());
  w.set("at_t2", ball(p.at.front()));
  w.set("phase_turn", p.at.front().T.turn);
  j.set("witnesses", w);
  return j;
}

kit::Json certificate_covering(const certified::CoveringProof& p, const std::string& claim) {
  if (!p.verdict.proved) throw std::logic_error("certificate_covering: not proved");
  kit::Json j = header("covering", claim);
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(p.box.a));
  par.set("b", exact_range(Range{p.box.b_lo, p.box.b_hi}));
  par.set("q", exact_range(Range{p.box.q_lo, p.box.q_hi}));
  j.set("parameters", par);
  kit::Json w = kit::Json::object();
  if (p.J0.used_lemma1 || p.J1.used_lemma1) {
    if (!p.lemma1.verdict.proved) throw std::logic_error("certificate_covering: a ball needed Lemma 1, which is not proved over the whole box");
    w.set("lemma1", lemma1_sub_boxes(p.lemma1));
  }
  kit::Json segs = kit::Json::array();
  segs.push(segment(p.J0)).push(segment(p.J1));
  w.set("segments", segs);
  j.set("witnesses", w);
  return j;
}

std::string covering_box_text(const certified::CoveringProof& p) {
  std::string t = certificate_covering(p, statement_covering(p.box)).dump(0);
  t.pop_back();  // the final newline
  return t;
}

std::string certificate_coverings_text(double a, const Range& b, const Range& q, const std::vector<std::string>& boxes, const std::string& claim) {
  kit::Json j = header("coverings", claim);
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(a)).set("b", exact_range(b)).set("q", exact_range(q));
  j.set("parameters", par);
  j.set("witnesses", kit::Json::object().set("boxes", kit::Json::array()));
  // The boxes are spliced into the empty array as text (each already a whole JSON document): a column
  // holds hundreds of boxes, which as one JSON value would take gigabytes.
  std::string text = certificate_text(j);
  const std::string empty = "\"boxes\": []";
  const std::size_t at = text.rfind(empty);
  if (at == std::string::npos) throw std::logic_error("certificate_coverings_text: no empty boxes array");
  std::string list = "\"boxes\": [";
  for (std::size_t i = 0; i < boxes.size(); ++i) list += (i ? ",\n  " : "\n  ") + boxes[i];
  list += boxes.empty() ? "]" : "\n  ]";
  return text.replace(at, empty.size(), list);
}

kit::Json certificate_periodic(const certified::CoveringProof& c, const std::vector<certified::PeriodicProof>& orbits, const std::string& claim) {
  if (!c.verdict.proved || !c.box.is_point()) throw std::logic_error("certificate_periodic: the covering is not proved at a point");
  kit::Json j = header("periodic", claim);
  j.set("parameters", point_parameters(c.box.a, c.box.b_lo, c.box.q_lo));
  kit::Json w = kit::Json::object();
  w.set("J0", hex_array({c.J0.lo, c.J0.hi})).set("J1", hex_array({c.J1.lo, c.J1.hi}));
  kit::Json all = kit::Json::array();
  for (const certified::PeriodicProof& p : orbits) {
    if (!p.verdict.proved) throw std::logic_error("certificate_periodic: the orbit of period " + std::to_string(p.period) + " is not proved");
    if (p.boxes.size() != static_cast<std::size_t>(p.period))
      throw std::logic_error("certificate_periodic: period " + std::to_string(p.period) + ": " +
                             (p.unrecorded.empty() ? "not recorded (PeriodicOptions::record)" : p.unrecorded));
    kit::Json boxes = kit::Json::array();
    for (const certified::OrbitBoxProof& x : p.boxes) {
      kit::Json e = kit::Json::object();
      e.set("X", exact_pair(x.lo, x.hi));
      e.set("on", ball(x.on)).set("at_lo", ball(x.at_lo)).set("at_hi", ball(x.at_hi));
      boxes.push(e);
    }
    kit::Json o = kit::Json::object();
    o.set("period", static_cast<long long>(p.period)).set("word", p.word).set("boxes", boxes);
    all.push(o);
  }
  w.set("orbits", all);
  j.set("witnesses", w);
  return j;
}

kit::Json certificate_entropy(const certified::EntropyProof& p, const std::string& claim) {
  if (!p.verdict.proved) throw std::logic_error("certificate_entropy: not proved");
  kit::Json j = header("entropy", claim);
  j.set("parameters", point_parameters(p.a, p.b, p.q));
  kit::Json w = kit::Json::object();
  if (p.used_lemma1) {
    if (!p.lemma1.verdict.proved) throw std::logic_error("certificate_entropy: a ball needed Lemma 1, which is not proved (EntropyOptions::record)");
    w.set("lemma1", lemma1_sub_boxes(p.lemma1));
  }
  kit::Json segs = kit::Json::array();
  for (const certified::GraphSegment& g : p.segments) {
    if (g.cover.empty()) throw std::logic_error("certificate_entropy: the proof was not recorded (EntropyOptions::record)");
    kit::Json succ = kit::Json::array();
    for (int k : g.successors) succ.push(static_cast<long long>(k));
    kit::Json e = kit::Json::object();
    e.set("I", hex_array({g.lo, g.hi})).set("weight", hex_double(g.weight)).set("successors", succ);
    e.set("cover", balls(g.cover)).set("at_lo", ball(g.at_lo)).set("at_hi", ball(g.at_hi));
    segs.push(e);
  }
  w.set("segments", segs).set("rho_lower", hex_double(p.rho_lower));
  j.set("witnesses", w);
  return j;
}

namespace {

/// `{"theta": [lo, hi], "T1": {...}}`: a T1 ball of Lemma 2 (exact ends, at the certificate's b).
kit::Json t1_ball(const certified::T1Piece& x) {
  kit::Json j = kit::Json::object();
  j.set("theta", exact_pair(x.lo, x.hi)).set("T1", t1_witness(x.proof));
  return j;
}

}  // namespace

kit::Json certificate_discontinuities(double a, double b, const std::string& segment, const certified::DiscontinuityProof& p,
                                      const std::string& claim) {
  if (!p.verdict.proved) throw std::logic_error("certificate_discontinuities: not proved");
  if (segment != "L0" && segment != "L2") throw std::logic_error("certificate_discontinuities: segment L0 or L2");
  kit::Json j = header("discontinuities", claim);
  kit::Json par = kit::Json::object();
  par.set("a", exact_number(a)).set("b", exact_number(b)).set("segment", segment);
  j.set("parameters", par);
  kit::Json w = kit::Json::object();
  w.set("lo", hex_double(p.lo)).set("hi", hex_double(p.hi));
  kit::Json ts = kit::Json::array();
  for (const certified::Tangency& t : p.z) {
    if (t.right_no_contact.empty()) throw std::logic_error("certificate_discontinuities: the proof was not recorded");
    kit::Json e = kit::Json::object();
    e.set("k", static_cast<long long>(t.k));
    e.set("z", exact_pair(t.z.lower_ball(), t.z.upper_ball()));
    e.set("window", exact_pair(t.window_lo, t.window_hi));
    e.set("left", t1_ball(t.left));
    kit::Json r = kit::Json::object();
    r.set("theta", exact_pair(t.right_lo, t.right_hi)).set("s0", hex_exact(t.right_s0)).set("no_contact", pieces(t.right_no_contact));
    e.set("right", r);
    ts.push(e);
  }
  w.set("tangencies", ts);
  if (p.z.empty()) w.set("k_above", p.k_above);
  kit::Json cover = kit::Json::array();
  for (const certified::T1Piece& x : p.cover) cover.push(t1_ball(x));
  w.set("cover", cover);
  j.set("witnesses", w);
  return j;
}

kit::Json certificate_paper_construction(const certified::CoveringProof& cov, const certified::DiscontinuityProof& d, const std::string& claim) {
  if (!cov.box.is_point()) throw std::logic_error("certificate_paper_construction: the covering is not at a point");
  kit::Json j = header("paper_construction", claim);
  j.set("parameters", point_parameters(cov.box.a, cov.box.b_lo, cov.box.q_lo));
  kit::Json w = kit::Json::object();
  w.set("covering", certificate_covering(cov, statement_covering(cov.box)));
  w.set("discontinuities",
        certificate_discontinuities(cov.box.a, cov.box.b_lo, "L2", d, statement_discontinuities("L2 = [101pi/100, 51pi/50]", d.z.size())));
  j.set("witnesses", w);
  return j;
}

std::string certificate_text(const kit::Json& certificate) { return certificate.dump(1); }

void check_certificate_path(const std::filesystem::path& path) {
  const std::filesystem::path target = kit::output_target(path, "certificate");
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw kit::OutputError("certificate: cannot create a file beside " + path.string() + ": " + dir.string() + " is not an existing directory", true);
}

WrittenCertificate write_certificate(const std::filesystem::path& path, const kit::Json& certificate) {
  check_certificate_path(path);  // the directory is not created
  const std::string text = certificate_text(certificate);
  kit::write_atomically(kit::output_target(path, "certificate"), text);
  return WrittenCertificate{path.string(), text.size(), kit::sha256_hex(text)};
}

kit::Json to_json(const WrittenCertificate& w) {
  kit::Json j = kit::Json::object();
  j.set("path", w.path);
  j.set("bytes", static_cast<long long>(w.bytes));
  j.set("sha256", w.sha256);
  return j;
}

}  // namespace dfchaos::certify
