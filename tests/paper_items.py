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
import claims_map as M  # noqa: E402


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
        self.assertEqual(row(cs, "thm2")[1], "consistent")  # a correction that is not shown does not count

    def test_precision_limited_is_inconclusive_never_refuted(self):
        cs = [claim("p", "Section 7", verdict="inconclusive", kind="precision-limited")]
        self.assertEqual(row(cs, "sec7")[1], "inconclusive")
        cs.append(claim("q", "Section 7", kind="analytic"))
        self.assertEqual(row(cs, "sec7")[1], "confirmed")

    def test_sampled_alone_is_consistent_not_confirmed(self):
        cs = [claim("s", "Section 10"), claim("t", "Section 10", kind="precision-limited", verdict="inconclusive")]
        self.assertEqual(row(cs, "sec10")[1], "consistent")  # one perturbation at one point proves nothing between
        cs.append(claim("c", "Section 10", kind="certified", verdict="fails"))
        self.assertEqual(row(cs, "sec10")[1], "refuted")
        cs[-1]["verdict"] = "holds"
        self.assertEqual(row(cs, "sec10")[1], "confirmed")  # one certified claim that holds is enough

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

    def test_union_of_boxes_and_column_bounds(self):
        band = (0.0, 1.0, 0.0, 1.0)
        self.assertAlmostEqual(P.union_fraction(band, [(0, 0.5, 0, 1)], []), 0.5)  # boxes alone
        self.assertAlmostEqual(P.union_fraction(band, [], [(0.5, 1, 2.0)]), 0.5)  # a bound above the band fills its column
        # overlap counted once: a box inside a column's proved part adds nothing, one beside it adds its area
        self.assertAlmostEqual(P.union_fraction(band, [(0.5, 1, 0, 0.5), (0, 0.5, 0, 0.5)], [(0.5, 1, 2.0)]), 0.75)
        self.assertAlmostEqual(P.union_fraction(band, [], [(0, 1, -1.0)]), 0.0)  # a bound below the band: nothing
        self.assertAlmostEqual(P.union_fraction(band, [(0, 1, 0.25, 0.75)], [(0, 1, 0.5)]), 0.75)

    def test_columns_of_bounds_in_the_scope(self):
        cols = [{"parameters": {"q_over_a": [0.7299642857, 0.74]}, "proved": True, "b_over_a_max": 7.5e-4},
                {"parameters": {"q_over_a": [0.74, 0.999]}, "proved": True, "b_over_a_max": 2.4468e-3},
                {"parameters": {"q_over_a": [0.72, 0.7299642857]}, "proved": False, "b_over_a_max": 7.8e-5}]
        c = claim("u", "Lemma 4", kind="certified+argument", params={"q_over_a": [0.72, 0.999], "columns": 3})
        c["evidence"] = {"columns": cols}
        scope = P.scope([c])
        self.assertIn(r"2 columns tiling $q/a\in[0.73,0.999]$", scope)  # the proved ones, the range printed inward
        self.assertIn(r"($0.00075$--$0.00244$)", scope)  # rounded down: bounds stay true
        self.assertNotIn("grids", scope)
        cols[1]["parameters"]["q_over_a"] = [0.75, 0.999]  # a gap between the proved columns: not a tiling
        self.assertIn(r"2 columns in $q/a\in[0.73,0.999]$", P.scope([c]))

    def test_a_written_argument_is_not_counted_as_certified(self):
        cs = [claim("u", "Lemma 4, Theorem 1", kind="certified+argument", params={"b_over_a_max": 7.8e-5, "q_over_a": [0.73, 0.999]}),
              claim("s", "Lemma 4")]
        self.assertEqual(row(cs, "lemma4")[2], "certified+argument 1, sampled 1")

    def test_a_claim_at_two_b_counts_two_points(self):
        # dynamics_gallery's Section 5 claims are checked at b/a and at b_proof
        cs = [claim("g", "Section 5 (theta in [t2, 5pi/4])", params={"b_over_a": 0.01, "b_proof": 5e-5, "q_over_a": 0.85})]
        self.assertEqual(row(cs, "sec5")[3], "2 points")

    def test_unassigned_claims_of_the_paper_are_reported(self):
        self.assertEqual(P.unassigned([claim("z", "Appendix Q")]), ["z"])

    def test_numbers_in_shortest_form(self):
        self.assertEqual(P.fmt(0.85), "0.85")
        self.assertEqual(P.fmt(1e-5), "10^{-5}")
        self.assertEqual(P.fmt(2.5e-7), r"2.5\cdot10^{-7}")


class OneRowPerFamily(unittest.TestCase):
    """The appendix merges claims that differ only in their parameter point (claims_map.py)."""

    def r(self, cid, stmt, verdict="holds", ref="Lemma 4"):
        return (cid, ref, stmt, verdict, "certified", "paper")

    def test_numbers_that_differ_are_listed_in_brackets(self):
        rows = [self.r("c.l4.A", "at b=0.001 q=0.85: J0 in [t2, 3pi/2]"), self.r("c.l4.B", "at b=0.003 q=0.85: J0 in [t2, 3pi/2]"),
                self.r("c.l4.C", "at b=0.01 q=0.95: J0 in [t2, 3pi/2]")]
        out = M.grouped_claim_rows(rows)
        self.assertEqual(len(out), 1)
        label, first, ref, stmt = out[0][:4]
        self.assertEqual((label, first, ref), ("c.l4.{A,B,C}", "c.l4.A", "Lemma 4"))
        self.assertEqual(stmt, "[A; B, C in brackets] at b=0.001 [B: 0.003; C: 0.01] q=0.85 [C: 0.95]: J0 in [t2, 3pi/2]")

    def test_parameters_are_listed_only_when_the_statement_does_not_name_them(self):
        rows = [self.r("c.l4.A", "at b=0.001 q=0.85: J0 in [t2, 3pi/2]"), self.r("c.l4.B", "at b=0.003 q=0.85: J0 in [t2, 3pi/2]")]
        named = M.grouped_claim_rows(rows, {"c.l4.A": "b=0.001, q=0.85", "c.l4.B": "b=0.003, q=0.85"})
        self.assertFalse(named[0][3].startswith("[A: "), named[0][3])
        other = M.grouped_claim_rows(rows, {"c.l4.A": "b=0.001, q=0.85", "c.l4.B": "b=0.003, q=0.9"})
        self.assertTrue(other[0][3].startswith("[A: b=0.001, q=0.85; B: b=0.003, q=0.9] "), other[0][3])

    def test_powers_and_much_less_are_typeset(self):
        self.assertEqual(M.typeset(r"cos\textasciicircum{}2 t3 and a\textasciicircum{}2, T\textasciicircum{}n, b $<$$<$ q"),
                         r"$\cos^{2}$ $t_3$ and $a^{2}$, $T^{n}$, b $\ll$ q")

    def test_a_different_word_verdict_or_reference_keeps_its_own_row(self):
        base = self.r("c.l2.A", "L0 has 158 jumps")
        for other in (self.r("c.l2.B", "L2 has 5 jumps"), self.r("c.l2.B", "L0 has 52 jumps", verdict="fails"),
                      self.r("c.l2.B", "L0 has 52 jumps", ref="Lemma 3"), self.r("c.other.B", "L0 has 52 jumps")):
            out = M.grouped_claim_rows([base, other])
            self.assertEqual([o[0] for o in out], [base[0], other[0]], other)

    def test_numbers_inside_words_fractions_and_powers_are_not_merged(self):
        for a, b in (("on [t2, 3pi/2]", "on [t2, 3pi/4]"), ("to 1E-3", "to 1E-5"), ("2^10 words", "2^12 words"),
                     ("file sec4-2.tsv", "file sec4-3.tsv"), ("x = -0.5", "x = -0.7")):
            out = M.grouped_claim_rows([self.r("c.l.A", a), self.r("c.l.B", b)])
            self.assertEqual(len(out), 2, (a, b))

    def test_the_parameters_of_each_variant_head_the_row(self):
        rows = [self.r("c.l.A", "has 158 jumps"), self.r("c.l.B", "has 52 jumps")]
        out = M.grouped_claim_rows(rows, {"c.l.A": "b=0.001", "c.l.B": "b=0.003"})
        self.assertEqual(out[0][3], "[A: b=0.001; B: b=0.003] [A; B in brackets] has 158 [B: 52] jumps")

    def test_identical_statements_promise_no_brackets(self):
        out = M.grouped_claim_rows([self.r("c.w1", "a window at q=0.85"), self.r("c.w2", "a window at q=0.85")])
        self.assertEqual(len(out), 1)
        self.assertNotIn("in brackets", out[0][3])
        self.assertIn("the same statement", out[0][3])

    def test_ids_without_a_variant_are_never_merged(self):
        rows = [self.r("c.negative", "x 1"), self.r("c.negative", "x 2")]
        self.assertEqual(len(M.grouped_claim_rows(rows)), 2)

    def test_tex_args_reads_nested_and_escaped_braces(self):
        line = "\\dfcclaimrow{a.b}{Eq. (1)}{set \\{x\\} with {nested {deep}} text}{holds}{sampled}{paper}\n"
        self.assertEqual(M.tex_args(line, 6), ["a.b", "Eq. (1)", "set \\{x\\} with {nested {deep}} text", "holds", "sampled", "paper"])
        with self.assertRaises(ValueError):
            M.tex_args("\\dfcclaimrow{a}{b}", 6)


class Typeset(unittest.TestCase):
    """The statements' mathematics typeset by claims_map.typeset: known words only, ids untouched."""

    def test_known_words_become_mathematics(self):
        self.assertEqual(M.typeset(r"T $>$= 3pi/2 on [t2, t3], J\_i, 1e-10, 5e-05, vartheta0, theta2 != t2"),
                         r"T $\ge$ $3\pi/2$ on [$t_2$, $t_3$], $J_i$, $10^{-10}$, $5\cdot10^{-5}$, $\vartheta_0$, $\theta_2$ $\ne$ $t_2$")
        self.assertEqual(M.typeset(r"(0\textasciicircum{}(m-1)1)\textasciicircum{}infinity"), r"$(0^{m-1}1)^\infty$")

    def test_identifiers_and_paths_are_left_alone(self):
        for text in (r"jump\_at\_least and t2\_cycle, b\_over\_a\_max", r"\path{cert.t2} and \texttt{t2}", "typical steps at 2k+1",
                     "the L1 distance", "Li-Yorke chaos, bi-infinite", r"costs \$t2 and \$\$", "3.5pi/2",
                     "(I1)-(I9), (z-0), (q-2b), 0-1 matrix", "the paper's values and (q/a)'s", r"\path{a - b} and \path{x\_k}"):
            self.assertEqual(M.typeset(text), text)

    def test_minus_signs_indices_and_formulas(self):
        # a hyphen between spaces, or before a bracket after a space, is a minus sign
        self.assertEqual(M.typeset(r"x - y $>$= -(2a + b)"), r"x $-$ y $\ge$ $-$(2a + b)")
        # a one-letter base with a one-character index, the spectral radius, and the tangency condition whole
        self.assertEqual(M.typeset(r"T(I\_j) contains I\_k, ln rho(A), z\_1 $<$ ... $<$ z\_n"),
                         r"T($I_j$) contains $I_k$, ln $\rho(A)$, $z_1$ $<$ ... $<$ $z_n$")
        self.assertEqual(M.typeset(r"the z\_k with 2z - (a/b) cos z = (2k+1) pi, T1(z\_k) = z\_k - (a/b) cos z\_k"),
                         r"the $z_k$ with $2z-(a/b)\cos z=(2k+1)\pi$, $T_1$($z_k$) = $z_k-(a/b)\cos z_k$")
        # derivatives, the left limit of a jump and minus infinity; a possessive stays
        self.assertEqual(M.typeset(r"$|$T1'$|$ $>$= 1000, T' = 0, u' $<$ 0, T1(z-0) - T1(z), lambda is minus infinity, T's fiber"),
                         r"$|T_1'|$ $\ge$ 1000, $T'$ = 0, $u'$ $<$ 0, $T_1(z-0)$ $-$ $T_1$(z), $\lambda$ is $-\infty$, T's fiber")
        # an opening quote after a space or a bracket is one; apostrophes stay
        self.assertEqual(M.typeset("the paper's 'b $<$$<$ q' (and 'x')"), r"the paper's `b $\ll$ q' (and `x')")


if __name__ == "__main__":
    unittest.main()
