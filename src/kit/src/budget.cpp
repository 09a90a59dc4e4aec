// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/budget.hpp"

#include <sys/resource.h>
#include <sys/time.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>

#include "dfchaos/errors.hpp"
#include "kit/options.hpp"
#include "kit/output.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define DFCHAOS_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DFCHAOS_ASAN 1
#endif
#endif

namespace dfchaos::kit {

namespace {
// The give-up lines, prepared before they may be needed (a signal handler cannot format).
char g_time_line[256];
char g_memory_line[256];
std::size_t g_time_length = 0, g_memory_length = 0;
std::string g_memory_text;

extern "C" void on_time_budget(int) {
  if (g_time_length > 0) {
    const ssize_t w = ::write(STDERR_FILENO, g_time_line, g_time_length);
    (void)w;
  }
  remove_guarded_temporaries();
  ::_exit(1);
}

std::string shortest(double x) { return dfchaos::format_shortest(x); }
}  // namespace

ProcessBudget parse_budget(const std::string& seconds, const std::string& gib) {
  ProcessBudget b;
  b.seconds = parse_number("max-seconds", seconds, false);
  if (!(b.seconds > 0 && b.seconds <= kMaxBudgetSeconds))
    throw InvalidParameter("max-seconds", "0 < max-seconds <= " + shortest(kMaxBudgetSeconds), b.seconds);
  b.gib = parse_number("max-memory", gib, false);
  if (!(b.gib >= kMinBudgetGiB && b.gib <= kMaxBudgetGiB))
    throw InvalidParameter("max-memory", shortest(kMinBudgetGiB) + " <= max-memory <= " + shortest(kMaxBudgetGiB) + " (GiB)", b.gib);
  return b;
}

bool memory_budget_applies() {
#ifdef DFCHAOS_ASAN
  return false;
#else
  return true;
#endif
}

void apply_process_budget(const std::string& program, const ProcessBudget& b) {
  const std::string t = program + ": gave up: the time budget of " + shortest(b.seconds) + " s ran out (--max-seconds raises it)\n";
  g_time_length = std::min(t.size(), sizeof g_time_line);
  std::memcpy(g_time_line, t.data(), g_time_length);

  struct sigaction sa {};
  sa.sa_handler = on_time_budget;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGALRM, &sa, nullptr);
  itimerval timer{};
  timer.it_value.tv_sec = static_cast<time_t>(b.seconds);
  timer.it_value.tv_usec = static_cast<suseconds_t>((b.seconds - std::floor(b.seconds)) * 1e6);
  if (timer.it_value.tv_sec == 0 && timer.it_value.tv_usec == 0) timer.it_value.tv_usec = 1;
  ::setitimer(ITIMER_REAL, &timer, nullptr);

  // The memory budget, unless a lower limit is already in force (ulimit -v): that one stays, and
  // the give-up line names it.
  g_memory_text = "the memory budget of " + shortest(b.gib) + " GiB ran out (--max-memory raises it)";
  rlimit lim{};
  if (::getrlimit(RLIMIT_AS, &lim) == 0) {
    const rlim_t want = static_cast<rlim_t>(b.gib * 1073741824.0);
    if (lim.rlim_cur != RLIM_INFINITY && lim.rlim_cur < want) {
      g_memory_text =
          "the address-space limit of " + shortest(static_cast<double>(lim.rlim_cur) / 1073741824.0) + " GiB set outside dfchaos (ulimit -v) ran out";
    } else if (memory_budget_applies()) {
      lim.rlim_cur = want;
      ::setrlimit(RLIMIT_AS, &lim);
    }
  }
  const std::string m = program + ": gave up: " + g_memory_text + "\n";
  g_memory_length = std::min(m.size(), sizeof g_memory_line);
  std::memcpy(g_memory_line, m.data(), g_memory_length);
}

void stop_time_budget() {
  itimerval off{};
  ::setitimer(ITIMER_REAL, &off, nullptr);
}

std::string memory_budget_line() { return g_memory_text; }

void exit_for_memory_budget() {
  static const char kFallback[] = "gave up: out of memory\n";
  const ssize_t w =
      g_memory_length > 0 ? ::write(STDERR_FILENO, g_memory_line, g_memory_length) : ::write(STDERR_FILENO, kFallback, sizeof kFallback - 1);
  (void)w;
  remove_guarded_temporaries();
  ::_exit(1);
}

}  // namespace dfchaos::kit
