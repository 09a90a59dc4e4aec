#include "t_evaluations.hpp"

#include <atomic>

#include "dfchaos/return_map.hpp"

namespace {
std::atomic<long long> g_evaluations{0};
}  // namespace

// The wrapped symbols, as the linker names them (see CMake: -Wl,--wrap=<mangled name>).
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

namespace dfchaos {
long long T_evaluations() { return g_evaluations.load(std::memory_order_relaxed); }
}  // namespace dfchaos
