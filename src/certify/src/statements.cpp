// SPDX-License-Identifier: GPL-3.0-or-later
#include "certify/statements.hpp"

#include <algorithm>

#include "dfchaos/errors.hpp"
#include "statements/request.hpp"

namespace dfchaos::certify {

const std::vector<Statement>& statements() {
  static const std::vector<Statement> all{vartheta0_statement(), lemma1_statement(),        b0_statement(),      discontinuities_statement(),
                                          covering_statement(),  periodic_statement(),      entropy_statement(), superstable_statement(),
                                          arc_l1_statement(),    lemma4_uniform_statement()};
  return all;
}

std::string statement_names(const std::string& last) {
  std::string s;
  const std::vector<Statement>& all = statements();
  for (std::size_t i = 0; i < all.size(); ++i) s += (i == 0 ? "" : i + 1 == all.size() ? last : ", ") + all[i].name;
  return s;
}

const Statement& statement(const std::string& name) {
  for (const Statement& s : statements())
    if (s.name == name) return s;
  throw InvalidParameter("what", "one of " + statement_names(", ") + " (got '" + name + "')");
}

bool reads(const Statement& s, Input input) { return std::find(s.inputs.begin(), s.inputs.end(), input) != s.inputs.end(); }

}  // namespace dfchaos::certify
