#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The paper, item by item: what each numbered item of Begun & Kryzhevich says (in a few of our
words), which claims bear on it, and the verdict about the paper that those claims support.

Used by scripts/claims_map.py for the report's opening table ("The paper at a glance"). A claim is
assigned to an item by its reference (the paper item it names, e.g. "Lemma 4, Theorem 1"), or by
ASSIGN when its reference is not enough; only claims whose origin is the paper or an erratum decide
the verdict. Our own hypotheses and findings never do (a failing hypothesis of ours is not a failure
of the paper), except the claims an item names in `threshold`, which make an explicit threshold of
a "b/a sufficiently small" in the paper.

Verdict about the paper (paper_verdict), the first rule that applies:
  - refuted (erratum): an erratum of the item holds, or a claim of the paper fails;
  - inconclusive (precision): no claim of the paper holds and some is inconclusive (or an erratum,
    its only evidence, is inconclusive);
  - confirmed as corrected: the claims of the paper hold, and so do the claims an item names in
    `corrections`, which check the statement as corrected in the report's errata list (a misprint,
    or a hypothesis the statement leaves out);
  - confirmed with an explicit threshold: the claims of the paper hold, and so do the claims an item
    names in `threshold`, which bound "b/a sufficiently small" explicitly;
  - consistent, sampled: the claims of the paper hold, and every one that holds is sampled (a grid, a
    few parameter sets, one perturbation): nothing between the samples is known, so the word is
    weaker than "confirmed";
  - confirmed: the claims of the paper hold (an inconclusive one aside, when another holds), and at
    least one of them is certified or analytic;
  - not checked: no claim of the paper, and no erratum that holds or is inconclusive, bears on it.
An erratum that fails refutes nothing and confirms nothing.
"""
import re

# The verdicts about the paper, in the order the report counts them.
VERDICTS = ["confirmed", "consistent", "corrected", "threshold", "refuted", "inconclusive", "not checked"]

# Evidence, strongest first (kit/claim.hpp).
STRENGTH = ["certified", "certified+argument", "analytic", "sampled", "precision-limited"]

# One row per item of the paper, in reading order. `home`: the label of the report's section that
# treats it; `match`: a regular expression on a claim's reference; `says`: the item in a few of our
# words (LaTeX); `threshold`, `corrections`: see the module's docstring.
ITEMS = [
    dict(key="eq1", home="sec:model", item="Eq.~(1)", match=r"^Eq\. \(1\)",
         says=r"$\pi-\vartheta_0=\cot(\vartheta_0/2)$ has one root in $[0,\pi/2]$, $\vartheta_0\approx0.81047$"),
    dict(key="sec2", home="sec:model", item="Sec.~2, Eqs.~(2)--(7)", match=r"Eqs?\. \((2|3)\)|Section 2",
         says=r"the model: forcing $a\sin t+2b$, friction $q$; phases $t_0<t_1$, $t_2<t_3$; free, progression, stop"),
    dict(key="sec3", home="sec:reduction", item="Sec.~3, Eq.~(10)", match=r"Section 3(?!.*Remark)|Eq\. \(10\)",
         says=r"every motion reaches a flight that starts at rest; its scenarios A--D are all the cases"),
    dict(key="lemma1", home="sec:reduction", item="Lemma~1", match=r"Lemma 1", threshold=["cert.lemma1.b0_grid", "lemma1.b0_interval"],
         says=r"for $b<b_0(q)$ the progression from rest at $t_0$ stops in $[t_1,t_2]$"),
    dict(key="sec4", home="sec:nexthit", item="Sec.~4, Eqs.~(11)--(16)", match=r"Section 4|Eq\. \((11|12|13|14|16)\)",
         corrections=["eq12.second_derivative", "eq13.bound"],
         says=r"$T_1$: the first root of $G_1$ (11); bounds on the flight (12)--(13); where $T_1$ jumps (14)--(16)"),
    dict(key="lemma2", home="sec:lemma2", item="Lemma~2", match=r"Lemma 2",
         says=r"$T_1$ has finitely many discontinuities on $L_0$ and decreases across each (15)"),
    dict(key="sec5", home="sec:lemma2", item="Sec.~5, after Lemma~2", match=r"Section 5",
         says=r"$\theta\in[t_2,5\pi/4]$ gives $\theta_1\in[3\pi/2,t_3]$"),
    dict(key="lemma3", home="sec:lemma3", item="Lemma~3", match=r"Lemma 3", corrections=["lemma3.needs_lemma1"],
         says=r"$T(\theta)=\theta_2 \bmod 2\pi$ when it lies in $[t_2,t_3)$, and $T(\theta)=t_2$ otherwise"),
    dict(key="lemma4", home="sec:lemma4", item="Lemma~4", match=r"Lemma 4(?!, Remark)", threshold=["cert.lemma4.uniform_small_b", "cert.thm1.uniform_band"],
         says=r"disjoint $J_0,J_1\subset[t_2,3\pi/2]$, $T$ continuous on each, $T(J_i)\supseteq[t_2,3\pi/2]$"),
    dict(key="lemma4remark", home="sec:periodic", item="Remark after Lemma~4", match=r"Lemma 4, Remark",
         says=r"the $J_i$ may be taken with $T(J_i)=[t_2,3\pi/2]$ exactly"),
    dict(key="sec6", home="sec:periodic", item="Sec.~6, Eq.~(20)", match=r"Section 6(?! \(numerics\))|Eq\. \(20\)",
         says=r"periodic points of every minimal period $m$ (itinerary $(0^{m-1}1)^\infty$)"),
    dict(key="sec7", home="sec:periodic", item="Sec.~7", match=r"Section 7",
         says=r"semi-conjugacy to the one-sided shift on two symbols, so $h_{\mathrm{top}}(T)\ge\ln2$"),
    dict(key="thm1", home="sec:plane", item="Theorem~1", match=r"Theorems? 1", threshold=["cert.lemma4.uniform_small_b", "cert.thm1.uniform_band"],
         says=r"for $b<b_0(a,q)$: covering segments, infinitely many periodic points, symbolic dynamics"),
    dict(key="thm2", home="sec:theorem2", item="Sec.~8, Theorem~2", match=r"Theorem 2|Section 8(?!, Remark)|Theorems 1 and 2",
         corrections=["thm2.nondegenerate", "cert.thm2.erratum"],
         says=r"under (2) and (22), or (21) and (23), $t_2$ is a superstable fixed point of $T$"),
    dict(key="sec8remark", home="sec:errata", item="Remark in Sec.~8", match=r"Section 8, Remark",
         says=r"with (21), (2) relaxes to (23), and $b/a$ need not be small in either case"),
    dict(key="sec9remark", home="sec:remark9", item="Remark in Sec.~9", match=r"Section 9",
         says=r"for $b\ge a/2$ the eventual regime depends on the parameters only, not on the start"),
    dict(key="sec10", home="sec:robustness", item="Sec.~10", match=r"Section 10(?! \(numerics\))",
         says=r"the covering survives small $C^2$ perturbations; the $J_i$ move continuously with $(a,b,q)$"),
]

# Claims whose reference names more than the item they decide.
ASSIGN = {
    # Its reference names Theorem 2 and Lemma 1 (what the counterexample is made of); it refutes the
    # Section 8 Remark's "b/a need not be small", not Lemma 1 or Theorem 2.
    "cert.thm2.erratum": ["sec8remark"],
}


def items_of(claim):
    """The keys of the items a claim bears on."""
    if claim["id"] in ASSIGN:
        return ASSIGN[claim["id"]]
    return [it["key"] for it in ITEMS if re.search(it["match"], claim["reference"])]


def paper_verdict(deciding, thresholds, corrections=()):
    """The verdict about the paper from the claims of the paper or errata that bear on an item
    (`deciding`), its threshold claims and its correction claims, as the module docstring states."""
    paper = [c for c in deciding if c["origin"] == "paper"]
    errata = [c for c in deciding if c["origin"] == "erratum"]
    if any(c["verdict"] == "holds" for c in errata) or any(c["verdict"] == "fails" for c in paper):
        return "refuted"
    if not paper:
        return "inconclusive" if any(c["verdict"] == "inconclusive" for c in errata) else "not checked"
    if not any(c["verdict"] == "holds" for c in paper):
        return "inconclusive"
    if corrections and all(c["verdict"] == "holds" for c in corrections):
        return "corrected"
    if thresholds and all(c["verdict"] == "holds" for c in thresholds):
        return "threshold"
    if all(c["evidence_kind"] == "sampled" for c in paper if c["verdict"] == "holds"):
        return "consistent"
    return "confirmed"


def evidence_summary(claims):
    """The kinds of evidence behind a verdict, strongest first, with how many claims of each hold
    ("certified 5, sampled 3"); the claims that do not hold are not counted."""
    held = [c["evidence_kind"] for c in claims if c["verdict"] == "holds"] or [c["evidence_kind"] for c in claims]
    return ", ".join(f"{k} {held.count(k)}" for k in STRENGTH if k in held)


def fmt_down(x, digits=3):
    """x > 0 rounded down to `digits` significant digits, for math mode (a bound stated as "every b/a
    <= X" stays true when X is printed smaller)."""
    import math
    e = math.floor(math.log10(x)) - (digits - 1)
    m = math.floor(x / 10**e)
    while m * 10**e > x:  # the division may round up
        m -= 1
    return fmt(float("%de%d" % (m, e)))


def fmt(x):
    """A number for the report: its shortest form that reads back to the same double, powers of ten
    typeset (for math mode)."""
    s = repr(float(x))
    if s.endswith(".0"):
        s = s[:-2]
    if "e" in s:
        mant, exp = s.split("e")
        return (mant + r"\cdot" if mant != "1" else "") + "10^{%d}" % int(exp)
    return s


def scope(claims):
    """Where the claims that hold were checked: regions of the (q/a, b/a) plane (with the fraction
    proved when a claim records it), parameter points, lines of fixed q/a (windows in b), and the
    grids of experiments whose claims name no point."""
    chosen = [c for c in claims if c["verdict"] == "holds"] or claims
    regions, points, lines, other, columns = [], set(), set(), set(), []
    number = lambda x: isinstance(x, (int, float)) and not isinstance(x, bool)
    for c in chosen:
        p = c["parameters"]
        b = p.get("b_over_a", p.get("b"))
        q = p.get("q_over_a", p.get("q"))
        ev = c.get("evidence")
        cols = ev.get("columns") if isinstance(ev, dict) else None
        # every b/a up to a bound of its own in each column of q/a (thm1_uniform_band)
        if isinstance(cols, list) and cols and all(isinstance(k, dict) and "b_over_a_max" in k for k in cols):
            proved = [k for k in cols if k.get("proved")]
            if proved:
                ranges = sorted(k["parameters"]["q_over_a"] for k in proved)
                tiled = all(ranges[i][1] == ranges[i + 1][0] for i in range(len(ranges) - 1))  # no gap between them
                columns.append((len(proved), min(k["b_over_a_max"] for k in proved), max(k["b_over_a_max"] for k in proved),
                                ranges[0][0], max(r[1] for r in ranges), tiled))
            continue
        # every b/a up to a bound: the item's statement itself (a step of a proof, "(proof)", proves less)
        if number(p.get("b_over_a_max")) and isinstance(q, list) and len(q) == 2 and "(proof)" not in c["reference"]:
            if (("max", p["b_over_a_max"]), q, None, None) not in regions:
                regions.append((("max", p["b_over_a_max"]), q, None, None))
        elif isinstance(b, list) and isinstance(q, list) and len(b) == 2 and len(q) == 2:
            frac = ev.get("proved_fraction_of_band") if isinstance(ev, dict) else None
            union = ev.get("proved_fraction_with_columns") if isinstance(ev, dict) else None
            if (b, q, frac, union) not in regions:
                regions.append((b, q, frac, union))
        elif number(b):
            points.add((b, q if number(q) else None))
            if number(p.get("b_proof")):  # a second b/a of the same claim (dynamics_gallery: the proof's)
                points.add((p["b_proof"], q if number(q) else None))
        elif b is None and number(q):
            lines.add(q)
        else:
            other.add(c["evidence_kind"])
    parts = []
    for b, q, frac, union in regions:
        if isinstance(b, tuple):  # every b/a in (0, bound]
            parts.append(r"every $b/a\le%s$, $q/a\in[%s,%s]$" % (fmt_down(b[1]), fmt(q[0]), fmt(q[1])))
            continue
        share = r"%d\,\%% of " % int(100 * frac) if number(frac) else ""  # rounded down
        with_columns = (r" by boxes, %d\,\%% with the columns (area)" % int(100 * union)) if number(union) else ""
        parts.append(share + r"$b/a\in[%s,%s]$, $q/a\in[%s,%s]$" % (fmt(b[0]), fmt(b[1]), fmt(q[0]), fmt(q[1])) + with_columns)
    for n, lo, hi, q0, q1, tiled in columns:  # the q/a range printed inward, to three decimals
        import math
        parts.append(r"every $b/a$ below its column's bound ($%s$--$%s$), %d columns %s $q/a\in[%s,%s]$" %
                     (fmt_down(lo), fmt_down(hi), n, "tiling" if tiled else "in", fmt(math.ceil(q0 * 1000) / 1000),
                      fmt(math.floor(q1 * 1000) / 1000)))
    if points:
        parts.append("%d point%s" % (len(points), "" if len(points) == 1 else "s"))
    for q in sorted(lines):
        parts.append(r"$b$-windows at $q/a=%s$" % fmt(q))
    if other - {"analytic"}:
        parts.append("grids or constants" if "certified" in other else "grids")
    if "analytic" in other:
        parts.append("closed forms")
    return "; ".join(parts)


def union_fraction(band, boxes, columns):
    """The share of the band (b_lo, b_hi, q_lo, q_hi) covered by the proved boxes (q_lo, q_hi, b_lo, b_hi)
    together with the columns (q_lo, q_hi, bound) proved for every b/a up to their bound, by area in
    the linear measure of (q/a, b/a). The boxes are disjoint, and so are the columns."""
    B0, B1, Q0, Q1 = band
    clip = lambda lo, hi, a, b: max(0.0, min(hi, b) - max(lo, a))
    rects = [(max(q0, Q0), min(q1, Q1), B0, min(bound, B1)) for q0, q1, bound in columns if bound > B0 and q1 > Q0 and q0 < Q1]
    area = sum((r[1] - r[0]) * (r[3] - r[2]) for r in rects if r[1] > r[0])
    for q0, q1, b0, b1 in boxes:
        area += clip(Q0, Q1, q0, q1) * clip(B0, B1, b0, b1) - sum(clip(r[0], r[1], q0, q1) * clip(r[2], r[3], b0, b1) for r in rects)
    return area / ((B1 - B0) * (Q1 - Q0))


def rows(claims):
    """One row per item: (item dict, verdict, evidence summary, scope)."""
    by_key = {it["key"]: [] for it in ITEMS}
    for c in claims:
        for k in items_of(c):
            by_key[k].append(c)
    ids = {c["id"]: c for c in claims}
    out = []
    for it in ITEMS:
        mine = by_key[it["key"]]
        deciding = [c for c in mine if c["origin"] in ("paper", "erratum")]
        thresholds = [ids[t] for t in it.get("threshold", []) if t in ids]
        corrections = [ids[t] for t in it.get("corrections", []) if t in ids]
        verdict = paper_verdict(deciding, thresholds, corrections)
        if verdict == "refuted":
            basis = [c for c in deciding if (c["origin"] == "erratum" and c["verdict"] == "holds") or
                     (c["origin"] == "paper" and c["verdict"] == "fails")]
        else:
            extra = thresholds if verdict == "threshold" else corrections if verdict == "corrected" else []
            # An erratum that does not hold is no evidence for the item.
            basis = [c for c in deciding if c["origin"] == "paper"] + [c for c in extra if c not in deciding]
        out.append((it, verdict, evidence_summary(basis), scope(basis) if basis else ""))
    return out


def unassigned(claims):
    """Claims of the paper or errata that no item takes (a build error: the table would hide them)."""
    return [c["id"] for c in claims if c["origin"] in ("paper", "erratum") and not items_of(c)]
