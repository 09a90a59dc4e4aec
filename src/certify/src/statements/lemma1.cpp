// SPDX-License-Identifier: GPL-3.0-or-later
/// @file lemma1.cpp
/// @brief `certify lemma1`: Lemma 1 (u(t2) < 0, Eq. 8) at a point or over a box of (b, q).
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

Result run_lemma1(const Request& r) {
  const certified::ParameterBox box = request::box_from(r, true, true);
  const certified::Lemma1Proof p = certified::certify_lemma1(certified::ParameterBalls(box));
  return request::result(r, p.verdict.proved, to_json(box, p), [&](const std::string& claim) {
    return certificate_lemma1(box.a, Range{box.b_lo, box.b_hi}, Range{box.q_lo, box.q_hi}, p, claim);
  });
}

}  // namespace

Statement lemma1_statement() {
  return {"lemma1", "Lemma 1 (u(t2) < 0, Eq. 8) at a point or over a box of (b, q)", {Input::a, Input::b_box, Input::q_box}, run_lemma1};
}

}  // namespace dfchaos::certify
