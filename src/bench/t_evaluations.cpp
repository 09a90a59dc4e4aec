// SPDX-License-Identifier: GPL-3.0-or-later
#include "t_evaluations.hpp"

#include <atomic>

#include "dfchaos/return_map.hpp"

namespace {
std::atomic<long long> g_evaluations{0};
}  // namespace

// The wrapped symbols, as the linker names them (see CMake: -Wl,--wrap=<mangled name>). They are
// C++ functions under their mangled names, so returning a class by value is what the caller
// expects; clang's warning about a C-linkage function returning a class does not apply.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wreturn-type-c-linkage"
#endif
extern "C" {
dfchaos::MapStep __real__ZN7dfchaos15return_map_stepERKNS_10ParametersEd(const dfchaos::Parameters& p, double theta);
double __real__ZN7dfchaos1TERKNS_10ParametersEd(const dfchaos::Parameters& p, double theta);

dfchaos::MapStep __wrap__ZN7dfchaos15return_map_stepERKNS_10ParametersEd(const dfchaos::Parameters& p, double theta) {
  g_evaluations.fetch_add(1, std::memory_order_relaxed);
  return __real__ZN7dfchaos15return_map_stepERKNS_10ParametersEd(p, theta);
}

double __wrap__ZN7dfchaos1TERKNS_10ParametersEd(const dfchaos::Parameters& p, double theta) {
  g_evaluations.fetch_add(1, std::memory_order_relaxed);
  return __real__ZN7dfchaos1TERKNS_10ParametersEd(p, theta);
}
}
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

namespace dfchaos {
long long T_evaluations() { return g_evaluations.load(std::memory_order_relaxed); }
}  // namespace dfchaos
