// SPDX-License-Identifier: GPL-3.0-or-later
/// @file budget.hpp
/// @brief A time and memory budget for a whole process: a command whose cost is not bounded by its
/// own counts (a proof at a tiny b/a can need minutes and gigabytes) either answers within it or
/// gives up with one line naming the budget that ran out, exit status 1.
///
/// - **Time**: a real-time timer; when it fires, the line `PROGRAM: gave up: the time budget of S s
///   ran out (--max-seconds raises it)` goes to stderr, the guarded temporaries are removed
///   (output.hpp) and the process exits with status 1 at once (what was already streamed to stdout
///   stays there).
/// - **Memory**: the address-space limit (RLIMIT_AS). A C++ allocation beyond it throws
///   std::bad_alloc, which the tool reports as `PROGRAM: gave up: the memory budget of G GiB ran out
///   (--max-memory raises it)` (memory_budget_line()); C libraries that cannot throw (Arb, FLINT,
///   GMP) call exit_for_memory_budget(). Not applied under AddressSanitizer, whose shadow memory is
///   address space (memory_budget_applies()).
#pragma once

#include <string>

namespace dfchaos::kit {

/// Default time budget of a one-point command, in seconds.
inline constexpr double kDefaultBudgetSeconds = 60;
/// Default memory budget of a one-point command, in GiB.
inline constexpr double kDefaultBudgetGiB = 2;
/// Largest time budget accepted, in seconds (about 11.6 days).
inline constexpr double kMaxBudgetSeconds = 1e6;
/// Smallest and largest memory budgets accepted, in GiB.
inline constexpr double kMinBudgetGiB = 0.25;
inline constexpr double kMaxBudgetGiB = 1e4;  ///< see kMinBudgetGiB

/// A budget for the whole process.
struct ProcessBudget {
  double seconds = kDefaultBudgetSeconds;  ///< wall-clock seconds, in (0, kMaxBudgetSeconds]
  double gib = kDefaultBudgetGiB;          ///< address space in GiB, in [kMinBudgetGiB, kMaxBudgetGiB]
};

/// Parses the texts of --max-seconds and --max-memory. @throws InvalidParameter naming the option.
ProcessBudget parse_budget(const std::string& seconds, const std::string& gib);

/// Applies `b` to this process (once; a second call replaces the timer and the limit). `program`
/// starts the give-up lines (e.g. "dfchaos"). A lower address-space limit already in force
/// (ulimit -v) is kept, and the give-up line names it instead.
void apply_process_budget(const std::string& program, const ProcessBudget& b);

/// Disarms the timer of the time budget (once the answer is computed: its printing is not cut).
void stop_time_budget();

/// Whether the memory part of a budget is enforced in this build (false under AddressSanitizer).
bool memory_budget_applies();

/// The give-up line for memory (without "PROGRAM: gave up: " and newline), or "" when no budget
/// was applied.
std::string memory_budget_line();

/// Prints the memory give-up line and exits with status 1 (async-signal-safe; for allocation
/// failures inside C libraries, which cannot throw).
[[noreturn]] void exit_for_memory_budget();

}  // namespace dfchaos::kit
