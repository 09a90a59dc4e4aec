// SPDX-License-Identifier: GPL-3.0-or-later
/// @file outcome.hpp
/// @brief Three-valued answers of the certified routines (proved, refuted, not proved) and bounded
/// work, in the spirit of Arb's `arb_calc`.
///
/// (Not to be confused with the verdict of a claim, kit/claim.hpp: an experiment turns Outcomes
/// into claims of kind `certified`.)
///
/// A certified routine answers **proved** (every inequality it needed was shown in ball arithmetic
/// over the whole set the statement is about) or **not proved**, naming the step that could not be
/// shown. "Not proved" is an answer, not an error, and never means "false": the statement may
/// still hold. When the computation happened to show the statement *false* (for example a root of
/// \f$G_1\f$ certainly before the supposed first root), `refuted` says so.
#pragma once

#include <string>

#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

/// The answer of a certified routine: proved, or not proved naming the step (refuted when the step
/// was shown false).
struct Outcome {
  bool proved = false;   ///< every step was proved
  bool refuted = false;  ///< (when not proved) the computation showed a step false, not merely undecided
  std::string step;      ///< (when not proved) the step that failed, e.g. "T1: no earlier root"
  std::string detail;    ///< (when not proved) where and why, with numbers

  /// A proved outcome.
  static Outcome ok() { return Outcome{true, false, "", ""}; }
  /// A step that could not be shown.
  static Outcome fail(std::string step, std::string detail) { return Outcome{false, false, std::move(step), std::move(detail)}; }
  /// A step shown false.
  static Outcome refute(std::string step, std::string detail) { return Outcome{false, true, std::move(step), std::move(detail)}; }
  explicit operator bool() const { return proved; }  ///< proved
  /// "proved", or "not proved: STEP (DETAIL)" ("refuted: ..." for a step shown false).
  std::string describe() const {
    if (proved) return "proved";
    std::string s = refuted ? "refuted: " : "not proved: ";
    s += step;
    if (!detail.empty()) s += " (" + detail + ")";
    return s;
  }
};

/// A bound on the work of one proof (counted in interval tests), shared by its sub-steps. Every
/// adaptive loop of the certified layer consumes it and gives up ("not proved: budget") when it is
/// spent, so that nothing runs unbounded.
struct Budget {
  long max_tests = 2'000'000;  ///< interval tests allowed in total
  long used = 0;               ///< interval tests done so far
  /// Consumes n tests; false when the budget is exceeded. @throws Stopped when a stop was requested
  /// (stop.hpp): every test spent is a poll.
  bool spend(long n = 1) {
    poll_stop();
    used += n;
    return used <= max_tests;
  }
  bool exhausted() const { return used > max_tests; }  ///< the budget is spent
};

}  // namespace dfchaos::certified
