// SPDX-License-Identifier: GPL-3.0-or-later
// Uses the installed library as a downstream project would: T at one phase, printed with 17 digits.
#include <cstdio>

#include <dfchaos/return_map.hpp>

int main() {
  const dfchaos::Parameters p(1.0, 0.01, 0.85);
  std::printf("%.17g\n", dfchaos::T(p, 4.0));
  return 0;
}
