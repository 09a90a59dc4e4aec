// SPDX-License-Identifier: GPL-3.0-or-later
/// @file t_evaluations.hpp
/// @brief A count of the evaluations of the return map T, for measurements (`make bench`) and
/// their tests; the library itself is not touched.
///
/// Linking the target `dfchaos_t_evaluations` wraps, with the linker's `--wrap`, every call from
/// outside return_map.cpp to `dfchaos::return_map_step` and to `dfchaos::T` in the executable: each
/// such call counts one evaluation (T's own call of return_map_step, inside return_map.cpp, is not
/// wrapped, so an evaluation is never counted twice). Thread-safe (a relaxed atomic counter).
/// Should the signature of either function change, the wrap would no longer match and the count
/// would stay 0 — a test (`TEvaluations.CountsEveryEvaluation` in test_sweep) guards against it.
#pragma once

namespace dfchaos {

/// The number of evaluations of T counted so far by this process.
long long T_evaluations();

}  // namespace dfchaos
