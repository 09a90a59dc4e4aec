#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Doxygen HTML of the dfchaos library, CLI and experiments in BUILD/docs/html, with MathJax for the
# formulas in the comments, and one page per experiment linking its source, its data tables, its
# LaTeX outputs and the figures drawn from it. Fails when Doxygen warns about the public API.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$build/docs/pages"
abs=$(cd "$build" && pwd)
pages="$abs/docs/pages"
rm -f "$pages"/*.md

# One page per experiment.
{
  echo "# Experiments {#experiments}"
  echo
  echo "One executable per claim of the paper; each writes build/data, build/tables and build/claims."
  echo
} > "$pages/experiments.md"
for src in "$root"/experiments/*.cpp; do
  name=$(basename "$src" .cpp)
  [[ $name == harness ]] && continue  # the shared shell, not an experiment
  brief=$(grep -m1 '@brief' "$src" | sed 's|.*@brief *||')
  echo "- @subpage exp_$name — $brief" >> "$pages/experiments.md"
  {
    echo "# $name {#exp_$name}"
    echo
    echo "$brief"
    echo
    echo "- Source: @ref $name.cpp \"experiments/$name.cpp\""
    echo "- Run: \`build/bin/experiments/$name --out build\` (\`--fast\` for the smoke mode, \`--help\` for its parameters)"
    echo "- Claims with verdicts: [build/claims/$name.json](../../claims/$name.json)"
    echo "- Data tables:"
    found=0
    for d in "$abs"/data/"$name".tsv "$abs"/data/"$name"-*.tsv; do
      [[ -f "$d" ]] || continue
      found=1
      echo "  - [$(basename "$d")](../../data/$(basename "$d"))"
    done
    ((found)) || echo "  - (none yet: run \`make reproduce\`)"
    echo "- Figures drawn from its data:"
    found=0
    for g in "$root"/figures/fig_*.gp; do
      if grep -q "$name" "$g"; then
        found=1
        f=$(basename "$g" .gp)
        echo "  - [$f.pdf](../../figures/$f.pdf), script figures/$f.gp"
      fi
    done
    ((found)) || echo "  - (none)"
  } > "$pages/exp_$name.md"
done

cat > "$abs/docs/Doxyfile" <<DOX
PROJECT_NAME           = dfchaos
PROJECT_BRIEF          = "Dry-friction oscillator of Begun & Kryzhevich: return maps, experiments, claims"
OUTPUT_DIRECTORY       = $abs/docs
INPUT                  = $root/README.md $root/src/dfchaos $root/src/dfchaos/certified $root/src/kit/kit $root/src/sweep/sweep $root/src/certify/certify/certificate.hpp $root/src/cli $root/experiments $pages
FILE_PATTERNS          = *.hpp *.cpp *.md
RECURSIVE              = NO
USE_MDFILE_AS_MAINPAGE = $root/README.md
EXTRACT_ALL            = NO
EXTRACT_STATIC         = NO
HIDE_UNDOC_MEMBERS     = NO
WARN_IF_UNDOCUMENTED   = YES
WARN_NO_PARAMDOC       = NO
WARN_LOGFILE           = $abs/docs/warnings.log
QUIET                  = YES
GENERATE_HTML          = YES
GENERATE_LATEX         = NO
USE_MATHJAX            = YES
SOURCE_BROWSER         = YES
EXCLUDE_SYMBOLS        = detail detail::* *::detail::*
STRIP_FROM_PATH        = $root
FULL_PATH_NAMES        = YES
HAVE_DOT               = NO
CLASS_GRAPH            = NO
DOX
doxygen "$abs/docs/Doxyfile"
# Warnings about the public API (the library headers) fail the build; others are shown.
if grep -E "src/dfchaos/.*\.hpp|src/certify/certify/certificate\.hpp" "$abs/docs/warnings.log" > "$abs/docs/api-warnings.log"; then
  echo "docs: Doxygen warnings on the public API:" >&2
  head -30 "$abs/docs/api-warnings.log" >&2
  exit 1
fi
other=$(wc -l < "$abs/docs/warnings.log")
echo "docs: $abs/docs/html/index.html (public API warning-free; $other other warning line(s) in docs/warnings.log)"
