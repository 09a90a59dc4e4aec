// SPDX-License-Identifier: GPL-3.0-or-later
/// @file discontinuities.cpp
/// @brief `certify discontinuities`: Lemma 2, the discontinuities of T1 on L0 or L2, at a point.
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/discontinuities.hpp"
#include "dfchaos/errors.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

Result run_discontinuities(const Request& r) {
  using namespace certified;
  const ParameterBox box = request::box_from(r, false, false);
  if (r.segment != "L0" && r.segment != "L2") throw InvalidParameter("segment", "L0 or L2 (got '" + r.segment + "')");
  const bool l2 = r.segment == "L2";
  const DiscontinuityProof p = prove_discontinuities(box.a, box.b_lo, L_101pi_100(), l2 ? L_51pi_50() : L_3pi_2(), 4000, r.certificate);
  return request::result(r, p.verdict.proved, to_json(box.a, box.b_lo, p, l2 ? "L2 = [101pi/100, 51pi/50]" : "L0 = [101pi/100, 3pi/2]"),
                         [&](const std::string& claim) { return certificate_discontinuities(box.a, box.b_lo, r.segment, p, claim); });
}

}  // namespace

Statement discontinuities_statement() {
  return {"discontinuities",
          "Lemma 2: the discontinuities of T1 on L0 or L2, at a point (a, b)",
          {Input::a, Input::b, Input::segment},
          run_discontinuities};
}

}  // namespace dfchaos::certify
