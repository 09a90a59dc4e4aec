# SPDX-License-Identifier: GPL-3.0-or-later
"""Timing tier: 10^6 phases through dfchaos.T against the bare C++ loop over the same phases
(dfchaos._bench_T: T(p, theta[i]) in C++, no conversion, no result array). The ratio is printed
(CTest runs this tier with -s, so it is in the test log), not asserted: the target is
at most 1.5, but timings on a shared machine vary.

One parameter set (b/a = 1e-2, q/a = 0.85; the cost of T hardly depends on b/a), best of two
interleaved passes of each: about 10 s here (2.3 us per evaluation).
DFCHAOS_TIMING_PHASES overrides the number of phases (default 10^6).
"""
import os
import time

import numpy as np
import pytest

import dfchaos

pytestmark = pytest.mark.timing

N = int(os.environ.get("DFCHAOS_TIMING_PHASES", "1000000"))
GOLDEN = 0.6180339887498949


def test_vectorized_T_against_the_cpp_loop():
    lines = []
    for ratio in (1e-2,):
        p = dfchaos.Parameters(1.0, ratio, 0.85)
        # The bench's phases (src/bench/bench_return_map.cpp): an irrational stride over [t2, t3).
        theta = p.t2 + (p.t3 - p.t2) * np.mod(0.5 + np.arange(N) * GOLDEN, 1.0)
        py_best = cpp_best = float("inf")
        for _ in range(2):  # best of two passes each, interleaved
            start = time.perf_counter()
            values = dfchaos.T(p, theta)
            py_best = min(py_best, time.perf_counter() - start)
            cpp_best = min(cpp_best, dfchaos._bench_T(p, theta))
        assert values.shape == (N,) and np.all((values >= p.t2) & (values < p.t3))
        lines.append(f"b/a={ratio:g}: {N} phases, dfchaos.T {py_best:.3f} s ({py_best / N * 1e9:.0f} ns each), "
                     f"C++ loop {cpp_best:.3f} s ({cpp_best / N * 1e9:.0f} ns each), ratio {py_best / cpp_best:.3f} "
                     f"(target <= 1.5)")
    print("\ntiming: " + "\ntiming: ".join(lines))
