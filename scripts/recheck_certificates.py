#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Re-checks every certificate that the experiments wrote, with the independent checker, and
writes the report's table of certified claims and their certificates.

usage: recheck_certificates.py BUILD RECHECK

BUILD/certificates/ID.json (or ID--PART.json, several for one claim) is a certificate of the claim
ID of BUILD/claims/*.json. Each is given to RECHECK (dfchaos-recheck: MPFI, no code of the prover);
its SHA-256 and size are recorded. Writes BUILD/tables/certificates.tex, one
\\dfccertrow{claim}{file stem}{sha256}{bytes}{status} per certificate (status "accepted") and one
row with the claim id as file stem, "---" for hash and size, and status "none" per certified claim
that has no certificate yet; a certified claim whose evidence names the claim it follows from
("rests_on", e.g. the entropy bound of Section 7 from the certified covering) is listed with that
claim's accepted certificates (status "premise"). Also BUILD/tables/certificates-macros.tex with \\dfcCertificatesAccepted,
\\dfcCertifiedClaims and \\dfcCertifiedClaimsWithout, BUILD/tables/certificates-grouped.tex (the same
rows, one per family of claims that differ only in their parameter point: the report's table) and
BUILD/certificates/SHA256SUMS (every accepted file, for `sha256sum -c`). Exits 1, writing nothing, when the checker
rejects a certificate, when a certificate names no certified claim, and when an accepted certificate
does not prove what its claim states (states_parameters(): the checker's verdict line states every
parameter of the certificate; bind(): the claim holds, and the certificate's claim text,
parameters and decisive values, b_low, the rounded doubles of vartheta0, the segments J0 and J1 or
the number of discontinuities of Lemma 2 and their segment, are the claim's record);
the tables are written whole (a temporary file renamed into place).
"""
import concurrent.futures
import glob
import hashlib
import json
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from claims_map import variant as family  # noqa: E402  (one definition of a claim family)


def fail(msg):
    sys.exit(f"recheck_certificates: {msg}")


def exact(x):
    """The binary number of an exact hexadecimal float string."""
    return float.fromhex(x)


REGION_BOXES = {}  # claim id -> boxes bound so far by its `coverings` certificates (one per column)
REGION_COLUMNS = {}  # claim id -> the columns bound so far (each at most once)


def bind_region(path, cert, claim, part):
    """A column of the certified region (statement coverings): the claim's statement, the band in b,
    the column's q range, and exactly the column's proved boxes of data/certified_region.tsv (their b
    ranges and the candidate ends of J0, J1, as doubles)."""
    par, ev = claim.get("parameters", {}), claim["evidence"]
    names = [f"column{i + 1:02d}" for i in range(len(ev.get("columns", [])))]
    if part not in names:  # exactly as the experiment names them (no alias such as column2 for column02)
        return f"part '{part}' is none of the claim's columns column01..column{len(names):02d}"
    i = names.index(part)
    if part in REGION_COLUMNS.setdefault(claim["id"], set()):
        return f"column {part} is bound twice"
    if cert.get("claim") != claim["statement"]:
        return "its claim text is not the claim's statement"
    cp = cert.get("parameters", {})
    q = [float(x) for x in ev["columns"][i]["q"]]
    got = (exact(cp["a"]["hex"]), [exact(cp["b"]["lo"]["hex"]), exact(cp["b"]["hi"]["hex"])], [exact(cp["q"]["lo"]["hex"]), exact(cp["q"]["hi"]["hex"])])
    if got != (1.0, [float(x) for x in par["b_over_a"]], q):
        return f"its parameters {got} are not a = 1, the band's b/a and column {i + 1}'s q/a"
    rows = []
    with open(os.path.join(os.path.dirname(os.path.dirname(path)), "data", "certified_region.tsv")) as f:
        lines = [l.rstrip("\n").split("\t") for l in f if not l.startswith("#")]
    head = lines[0]
    for r in lines[1:]:
        d = dict(zip(head, r))
        if d["proved"] == "1" and [float(d["q_lo"]), float(d["q_hi"])] == q:
            rows.append(tuple(float(d[k]) for k in ("b_lo", "b_hi", "J0_top", "J0_t2", "J1_top", "J1_t2")))
    boxes = []
    for b in cert.get("witnesses", {}).get("boxes", []):
        bp = b["parameters"]
        if exact(bp["a"]["hex"]) != 1.0 or [exact(bp["q"]["lo"]["hex"]), exact(bp["q"]["hi"]["hex"])] != q:
            return "a box is not at a = 1 over the column's whole q range"
        s0, s1 = b["witnesses"]["segments"]
        boxes.append((exact(bp["b"]["lo"]["hex"]), exact(bp["b"]["hi"]["hex"]), exact(s0["theta_top"]),
                      exact(s0["theta_t2"]), exact(s1["theta_top"]), exact(s1["theta_t2"])))
    if boxes != rows:
        return f"its {len(boxes)} boxes are not the column's {len(rows)} proved boxes of data/certified_region.tsv"
    REGION_COLUMNS[claim["id"]].add(part)
    REGION_BOXES[claim["id"]] = REGION_BOXES.get(claim["id"], 0) + len(boxes)
    return None


# The statement a certificate of each claim family must prove (first match wins): the checker verifies
# a file's own statement, so without this a valid proof of another statement could stand for a claim.
REQUIRED_STATEMENT = [
    (r"cert\.thm1\.region$", "coverings"),
    (r"cert\.thm1\.uniform_band$", "lemma4-uniform"),
    (r"cert\.sec6\.periodic\.", "periodic"),
    (r"cert\.sec7\.entropy_graph\.", "entropy"),
    (r"cert\.thm2\.window\d+$", "window"),
    (r"cert\.thm2\.all_windows$", "window"),
    (r"cert\.thm2\.outside$", "not_superstable"),
    (r"cert\.thm2\.erratum$", "theorem2_counterexample"),
    (r"cert\.lemma1\.b0_grid$", "b0"),
    (r"cert\.lemma1\.", "lemma1"),
    (r"cert\.lemma2\.", "discontinuities"),
    (r"cert\.lemma4\.paper_construction$", "paper_construction"),
    (r"cert\.lemma4\.arc_l1$", "arc-l1"),
    (r"cert\.lemma4\.uniform_small_b$", "lemma4-uniform"),
    (r"cert\.lemma4\.", "covering"),
    (r"cert\.eq1\.", "vartheta0"),
]


def required_statement(claim_id):
    for pattern, statement in REQUIRED_STATEMENT:
        if re.match(pattern, claim_id):
            return statement
    return None


def bind(path, cert, claim, part):
    """Checks that the certificate (already accepted by the checker) proves what the claim states:
    the claim holds, and the certificate's claim text, statement parameters and decisive values (b_low,
    the rounded doubles of vartheta0, the segments J0, J1 of a covering, the periods and words of
    periodic orbits, the segment and the number of discontinuities of Lemma 2) are
    those of the claim's record (for a claim resting on several proofs, the record of its PART).
    Returns None, or what differs."""
    if claim["verdict"] != "holds":
        return f"its claim {claim['id']} does not hold (verdict {claim['verdict']})"
    want = required_statement(claim["id"])
    if want is None:
        return f"no certificate statement is declared for claim {claim['id']} (REQUIRED_STATEMENT)"
    if cert.get("statement") != want:
        return f"its statement is {cert.get('statement')!r}, claim {claim['id']} needs {want!r}"
    if cert.get("statement") == "coverings":
        return bind_region(path, cert, claim, part)
    ev = claim["evidence"]
    if "grid" in ev:  # one certificate per proof of the grid, named by its q/a
        recs = {f"q{float(r['parameters']['q']):.2f}": r for r in ev["grid"]}
        if part not in recs:
            return f"part '{part}' is none of the claim's proofs ({', '.join(recs)})"
        rec = recs[part]
    elif "columns" in ev and cert.get("statement") == "lemma4-uniform":  # one certificate per column, named by its q/a
        recs = {f"q{float(r['parameters']['q_over_a'][0]):.2f}": r for r in ev["columns"]}
        if part not in recs:
            return f"part '{part}' is none of the claim's columns ({', '.join(recs)})"
        rec = recs[part]
    elif "windows" in ev and cert.get("statement") == "window":  # one certificate per window, named by its number
        recs = {f"w{int(r['window']):03d}": r for r in ev["windows"]}
        if part not in recs:
            return f"part '{part}' is none of the claim's windows"
        rec = recs[part]
    elif part is not None:
        return f"part '{part}' given, but the claim rests on one proof"
    else:
        rec = ev
    # A refutation (not_superstable) or an erratum's counterexample is recorded as a claim that holds
    # while the proof of the paper's statement failed; every other proof must be recorded as proved.
    if cert.get("statement") == "periodic":  # one record per orbit, each proved
        if not rec.get("orbits") or not all(o.get("proved") for o in rec["orbits"]):
            return "the claim's record of an orbit is not proved"
    elif cert.get("statement") == "paper_construction":  # the record of its covering, proved
        if not rec.get("covering", {}).get("proved"):
            return "the claim's record of the covering is not proved"
    elif cert.get("statement") not in ("not_superstable", "theorem2_counterexample") and not rec.get("proved"):
        return "the claim's record of this proof is not proved"
    if cert.get("claim") not in (rec.get("statement"), claim["statement"]):
        return "its claim text is neither the claim's statement nor its record's"
    cp, rp = cert.get("parameters", {}), rec.get("parameters") or claim.get("parameters", {})
    if cert.get("statement") in ("arc-l1", "lemma4-uniform"):  # ratios: a, the box of q/a and the bound of b/a
        extra = {"delta_max"} if cert.get("statement") == "arc-l1" else {"w_lo", "w_hi"}
        if set(cp) != {"a", "q_over_a", "b_over_a_max"} | extra or set(rp) != {"a", "q_over_a"}:
            return f"parameters {sorted(cp)} / record {sorted(rp)} are not a, q_over_a, b_over_a_max, {', '.join(sorted(extra))}"
        if cert.get("statement") == "lemma4-uniform" and [exact(cp[k]["hex"]) for k in ("w_lo", "w_hi")] != [float(x) for x in rec["segment"]]:
            return "its segment is not the claim's"
        if cert.get("statement") == "arc-l1" and exact(cp["delta_max"]["hex"]) != float(rec["delta_max"]):
            return "its arc is not the claim's"
        if exact(cp["a"]["hex"]) != float(rp["a"]):
            return "its a is not the claim's"
        if [exact(cp["q_over_a"][e]["hex"]) for e in ("lo", "hi")] != [float(x) for x in rp["q_over_a"]]:
            return "its box of q/a is not the claim's"
        if exact(cp["b_over_a_max"]["hex"]) != float(rec["b_over_a_max"]):
            return "its bound of b/a is not the claim's"
        return None
    if cert.get("statement") == "discontinuities":  # the segment is a name: "L0" for the record's "L0 = [...]"
        cp = {k: v for k, v in cp.items() if k != "segment"}
        if not str(rec.get("segment", "")).startswith(f"{cert['parameters'].get('segment')} = "):
            return "its segment is not the claim's"
    if set(cp) != set(rp):
        return f"parameters {sorted(cp)} instead of {sorted(rp)}"
    for k, v in cp.items():
        ends = [v["hex"]] if "hex" in v else [v["lo"]["hex"], v["hi"]["hex"]]
        if any(exact(e) != float(rp[k]) for e in ends):
            return f"parameter {k} is not the claim's {rp[k]!r}"
    w = cert.get("witnesses", {})
    if cert.get("statement") == "b0" and exact(w["b_low"]["hex"]) != float(rec["b0_lower_bound"]):
        return "its b_low is not the claim's b0 lower bound"
    if cert.get("statement") == "covering":
        segs = w.get("segments", [])
        for name, seg in zip(("J0", "J1"), segs):
            if [exact(seg["lo"]), exact(seg["hi"])] != [float(x) for x in rec.get(name, [])]:
                return f"its {name} is not the claim's {name}"
        if len(segs) != 2:
            return "it does not hold two segments"
    if cert.get("statement") == "periodic":  # the same orbits, through the same J0, J1 as the claim's records
        got = [(o["period"], o["word"], [exact(x) for x in w["J0"]], [exact(x) for x in w["J1"]]) for o in w.get("orbits", [])]
        want = [(o["period"], o["itinerary"], [float(x) for x in o["J0"]], [float(x) for x in o["J1"]]) for o in rec["orbits"]]
        if got != want:
            return "its orbits (periods, words, J0, J1) are not the claim's"
    if cert.get("statement") == "discontinuities":
        if len(w.get("tangencies", [])) != int(rec.get("n", -1)):
            return "its number of discontinuities is not the claim's"
        if [t.get("k") for t in w["tangencies"]] != [z.get("k") for z in rec.get("discontinuities", [])]:
            return "its k of the discontinuities are not the claim's"
    if cert.get("statement") == "paper_construction":  # the claim's J0, J1 and number of discontinuities on L2
        segs, dis = w["covering"]["witnesses"]["segments"], w["discontinuities"]["witnesses"]["tangencies"]
        if [[exact(g["lo"]), exact(g["hi"])] for g in segs] != [[float(x) for x in rec["covering"][n]] for n in ("J0", "J1")]:
            return "its J0, J1 are not the claim's"
        if len(dis) != int(rec.get("discontinuities_L2", -1)):
            return "its number of discontinuities on L2 is not the claim's"
    if cert.get("statement") == "entropy":  # the claim's bound, from as many segments
        if exact(w["rho_lower"]) != float(rec.get("rho_lower", "nan")) or len(w.get("segments", [])) != int(rec.get("segments", -1)):
            return "its rho_lower or its number of segments is not the claim's"
        # the claim states h_top > ln 2 and prints h_lower: both must follow from rho_lower
        if not exact(w["rho_lower"]) > 2 or not float(rec.get("h_lower", "nan")) <= math.log(exact(w["rho_lower"])) * (1 + 1e-15):
            return "its rho_lower does not give the claim's h_lower > ln 2"
    if cert.get("statement") == "window":
        got = [exact(w[k]) for k in ("left_out", "left_in", "right_in", "right_out")]
        if got != [float(x) for x in rec.get("left_edge", []) + rec.get("right_edge", [])]:
            return "its edge brackets are not the claim's"
    if cert.get("statement") == "vartheta0" and "paper" in rec:  # the paper's printed digits
        got = ", ".join(d["value"] for d in w.get("decimals", []))
        if got != rec["paper"]:
            return f"its decimals {got!r} are not the claim's {rec['paper']!r}"
    if cert.get("statement") == "vartheta0" and rec.get("rounding_certified"):
        for key, want in (("value_double", "vartheta0_double"), ("sine_double", "sin_vartheta0_double")):
            if key not in w or exact(w[key]["hex"]) != float(rec[want]):
                return f"its {key} is missing or not the claim's correctly rounded double"
    return None


# A number standing alone: not the digits of a name such as (I1), L2 or t2 (nor the tail of another number).
NUMBER = re.compile(r"(?<![\w.])(?:-?0x[0-9a-f]+(?:\.[0-9a-f]*)?p[+-]?\d+|-?\d+(?:\.\d*)?(?:e[+-]?\d+)?)", re.IGNORECASE)


def states_parameters(line, cert):
    """The checker's verdict line states what it verified in the certificate's own numbers: every
    number of the certificate's parameters (a, b, q, their boxes, the bound of b/a, ...) occurs in the
    line exactly, in decimal or hexadecimal, and so does every name among them (the segment). The
    same test for every statement: no branch per statement. Returns None, or what is missing."""
    if "; " not in line:
        return "the checker's line does not say what it verified"
    said = line.split("; ", 1)[1]
    shown = set()
    for tok in NUMBER.findall(said):
        try:
            shown.add(float.fromhex(tok) if "x" in tok.lower() else float(tok))
        except ValueError:
            pass

    def walk(v, where):
        if isinstance(v, dict) and "hex" in v:
            x = exact(v["hex"])
            return [] if x in shown else [f"{where} = {v['hex']}"]
        if isinstance(v, dict):
            return [m for k, u in v.items() for m in walk(u, f"{where}.{k}")]
        if isinstance(v, list):
            return [m for i, u in enumerate(v) for m in walk(u, f"{where}[{i}]")]
        if isinstance(v, str):
            return [] if v in said else [f"{where} = {v!r}"]
        return []
    missing = walk(cert.get("parameters", {}), "parameters")
    return f"the checker's line does not state {', '.join(missing)}" if missing else None


def write(path, text):
    """Writes text to path whole or not at all (a temporary beside it, renamed into place)."""
    tmp = f"{path}.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def grouped(listed, premise_of=None):
    """One \\dfccertgroup{claims}{files}{bytes}{status} (files and bytes of its own accepted
    certificates) per family of claims: ids equal but for their variant (the parameter point A-D, the
    window number), whatever else their statements say. The report's table. Families keep the order
    of their first claim; the status counts the files accepted, and names the claims whose proof rests
    on another's certificate (premise_of: claim id -> the claim it follows from) and the variants
    without a certificate."""
    premise_of = premise_of or {}
    order, members = [], {}
    for cid, stem, sha, size, status in listed:
        fam, var = family(cid)
        key = (fam, var is not None)  # an id without a variant never joins a family it is the prefix of
        if key not in members:
            order.append(key)
            members[key] = []
        members[key].append((cid, size, status))
    out = []
    for key in order:
        rows = members[key]
        variants = []
        for cid, _, _ in rows:
            v = family(cid)[1]
            if v is not None and v not in variants:
                variants.append(v)
        ids = {cid for cid, _, _ in rows}
        label = key[0] + "{" + ",".join(variants) + "}" if len(ids) > 1 else rows[0][0]
        parts = []
        accepted = sum(1 for _, _, st in rows if st == "accepted")
        if accepted:
            parts.append(f"{accepted} accepted")
        premises = [cid for cid, _, st in rows if st == "premise"]
        if premises:
            bases = sorted({premise_of.get(cid, "?") for cid in premises})
            parts.append(f"premise: {', '.join(bases)}" if len(bases) <= 1 else
                         f"premises: {family(bases[0])[0]}{{{','.join(family(b)[1] or b for b in bases)}}}")
        missing = [family(cid)[1] or cid for cid, _, st in rows if st == "none"]
        if missing:
            parts.append("none yet: " + ", ".join(dict.fromkeys(missing)))
        own = [size for _, size, st in rows if st == "accepted"]  # a premise's file is counted in its own row
        status = "; ".join(parts).replace("_", "\\_")  # claim ids in the status are LaTeX text
        out.append(f"\\dfccertgroup{{{label}}}{{{len(own)}}}{{{sum(own)}}}{{{status}}}")
    return out


def main():
    if len(sys.argv) != 3:
        fail("usage: recheck_certificates.py BUILD RECHECK")
    build, recheck = sys.argv[1], sys.argv[2]
    if not os.access(recheck, os.X_OK):
        fail(f"the checker {recheck} is not an executable")
    claims = []  # certified claim ids, in experiment and claim order
    record = {}  # id -> the claim
    for path in sorted(glob.glob(os.path.join(build, "claims", "*.json"))):
        with open(path) as f:
            doc = json.load(f)
        for c in doc["claims"]:
            if c["evidence_kind"] in ("certified", "certified+argument"):
                claims.append(c["id"])
                record[c["id"]] = c
    by_claim = {cid: [] for cid in claims}
    for path in sorted(glob.glob(os.path.join(build, "certificates", "*.json"))):
        stem = os.path.basename(path)[: -len(".json")]
        cid = stem.split("--", 1)[0]
        if cid not in by_claim:
            fail(f"{path} names no certified claim of {build}/claims (claim id '{cid}')")
        by_claim[cid].append(path)

    # The checker runs on every file first, one process per core (a region's columns take seconds each).
    paths = [path for cid in claims for path in by_claim[cid]]
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        checked = dict(zip(paths, pool.map(lambda p: subprocess.run([recheck, p], capture_output=True, text=True, timeout=600), paths)))

    rows, accepted, rejected, without = [], 0, [], 0
    listed = []  # (claim id, file stem, sha256, bytes, status) of every row, for the grouped table
    accepted_of = {}  # claim id -> [(file stem, sha256, bytes)] of its accepted certificates
    for cid in claims:
        rests_on = record[cid]["evidence"].get("rests_on")
        if not by_claim[cid] and rests_on in accepted_of and record[cid]["verdict"] == "holds":
            # a claim that follows from another certified claim by an argument of the paper (e.g. the
            # entropy bound from the certified covering, Section 7): that claim's certificate
            for stem, sha, size in accepted_of[rests_on]:
                rows.append(f"\\dfccertrow{{{cid}}}{{{cid}}}{{{sha}}}{{{size}}}{{premise}}")
                listed.append((cid, cid, sha, size, "premise"))
            continue
        if not by_claim[cid]:
            without += 1
            rows.append(f"\\dfccertrow{{{cid}}}{{{cid}}}{{---}}{{---}}{{none}}")
            listed.append((cid, cid, None, 0, "none"))
            continue
        for path in by_claim[cid]:
            data = open(path, "rb").read()
            run = checked[path]
            if run.returncode != 0:
                rejected.append(f"{path}: exit {run.returncode}: {(run.stdout + run.stderr).strip()}")
                continue
            # The checker verified the file's own statement and parameters; they must be the claim's.
            stem = os.path.basename(path)[: -len(".json")]
            part = stem.split("--", 1)[1] if "--" in stem else None
            why = states_parameters(run.stdout.strip(), json.loads(data)) or bind(path, json.loads(data), record[cid], part)
            if why:
                rejected.append(f"{path}: accepted by the checker, but not a proof of claim {cid}: {why}")
                continue
            accepted += 1
            accepted_of.setdefault(cid, []).append((stem, hashlib.sha256(data).hexdigest(), len(data)))
            rows.append(f"\\dfccertrow{{{cid}}}{{{os.path.basename(path)[: -len('.json')]}}}{{{hashlib.sha256(data).hexdigest()}}}"
                        f"{{{len(data)}}}{{accepted}}")
            listed.append((cid, stem, hashlib.sha256(data).hexdigest(), len(data), "accepted"))
    for cid, n in REGION_BOXES.items():  # a region's certificates hold all of its proved boxes
        if n != record[cid]["evidence"].get("boxes_proved"):
            rejected.append(f"claim {cid}: its certificates hold {n} boxes, the claim {record[cid]['evidence'].get('boxes_proved')} proved")
    if rejected:
        fail("the checker rejected " + str(len(rejected)) + " certificate(s):\n  " + "\n  ".join(rejected))

    tables = os.path.join(build, "tables")
    os.makedirs(tables, exist_ok=True)
    head = "% generated by scripts/recheck_certificates.py: certified claims, their certificates and the checker's answer\n"
    # The macros first, the rows last: make takes the rows' file as the sign that both are complete.
    # The libraries the checker ran on, as it reports them, and the digest of the list of digests
    # (SHA256SUMS below), which the report prints so that a reader can tell the certificates at hand
    # are the ones it describes.
    version = subprocess.run([recheck, "--version"], capture_output=True, text=True, timeout=60)
    libs = re.fullmatch(r"dfchaos-recheck \S+ \((.*)\)\s*", version.stdout)
    if version.returncode != 0 or not libs:
        fail(f"{recheck} --version printed {version.stdout!r} (exit {version.returncode}), not its libraries")
    sums = "".join(f"{sha}  {stem}.json\n" for _, stem, sha, _, status in listed if status == "accepted")
    write(os.path.join(tables, "certificates-macros.tex"),
          head + f"\\newcommand{{\\dfcRecheckLibraries}}{{{libs.group(1)}}}\n"
                 f"\\newcommand{{\\dfcCertificateSumsDigest}}{{{hashlib.sha256(sums.encode()).hexdigest()}}}\n"
                 f"\\newcommand{{\\dfcCertificatesAccepted}}{{{accepted}}}\n"
                 f"\\newcommand{{\\dfcCertifiedClaims}}{{{len(claims)}}}\n"
                 f"\\newcommand{{\\dfcCertifiedClaimsWithout}}{{{without}}}\n")
    premise_of = {cid: record[cid]["evidence"].get("rests_on") for cid in claims if isinstance(record[cid]["evidence"], dict)}
    write(os.path.join(tables, "certificates-grouped.tex"), head + "\n".join(grouped(listed, premise_of)) + "\n")
    # Every file's digest, in the format of sha256sum, so that `sha256sum -c` checks them.
    write(os.path.join(build, "certificates", "SHA256SUMS"), sums)
    write(os.path.join(tables, "certificates.tex"), head + "\n".join(rows) + "\n")
    print(f"recheck_certificates: {accepted} certificate(s) accepted by {os.path.basename(recheck)}; "
          f"{without} of {len(claims)} certified claims have no certificate yet")


if __name__ == "__main__":
    main()
