// SPDX-License-Identifier: GPL-3.0-or-later
/// @file b0.cpp
/// @brief `certify b0`: a certified lower bound of b0(q), Lemma 1 for every smaller b.
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/errors.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

Result run_b0(const Request& r) {
  const double a = request::amplitude(r);
  if (!r.q) throw InvalidParameter("q", "required for certify b0");
  if (r.q->lo != r.q->hi) throw InvalidParameter("q", "a single value (certify b0 works at one q)");
  const double q = request::bounded("q", r.q->lo);
  if (!(q > 0 && q < a)) throw InvalidParameter("q", "0 < q < a", q);
  const certified::Lemma1Bound p = certified::lemma1_b0_lower_bound(a, q);
  return request::result(r, p.verdict.proved, to_json(a, q, p), [&](const std::string& claim) { return certificate_b0(a, q, p, claim); });
}

}  // namespace

Statement b0_statement() { return {"b0", "a certified lower bound of b0(q): Lemma 1 for every b below it, at one q", {Input::a, Input::q}, run_b0}; }

}  // namespace dfchaos::certify
