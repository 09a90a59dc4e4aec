#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A researcher's extension of the report (docs/adding-an-experiment.md) must not fail on the project's
# page limits when built with REPORT_LIMITS=warn, and must fail without it. After `make reproduce`,
# this copies the report's sources to a scratch tree, adds a throwaway section with a figure of its
# own (a gnuplot script over an experiment's data, as a new experiment would have) and three pages of
# text, and typesets it with scripts/build-report.sh over the build's results (linked, not touched):
#   - DFCHAOS_REPORT_LIMITS=strict: it must fail, naming the length;
#   - DFCHAOS_REPORT_LIMITS=warn: it must succeed, with the length as a warning.
# Usage: scripts/check-report-extension.sh [BUILD]     (make check-report-extension)
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
root=$(cd "$(dirname "$0")/.." && pwd)
for need in bin/experiments claims data figures tables certificates; do
  [[ -e "$build/$need" ]] || { echo "check-report-extension: $build/$need is missing: run make reproduce first" >&2; exit 2; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The scratch tree: the scripts, figures and paper of this checkout, and a build directory whose
# results are links to the real ones; tables and paper are copies, since the report step writes them.
mkdir -p "$tmp/src" "$tmp/build"
cp -r "$root/scripts" "$root/figures" "$root/paper" "$root/tests" "$tmp/src/"
for d in bin claims data certificates region bench stamps; do
  [[ -e "$build/$d" ]] && ln -s "$build/$d" "$tmp/build/$d"
done
cp -r "$build/tables" "$tmp/build/tables"
mkdir -p "$tmp/build/figures"
cp "$build"/figures/*.tex "$build"/figures/*.pdf "$tmp/build/figures/"
# The throwaway experiment's figure and section.
cat > "$tmp/src/figures/fig_throwaway.gp" <<'GP'
load figdir."/style.gp"
set terminal cairolatex pdf input size 10cm,5cm
set output "fig_throwaway.tex"
set xlabel '$\theta$'; set ylabel '$T$'
plot data."/sec6_periodic_points-graph.tsv" using "theta":"T" w p pt 7 ps 0.1 notitle
GP
(cd "$tmp/build/figures" && gnuplot -e "data='$build/data'; figdir='$tmp/src/figures'" "$tmp/src/figures/fig_throwaway.gp")
cat > "$tmp/section.tex" <<'TEX'
\section{A throwaway extension}\label{app:throwaway}
Fig.~\ref{fig:fig_throwaway} shows $T$ again.
\dfcfigure{fig_throwaway}{$T$ once more, for the check of an extension.}{sec6_periodic_points}
\clearpage\null\clearpage\null\clearpage\null
TEX
python3 - "$tmp/src/paper/report.tex" "$tmp/section.tex" <<'PY'
import sys
path, section = sys.argv[1], open(sys.argv[2]).read()
text = open(path).read()
anchor = "\\section{Every claim, by experiment}"
assert anchor in text, "the report has no appendix of claims to put the extension before"
open(path, "w").write(text.replace(anchor, section + anchor, 1))
PY
if DFCHAOS_REPORT_LIMITS=strict bash "$tmp/src/scripts/build-report.sh" "$tmp/build" > "$tmp/strict.log" 2>&1; then
  echo "check-report-extension: FAIL: the extended report passed the strict length check" >&2; cat "$tmp/strict.log" >&2; exit 1
fi
grep -q "pages (at most" "$tmp/strict.log" || { echo "check-report-extension: FAIL: the strict build failed, but not on the length:" >&2; cat "$tmp/strict.log" >&2; exit 1; }
if ! DFCHAOS_REPORT_LIMITS=warn bash "$tmp/src/scripts/build-report.sh" "$tmp/build" > "$tmp/warn.log" 2>&1; then
  echo "check-report-extension: FAIL: the extended report failed with DFCHAOS_REPORT_LIMITS=warn:" >&2; cat "$tmp/warn.log" >&2; exit 1
fi
grep -q "warning: the report has" "$tmp/warn.log" || { echo "check-report-extension: FAIL: no length warning:" >&2; cat "$tmp/warn.log" >&2; exit 1; }
if DFCHAOS_REPORT_LIMITS=loose bash "$tmp/src/scripts/build-report.sh" "$tmp/build" > "$tmp/bad.log" 2>&1 || [[ $? -ne 2 ]]; then
  echo "check-report-extension: FAIL: DFCHAOS_REPORT_LIMITS=loose was not refused with exit 2" >&2; cat "$tmp/bad.log" >&2; exit 1
fi
echo "check-report-extension: a $(pdfinfo "$tmp/build/paper/report.pdf" | awk '/^Pages:/ {print $2}')-page extension fails the strict limits and passes with REPORT_LIMITS=warn"
