#!/usr/bin/env bash
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
  if ! grep -qF -e "\\dfcfigure{$name}" -e "\\dfcfigurenodata{$name}" "$root/paper/report.tex"; then
    echo "build-report: figure $name (figures/$name.gp) is not in paper/report.tex" >&2
    exit 1
  fi
done

export TEXINPUTS="$root/paper:$abs/figures:$abs/tables:$abs/bench:"
force=()
# latexmk does not know of a table that did not exist at its last run (the optional bench table)
if [[ -f "$abs/bench/bench.tex" && -f "$out/report.pdf" && "$abs/bench/bench.tex" -nt "$out/report.pdf" ]]; then force=(-g); fi
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
pages=$(pdfinfo "$out/report.pdf" 2>/dev/null | awk '/^Pages:/ {print $2}')
echo "report: $out/report.pdf (${pages:-?} pages)"
