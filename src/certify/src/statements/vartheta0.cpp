// SPDX-License-Identifier: GPL-3.0-or-later
/// @file vartheta0.cpp
/// @brief `certify vartheta0`: Eq. (1), the root vartheta0 of pi - x = cot(x/2), enclosed.
#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

Result run_vartheta0(const Request& r) {
  const certified::Vartheta0 v = certified::certify_vartheta0(200);
  return request::result(r, v.verdict.proved, to_json(v), [&](const std::string& claim) { return certificate_vartheta0(v, claim); });
}

}  // namespace

Statement vartheta0_statement() {
  return {"vartheta0", "Eq. (1): the root vartheta0 of pi - x = cot(x/2) and its sine, enclosed", {}, run_vartheta0};
}

}  // namespace dfchaos::certify
