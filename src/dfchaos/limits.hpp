// SPDX-License-Identifier: GPL-3.0-or-later
/// @file limits.hpp
/// @brief Bounds on counts accepted by both front ends of the library, the `dfchaos` tool and the
/// Python module, defined once so that both refuse the same values with the same message.
#pragma once

namespace dfchaos {

/// Most steps of one orbit of \f$T\f$: `dfchaos orbit --steps N` and `dfchaos.orbit(p, theta0,
/// steps)` accept \f$1 \le N \le\f$ kMaxOrbitSteps (each step one evaluation of \f$T\f$, a few
/// minutes and 0.8 GB per output column at the bound).
inline constexpr long long kMaxOrbitSteps = 100'000'000;

/// Largest event limit of one simulation: `dfchaos simulate --max-events N` and
/// `dfchaos.simulate(..., max_events=N)` accept \f$1 \le N \le\f$ kMaxSimulationEvents
/// (SimulationOptions::max_events, simulator.hpp).
inline constexpr long long kMaxSimulationEvents = 100'000'000;

}  // namespace dfchaos
