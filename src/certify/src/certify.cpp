// SPDX-License-Identifier: GPL-3.0-or-later
#include "certify/certify.hpp"

#include <cmath>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/symbolic.hpp"

namespace dfchaos::certify {

namespace {

using namespace dfchaos::certified;

/// The record's "statement" (every record has one).
std::string claim_of(const Result& c) { return c.record.value().at("statement").get<std::string>(); }

/// x itself, after checking |x| <= kMaxParameter (which also refuses NaN). @throws InvalidParameter naming `name`.
double bounded(const std::string& name, double x) {
  if (!(std::fabs(x) <= kMaxParameter)) throw InvalidParameter(name, "|" + name + "| <= " + format_shortest(kMaxParameter), x);
  return x;
}

/// r itself, after checking both ends (bounded) and lo <= hi.
Range bounded(const std::string& name, const Range& r) {
  bounded(name, r.lo);
  if (r.lo == r.hi) return r;
  bounded(name, r.hi);
  if (!(r.lo <= r.hi)) throw InvalidParameter(name, "LO <= HI in LO:HI (got '" + format_shortest(r.lo) + ":" + format_shortest(r.hi) + "')");
  return r;
}

/// The parameter box of a request, its ranges checked in the order a, b, q (the first bad one is
/// named; the tool has parsed the syntax of every option before).
ParameterBox box_from(const Request& r, bool need_q, bool allow_box) {
  const double a = bounded("a", r.a);
  if (!(a > 0)) throw InvalidParameter("a", "a > 0", a);
  if (!r.b) throw InvalidParameter("b", "required for certify " + r.what);
  const auto [blo, bhi] = bounded("b", *r.b);
  if (!(blo > 0)) throw InvalidParameter("b", "b > 0", blo);
  if (!(2 * bhi < a)) throw InvalidParameter("b", "b < a/2", bhi);
  double qlo = 0.5 * a + 2 * bhi, qhi = qlo;
  if (need_q) {
    if (!r.q) throw InvalidParameter("q", "required for certify " + r.what);
    const Range q = bounded("q", *r.q);
    qlo = q.lo;
    qhi = q.hi;
    if (!(qlo > 2 * bhi)) throw InvalidParameter("q", "q > 2b (every progression stops)", qlo);
    if (!(qhi - 2 * blo < a)) throw InvalidParameter("q", "q - 2b < a (t0, t1 exist)", qhi);
  }
  if (!allow_box && (blo != bhi || qlo != qhi))
    throw InvalidParameter(blo != bhi ? "b" : "q", "a single value (certify " + r.what + " works at a parameter point)");
  return ParameterBox{a, blo, bhi, qlo, qhi};
}

/// The candidate of a given segment, its ends checked to be finite and inside [t2(b_hi), 3pi/2] (t2
/// grows with b: a covering segment of Lemma 4 lies above t2 for every b of the box), in the order
/// top, t2.
Candidate candidate(const std::string& name, const SegmentEnds& e, const ParameterBox& box) {
  const Parameters corner(box.a, box.b_hi, box.q_lo);
  const double t2 = *corner.t2(), top = 1.5 * M_PI;
  for (double x : {e.theta_top, e.theta_t2})
    if (!(x >= t2 && x <= top))
      throw InvalidParameter(name, "both ends in [t2(b_hi), 3pi/2] = [" + format_shortest(t2) + ", " + format_shortest(top) + "]", x);
  return Candidate{e.theta_top, e.theta_t2};
}

}  // namespace

void check_statement(const std::string& what) {
  for (const char* known : {"vartheta0", "lemma1", "b0", "discontinuities", "covering", "periodic", "superstable", "arc-l1", "lemma4-uniform"})
    if (what == known) return;
  throw InvalidParameter(
      "what", "one of vartheta0, lemma1, b0, discontinuities, covering, periodic, superstable, arc-l1, lemma4-uniform (got '" + what + "')");
}

Result certify(const Request& r) {
  check_statement(r.what);
  if (!r.word.empty() && r.what != "periodic") throw InvalidParameter("word", "only certify periodic takes an itinerary word (not " + r.what + ")");
  if (r.what == "vartheta0") {
    const Vartheta0 v = certify_vartheta0(200);
    Result c{v.verdict.proved, to_json(v)};
    if (c.proved && r.certificate) c.certificate = certificate_vartheta0(v, claim_of(c));
    return c;
  }
  if (r.what == "lemma1") {
    const ParameterBox box = box_from(r, true, true);
    const Lemma1Proof p = certify_lemma1(ParameterBalls(box));
    Result c{p.verdict.proved, to_json(box, p)};
    if (c.proved && r.certificate) c.certificate = certificate_lemma1(box.a, Range{box.b_lo, box.b_hi}, Range{box.q_lo, box.q_hi}, p, claim_of(c));
    return c;
  }
  if (r.what == "b0") {
    const double a = bounded("a", r.a);
    if (!(a > 0)) throw InvalidParameter("a", "a > 0", a);
    if (!r.q) throw InvalidParameter("q", "required for certify b0");
    if (r.q->lo != r.q->hi) throw InvalidParameter("q", "a single value (certify b0 works at one q)");
    const double q = bounded("q", r.q->lo);
    if (!(q > 0 && q < a)) throw InvalidParameter("q", "0 < q < a", q);
    const Lemma1Bound p = lemma1_b0_lower_bound(a, q);
    Result c{p.verdict.proved, to_json(a, q, p)};
    if (c.proved && r.certificate) c.certificate = certificate_b0(a, q, p, claim_of(c));
    return c;
  }
  if (r.what == "arc-l1" || r.what == "lemma4-uniform") {
    const double a = bounded("a", r.a);
    if (!(a > 0)) throw InvalidParameter("a", "a > 0", a);
    if (!r.q) throw InvalidParameter("q", "required for certify " + r.what);
    const Range q = bounded("q", *r.q);
    if (!(q.lo > 0)) throw InvalidParameter("q", "q > 0", q.lo);
    if (!(q.hi <= a)) throw InvalidParameter("q", "q <= a (t0 exists for every b > 0)", q.hi);
    // q/a enclosed: the proof is about the ratios (lower end rounded down, upper end up).
    const double k_lo = (Ball(q.lo) / Ball(a)).lower(), k_hi = (Ball(q.hi) / Ball(a)).upper();
    if (r.what == "arc-l1") {
      const ArcL1Proof p = prove_arc_l1(k_lo, k_hi);
      Result c{p.verdict.proved, to_json(a, p)};
      if (c.proved && r.certificate) c.certificate = certificate_arc_l1(a, p, claim_of(c));
      return c;
    }
    const Lemma4UniformProof p = best_lemma4_uniform(k_lo, k_hi);
    Result c{p.verdict.proved, to_json(a, p)};
    if (c.proved && r.certificate) c.certificate = certificate_lemma4_uniform(a, p, claim_of(c));
    return c;
  }
  if (r.what == "discontinuities") {
    const ParameterBox box = box_from(r, false, false);
    if (r.segment != "L0" && r.segment != "L2") throw InvalidParameter("segment", "L0 or L2 (got '" + r.segment + "')");
    const bool l2 = r.segment == "L2";
    const DiscontinuityProof p = prove_discontinuities(box.a, box.b_lo, L_101pi_100(), l2 ? L_51pi_50() : L_3pi_2(), 4000, r.certificate);
    Result c{p.verdict.proved, to_json(box.a, box.b_lo, p, l2 ? "L2 = [101pi/100, 51pi/50]" : "L0 = [101pi/100, 3pi/2]")};
    if (c.proved && r.certificate) c.certificate = certificate_discontinuities(box.a, box.b_lo, r.segment, p, claim_of(c));
    return c;
  }
  if (r.what == "covering") {
    const ParameterBox box = box_from(r, true, true);
    CoveringOptions opt;
    opt.record = r.certificate;
    CoveringProof p;
    if (!r.J0 && !r.J1) {
      p = prove_covering(box, opt);
    } else {
      if (!r.J0 || !r.J1) throw InvalidParameter(r.J0 ? "J1" : "J0", "given together with " + std::string(r.J0 ? "J0" : "J1"));
      const Candidate c0 = candidate("J0", *r.J0, box), c1 = candidate("J1", *r.J1, box);
      if (!(c0.hi() < c1.lo())) throw InvalidParameter("J1", "J1 to the right of J0 (J0 and J1 disjoint)", c1.lo());
      p = prove_covering(box, std::vector<Candidate>{c0, c1}, opt);
      // Say which of the given segments failed (prove_covering reports the last failure it met).
      if (!p.verdict.proved) {
        const bool one_proved = p.J0.verdict.proved, it_was_J0 = one_proved && p.J0.lo == c0.lo();
        p.verdict.step = (one_proved ? (it_was_J0 ? "J1: " : "J0: ") : "J0 and J1 both failed; J1: ") + p.verdict.step;
      }
    }
    Result c{p.verdict.proved, to_json(p)};
    if (c.proved && r.certificate) {
      try {
        c.certificate = certificate_covering(p, claim_of(c));
      } catch (const std::logic_error& e) {
        c.no_certificate = e.what();
      }
    }
    return c;
  }
  if (r.what == "periodic") {
    const ParameterBox box = box_from(r, true, false);
    if (!r.word.empty() && r.period != 0) throw InvalidParameter("word", "give the period M or the word W, not both");
    if (r.word.empty() && (r.period < 1 || r.period > 64)) throw InvalidParameter("period", "an integer 1 <= m <= 64 (or give a word)", r.period);
    if (!r.word.empty()) require_itinerary_word("word", r.word, 64);
    const CoveringProof c = prove_covering(box);
    PeriodicOptions opt;
    opt.record = r.certificate;
    const PeriodicProof p = r.word.empty() ? prove_periodic(c, r.period, opt) : prove_periodic(c, r.word, opt);
    Result res{p.verdict.proved, to_json(c, p)};
    if (res.proved && r.certificate) {
      try {
        res.certificate = certificate_periodic(c, {p}, claim_of(res));
      } catch (const std::logic_error& e) {
        res.no_certificate = e.what();
      }
    }
    return res;
  }
  // superstable
  const ParameterBox box = box_from(r, true, false);
  if (!r.window) {
    const SuperstableProof p = prove_superstable(box.a, box.b_lo, box.q_lo, 0.0 / 0.0, r.certificate);
    Result c{p.verdict.proved, to_json(box.a, box.b_lo, box.q_lo, p)};
    if (c.proved && r.certificate) c.certificate = certificate_superstable(box.a, box.b_lo, box.q_lo, p, claim_of(c));
    return c;
  }
  const auto [lo, hi] = bounded("window", *r.window);
  if (!(lo > 0 && lo < hi && 2 * hi < box.a)) throw InvalidParameter("window", "0 < LO < HI < a/2", lo);
  const WindowProof w = prove_window(box.a, box.q_lo, lo, hi, 1e-9, r.certificate);
  Result c{w.verdict.proved, to_json(box.a, box.q_lo, w)};
  if (c.proved && r.certificate) c.certificate = certificate_window(box.a, box.q_lo, w, claim_of(c));
  return c;
}

}  // namespace dfchaos::certify
