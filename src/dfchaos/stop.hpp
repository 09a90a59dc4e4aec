// SPDX-License-Identifier: GPL-3.0-or-later
/// @file stop.hpp
/// @brief A cooperative stop: a caller in another thread asks a long computation to end, and the
/// computation ends at its next poll with the exception Stopped.
///
/// The long loops of the library poll (poll_stop()): every step of an orbit (Orbit), every
/// branch or cut of the floating covering search, every box of a certified subdivision, every first
/// contact isolated in ball arithmetic, every cell of a sweep. A poll is a load of a thread-local
/// pointer and, when a token is installed, of one atomic flag; with no token it never throws, so
/// the command-line tool, which stops by signals and process budgets (kit/budget.hpp), is not
/// affected. The Python module installs a token around each long call (python/convert.hpp) and sets
/// it on Ctrl-C or when the call's budget runs out.
///
/// A token reaches only the threads it is installed in (StopScope): code that starts threads of its
/// own installs the caller's token in each (sweep::compute_cells does, for its OpenMP threads).
/// The result of a computation stopped this way is never used: Stopped may be caught and recorded
/// on the way out (a sweep cell records it as an error), so the caller that set the token discards
/// whatever comes back.
#pragma once

#include <atomic>
#include <stdexcept>

namespace dfchaos {

/// A stop was requested through the token of the calling thread. Not bad input (InvalidParameter)
/// and not a bound of the computation (GaveUp): the caller asked for it.
class Stopped : public std::runtime_error {
 public:
  Stopped() : std::runtime_error("stopped on request") {}
};

/// A request to stop, shared by the caller and the threads of one computation.
class StopToken {
 public:
  /// Asks every thread that has this token installed to stop at its next poll (thread-safe).
  void request() noexcept { requested_.store(true, std::memory_order_relaxed); }
  /// Whether request() was called.
  bool requested() const noexcept { return requested_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> requested_{false};
};

namespace detail {
/// The token installed in this thread (nullptr: none).
inline thread_local const StopToken* t_stop_token = nullptr;
}  // namespace detail

/// Installs a token in the calling thread for the scope's lifetime (nullptr installs none); the
/// previous one comes back at the end.
class StopScope {
 public:
  /// Installs `token` (nullptr: none) in the calling thread until the scope ends.
  explicit StopScope(const StopToken* token) noexcept : previous_(detail::t_stop_token) { detail::t_stop_token = token; }
  ~StopScope() { detail::t_stop_token = previous_; }
  StopScope(const StopScope&) = delete;
  StopScope& operator=(const StopScope&) = delete;

 private:
  const StopToken* previous_;
};

/// The token installed in the calling thread, or nullptr.
inline const StopToken* current_stop_token() noexcept { return detail::t_stop_token; }

/// Whether a stop has been requested through the calling thread's token.
inline bool stop_requested() noexcept { return detail::t_stop_token != nullptr && detail::t_stop_token->requested(); }

/// @throws Stopped if a stop has been requested through the calling thread's token.
inline void poll_stop() {
  if (stop_requested()) throw Stopped();
}

}  // namespace dfchaos
