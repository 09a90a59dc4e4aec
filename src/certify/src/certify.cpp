// SPDX-License-Identifier: GPL-3.0-or-later
#include "certify/certify.hpp"

#include "certify/statements.hpp"
#include "dfchaos/errors.hpp"

namespace dfchaos::certify {

void check_statement(const std::string& what) { statement(what); }

Result certify(const Request& r) {
  const Statement& s = statement(r.what);
  if (!r.word.empty() && !reads(s, Input::period))
    throw InvalidParameter("word", "only certify periodic takes an itinerary word (not " + r.what + ")");
  return s.run(r);
}

}  // namespace dfchaos::certify
