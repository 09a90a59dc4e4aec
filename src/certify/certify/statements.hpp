// SPDX-License-Identifier: GPL-3.0-or-later
/// @file statements.hpp
/// @brief The registry of the statements `dfchaos certify` proves: one entry per statement, with
/// its name, what it proves, the inputs it reads and the function that proves it.
///
/// Every list of statements is generated from this one: the subcommands of `dfchaos certify`,
/// their options and help, the names `dfchaos.certify` accepts and its docstring, and the messages
/// that name the statements. Each entry lives in its own file, `certify/src/statements/<name>.cpp`
/// (the request checked, the prover called, the record and the certificate built); adding a
/// statement is adding such a file and one line to the table in `statements.cpp`.
#pragma once

#include <string>
#include <vector>

#include "certify/certify.hpp"

namespace dfchaos::certify {

/// An input of a statement, as an option of `dfchaos certify` and a keyword of `dfchaos.certify`.
enum class Input {
  a,         ///< -a: the forcing amplitude (default 1)
  b,         ///< -b: one value of b
  b_box,     ///< -b: one value, or a box LO:HI
  q,         ///< -q: one value of q
  q_box,     ///< -q: one value, or a box LO:HI
  q_ratio,   ///< -q: a box of q, the proof being about q/a for every b/a up to a bound
  segment,   ///< --segment L0|L2
  period,    ///< --period M or --word W (the itinerary of a periodic orbit)
  window,    ///< --window LO:HI (a window in b)
  segments,  ///< --J0 TOP:T2 --J1 TOP:T2 (the covering segments, instead of a search)
};

/// One statement of `dfchaos certify`.
struct Statement {
  std::string name;                         ///< the subcommand, e.g. "lemma4-uniform" (also the certificate's "statement")
  std::string summary;                      ///< what it proves, one sentence citing the paper
  std::vector<Input> inputs;                ///< the inputs it reads, in the order they are checked
  Result (*run)(const Request&) = nullptr;  ///< checks the request and runs the proof (certify.hpp)
};

/// Every statement, in the order of the help.
const std::vector<Statement>& statements();

/// The statement named `name`. @throws InvalidParameter naming "what" (and listing the
/// statements) when there is none.
const Statement& statement(const std::string& name);

/// Whether the statement `name` reads `input`.
bool reads(const Statement& s, Input input);

/// The names of the statements, separated by ", " and the last by `last` (e.g. " or ").
std::string statement_names(const std::string& last);

}  // namespace dfchaos::certify
