# SPDX-License-Identifier: GPL-3.0-or-later
"""A tour of the dfchaos module: from parameters to a certified covering and a sweep, in cells.

Each cell (a '# %%' line: VS Code, Spyder and jupytext run them one by one) states in a comment
what it computes and where the paper (Begun and Kryzhevich, arXiv:1302.3377) has it, then does it
in a few lines. Run as a whole it prints what each cell found and writes five PNGs into --out:
  tour_T.png          the return map T over [t2, t3), coloured by scenario
  tour_orbits.png     an orbit (bifurcation) diagram over b/a
  tour_lyapunov.png   the Lyapunov exponent of T against b/a
  tour_covering.png   the covering segments J0, J1 proved in ball arithmetic at one point
  tour_sweep.png      a 20 x 20 sweep of the (q/a, b/a) plane: covering (sampled and proved) and lambda

    make build        # or: cmake --build build --target dfchaos_python
    PYTHONPATH=build/python /usr/bin/python3 examples/tour.py --out build/tour

About 7 s of one core (most of it the sweep's proofs); matplotlib's Agg backend, no display needed.
"""
# %% Setup. Run as a script, the options come from the command line; run cell by cell in an
# editor's interactive window, the defaults are used.
import argparse
import os
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap, TwoSlopeNorm  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import dfchaos  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
ap.add_argument("--out", default="tour", help="directory for the PNGs, created if missing [tour]")
ap.add_argument("--b", type=float, default=0.005, help="b/a of the single-point cells [0.005]")
ap.add_argument("--q", type=float, default=0.85, help="q/a of every cell but the sweep [0.85]")
args = ap.parse_args([] if hasattr(sys, "ps1") or "ipykernel" in sys.modules else None)
out = Path(args.out)
try:
    if not args.out:
        raise OSError("an empty path")
    if out.exists() and not out.is_dir():
        raise OSError("exists and is not a directory")
    out.mkdir(parents=True, exist_ok=True)
    if not os.access(out, os.W_OK | os.X_OK):
        raise OSError("not writable")
except OSError as e:
    print(f"tour.py: error: --out '{args.out}': cannot write PNGs there: {e.strerror or e}", file=sys.stderr)
    sys.exit(2)


def save(fig, name):
    """One PNG of a fixed pixel size (figsize x 100 dpi; the tests check it)."""
    fig.savefig(out / name, dpi=100)
    plt.close(fig)
    print(f"  wrote {out / name}")


# %% Parameters. The oscillator of Section 2: free flight x'' = a sin t + 2b (Eq. 3), progression
# with the delimiter x'' = a sin t + 2b - q (Eq. 4), stop (Eq. 5). Only b/a and q/a matter. The
# switching phases t0..t3 are the zeros of F - q and of F; the paper's standing assumption is Eq. 2,
# a sin(vartheta0) < q < a with vartheta0 from Eq. 1. Lemma 1 needs b below some b0(q): certify "b0"
# gives a lower bound of it, proved in ball arithmetic.
try:
    p = dfchaos.Parameters(1.0, args.b, args.q)
    p.require_return_map()
except ValueError as e:
    print(f"tour.py: error: {e}", file=sys.stderr)
    sys.exit(2)
print(p, "|", p.assumptions["describe"])
print(f"  t0 = {p.t0:.6f}  t1 = {p.t1:.6f}  t2 = {p.t2:.6f}  t3 = {p.t3:.6f}"
      f"  vartheta0 = {dfchaos.vartheta0:.6f}")
b0 = dfchaos.certify("b0", q=args.q)
print(f"  Lemma 1 holds for b/a up to {b0['b0_lower_bound']:.6g} (proved: {b0.proved})")

# %% The return map T over [t2, t3) (Lemma 3): the phase at which the mass, left at rest at the
# delimiter at phase theta (Eq. 10), next starts a free flight. step() also says which scenario of
# Section 3 happened: A, the progression after the impact ends inside [t2, t3) and the flight goes
# on; B and C, the mass comes to a stop and leaves at t2, so T = t2; G (ours), a grazing touch.
theta = np.linspace(p.t2, p.t3, 20000, endpoint=False)
s = dfchaos.step(p, theta)
fig, ax = plt.subplots(figsize=(7, 4.5), layout="constrained")
for name in dfchaos.scenario_names:
    m = s["scenario"] == name
    if m.any():
        ax.plot(theta[m], s["T"][m], ".", ms=1.5, mec="none", label=f"{name}: {m.sum()} phases")
ax.axhline(1.5 * np.pi, lw=0.8, ls="--", color="0.6", label=r"$3\pi/2$")
ax.set(xlabel=r"phase $\theta$ (rad)", ylabel=r"$T(\theta)$ (rad)", xlim=(p.t2, p.t3),
       title=f"return map T (Lemma 3), b/a = {p.b / p.a:g}, q/a = {p.q / p.a:g}")
ax.legend(title="scenario (Section 3)", markerscale=6, fontsize=8, loc="upper right")
print(f"  scenarios: { {n: int((s['scenario'] == n).sum()) for n in dfchaos.scenario_names} }")
save(fig, "tour_T.png")

# %% An orbit (bifurcation) diagram over b/a: the iterates T^n(theta0) after a transient, for each
# b/a at this q/a. Theorem 1 gives chaos for small b/a only. At the default q/a the orbit settles,
# for larger b/a, on an attracting fixed point, then on cycles through a stop (superstable, as
# the fixed point t2 of Section 8), and near b/a = 0.4 the mass never leaves the delimiter again
# (dfchaos.GaveUp: nothing to draw).
ratios = np.geomspace(1e-3, 0.42, 400)
xs, ys = [], []
for r in ratios:
    pr = dfchaos.Parameters(1.0, r, args.q)
    try:
        tail = dfchaos.orbit(pr, (pr.t2 + pr.t3) / 2, 500)["theta"][300:]
    except dfchaos.GaveUp:  # the motion never flies again (eternal stick-slip): nothing to draw
        continue
    xs.append(np.full(tail.size, r))
    ys.append(tail)
fig, ax = plt.subplots(figsize=(7, 4.5), layout="constrained")
ax.plot(np.concatenate(xs), np.concatenate(ys), ",", color="k", alpha=0.5)
ax.axvline(p.b / p.a, lw=0.8, color="tab:red", label=f"b/a = {p.b / p.a:g} (the other cells)")
ax.set(xscale="log", xlabel="b/a", ylabel=r"$T^n(\theta_0)$ (rad), n = 300..499",
       title=f"orbit diagram of T, q/a = {args.q:g}, " + r"$\theta_0$ the middle of $[t_2, t_3)$")
ax.legend(loc="lower left", fontsize=8)
save(fig, "tour_orbits.png")

# %% The Lyapunov exponent lambda of T along the same orbits: the mean of ln|T'| (T' by the implicit
# function theorem on Eqs. 11 and 17). The paper proves chaos topologically (Theorem 1) and has no
# lambda; lambda > 0 is the usual numerical sign of chaos. A step through a stop has T' = 0, so
# lambda = -inf: the orbit is caught by a superstable cycle, as t2 is in Section 8 (Theorem 2).
def lyapunov(r):
    try:
        return dfchaos.lyapunov(dfchaos.Parameters(1.0, r, args.q), steps=2000, transient=500)
    except dfchaos.GaveUp:
        return np.nan


lam = np.array([lyapunov(r) for r in ratios])
fig, ax = plt.subplots(figsize=(7, 4.5), layout="constrained")
finite = np.where(np.isfinite(lam), lam, np.nan)
ax.plot(ratios, finite, ".-", ms=2, lw=1, color="tab:blue", label=r"$\lambda$, 2000 steps after 500")
ax.fill_between(ratios, finite, 0, where=finite > 0, color="tab:red", alpha=0.3, label=r"$\lambda > 0$")
bottom = np.nanmin(finite) - 0.5
ax.plot(ratios[np.isneginf(lam)], np.full(np.isneginf(lam).sum(), bottom), "v", color="tab:red",
        label=r"$\lambda = -\infty$ (a stop: superstable)")
ax.axhline(0, lw=0.8, color="0.6")
ax.axvline(p.b / p.a, lw=0.8, color="tab:red", ls=":", label=f"b/a = {p.b / p.a:g} (the other cells)")
ax.set(xscale="log", xlabel="b/a", ylabel=r"Lyapunov exponent $\lambda$ (per step of T)",
       title=f"Lyapunov exponent of T, q/a = {args.q:g}")
ax.legend(fontsize=8)
print(f"  lambda > 0 for {np.sum(lam > 0)} of {lam.size} values of b/a, -inf for {np.isneginf(lam).sum()}")
save(fig, "tour_lyapunov.png")

# %% A certified covering at one point: Lemma 4 (Eq. 18) and the covering of Theorem 1, proved in
# ball arithmetic. J0 and J1 are disjoint segments of [t2, 3 pi/2] on which T is continuous and
# reaches both t2 and 3 pi/2, so that T(Ji) contains [t2, 3 pi/2], which contains J0 and J1: the
# horseshoe from which Theorem 1 gets periodic points of every period and symbolic dynamics (Eq. 20).
c = dfchaos.certify("covering", b=p.b, q=p.q)
print(f"  proved: {c.proved}\n  statement: {c.statement}\n  J0 = {c.J0}\n  J1 = {c.J1}")
if not c.proved:
    print(f"  not proved: {c.failed_step}: {c.detail}")
theta = np.linspace(p.t2, 1.5 * np.pi, 20000)
fig, ax = plt.subplots(figsize=(7, 4.5), layout="constrained")
ax.plot(theta, dfchaos.T(p, theta), ".", ms=1.5, mec="none", color="k", label=r"$T(\theta)$")
for name, J, colour in (("J0", c.J0, "tab:orange"), ("J1", c.J1, "tab:green")):
    if J is not None:
        ax.axvspan(J.lo, J.hi, color=colour, alpha=0.35, label=f"{name} = [{J.lo:.4f}, {J.hi:.4f}]")
for level, text in ((p.t2, "$t_2$"), (1.5 * np.pi, r"$3\pi/2$")):
    ax.axhline(level, lw=0.8, ls="--", color="0.6")
    ax.text(1.5 * np.pi, level, " " + text, va="center", fontsize=9)
ax.set(xlim=(p.t2, 1.5 * np.pi), xlabel=r"phase $\theta$ (rad)", ylabel=r"$T(\theta)$ (rad)",
       title=f"Lemma 4 at b/a = {p.b / p.a:g}, q/a = {p.q / p.a:g}: "
       + ("proved in ball arithmetic" if c.proved else "not proved"))
ax.legend(loc="upper right", fontsize=8, markerscale=6)
save(fig, "tour_covering.png")

# %% A small sweep of the (q/a, b/a) plane, as `dfchaos sweep` computes it: for each cell, whether
# Lemma 4's covering is found on a grid (sampled, "covering"), whether it is proved ("certified",
# the previous cell's proof) and lambda. q/a spans Eq. 2's range (sin(vartheta0), 1); Theorem 1
# speaks of small b/a.
cols, prov = dfchaos.sweep((0.73, 0.99, 20), (1e-3, 0.2, 20, "log"),
                           observables="covering,lyapunov,certified")
Q, B = cols["q_over_a"].reshape(20, 20), cols["b_over_a"].reshape(20, 20)  # index = i * n_b + j
kind = (cols["covering"] + 2 * cols["certified"]).reshape(20, 20)  # 0 none, 1 sampled, 2 proved, 3 both
lam = cols["lyapunov"].reshape(20, 20)
print(f"  {dict(zip(*np.unique(cols['status'], return_counts=True)))} cells; covering found in"
      f" {int(np.nansum(cols['covering']))}, proved in {int(np.nansum(cols['certified']))},"
      f" lambda > 0 in {np.sum(lam > 0)}, -inf in {np.sum(np.isneginf(lam))}")


def edges(x, log):
    """Cell edges around the centres x (geometric midpoints on a log axis)."""
    y = np.log(x) if log else x
    e = np.concatenate(([1.5 * y[0] - 0.5 * y[1]], (y[1:] + y[:-1]) / 2, [1.5 * y[-1] - 0.5 * y[-2]]))
    return np.exp(e) if log else e


qe, be = edges(Q[:, 0], False), edges(B[0], True)
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5), layout="constrained")
colours = ["0.85", "tab:olive", "tab:purple", "tab:green"]
left.pcolormesh(qe, be, kind.T, cmap=ListedColormap(colours), vmin=-0.5, vmax=3.5)
left.legend(handles=[Patch(color=k, label=t) for k, t in zip(colours, (
    "no covering", "found on a grid only", "proved only", "found and proved"))], fontsize=8, loc="lower left")
cmap = plt.get_cmap("RdBu_r").copy()
cmap.set_under("black")
cmap.set_bad("0.7")
shown = np.ma.masked_invalid(np.where(np.isneginf(lam), -99.0, lam))  # -inf: below vmin, the under colour
mesh = right.pcolormesh(qe, be, shown.T, cmap=cmap,
                        norm=TwoSlopeNorm(0, vmin=np.nanmin(lam[np.isfinite(lam)]), vmax=np.nanmax(lam)))
fig.colorbar(mesh, ax=right, extend="min", label=r"Lyapunov exponent $\lambda$ (black: $-\infty$)")
for ax, title in ((left, "Lemma 4's covering J0, J1"), (right, r"Lyapunov exponent $\lambda$ of T")):
    ax.plot(p.q / p.a, p.b / p.a, "*", ms=12, mfc="yellow", mec="k")  # the point of the cells above
    ax.set(yscale="log", xlabel="q/a", ylabel="b/a", title=title + ", 20 x 20 sweep")
save(fig, "tour_sweep.png")
