#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Certificates of `dfchaos certify ... --certificate FILE`, re-verified by dfchaos-recheck (MPFI).

One CTest test per CASE: the tool writes a certificate, the checker accepts it (exit 0), or a
mutated copy of it is rejected with the exit status of its kind of damage (1: a step fails;
2: malformed). docs/certificates.md describes the format.

usage: recheck_certificates.py DFCHAOS DFCHAOS_RECHECK CASE
"""
import importlib.util
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

# The requests whose certificates the cases use.
REQUESTS = {
    "vartheta0": ["vartheta0"],
    "lemma1_point": ["lemma1", "--a", "1", "--b", "0.001", "--q", "0.85"],
    # a box across which u(t2) is near 0 at the low q: the prover splits it into several sub-boxes
    "entropy": ["entropy", "--a", "1", "--b", "0.01", "--q", "0.95"],
    "lemma1_box": ["lemma1", "--a", "1", "--b", "0.001:0.0035", "--q", "0.73:0.76"],
    "b0": ["b0", "--a", "1", "--q", "0.85"],
    # Lemma 4 at point A of the report: every ball in case AB (theta2 bracketed)
    "covering_point": ["covering", "--a", "1", "--b", "0.001", "--q", "0.85"],
    # at q/a = 0.76 the t2 ends are proved by the stop arc, through Lemma 1 (witnesses.lemma1)
    "covering_stop": ["covering", "--a", "1", "--b", "0.001", "--q", "0.76"],
    # Theorem 2's conclusion at a point inside the window near b/a = 0.0641 (condition (21))
    "superstable": ["superstable", "--a", "1", "--b", "0.0641", "--q", "0.85"],
    # that window, with its edges bracketed (the floating estimate of certified_claims)
    "window": ["superstable", "--a", "1", "--b", "0.0641", "--q", "0.85", "--window", "0.064075562769072836:0.064187276762950898"],
    # Sections 6-7 at point A: the orbit of period 3, itinerary (001)^infinity, in three boxes
    "periodic": ["periodic", "--a", "1", "--b", "0.001", "--q", "0.85", "--period", "3"],
    # Lemma 2 on L0 at b = 0.01 (point C of certified_claims: 15 tangencies), on L2 at b = 5e-5 (point D:
    # 5), and on L2 at b = 0.001, where h(L2) holds no odd multiple of pi (no tangency: the witness k_above)
    "discontinuities": ["discontinuities", "--a", "1", "--b", "0.01"],
    "discontinuities_L2": ["discontinuities", "--a", "1", "--b", "5e-5", "--segment", "L2"],
    "discontinuities_empty": ["discontinuities", "--a", "1", "--b", "0.001", "--segment", "L2"],
    # a box of certified_region, re-proved with the J0, J1 its row records
    # the arc L1 of Lemma 4's proof, for every b/a up to sin(3pi/100)/2 and q/a in [0.72, 1]
    "arc_l1": ["arc-l1", "--q", "0.72:1"],
    # Lemma 4 by the paper's construction for every b/a up to its bound, q/a in [0.73, 0.999]
    "lemma4_uniform": ["lemma4-uniform", "--q", "0.73:0.999"],
    "covering_box": ["covering", "--a", "1", "--b", "0.0019697602976329739:0.00196980455453853",
                     "--q", "0.80000000000000004:0.81000000000000005", "--J0", "3.2595461317302936:3.3248980967076651",
                     "--J1", "3.3397741191384851:3.3845640013715848"],
}


def write_certificate(cli, request, directory):
    """Runs the tool with --certificate; returns (path, record)."""
    path = os.path.join(directory, request + ".json")
    proc = subprocess.run([cli, "certify", *REQUESTS[request], "--certificate", path], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: dfchaos certify {' '.join(REQUESTS[request])} --certificate: exit {proc.returncode}: {proc.stderr.strip()}")
    record = json.loads(proc.stdout)
    info = record.get("certificate", {})
    size = os.path.getsize(path)
    if info.get("bytes") != size or len(info.get("sha256", "")) != 64:
        sys.exit(f"FAIL: the record's certificate {info} does not match the file ({size} bytes)")
    print(f"ok:   {request}: certificate of {size} bytes, sha256 {info['sha256'][:16]}...")
    return path, record


def recheck(checker, path, want, why):
    proc = subprocess.run([checker, path], capture_output=True, text=True)
    line = (proc.stdout + proc.stderr).strip()
    if proc.returncode != want:
        sys.exit(f"FAIL: {why}: dfchaos-recheck exit {proc.returncode}, want {want}: {line}")
    print(f"ok:   {why}: exit {want}: {line}")


def mutate(path, out, change):
    """Writes to `out` the certificate at `path` after change(cert) (a function on the dict)."""
    with open(path) as f:
        cert = json.load(f)
    change(cert)
    with open(out, "w") as f:
        json.dump(cert, f, indent=1)
    return out


def next_double_hex(h, direction):
    """The hex float of the neighbour of the double `h` (direction +1 up, -1 down)."""
    import math
    return float.hex(math.nextafter(float.fromhex(h), direction * math.inf))


def rejected(checker, path, bad, cases, what, label):
    """Applies the mutation `what` of `cases` (name: (change, exit status, a word of the step the checker
    must name)) to the certificate at `path`; the checker must reject it so."""
    change, want, word = cases[what]
    proc = subprocess.run([checker, mutate(path, bad, change)], capture_output=True, text=True)
    line = (proc.stdout + proc.stderr).strip()
    if proc.returncode != want or word not in line:
        sys.exit(f"FAIL: {label} mutation {what}: dfchaos-recheck exit {proc.returncode}, want {want} naming '{word}': {line}")
    print(f"ok:   {label} mutation {what}: exit {want}: {line}")


def rejects_discontinuities(cli, checker, what, d, bad):
    """The mutations of a Lemma 2 certificate (b = 0.01 on L0; for k_above, the one without tangency):
    each rejected, with the step named."""
    path, _ = write_certificate(cli, "discontinuities_empty" if what == "k_above" else "discontinuities", d)
    with open(path) as f:
        n = len(json.load(f)["witnesses"]["tangencies"])
    if n < 3 and what != "k_above":
        sys.exit(f"FAIL: the Lemma 2 certificate holds {n} tangencies; the cases need several")
    mid = n // 2

    def tangency(c):
        return c["witnesses"]["tangencies"][mid]

    def t_star(t):  # (2k+1) pi - z, in doubles
        return (2 * t["k"] + 1) * math.pi - float.fromhex(t["z"][0])

    def widen(c):  # W stretched to 3 on each side: F = a sin t + 2b >= 0 somewhere in it
        t = tangency(c)
        t["window"] = [float.hex(float.fromhex(t["window"][0]) - 3), float.hex(float.fromhex(t["window"][1]) + 3)]

    def move(c):  # W moved past t* by its own width
        t = tangency(c)
        lo, hi = (float.fromhex(x) for x in t["window"])
        t["window"] = [float.hex(hi + 1e-9), float.hex(2 * hi - lo + 1e-9)]

    def narrow(c):  # W narrowed around t*: the left ball's skipped gap no longer lies inside it
        t = tangency(c)
        lo, hi, ts = float.fromhex(t["window"][0]), float.fromhex(t["window"][1]), t_star(t)
        t["window"] = [float.hex(ts - (ts - lo) / 4), float.hex(ts + (hi - ts) / 4)]

    def z_off(c):  # the z bracket replaced by [z + 1e-3, z + 2e-3], beside its root
        t = tangency(c)
        z = float.fromhex(t["z"][0])
        t["z"] = [float.hex(z + 1e-3), float.hex(z + 2e-3)]

    def k_changed(c):
        tangency(c)["k"] += 1

    def drop_cover(c):
        cover = c["witnesses"]["cover"]
        cover.pop(len(cover) // 2)

    cases = {  # name: (change, exit status, a word of the step the checker must name)
        "count": (lambda c: c["witnesses"]["tangencies"].pop(), 1, "count"),
        "z_off_root": (z_off, 1, "z bracket"),
        "cover_gap": (drop_cover, 1, "cover [lo, hi]"),
        "window_widened": (widen, 1, "F < 0 on W"),
        "window_moved": (move, 1, "wl < t*"),
        "window_narrowed": (narrow, 1, "outside the window"),
        "k_changed": (k_changed, 1, "k = k_0"),
        "k_above": (lambda c: c["witnesses"].update(k_above=c["witnesses"]["k_above"] + 1), 1, "count"),
        "segment_unknown": (lambda c: c["parameters"].update(segment="L1"), 2, "segment"),
        "z_decimal": (lambda c: tangency(c).update(z=["3.2", "3.3"]), 2, "exact hexadecimal"),
    }
    rejected(checker, path, bad, cases, what, "Lemma 2")


def rejects_arc_l1(cli, checker, what, d, bad):
    """The mutations of an arc-l1 certificate, each rejected with the step named."""
    path, _ = write_certificate(cli, "arc_l1", d)

    def set_hex(c, where, key, x):
        c[where][key]["hex"] = float.hex(x)

    def g_hi_down(c):  # g_hi lowered below the enclosure of g on some cell
        w = c["witnesses"]
        lo, hi = float.fromhex(w["g_lo"]["hex"]), float.fromhex(w["g_hi"]["hex"])
        set_hex(c, "witnesses", "g_hi", hi - (hi - lo) / 4)

    cases = {  # name: (change, exit status, a word of the step the checker must name)
        "g_bound": (g_hi_down, 1, "g in [g_lo, g_hi]"),
        "W_short": (lambda c: set_hex(c, "witnesses", "W", float.fromhex(c["witnesses"]["W"]["hex"]) / 2), 1, "stops within W"),
        "q_lower": (lambda c: c["parameters"]["q_over_a"]["lo"].update(hex=float.hex(0.6)), 1, "stops within W"),
        "b_larger": (lambda c: set_hex(c, "parameters", "b_over_a_max", 0.2), 1, "stops within W"),
        "grid_short": (lambda c: c["witnesses"]["delta_cuts"].pop(), 1, "grid covers"),
        # the amplitude is a field of the format even where only ratios matter
        "a_missing": (lambda c: c["parameters"].pop("a"), 2, "parameters.a"),
        "a_nan": (lambda c: c["parameters"]["a"].update(hex="nan"), 2, "parameters.a"),
        "a_negative": (lambda c: c["parameters"]["a"].update(hex=float.hex(-1.0)), 2, "parameters.a"),
    }
    rejected(checker, path, bad, cases, what, "arc-l1")


def rejects_lemma4_uniform(cli, checker, what, d, bad):
    """The mutations of a lemma4-uniform certificate, each rejected with the step named."""
    path, _ = write_certificate(cli, "lemma4_uniform", d)
    cases = {  # name: (change, exit status, a word of the step the checker must name)
        "b_larger": (lambda c: c["parameters"]["b_over_a_max"].update(hex=float.hex(4 * float.fromhex(c["parameters"]["b_over_a_max"]["hex"]))), 1, "(I"),
        "q_lower": (lambda c: c["parameters"]["q_over_a"]["lo"].update(hex=float.hex(0.5)), 1, "(I8)"),
        "arc_tau": (lambda c: c["witnesses"]["arc_l1"]["witnesses"]["tau"].__setitem__(0, float.hex(3.2)), 1, "landing precedes"),
        "arc_missing": (lambda c: c["witnesses"].pop("arc_l1"), 2, "arc_l1"),
        "lemma1_gap": (lambda c: c["witnesses"]["lemma1"]["sub_boxes"].pop(), 1, "Lemma 1"),
        # the embedded arc-l1 certificate must be one of this format and version
        "arc_format_missing": (lambda c: c["witnesses"]["arc_l1"].pop("format"), 2, "witnesses.arc_l1.format"),
        "arc_format_garbled": (lambda c: c["witnesses"]["arc_l1"].update(format="dfchaos-certificat"), 2, "witnesses.arc_l1.format"),
        "arc_version_missing": (lambda c: c["witnesses"]["arc_l1"].pop("version"), 2, "witnesses.arc_l1.version"),
        "arc_version_garbled": (lambda c: c["witnesses"]["arc_l1"].update(version="1"), 2, "witnesses.arc_l1.version"),
        "a_missing": (lambda c: c["parameters"].pop("a"), 2, "parameters.a"),
        "a_nan": (lambda c: c["parameters"]["a"].update(hex="nan"), 2, "parameters.a"),
    }
    rejected(checker, path, bad, cases, what, "lemma4-uniform")


def main():
    if len(sys.argv) != 4:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    cli, checker, case = sys.argv[1:]
    with tempfile.TemporaryDirectory() as d:
        bad = os.path.join(d, "mutated.json")
        if case == "scale_invariance":
            # Scale invariance, G1(.; a, b) = a G1(.; 1, b/a) and the same for G2 (docs/certified.md): the
            # covering at a = 1 with a, b, q (and every ball's b, q) doubled exactly is a covering at a = 2,
            # with the same phases; the checker must accept it as it stands.
            path, _ = write_certificate(cli, "covering_stop", d)

            def double(c):
                two = lambda h: float.hex(2 * float.fromhex(h))
                p = c["parameters"]
                p["a"]["hex"] = two(p["a"]["hex"])
                for k in ("b", "q"):
                    for end in ("lo", "hi"):
                        p[k][end]["hex"] = two(p[k][end]["hex"])
                w = c["witnesses"]
                for box in w.get("lemma1", {}).get("sub_boxes", []):
                    box[:] = [two(x) for x in box]
                for seg in w["segments"]:
                    for lst in ("top", "t2_end", "cover"):
                        for ball in seg[lst]:
                            ball["b"] = [two(x) for x in ball["b"]]
                            ball["q"] = [two(x) for x in ball["q"]]
            recheck(checker, mutate(path, bad, double), 0, "the covering at a = 1 scaled to a = 2")
        elif case == "binding_states_parameters":
            # The binding script's generic test (scripts/recheck_certificates.py, states_parameters):
            # the checker's line states every parameter of the certificate; a line that leaves one out,
            # or shows it only as part of a name such as (I1), is refused.
            spec = importlib.util.spec_from_file_location("binding", os.path.join(HERE, "..", "scripts", "recheck_certificates.py"))
            binding = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(binding)
            path, _ = write_certificate(cli, "lemma1_box", d)
            with open(path) as f:
                cert = json.load(f)
            proc = subprocess.run([checker, path], capture_output=True, text=True)
            line = proc.stdout.strip()
            if proc.returncode != 0 or binding.states_parameters(line, cert) is not None:
                sys.exit(f"FAIL: the checker's line of a good certificate is not bound: {line!r}: {binding.states_parameters(line, cert)}")
            q_lo = cert["parameters"]["q"]["lo"]["decimal"]
            cut = line.replace(q_lo, "q_lo")
            if binding.states_parameters(cut, cert) is None:
                sys.exit(f"FAIL: a line without q = {q_lo} was bound: {cut!r}")
            par = cert["parameters"]
            said = (line.split("; ", 1)[0] + f"; (I1) for b in [{par['b']['lo']['decimal']}, {par['b']['hi']['decimal']}], "
                    f"q in [{par['q']['lo']['decimal']}, {par['q']['hi']['decimal']}]")  # a = 1 only inside the name (I1)
            if binding.states_parameters(said, cert) is None:
                sys.exit(f"FAIL: the 1 of (I1) was taken for a = 1: {said!r}")
            if binding.states_parameters(line.split("; ", 1)[0], cert) is None:
                sys.exit("FAIL: a line that does not say what it verified was bound")
            print(f"ok:   the checker's line binds, and three lines that leave a parameter out are refused")
        elif case.startswith("accepts_"):
            path, _ = write_certificate(cli, case[len("accepts_"):], d)
            recheck(checker, path, 0, f"the {case[len('accepts_'):]} certificate")
        elif case == "rejects_gap":  # a sub-box deleted: the rest no longer covers the box
            path, _ = write_certificate(cli, "lemma1_box", d)
            with open(path) as f:
                n = len(json.load(f)["witnesses"]["sub_boxes"])
            if n < 2:
                sys.exit(f"FAIL: the lemma1 box proof used {n} sub-box(es); the case needs several")
            recheck(checker, mutate(path, bad, lambda c: c["witnesses"]["sub_boxes"].pop(n // 2)), 1, "a sub-box deleted")
        elif case == "rejects_outside":  # a sub-box moved outside the box (b shifted past b_hi)
            path, _ = write_certificate(cli, "lemma1_box", d)

            def move(c):
                s = c["witnesses"]["sub_boxes"][0]
                width = float.fromhex(s[1]) - float.fromhex(s[0])
                top = float.fromhex(c["parameters"]["b"]["hi"]["hex"])
                s[0], s[1] = float.hex(top + 1e-6), float.hex(top + 1e-6 + width)
            recheck(checker, mutate(path, bad, move), 1, "a sub-box moved outside the box")
        elif case == "rejects_bracket_off_root":  # the vartheta0 bracket moved beside the root
            path, _ = write_certificate(cli, "vartheta0", d)

            def off(c):
                br = c["witnesses"]["bracket"]
                br["lo"]["hex"], br["hi"]["hex"] = br["hi"]["hex"], float.hex(1.0)
            recheck(checker, mutate(path, bad, off), 1, "the vartheta0 bracket moved off its root")
        elif case == "rejects_parameter_last_bit":  # b_lo one ulp lower: the sub-boxes leave a gap at the edge
            path, _ = write_certificate(cli, "lemma1_box", d)

            def ulp(c):
                b = c["parameters"]["b"]["lo"]
                b["hex"] = next_double_hex(b["hex"], -1)
            recheck(checker, mutate(path, bad, ulp), 1, "parameter b_lo changed in its last bit")
        elif case == "rejects_covering_piece_deleted":  # one piece of a no-contact proof deleted: a gap in t
            path, _ = write_certificate(cli, "covering_point", d)

            def drop(c):
                pieces = c["witnesses"]["segments"][0]["cover"][0]["T1"]["no_contact"]
                if len(pieces) < 3:
                    sys.exit(f"FAIL: the no-contact proof has {len(pieces)} piece(s); the case needs several")
                pieces.pop(len(pieces) // 2)
            recheck(checker, mutate(path, bad, drop), 1, "a piece of a negativity proof deleted")
        elif case == "rejects_covering_overlap":  # J1 replaced by a copy of J0: each segment valid, not disjoint
            path, _ = write_certificate(cli, "covering_point", d)

            def same(c):
                segs = c["witnesses"]["segments"]
                segs[1] = json.loads(json.dumps(segs[0]))
            recheck(checker, mutate(path, bad, same), 1, "J0 and J1 overlapping")
        elif case == "rejects_covering_bracket_off_root":  # a T1 bracket moved by 0.01 past its root
            path, _ = write_certificate(cli, "covering_point", d)

            def shift(c):
                t1 = c["witnesses"]["segments"][1]["cover"][0]["T1"]
                t1["t_lo"], t1["t_hi"] = float.hex(float.fromhex(t1["t_lo"]) + 0.01), float.hex(float.fromhex(t1["t_hi"]) + 0.01)
            recheck(checker, mutate(path, bad, shift), 1, "a T1 bracket moved off its root")
        elif case == "rejects_covering_across_discontinuity":  # J0 widened beyond its t2 end, across the jump of T1 there
            path, _ = write_certificate(cli, "covering_point", d)

            def widen(c):
                j = c["witnesses"]["segments"][0]
                top, t2 = float.fromhex(j["theta_top"]), float.fromhex(j["theta_t2"])
                new_t2 = t2 + (0.05 if t2 > top else -0.05)
                j["theta_t2"] = float.hex(new_t2)
                j["lo"], j["hi"] = float.hex(min(top, new_t2)), float.hex(max(top, new_t2))
                for b in j["t2_end"]:
                    b["theta"] = [float.hex(new_t2)] * 2
                # the cover ball at the t2 end stretched to the new end
                edge = max if t2 > top else min
                ball = edge(j["cover"], key=lambda b: float.fromhex(b["theta"][1 if t2 > top else 0]))
                ball["theta"][1 if t2 > top else 0] = float.hex(new_t2)
            recheck(checker, mutate(path, bad, widen), 1, "J0 widened across a discontinuity of T1")
        elif case == "rejects_covering_turn":  # the number of whole turns k of one ball changed by one
            path, _ = write_certificate(cli, "covering_point", d)

            def turn(c):
                c["witnesses"]["segments"][0]["top"][0]["k"] += 1
            recheck(checker, mutate(path, bad, turn), 1, "the turn k of a ball changed")
        elif case == "rejects_covering_lemma1_dropped":  # the stop arcs need Lemma 1: its witness deleted
            path, _ = write_certificate(cli, "covering_stop", d)

            def drop(c):
                if "lemma1" not in c["witnesses"]:
                    sys.exit("FAIL: the covering at q/a = 0.76 did not use Lemma 1; the case needs it")
                del c["witnesses"]["lemma1"]
            recheck(checker, mutate(path, bad, drop), 1, "the Lemma 1 witness deleted")
        elif case == "rejects_covering_parameter_last_bit":  # q one ulp higher: the balls no longer lie in the box
            path, _ = write_certificate(cli, "covering_point", d)

            def ulp(c):
                for end in ("lo", "hi"):
                    c["parameters"]["q"][end]["hex"] = next_double_hex(c["parameters"]["q"][end]["hex"], +1)
            recheck(checker, mutate(path, bad, ulp), 1, "parameter q changed in its last bit")
        elif case == "rejects_covering_unknown_test":  # a piece closed by a test the format does not have
            path, _ = write_certificate(cli, "covering_point", d)

            def rename(c):
                c["witnesses"]["segments"][0]["cover"][0]["T1"]["simple_root"][0][2] = "trust-me"
            recheck(checker, mutate(path, bad, rename), 2, "a piece with an unknown test")
        elif case == "rejects_superstable_condition":  # (22) claimed where theta2(t2) satisfies (21)
            path, _ = write_certificate(cli, "superstable", d)

            def swap(c):
                w = c["witnesses"]
                if w["condition"] != 21:
                    sys.exit(f"FAIL: the superstable certificate names condition {w['condition']}; the case needs (21)")
                w["condition"] = 22
            recheck(checker, mutate(path, bad, swap), 1, "the condition (21) renamed (22)")
        elif case == "rejects_window_edge_last_bit":  # left_in one ulp lower: the b-boxes no longer cover [left_in, right_in]
            path, _ = write_certificate(cli, "window", d)

            def ulp(c):
                w = c["witnesses"]
                w["left_in"] = next_double_hex(w["left_in"], -1)
            recheck(checker, mutate(path, bad, ulp), 1, "a window edge moved by one ulp")
        elif case == "rejects_window_outer_moved":  # the outer point moved into the window: its ball is not at left_out
            path, _ = write_certificate(cli, "window", d)

            def move(c):
                w = c["witnesses"]
                w["left_out"] = next_double_hex(w["left_out"], +1)
            recheck(checker, mutate(path, bad, move), 1, "left_out changed in its last bit, its proof left as it was")
        elif case == "rejects_window_no_neighbourhood":  # a box's phases cut to [t2(b), t2(b_lo)]: no eps > 0 at every b
            path, _ = write_certificate(cli, "window", d)

            def cut(c):
                box = c["witnesses"]["boxes"][0]
                if box["theta"][0] != "t2":
                    sys.exit("FAIL: a window box does not start at t2")
                box["theta"][1] = c["witnesses"]["outer"][0]["theta"][1]  # the double above t2 at left_out < b
            recheck(checker, mutate(path, bad, cut), 1, "a window box without a neighbourhood of t2")
        elif case == "rejects_periodic_period":  # the period changed to 4 (word 0001): three boxes are not four points
            path, _ = write_certificate(cli, "periodic", d)

            def longer(c):
                c["witnesses"]["orbits"][0]["period"] = 4
                c["witnesses"]["orbits"][0]["word"] = "0001"
            recheck(checker, mutate(path, bad, longer), 1, "the period of an orbit changed")
        elif case == "rejects_periodic_shortened":  # the middle box deleted, period 2 (word 01): T(X_0) does not cover X_1
            path, _ = write_certificate(cli, "periodic", d)

            def shorter(c):
                o = c["witnesses"]["orbits"][0]
                del o["boxes"][1]
                o["period"], o["word"] = 2, "01"
            recheck(checker, mutate(path, bad, shorter), 1, "an orbit shortened to period 2")
        elif case == "rejects_periodic_overlap":  # J1 made a copy of J0: the itinerary no longer separates the points
            path, _ = write_certificate(cli, "periodic", d)

            def same(c):
                c["witnesses"]["J1"] = list(c["witnesses"]["J0"])
            recheck(checker, mutate(path, bad, same), 1, "J0 and J1 overlap")
        elif case.startswith("rejects_discontinuities_"):
            rejects_discontinuities(cli, checker, case[len("rejects_discontinuities_"):], d, bad)
        elif case.startswith("rejects_lemma4_uniform_"):
            rejects_lemma4_uniform(cli, checker, case[len("rejects_lemma4_uniform_"):], d, bad)
        elif case.startswith("rejects_arc_l1_"):
            rejects_arc_l1(cli, checker, case[len("rejects_arc_l1_"):], d, bad)
        elif case == "rejects_truncated":
            path, _ = write_certificate(cli, "lemma1_point", d)
            with open(path, "rb") as f:
                data = f.read()
            with open(bad, "wb") as f:
                f.write(data[: len(data) // 2])
            recheck(checker, bad, 2, "a truncated certificate")
        elif case == "rejects_missing_field":
            path, _ = write_certificate(cli, "b0", d)
            recheck(checker, mutate(path, bad, lambda c: c["witnesses"].pop("b_low")), 2, "a missing field (b_low)")
        elif case == "rejects_inexact_number":
            path, _ = write_certificate(cli, "lemma1_point", d)

            def decimal(c):
                c["parameters"]["q"]["lo"]["hex"] = "0.85"
            recheck(checker, mutate(path, bad, decimal), 2, "a number that is not an exact hex float")
        elif case == "rejects_duplicate_key":
            # a key twice in one object (JSON leaves which value counts undefined): refused, at the top
            # and deep inside, whichever value comes last
            path, _ = write_certificate(cli, "lemma1_point", d)
            with open(path) as f:
                text = f.read()
            top = text.replace('"statement":', '"statement": "lemma1", "statement":', 1)
            deep = text.replace('"hi":', '"hi": {"hex": "0x1p+0", "decimal": "1"}, "hi":', 1)
            for what, changed in (("at the top level", top), ("inside parameters", deep)):
                if changed == text:
                    sys.exit(f"FAIL: duplicate key {what}: the certificate has no such key to repeat")
                with open(bad, "w") as f:
                    f.write(changed)
                proc = subprocess.run([checker, bad], capture_output=True, text=True)
                if proc.returncode != 2 or "appears twice" not in proc.stdout:
                    sys.exit(f"FAIL: duplicate key {what}: exit {proc.returncode}: {proc.stdout.strip()}")
                print(f"ok:   duplicate key {what}: exit 2: {proc.stdout.strip()}")
        elif case == "rejects_wrong_version":
            path, _ = write_certificate(cli, "vartheta0", d)
            recheck(checker, mutate(path, bad, lambda c: c.update(version=2)), 2, "a wrong format version")
        elif case == "unwritable":  # --certificate below a regular file (no directory can be made there): exit 2, no file
            with open(os.path.join(d, "plain"), "w") as f:
                f.write("a file, not a directory\n")
            target = os.path.join(d, "plain", "c.json")
            proc = subprocess.run([cli, "certify", "vartheta0", "--certificate", target], capture_output=True, text=True)
            lines = proc.stderr.strip().splitlines()
            if proc.returncode != 2 or proc.stdout or len(lines) != 1 or "certificate" not in lines[0]:
                sys.exit(f"FAIL: unwritable --certificate: exit {proc.returncode}, stdout {proc.stdout[:100]!r}, stderr {proc.stderr!r}")
            print(f"ok:   unwritable --certificate: exit 2: {lines[0]}")
            # a read-only directory (unless root, who may write anyway): exit 2 and nothing left in it
            ro = os.path.join(d, "ro")
            os.mkdir(ro, 0o555)
            proc = subprocess.run([cli, "certify", "lemma1", "--b", "0.001", "--q", "0.85", "--certificate", os.path.join(ro, "c.json")],
                                  capture_output=True, text=True)
            if os.geteuid() != 0 and (proc.returncode != 2 or os.listdir(ro)):
                sys.exit(f"FAIL: read-only directory: exit {proc.returncode}, left {os.listdir(ro)}")
            # a directory that does not exist: refused before the proof (a covering takes some 30 ms; well under
            # the 10 s allowed here), and not created
            missing = os.path.join(d, "nodir", "c.json")
            proc = subprocess.run([cli, "certify", "covering", "--b", "0.001", "--q", "0.85", "--certificate", missing],
                                  capture_output=True, text=True, timeout=10)
            if proc.returncode != 2 or proc.stdout or "certificate" not in proc.stderr or os.path.exists(os.path.dirname(missing)):
                sys.exit(f"FAIL: --certificate in a missing directory: exit {proc.returncode}, stdout {proc.stdout[:80]!r}, "
                         f"created: {os.path.exists(os.path.dirname(missing))}, stderr {proc.stderr!r}")
            print(f"ok:   --certificate in a missing directory: exit 2, nothing created: {proc.stderr.strip()}")
            # an empty file name
            proc = subprocess.run([cli, "certify", "vartheta0", "--certificate", ""], capture_output=True, text=True)
            if proc.returncode != 2 or proc.stdout or len(proc.stderr.strip().splitlines()) != 1 or "certificate" not in proc.stderr:
                sys.exit(f"FAIL: --certificate '': exit {proc.returncode}, stderr {proc.stderr!r}")
            print(f"ok:   --certificate '': exit 2: {proc.stderr.strip()}")
            # (every statement of the tool has a certificate format: no refusal of a statement to test)
            # a statement not proved writes no certificate (exit 1)
            target = os.path.join(d, "not-proved.json")
            proc = subprocess.run([cli, "certify", "lemma1", "--b", "0.05", "--q", "0.73", "--certificate", target], capture_output=True, text=True)
            if proc.returncode != 1 or os.path.exists(target) or '"written": false' not in proc.stdout:
                sys.exit(f"FAIL: not proved: exit {proc.returncode}, file left: {os.path.exists(target)}, stdout {proc.stdout[:300]!r}")
            print("ok:   a statement not proved: exit 1, no certificate")
            leftovers = [f for f in os.listdir(d) if f not in ("ro", "plain")]
            if leftovers:
                sys.exit(f"FAIL: files left behind: {leftovers}")
        else:
            print(f"unknown case {case}", file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
