// SPDX-License-Identifier: GPL-3.0-or-later
/// @file periodic.cpp
/// @brief `certify periodic`: Sections 6-7, a periodic point of a given minimal period or
/// itinerary, at a point.

#include <string>

#include "certify/certificate.hpp"
#include "certify/json.hpp"
#include "dfchaos/certified/covering.hpp"
#include "dfchaos/certified/periodic.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/symbolic.hpp"
#include "request.hpp"

namespace dfchaos::certify {

namespace {

using namespace certified;

Result run_periodic(const Request& r) {
  const ParameterBox box = request::box_from(r, true, false);
  if (!r.word.empty() && r.period != 0) throw InvalidParameter("word", "give the period M or the word W, not both");
  if (r.word.empty() && (r.period < 1 || r.period > 64)) throw InvalidParameter("period", "an integer 1 <= m <= 64 (or give a word)", r.period);
  if (!r.word.empty()) require_itinerary_word("word", r.word, 64);
  const CoveringProof c = prove_covering(box);
  PeriodicOptions opt;
  opt.record = r.certificate;
  const PeriodicProof p = r.word.empty() ? prove_periodic(c, r.period, opt) : prove_periodic(c, r.word, opt);
  return request::result(r, p.verdict.proved, to_json(c, p), [&](const std::string& claim) { return certificate_periodic(c, {p}, claim); });
}

}  // namespace

Statement periodic_statement() {
  return {"periodic", "Sections 6-7: a periodic point of minimal period M, at a point", {Input::a, Input::b, Input::q, Input::period}, run_periodic};
}

}  // namespace dfchaos::certify
