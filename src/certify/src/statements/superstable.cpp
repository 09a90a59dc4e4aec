// SPDX-License-Identifier: GPL-3.0-or-later
/// @file superstable.cpp
/// @brief `certify superstable`: Theorem 2 at a point, or a window in b with both its edges.
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/superstable.hpp"
#include "dfchaos/errors.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

using namespace certified;

Result run_superstable(const Request& r) {
  const ParameterBox box = request::box_from(r, true, false);
  if (!r.window) {
    const SuperstableProof p = prove_superstable(box.a, box.b_lo, box.q_lo, 0.0 / 0.0, r.certificate);
    return request::result(r, p.verdict.proved, to_json(box.a, box.b_lo, box.q_lo, p),
                           [&](const std::string& claim) { return certificate_superstable(box.a, box.b_lo, box.q_lo, p, claim); });
  }
  const auto [lo, hi] = request::bounded("window", *r.window);
  if (!(lo > 0 && lo < hi && 2 * hi < box.a)) throw InvalidParameter("window", "0 < LO < HI < a/2", lo);
  const WindowProof w = prove_window(box.a, box.q_lo, lo, hi, 1e-9, r.certificate);
  return request::result(r, w.verdict.proved, to_json(box.a, box.q_lo, w),
                         [&](const std::string& claim) { return certificate_window(box.a, box.q_lo, w, claim); });
}

}  // namespace

Statement superstable_statement() {
  return {"superstable",
          "Theorem 2 at a point, or a window in b with both its edges (--window)",
          {Input::a, Input::b, Input::q, Input::window},
          run_superstable};
}

}  // namespace dfchaos::certify
