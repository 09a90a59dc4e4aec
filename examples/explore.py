#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Explore the return map T of the dry-friction oscillator from Python (the dfchaos module).

Draws two panels into one PNG:
  left   T(theta) over [t2, t3) (Lemma 3), coloured by the scenario of Section 3, with the
         diagonal and the levels t2 and 3 pi/2 of Lemma 4 (a branch that climbs from t2 above
         3 pi/2 without a jump is a covering segment);
  right  an orbit diagram: for each b/a on a log scale, the iterates T^n(theta0) after a transient.

    make build        # or: cmake --build build --target dfchaos_python
    PYTHONPATH=build/python /usr/bin/python3 examples/explore.py --out build/python/explore.png

Runs with matplotlib's Agg backend (no display needed). Takes about a second.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
import numpy as np  # noqa: E402

import dfchaos  # noqa: E402

COLOURS = {"A": "tab:blue", "B": "tab:orange", "C": "tab:green", "D": "tab:red", "C'": "tab:purple",
           "D'": "tab:brown", "G": "black", "other": "tab:gray"}


def draw_T(ax, p, n):
    """T over the arc [t2, t3), one dot per phase, coloured by scenario."""
    theta = np.linspace(p.t2, p.t3, n, endpoint=False)
    s = dfchaos.step(p, theta)
    for name in dfchaos.scenario_names:
        mask = s["scenario"] == name
        if mask.any():
            ax.plot(theta[mask], s["T"][mask], ".", ms=1.5, mec="none", color=COLOURS[name],
                    label=f"{name} ({mask.sum()} phases)")
    ax.plot([p.t2, p.t3], [p.t2, p.t3], lw=0.6, color="0.5")
    for level, text in ((p.t2, "$t_2$"), (1.5 * np.pi, r"$3\pi/2$")):
        ax.axhline(level, lw=0.6, ls="--", color="0.4")
        ax.text(p.t3, level, " " + text, va="center", fontsize=8)
    ax.set_xlim(p.t2, p.t3)
    ax.set_ylim(p.t2 - 0.04 * (p.t3 - p.t2), p.t3)  # T = t2 (scenarios B, C) stays visible
    ax.set_xlabel(r"$\theta$")
    ax.set_ylabel(r"$T(\theta)$")
    ax.set_title(f"return map, b/a = {p.b / p.a:g}, q/a = {p.q / p.a:g}", fontsize=10)
    ax.legend(title="scenario", markerscale=5, fontsize=7, loc="upper right")


def draw_orbit_diagram(ax, q, ratios, transient, keep):
    """For each b/a: T^n(theta0), n = transient .. transient + keep - 1."""
    xs, ys, skipped = [], [], 0
    for ratio in ratios:
        p = dfchaos.Parameters(1.0, ratio, q)
        theta0 = p.t2 + 0.37 * (p.t3 - p.t2)
        try:
            tail = dfchaos.orbit(p, theta0, transient + keep)["theta"][transient:]
        except dfchaos.GaveUp:  # the motion never flies again (eternal stick-slip): nothing to draw
            skipped += 1
            continue
        xs.append(np.full(keep, ratio))
        ys.append(tail)
    ax.plot(np.concatenate(xs), np.concatenate(ys), ".", ms=1, mec="none", color="k", alpha=0.6)
    ax.set_xscale("log")
    ax.set_xlabel("b/a")
    ax.set_ylabel(r"$T^n(\theta_0)$, after %d steps" % transient)
    ax.set_title(f"orbit diagram, q/a = {q:g}" + (f" ({skipped} b/a gave up)" if skipped else ""), fontsize=10)
    return skipped


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default="explore.png", help="the PNG to write [explore.png]")
    ap.add_argument("--b", type=float, default=0.01, help="b/a of the left panel [0.01]")
    ap.add_argument("--q", type=float, default=0.85, help="q/a of both panels [0.85]")
    ap.add_argument("--phases", type=int, default=20000, help="phases of the left panel [20000]")
    args = ap.parse_args(argv)
    try:
        p = dfchaos.Parameters(1.0, args.b, args.q)
        p.require_return_map()
    except ValueError as e:
        print(f"explore.py: error: {e}", file=sys.stderr)
        return 2
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5), constrained_layout=True)
    draw_T(left, p, args.phases)
    draw_orbit_diagram(right, args.q, np.geomspace(1e-3, 0.2, 300), transient=300, keep=150)
    fig.savefig(args.out, dpi=130)
    print(f"explore.py: wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
