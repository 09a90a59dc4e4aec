// SPDX-License-Identifier: GPL-3.0-or-later
/// @file entropy.cpp
/// @brief `certify entropy`: Section 7 beyond two symbols, h_top(T) >= ln rho(A) from a proved
/// covering graph at a point (certified/entropy.hpp).
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/entropy.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

Result run_entropy(const Request& r) {
  const certified::ParameterBox box = request::box_from(r, true, false);
  certified::EntropyOptions opt;
  opt.record = r.certificate;
  const certified::EntropyProof p = certified::prove_entropy_bound(box.a, box.b_lo, box.q_lo, opt);
  return request::result(r, p.verdict.proved, to_json(p), [&](const std::string& claim) { return certificate_entropy(p, claim); });
}

}  // namespace

Statement entropy_statement() {
  return {"entropy",
          "Section 7 beyond two symbols: a lower bound ln rho(A) of the topological entropy from a proved covering graph, at a point",
          {Input::a, Input::b, Input::q},
          run_entropy};
}

}  // namespace dfchaos::certify
