// SPDX-License-Identifier: GPL-3.0-or-later
/// @file request.hpp
/// @brief The checks every statement applies to its request (certify.hpp): the ranges of a, b and
/// q, and the declarations of the statements of the registry (statements.hpp), one file each.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include "certify/certify.hpp"
#include "certify/statements.hpp"
#include "dfchaos/certified/parameters.hpp"

namespace dfchaos::certify::request {

/// The record's "statement" (every record has one): the claim a certificate repeats.
std::string claim_of(const Result& c);

/// x itself, after checking |x| <= kMaxParameter (which also refuses NaN). @throws InvalidParameter naming `name`.
double bounded(const std::string& name, double x);

/// r itself, after checking both ends (bounded) and lo <= hi.
Range bounded(const std::string& name, const Range& r);

/// a, checked bounded and positive.
double amplitude(const Request& r);

/// The parameter box of a request, its ranges checked in the order a, b, q (the first bad one is
/// named; the tool has parsed the syntax of every option before). Without `need_q`, q is set to
/// a/2 + 2b_hi (unused). Without `allow_box`, b and q must be single values.
certified::ParameterBox box_from(const Request& r, bool need_q, bool allow_box);

/// The result of a proof: `record` (its "statement" is the claim), and when the request asks for a
/// certificate and the proof succeeded, `write(claim)`. A writer that finds the proof cannot be
/// written (std::logic_error: a witness that is not exact) leaves the certificate null and says
/// why in Result::no_certificate.
template <class Write>
Result result(const Request& r, bool proved, kit::Json record, Write&& write) {
  Result c{proved, std::move(record)};
  if (!c.proved || !r.certificate) return c;
  try {
    c.certificate = write(claim_of(c));
  } catch (const std::logic_error& e) {
    c.no_certificate = e.what();
  }
  return c;
}

/// The box of q/a of a statement for every b/a up to a bound: q checked (0 < q_lo, q_hi <= a),
/// the ratios enclosed outward (lower end rounded down, upper end up).
std::pair<double, double> ratio_box(const Request& r);

}  // namespace dfchaos::certify::request

namespace dfchaos::certify {

/// The registry's entries (statements.cpp lists them in the order of the help).
Statement vartheta0_statement();
Statement lemma1_statement();
Statement b0_statement();
Statement discontinuities_statement();
Statement covering_statement();
Statement periodic_statement();
Statement entropy_statement();
Statement superstable_statement();
Statement arc_l1_statement();
Statement lemma4_uniform_statement();

}  // namespace dfchaos::certify
