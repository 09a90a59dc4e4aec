// SPDX-License-Identifier: GPL-3.0-or-later
#include "statements.hpp"

namespace recheck {

const std::vector<Statement>& statements() {
  static const std::vector<Statement> table = {
      {"vartheta0", check_vartheta0},
      {"lemma1", check_lemma1},
      {"b0", check_b0},
      {"covering", check_covering},
      {"coverings", check_coverings},
      {"periodic", check_periodic},
      {"superstable", check_superstable},
      {"not_superstable", check_not_superstable},
      {"window", check_window},
      {"theorem2_counterexample", check_theorem2_counterexample},
      {"discontinuities", check_discontinuities},
      {"paper_construction", check_paper_construction},
      {"entropy", check_entropy},
      {"arc-l1", check_arc_l1},
      {"lemma4-uniform", check_lemma4_uniform},
  };
  return table;
}

std::string statement_names() {
  std::string s;
  for (const Statement& t : statements()) s += (s.empty() ? "" : ", ") + std::string(t.name);
  return s;
}

}  // namespace recheck
