#!/usr/bin/env bash
# Bad-input battery for every experiment: for each numeric option its --help lists, a non-number,
# an empty string, NaN, infinities and a negative value (for counts also zero and huge values; for
# the model's b and q also zero, and b >= a/2) must give exit
# status 2, exactly one line on stderr naming the option, nothing on stdout, and no output file at
# all (outputs are written only at the end, atomically). Usage: experiment_errors.sh BIN_DIR
set -u
dir=$1
fails=0
checks=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for exe in "$dir"/*; do
  name=$(basename "$exe")
  # numeric options: lines like "  --b FLOAT ..." or "  --n INT ..."
  mapfile -t opts < <("$exe" --help | grep -oE -- '--[a-z][a-z0-9-]* (FLOAT|INT)' | sort -u)
  for entry in "${opts[@]}"; do
    opt=${entry%% *}
    type=${entry##* }
    values=(x nan inf -inf -1 "")
    # zero: an empty grid or count (except options for which 0 is meaningful)
    [[ $type == INT && $opt != --transient && $opt != --uniform ]] && values+=(0 1e300 99999999999999999999)
    # the parameters of the model: zero, and b >= a/2 (no return map)
    [[ $opt == --b || $opt == --q ]] && values+=(0)
    [[ $opt == --b ]] && values+=(0.5 0.7)
    for v in "${values[@]}"; do
      checks=$((checks + 1))
      out="$tmp/out-$name"
      rm -rf "$out"
      "$exe" --fast --out "$out" "$opt" "$v" >"$tmp/stdout" 2>"$tmp/stderr"
      rc=$?
      lines=$(wc -l <"$tmp/stderr")
      files=$( [[ -d "$out" ]] && find "$out" -type f | wc -l || echo 0)
      if [[ $rc -ne 2 || -s "$tmp/stdout" || $lines -ne 1 || $files -ne 0 ]] || ! grep -q -- "${opt#--}" "$tmp/stderr"; then
        echo "FAIL: $name $opt $v -> rc=$rc, stdout $(wc -c <"$tmp/stdout") bytes, stderr $lines lines, $files files: $(head -c 300 "$tmp/stderr")"
        fails=$((fails + 1))
      fi
    done
  done
  # an unknown option
  checks=$((checks + 1))
  "$exe" --fast --out "$tmp/unk" --no-such-option 1 >"$tmp/stdout" 2>"$tmp/stderr"
  rc=$?
  if [[ $rc -ne 2 || $(wc -l <"$tmp/stderr") -ne 1 || -e "$tmp/unk" ]]; then
    echo "FAIL: $name --no-such-option -> rc=$rc: $(head -c 300 "$tmp/stderr")"
    fails=$((fails + 1))
  fi
done
echo "$((checks - fails)) passed, $fails failed"
((fails == 0))
