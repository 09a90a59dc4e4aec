#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The rules of the report's opening table (scripts/paper_items.py) on claims with known answers:
a refutation is never shown as confirmed, a precision-limited item never as refuted, our own
hypotheses never decide, thresholds are required in full, every claim of the paper finds an item."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
import paper_items as P  # noqa: E402


def claim(cid, ref, origin="paper", verdict="holds", kind="sampled", params=None):
    return {"id": cid, "reference": ref, "origin": origin, "verdict": verdict, "evidence_kind": kind,
            "parameters": params or {}, "evidence": {}}


def row(claims, key):
    return next(r for r in P.rows(claims) if r[0]["key"] == key)


class Verdicts(unittest.TestCase):
    def test_confirmed_needs_every_claim_of_the_paper(self):
        cs = [claim("a", "Lemma 2"), claim("b", "Lemma 2, (15)", kind="certified", params={"a": 1, "b": 1e-3})]
        it, verdict, evidence, scope = row(cs, "lemma2")
        self.assertEqual(verdict, "confirmed")
        self.assertEqual(evidence, "certified 1, sampled 1")
        self.assertEqual(scope, "1 point; grids")
        cs.append(claim("c", "Lemma 2", verdict="fails"))  # one failing claim of the paper is enough
        self.assertEqual(row(cs, "lemma2")[1], "refuted")

    def test_an_erratum_that_holds_refutes(self):
        cs = [claim("e", "Theorem 2, Lemma 1", origin="erratum", kind="certified")]
        self.assertEqual(row(cs, "lemma1")[1], "refuted")  # by its reference, it refutes Lemma 1 ...
        cs = [claim("cert.thm2.erratum", "Theorem 2, Lemma 1", origin="erratum", kind="certified")]
        self.assertEqual(row(cs, "sec8remark")[1], "refuted")  # ... but the known erratum goes to its Remark only
        self.assertEqual(row(cs, "lemma1")[1], "not checked")
        for v, expected in (("fails", "not checked"), ("inconclusive", "inconclusive")):
            cs[0]["verdict"] = v  # an erratum that does not hold refutes nothing and confirms nothing
            self.assertEqual(row(cs, "sec8remark")[1], expected)
            self.assertEqual(row(cs, "sec8remark")[2], "")  # and is no evidence for the item

    def test_corrections_are_named_and_must_hold(self):
        cs = [claim("thm2.superstable", "Theorem 2"), claim("thm2.nondegenerate", "Section 8"),
              claim("cert.thm2.erratum", "Theorem 2, Lemma 1", origin="erratum", kind="certified")]
        self.assertEqual(row(cs, "thm2")[1], "corrected")  # needs b < b0(q): the erratum, as a correction
        self.assertEqual(row(cs, "sec8remark")[1], "refuted")  # and the Remark it refutes
        cs[1]["verdict"] = "inconclusive"
        self.assertEqual(row(cs, "thm2")[1], "confirmed")  # a correction that is not shown does not count

    def test_precision_limited_is_inconclusive_never_refuted(self):
        cs = [claim("p", "Section 7", verdict="inconclusive", kind="precision-limited")]
        self.assertEqual(row(cs, "sec7")[1], "inconclusive")
        cs.append(claim("q", "Section 7"))
        self.assertEqual(row(cs, "sec7")[1], "confirmed")

    def test_our_claims_never_decide(self):
        cs = [claim("o", "Lemma 3", origin="ours", verdict="fails")]
        self.assertEqual(row(cs, "lemma3")[1], "not checked")
        self.assertEqual(P.unassigned(cs), [])

    def test_threshold_needs_all_threshold_claims(self):
        cs = [claim("l", "Lemma 1"), claim("cert.lemma1.b0_grid", "Lemma 1", kind="certified"),
              claim("lemma1.b0_interval", "Lemma 1", origin="ours")]
        self.assertEqual(row(cs, "lemma1")[1], "threshold")
        cs[2]["verdict"] = "fails"
        self.assertEqual(row(cs, "lemma1")[1], "confirmed")

    def test_region_scope_and_remarks(self):
        cs = [claim("r", "Theorem 1, Lemma 4", kind="certified",
                    params={"b_over_a": [0.00195, 0.002], "q_over_a": [0.76, 0.99]})]
        cs[0]["evidence"] = {"proved_fraction_of_band": 0.8839}
        self.assertIn(r"88\,\% of $b/a\in[0.00195,0.002]$", row(cs, "thm1")[3])  # the share proved, rounded down
        self.assertEqual(P.items_of(claim("x", "Lemma 4, Remark")), ["lemma4remark"])
        self.assertEqual(P.items_of(claim("x", "Section 8, Remark (23)")), ["sec8remark"])

    def test_unassigned_claims_of_the_paper_are_reported(self):
        self.assertEqual(P.unassigned([claim("z", "Appendix Q")]), ["z"])

    def test_numbers_in_shortest_form(self):
        self.assertEqual(P.fmt(0.85), "0.85")
        self.assertEqual(P.fmt(1e-5), "10^{-5}")
        self.assertEqual(P.fmt(2.5e-7), r"2.5\cdot10^{-7}")


if __name__ == "__main__":
    unittest.main()
