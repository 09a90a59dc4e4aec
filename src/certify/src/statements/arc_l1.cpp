// SPDX-License-Identifier: GPL-3.0-or-later
/// @file arc_l1.cpp
/// @brief `certify arc-l1`: the arc L1 of Lemma 4's proof, for every b/a up to an explicit bound.
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/arc_l1.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

Result run_arc_l1(const Request& r) {
  const auto [k_lo, k_hi] = request::ratio_box(r);
  const certified::ArcL1Proof p = certified::prove_arc_l1(k_lo, k_hi);
  return request::result(r, p.verdict.proved, to_json(r.a, p), [&](const std::string& claim) { return certificate_arc_l1(r.a, p, claim); });
}

}  // namespace

Statement arc_l1_statement() {
  return {"arc-l1",
          "proof of Lemma 4, arc L1 = [197pi/100, t3): from rest there the progression stops in (t3, t0 + 2pi), for every b/a up to an "
          "explicit bound and q/a in a box",
          {Input::a, Input::q_ratio},
          run_arc_l1};
}

}  // namespace dfchaos::certify
