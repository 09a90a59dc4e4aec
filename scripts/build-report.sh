#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Typesets build/paper/report.pdf from paper/report.tex with latexmk, and fails loudly when the
# report is incomplete:
#   - a figure, table or macro file that is missing stops LaTeX (\input of a missing file,
#     undefined control sequence: -halt-on-error);
#   - an undefined reference or citation, or a verdict that no experiment produced, is an error;
#   - the claims map and the per-experiment appendices are generated (scripts/claims_map.py) from
#     every experiment's declaration and claims, so no experiment can be left out.
# latexmk reruns only when one of the report's inputs changed.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
abs=$(cd "$build" && pwd)
out="$abs/paper"
mkdir -p "$out"

# The generated parts: every experiment's macros and verdicts, the claims map, the appendices.
python3 "$root/scripts/claims_map.py" "$abs" "$root" > "$abs/claims-map.log" || { cat "$abs/claims-map.log" >&2; exit 1; }
# Every figure script has its figure in the report.
for g in "$root"/figures/fig_*.gp; do
  name=$(basename "$g" .gp)
  if ! grep -qF -e "\\dfcfigure{$name}" -e "\\dfcfigureof{$name}" -e "\\dfcfigurenodata{$name}" "$root/paper/report.tex"; then
    echo "build-report: figure $name (figures/$name.gp) is not in paper/report.tex" >&2
    exit 1
  fi
done

export TEXINPUTS="$root/paper:$abs/figures:$abs/tables:$abs/bench:$abs/region:"
force=()
# latexmk does not know of a file that did not exist at its last run (the optional bench table and
# the summary of make certify-region)
for optional in "$abs/bench/bench.tex" "$abs/region/certify-region.tex"; do
  if [[ -f "$optional" && -f "$out/report.pdf" && "$optional" -nt "$out/report.pdf" ]]; then force=(-g); fi
done
if ! (cd "$root/paper" && latexmk "${force[@]}" -pdf -interaction=nonstopmode -halt-on-error -file-line-error \
        -outdir="$out" report.tex > "$out/latexmk.out" 2>&1); then
  rm -f "$out/report.fdb_latexmk"   # so that the next run retries instead of reporting a stale state
  echo "build-report: LaTeX failed; the first errors:" >&2
  grep -E -A3 '^[^:]+:[0-9]+:|^! ' "$out/report.log" 2>/dev/null | head -30 >&2 || tail -30 "$out/latexmk.out" >&2
  exit 1
fi
if grep -E "Reference .* undefined|Citation .* undefined|There were undefined references|dfchaos: missing" "$out/report.log"; then
  echo "build-report: the report has undefined references or missing verdicts (see $out/report.log)" >&2
  exit 1
fi
# Content that ran off a page is not in the PDF at all.
if grep -q 'Overfull \\vbox' "$out/report.log"; then
  grep -B1 'Overfull \\vbox' "$out/report.log" | head -10 >&2
  echo "build-report: content ran off a page (Overfull \\vbox in $out/report.log): it is not in the PDF" >&2
  exit 1
fi
# A line wider than the text by more than 1 pt runs into the margin (a table or a formula too wide).
if awk '/^Overfull \\hbox \(/ { w = $3; sub(/^\(/, "", w); sub(/pt$/, "", w); if (w + 0 > 1) { print; bad = 1 } } END { exit !bad }' "$out/report.log" >&2; then
  echo "build-report: lines wider than the text by more than 1 pt (Overfull \\hbox in $out/report.log)" >&2
  exit 1
fi
# Every claim is in the PDF; no nan, inf or unresolved reference (??) reached it; the main text
# (before the appendices) and the whole report stay within the limits below.
pdftotext -layout "$out/report.pdf" "$out/report.txt"
python3 - "$abs" "$out" <<'PY'
import glob, json, re, subprocess, sys
build, out = sys.argv[1], sys.argv[2]
# The report's length. A referee asked for a main text of at most 24 pages and 32 in all; the main
# text is within it, the whole report one page over with the four views the same referee asked for
# (docs/architecture.md says what was cut and what is left), and one more for the written argument
# behind Lemma 4 for every small b/a (Appendix, issue 50): the second limit stops it growing.
MAX_MAIN, MAX_TOTAL = 24, 34
text = open(out + "/report.txt", encoding="utf-8", errors="replace").read()
flat = re.sub(r"\s+", "", text)
ids = [c["id"] for f in sorted(glob.glob(build + "/claims/*.json")) for c in json.load(open(f))["claims"]]
# Every claim has its row in the appendix of claims: the ids are read as whole tokens from the text
# after that appendix's heading, in content order (-raw: with -layout a table cell that wraps is
# interleaved with its neighbours), rejoining ids that \path broke after a dot or an underscore. A
# family row, e.g. cert.lemma4.{A,B,C,D}, shows each of its claims.
subprocess.run(["pdftotext", "-raw", out + "/report.pdf", out + "/report-raw.txt"], check=True)
raw = open(out + "/report-raw.txt", encoding="utf-8", errors="replace").read()
start = raw.rfind("Every claim, by experiment")
appendix = re.sub(r"([._])\s*\n\s*", r"\1", raw[start:] if start >= 0 else "")
tokens = set()
for tok in re.findall(r"[A-Za-z0-9_.]+(?:\{[A-Za-z0-9,]+\})?", appendix):
    m = re.fullmatch(r"(.*)\{([A-Za-z0-9,]+)\}", tok)
    tokens.update([m.group(1) + v for v in m.group(2).split(",")] if m else [tok.rstrip(".")])
missing = [i for i in ids if i not in tokens]
problems = []
if missing:
    problems.append("claims not in the PDF: " + ", ".join(missing))
# No verdict misread: an erratum that holds is a refutation (never "holds"), and a claim whose
# evidence is precision-limited, or that recorded cases double precision could not decide without a
# counterexample, is never "fails".
for f in sorted(glob.glob(build + "/claims/*.json")):
    for c in json.load(open(f))["claims"]:
        if c["origin"] == "erratum" and c["report_verdict"] == "holds":
            problems.append(f"erratum {c['id']} shown as holds")
        undecided = c["evidence"].get("precision_undecided", 0) if isinstance(c["evidence"], dict) else 0
        if c["verdict"] == "fails" and (c["evidence_kind"] == "precision-limited" or
                                        (undecided and not c["evidence"].get("counterexamples", 0))):
            problems.append(f"claim {c['id']} fails on precision-limited evidence")
for pattern, what in ((r"\?\?", "an unresolved reference (??)"), (r"(?<![A-Za-z])-?nan(?![A-Za-z])", "nan"),
                      (r"(?<![A-Za-z])-?inf(?![A-Za-z])", "inf")):
    m = re.search(pattern, text, flags=re.IGNORECASE)
    if m:
        problems.append(what + " in the PDF text: ..." + text[max(0, m.start() - 60):m.end() + 40].replace("\n", " ") + "...")
aux = open(out + "/report.aux").read()
m = re.search(r"\\newlabel\{app:start\}\{\{[^}]*\}\{(\d+)\}", aux)
if not m:
    problems.append("no label app:start at the appendices")
elif int(m.group(1)) - 1 > MAX_MAIN:
    problems.append(f"the main text runs to page {int(m.group(1)) - 1} (at most {MAX_MAIN}; docs/architecture.md, the report's length)")
pages = int(re.search(r"^Pages:\s+(\d+)", subprocess.run(["pdfinfo", out + "/report.pdf"], capture_output=True, text=True,
                                                           check=True).stdout, re.M).group(1))
if pages > MAX_TOTAL:
    problems.append(f"the report has {pages} pages (at most {MAX_TOTAL}; docs/architecture.md, the report's length)")
# The title page names the version and the git hash of the build (tables/build-info.tex).
info = dict(re.findall(r"\\dfcbuildrow\{([^}]*)\}\{([^}]*)\}", open(build + "/tables/build-info.tex").read()))
title_page = re.sub(r"\s+", "", text.split("\f")[0])
for key in ("dfchaos", "git"):
    if not info.get(key) or re.sub(r"\s+", "", info[key]) not in title_page:
        problems.append(f"the title page does not show {key} {info.get(key)!r} of tables/build-info.tex")
if problems:
    for p in problems:
        print("build-report: " + p, file=sys.stderr)
    sys.exit(1)
print(f"report checks: {len(ids)} claims in the PDF, no nan/inf/??, main text {int(m.group(1)) - 1} pages")
PY
pages=$(pdfinfo "$out/report.pdf" 2>/dev/null | awk '/^Pages:/ {print $2}')
echo "report: $out/report.pdf (${pages:-?} pages)"
