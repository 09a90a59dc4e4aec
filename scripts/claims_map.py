#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The claims map, generated: paper item -> experiments -> claims (verdict, evidence kind) -> figures
-> tables -> tests, from what the experiments declare (`--describe`), what they computed
(build/claims/*.json), and which figure scripts read their data (figures/*.gp).

Writes BUILD/claims-map.md (for readers of the repository) and, for the report,
BUILD/tables/dfchaos-experiments.tex (every experiment's macros and verdicts),
BUILD/tables/paper-items.tex and paper-items-totals.tex (the verdicts about the paper, item by item)
and BUILD/tables/dfchaos-appendix-claims.tex (every claim, by experiment, with its figures and tests;
claims that differ only in their parameter point in one row). Fails when a declared test suite does
not exist, when an experiment binary has no claims file, when a claim is in no item of the map, and
when a claim of the paper is in no item of scripts/paper_items.py. Usage: claims_map.py BUILD [ROOT]
"""
import glob
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_items  # noqa: E402

# Where each numbered item sits in the paper, to sort the map in reading order.
ORDER = ["Eq. (1)", "Eq. (2)", "Section 2", "Eq. (3)", "Eq. (4)", "Eq. (5)", "Eq. (6)", "Eq. (7)", "Section 3",
         "Lemma 1", "Eq. (8)", "Eq. (9)", "Eq. (10)", "Section 4", "Eq. (11)", "Eq. (12)", "Eq. (13)", "Eq. (14)",
         "Section 5", "Lemma 2", "Eq. (15)", "Eq. (16)", "Eq. (17)", "Lemma 3", "Lemma 4", "Eq. (18)", "Eq. (19)",
         "Section 6", "Eq. (20)", "Section 7", "Section 8", "Eq. (21)", "Eq. (22)", "Eq. (23)", "Section 9",
         "Theorem 1", "Theorem 2", "Section 10"]


def rank(item):
    return ORDER.index(item) if item in ORDER else len(ORDER)


def tex_args(line, n):
    """The n brace-delimited arguments of a macro call on one line (the kit's rows), braces nested
    and escaped ones (backslash-brace) skipped."""
    args, depth, cur, i = [], 0, [], line.index("{")
    while i < len(line) and len(args) < n:
        ch = line[i]
        if ch == "\\" and i + 1 < len(line):
            if depth:
                cur.append(line[i:i + 2])
            i += 2
            continue
        if ch == "{":
            if depth:
                cur.append(ch)
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth:
                cur.append(ch)
            else:
                args.append("".join(cur))
                cur = []
        elif depth:
            cur.append(ch)
        i += 1
    if len(args) != n:
        raise ValueError(f"expected {n} arguments in {line!r}")
    return args


# A number standing alone: not part of a word, a fraction, a power, an exponent or a range (so
# 3pi/2, 2^10, 1E-3 and sec4-2 are words, not numbers that may differ between variants).
NUMBER = re.compile(r"(?<![\w.\-/^{}])\d+(?:\.\d+)?(?:e[-+]?\d+)?(?![\w/^}]|\.\d|-\d)")


def variant(cid):
    """A claim id split into its family and variant: cert.lemma4.A -> (cert.lemma4., A),
    cert.thm2.window3 -> (cert.thm2.window, 3), else (id, None). scripts/recheck_certificates.py groups
    certificates by it too."""
    m = re.fullmatch(r"(.*\.)([A-Z])", cid) or re.fullmatch(r"(.*[a-z_])(\d+)", cid)
    return (m.group(1), m.group(2)) if m else (cid, None)


def grouped_claim_rows(rows, parameters=None):
    """Claims of one family (same id but for the variant) whose statements differ only in numbers,
    with the same reference, verdict, kind and origin, become one row: the first statement, each
    number that differs followed by the others' values in brackets ([B: 0.003; D: 5e-05]), after the
    parameters of each variant (parameters: id -> "q=0.85, b=0.001", when known). Rows are
    (id, reference, statement, verdict, kind, origin); returns (label, first id, reference, statement,
    verdict, kind, origin), order kept."""
    parameters = parameters or {}
    out, used = [], set()
    for i, r in enumerate(rows):
        if i in used:
            continue
        fam, var = variant(r[0])
        skeleton = NUMBER.split(r[2])
        group = [i]
        if var is not None:
            for j in range(i + 1, len(rows)):
                o = rows[j]
                if j not in used and variant(o[0])[0] == fam and variant(o[0])[1] is not None and \
                        NUMBER.split(o[2]) == skeleton and o[1] == r[1] and o[3:] == r[3:]:
                    group.append(j)
        if len(group) == 1:
            out.append((r[0],) + r)
            continue
        used.update(group)
        nums = [NUMBER.findall(rows[j][2]) for j in group]
        pieces = []
        for k, part in enumerate(skeleton):
            pieces.append(part)
            if k < len(nums[0]):
                others = [f"{variant(rows[j][0])[1]}: {nums[g][k]}" for g, j in enumerate(group) if g and nums[g][k] != nums[0][k]]
                pieces.append(nums[0][k] + (" [" + "; ".join(others) + "]" if others else ""))
        names = [variant(rows[j][0])[1] for j in group]
        label = fam + "{" + ",".join(names) + "}"
        # each variant's parameters, unless its statement already names every one of their values
        # (then the listing would repeat the statement; the values stay in the claims files)
        def named(j, g):
            values = re.findall(r"=\s*([^,]+)", parameters.get(rows[j][0], ""))
            said = {float(x) for x in nums[g]}
            try:
                return all(float(v) in said for v in values)
            except ValueError:
                return False
        at = "" if all(named(j, g) for g, j in enumerate(group)) else \
            "; ".join(f"{n}: {parameters[rows[j][0]]}" for n, j in zip(names, group) if parameters.get(rows[j][0]))
        differ = any(nums[g][k] != nums[0][k] for g in range(1, len(group)) for k in range(len(nums[0])))
        head = (f"[{at}] " if at else "") + (f"[{names[0]}; " + ", ".join(names[1:]) + " in brackets] " if differ else
                                             f"[{', '.join(names)}: the same statement; their numbers are in their claims files] ")
        out.append((label, r[0], r[1], head + "".join(pieces), r[3], r[4], r[5]))
    return out


# The statements are plain text written by the experiments (escaped for LaTeX by the kit): the
# mathematics in them is typeset here, by a few conservative rules on whole words, so that the PDF
# shows t_2, 3pi/2, J_0, >= as mathematics. A word no rule knows is left as it was.
_W = r"(?<![\w\\.$])"   # not inside a word, a number, a command or after an escaped dollar
_E = r"(?![\w\\-])"      # the end of a word, not joined to the next by a hyphen
_TYPESET = [  # (pattern, replacement as for re.sub: group references \1, LaTeX backslashes doubled)
    # an opening quote (after a space or a bracket) typeset as one, not as an apostrophe; first, while
    # no rule has yet put a $ before an apostrophe (t2's)
    (r"(?<![^\s(\[])'(?=\w)", r"`"),
    # the tangency condition of Lemma 2 and its value, whole, as written by the experiments
    (_W + r"2z - \(a/b\) cos z = \(2k\+1\) pi" + _E, r"$2z-(a/b)\\cos z=(2k+1)\\pi$"),
    (_W + r"z\\_k - \(a/b\) cos z\\_k" + _E, r"$z_k-(a/b)\\cos z_k$"),
    (r"\(0\\textasciicircum\{\}\(m-1\)1\)\\textasciicircum\{\}infinity", r"$(0^{m-1}1)^\\infty$"),
    (r"(?<![\w\\])0\\textasciicircum\{\}\(m-1\)1" + _E, r"$0^{m-1}1$"),
    (_W + r"(cos|sin)\\textasciicircum\{\}(\d+)" + _E, r"$\\\1^{\2}$"),
    (_W + r"([A-Za-z0-9])\\textasciicircum\{\}(\d+|[a-z])" + _E, r"$\1^{\2}$"),
    (r"\$<\$\$<\$", r"$\\ll$"), (r"\$>\$\$>\$", r"$\\gg$"),
    (r"\$>\$=", r"$\\ge$"), (r"\$<\$=", r"$\\le$"), (r"!=", r"$\\ne$"), (r"-\$>\$", r"$\\to$"),
    (_W + r"(\d*)pi/(\d+)" + _E, r"$\1\\pi/\2$"), (_W + r"(\d*)pi" + _E, r"$\1\\pi$"),
    # derivatives and a one-sided limit, whole: |T1'|, T1', T', u', T1(z-0); minus infinity
    (r"\$\|\$T1'\$\|\$", r"$|T_1'|$"),
    (_W + r"([Tu])(1?)'(?!\w)", lambda m: "$" + m.group(1) + ("_1" if m.group(2) else "") + "'$"),
    (_W + r"T1\(z-0\)", r"$T_1(z-0)$"),
    (_W + r"minus infinity" + _E, r"$-\\infty$"),
    (_W + r"vartheta0" + _E, r"$\\vartheta_0$"), (_W + r"theta(\d)" + _E, r"$\\theta_\1$"), (_W + r"theta" + _E, r"$\\theta$"),
    (_W + r"eps\\_b" + _E, r"$\\varepsilon_b$"), (_W + r"(?:epsilon|eps)" + _E, r"$\\varepsilon$"),
    (_W + r"delta" + _E, r"$\\delta$"), (_W + r"lambda" + _E, r"$\\lambda$"),
    (_W + r"h\\_top" + _E, r"$h_{\\mathrm{top}}$"),
    (_W + r"([tTJKLGzb])(?:\\_)?(\d|[ik])" + _E + r"(?! distance)", r"$\1_\2$"),  # L1 distance is a norm, not the arc L_1
    (_W + r"(\d+(?:\.\d+)?)e([-+]?)0*(\d+)" + _E, lambda m: "$" + ("" if m.group(1) == "1" else m.group(1) + r"\cdot") +
     "10^{" + m.group(2).replace("+", "") + m.group(3) + "}$"),
    (_W + r"rho\(([A-Z])\)", r"$\\rho(\1)$"),  # a spectral radius
    (_W + r"([A-Za-z])\\_([a-z0-9])" + _E, r"$\1_\2$"),  # any one letter with a one-character index: I_j, x_k
    # a minus sign: a hyphen standing alone between spaces, or before a bracket after a space (-(2a + b));
    # a hyphen inside a word or a range (Li-Yorke, (I1)-(I9), z-0) stays one
    (r"(?<= )-(?= |\()", r"$-$"),
]


def typeset(text):
    """The mathematics of a statement typeset (see _TYPESET); \path{...} and \texttt{...} untouched."""
    parts = re.split(r"(\\(?:path|texttt)\{[^{}]*\})", text)
    for i in range(0, len(parts), 2):
        for pattern, repl in _TYPESET:
            parts[i] = re.sub(pattern, repl, parts[i])
        parts[i] = re.sub(r"(?<!\\)\$\$", "", parts[i])  # adjacent formulas ($t_2$$\ge$ -> one); not an escaped \$
    return "".join(parts)


def read_tsv(path):
    """The rows of a data file of the kit (column names on the first line, # comments) as dicts of
    strings."""
    with open(path) as f:
        lines = [l.rstrip("\n") for l in f if l.strip() and not l.startswith("#")]
    names = lines[0].split("\t")
    return [dict(zip(names, l.split("\t"))) for l in lines[1:]]


def region_with_columns(build, claims):
    """The certified band of make reproduce (cert.thm1.region, its boxes in data/certified_region.tsv)
    together with the columns of q/a proved for every b/a below a bound (cert.thm1.uniform_band,
    data/thm1_uniform_band.tsv): the share of the band proved by either, recorded in the region
    claim's evidence (proved_fraction_with_columns) for the scope column, and as a macro for the
    text. Nothing when either claim is absent or does not hold."""
    by_id = {c["id"]: c for c in claims}
    region, band = by_id.get("cert.thm1.region"), by_id.get("cert.thm1.uniform_band")
    if not region or not band or region["verdict"] != "holds" or band["verdict"] != "holds":
        return None
    b, q = region["parameters"]["b_over_a"], region["parameters"]["q_over_a"]
    boxes = [tuple(float(r[k]) for k in ("q_lo", "q_hi", "b_lo", "b_hi"))
             for r in read_tsv(os.path.join(build, "data", "certified_region.tsv")) if r["proved"] == "1"]
    columns = [(float(r["q_lo"]), float(r["q_hi"]), float(r["b_over_a_max"]))
               for r in read_tsv(os.path.join(build, "data", "thm1_uniform_band.tsv")) if r["proved"] == "1"]
    frac = paper_items.union_fraction((b[0], b[1], q[0], q[1]), boxes, columns)
    region["evidence"]["proved_fraction_with_columns"] = frac
    return frac


def main():
    build = os.path.abspath(sys.argv[1])
    root = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), ".."))
    exe_dir = os.path.join(build, "bin", "experiments")
    experiments = {}
    for exe in sorted(glob.glob(os.path.join(exe_dir, "*"))):
        name = os.path.basename(exe)
        desc = json.loads(subprocess.run([exe, "--describe"], capture_output=True, text=True, check=True).stdout)
        claims_file = os.path.join(build, "claims", name + ".json")
        if not os.path.exists(claims_file):
            sys.exit(f"claims_map: experiment {name} has no {claims_file}: run it first (make experiments)")
        desc["claims"] = json.load(open(claims_file))["claims"]
        for t in desc["tests"]:
            # a GoogleTest suite (tests/T.cpp) or a script test (tests/T.sh, tests/T.py)
            if not any(os.path.exists(os.path.join(root, "tests", t + ext)) for ext in (".cpp", ".sh", ".py")):
                sys.exit(f"claims_map: experiment {name} declares test {t}, but none of tests/{t}.cpp, .sh, .py exists")
        desc["figures"] = sorted(os.path.basename(g)[:-3] for g in glob.glob(os.path.join(root, "figures", "fig_*.gp"))
                                 if re.search(r"[/\"']" + re.escape(name) + r"[-.\"']", open(g).read()))
        experiments[name] = desc

    items = {}
    for name, d in experiments.items():
        for item in d["paper"]:
            items.setdefault(item, []).append(name)
    rows = sorted(items.items(), key=lambda kv: (rank(kv[0]), kv[0]))

    md = ["# Claims map (generated by scripts/claims_map.py; do not edit)", "",
          "| paper item | experiment | claims: verdict [evidence] | figures | LaTeX tables | tests |", "|---|---|---|---|---|---|"]
    # A claim whose reference names none of its experiment's items (e.g. "Eqs. (3)-(7)") is listed
    # under the experiment's first item, so that every claim is in the map.
    shown = set()
    for item, names in rows:
        for name in names:
            d = experiments[name]
            refs = [c for c in d["claims"] if item in c["reference"] or
                    (item == d["paper"][0] and not any(i in c["reference"] for i in d["paper"]))]
            shown.update(c["id"] for c in refs)
            claims_md = "; ".join(f"`{c['id']}` {c['report_verdict']} [{c['evidence_kind']}]" for c in refs) or "(see all its claims)"
            tables = [o["name"] for o in d["outputs"] if o["kind"] == "latex"]
            md.append(f"| {item} | `experiments/{name}.cpp` | {claims_md} | {', '.join(d['figures']) or '-'} | "
                      f"{', '.join(tables) or '-'} | {', '.join(d['tests']) or '-'} |")
    missing = [c["id"] for d in experiments.values() for c in d["claims"] if c["id"] not in shown]
    if missing:
        sys.exit("claims_map: claims not in the map: " + ", ".join(missing))
    md.append("")
    md.append("Every experiment also runs as a CTest smoke test (`smoke_<name>`, label `smoke`).")
    with open(os.path.join(build, "claims-map.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    os.makedirs(os.path.join(build, "tables"), exist_ok=True)
    with open(os.path.join(build, "tables", "dfchaos-experiments.tex"), "w") as f:
        f.write("% generated by scripts/claims_map.py: every experiment's macros and verdicts\n")
        for name in experiments:
            f.write(f"\\dfcload{{{name}}}\n")
    # The report's opening: one row per item of the paper with the verdict about the paper.
    claims = [c for d in experiments.values() for c in d["claims"]]
    lost = paper_items.unassigned(claims)
    if lost:
        sys.exit("claims_map: claims of the paper that no item of scripts/paper_items.py takes: " + ", ".join(lost))
    union = region_with_columns(build, claims)
    with open(os.path.join(build, "tables", "region-union.tex"), "w") as f:
        f.write("% generated by scripts/claims_map.py: the certified band with the column bounds (linear area)\n")
        f.write("\\def\\dfcRegionUnionPercent{%s}\n" % (str(int(100 * union)) if union is not None else "---"))
    totals = {}
    with open(os.path.join(build, "tables", "paper-items.tex"), "w") as f:
        f.write("% generated by scripts/claims_map.py (items and verdict rules: scripts/paper_items.py)\n")
        for it, verdict, evidence, scope in paper_items.rows(claims):
            totals[verdict] = totals.get(verdict, 0) + 1
            evidence = evidence.replace("+", "+\\allowbreak{}")  # certified+argument may break in the narrow column
            f.write(f"\\dfcitemrow{{{it['item']}}}{{{it['says']}}}{{{verdict}}}{{{evidence or '---'}}}"
                    f"{{{scope or '---'}}}{{{it['home']}}}\n")
    with open(os.path.join(build, "tables", "paper-items-totals.tex"), "w") as f:
        f.write("% generated by scripts/claims_map.py: items of the paper per verdict\n")
        f.write("\\def\\dfcItemsTotal{%d}\n" % sum(totals.values()))
        for v in paper_items.VERDICTS:
            f.write("\\def\\dfcItems%s{%d}\n" % (v.title().replace(" ", ""), totals.get(v, 0)))
    # Every claim, by experiment (the report's appendix): the kit's rows, families of claims that
    # differ only in their parameter point merged into one row, with the experiment's figures and tests.
    with open(os.path.join(build, "tables", "dfchaos-appendix-claims.tex"), "w") as f:
        f.write("% generated by scripts/claims_map.py: every experiment's claims\n")
        f.write("\\begin{dfcallclaims}%\n")  # one table for all (paper/dfchaos.sty)
        for name in experiments:
            d = experiments[name]
            with open(os.path.join(build, "tables", name + "-claims.tex")) as g:
                kit_rows = [tuple(tex_args(line, 6)) for line in g if line.startswith("\\dfcclaimrow{")]
            if len(kit_rows) != len(d["claims"]):
                sys.exit(f"claims_map: {name}-claims.tex has {len(kit_rows)} rows for {len(d['claims'])} claims")
            paths = lambda xs: ", ".join(f"\\path{{{x}}}" for x in xs) or "---"
            f.write(f"\\dfcclaims{{{name}}}{{{paths(d['figures'])}}}{{{paths(d['tests'])}}}{{%\n")
            at = {c["id"]: ", ".join(f"{k.replace('_', chr(92) + '_')}={v!r}" for k, v in c["parameters"].items())
                  for c in d["claims"] if isinstance(c.get("parameters"), dict)}
            for row in grouped_claim_rows(kit_rows, at):
                row = row[:2] + (typeset(row[2]), typeset(row[3])) + row[4:]
                f.write("\\dfcclaimentry" + "".join("{" + x + "}" for x in row) + "\n")
            f.write("}%\n")
        f.write("\\end{dfcallclaims}\n")
    print(f"claims map: {len(rows)} paper items, {len(experiments)} experiments -> {build}/claims-map.md")


if __name__ == "__main__":
    main()
