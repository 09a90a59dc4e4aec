// SPDX-License-Identifier: GPL-3.0-or-later
/// @file lemma4_uniform.cpp
/// @brief `certify lemma4-uniform`: Lemma 4 / Theorem 1 for every b/a up to an explicit bound,
/// by the paper's construction on the best segment found.
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/lemma4_uniform.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

Result run_lemma4_uniform(const Request& r) {
  const auto [k_lo, k_hi] = request::ratio_box(r);
  const certified::Lemma4UniformProof p = certified::best_lemma4_uniform(k_lo, k_hi);
  return request::result(r, p.verdict.proved, to_json(r.a, p), [&](const std::string& claim) { return certificate_lemma4_uniform(r.a, p, claim); });
}

}  // namespace

Statement lemma4_uniform_statement() {
  return {"lemma4-uniform",
          "Lemma 4 / Theorem 1 for every b/a up to an explicit bound and q/a in a box: the paper's construction on the best segment "
          "[pi + w_lo, pi + w_hi] found (the paper's L2 or a wider one; the result names it), its inequalities proved for all such b/a at "
          "once",
          {Input::a, Input::q_ratio},
          run_lemma4_uniform};
}

}  // namespace dfchaos::certify
