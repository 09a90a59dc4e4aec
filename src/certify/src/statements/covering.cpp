// SPDX-License-Identifier: GPL-3.0-or-later
/// @file covering.cpp
/// @brief `certify covering`: Lemma 4 / Theorem 1, two disjoint covering segments J0, J1 at a
/// point or over a box; searched, or given (--J0, --J1) as certified_region records them.
#include <cmath>
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

using namespace certified;

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

Result run_covering(const Request& r) {
  const ParameterBox box = request::box_from(r, true, true);
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
  return request::result(r, p.verdict.proved, to_json(p), [&](const std::string& claim) { return certificate_covering(p, claim); });
}

}  // namespace

Statement covering_statement() {
  return {"covering",
          "Lemma 4 / Theorem 1: two disjoint covering segments J0, J1, at a point or over a box",
          {Input::a, Input::b_box, Input::q_box, Input::segments},
          run_covering};
}

}  // namespace dfchaos::certify
