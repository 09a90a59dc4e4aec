#!/usr/bin/python3
"""Test of scripts/compare/judge.py, the verdict of scripts/compare-builds.sh.

  compare_judge.py T_TABLE      (T_TABLE: the driver scripts/compare/t_table.cpp, built against this library)

1. The driver's table against itself: every b/a row reports 0 changed values.
2. A table where single values of T are moved off the reference: one phase at b/a = 1e-3 moved by
   5e-13 in OLD (NEW keeps the library's value), one at b/a = 0.1 moved by 5e-13 in NEW. The judge
   must report each as changed and name the closer side correctly, and a table with a different
   phase must be refused (exit status 1).
"""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
JUDGE = os.path.join(HERE, '..', 'scripts', 'compare', 'judge.py')


def judge(old, new):
    r = subprocess.run(['/usr/bin/python3', JUDGE, old, new], capture_output=True, text=True)
    rows = {}
    for line in r.stdout.splitlines()[1:]:
        f = line.split('\t')
        if len(f) == 10:
            rows[f[0]] = f
    return r.returncode, rows, r.stdout + r.stderr


def write(path, lines):
    with open(path, 'w') as f:
        f.write('\n'.join(' '.join(x) for x in lines) + '\n')


def main():
    table = subprocess.run([sys.argv[1]], capture_output=True, text=True, check=True).stdout
    lines = [l.split() for l in table.splitlines()]
    failures = []
    if len(lines) != 36324:
        failures.append(f'the driver printed {len(lines)} phases, expected 36324 (12 b/a x 3 q/a x 1009)')
    with tempfile.TemporaryDirectory() as d:
        same = os.path.join(d, 'same.txt')
        write(same, lines)
        code, rows, text = judge(same, same)
        if code != 0 or len(rows) != 12 or any(r[2] != '0' for r in rows.values()):
            failures.append('a table against itself: expected 12 rows with 0 changed, got:\n' + text)

        def first(ba):
            return next(i for i, l in enumerate(lines) if float(l[0]) == ba and l[3] != 'nan')

        old, new = [list(l) for l in lines], [list(l) for l in lines]
        i, j = first(1e-3), first(0.1)
        old[i][3] = repr(float(lines[i][3]) + 5e-13)  # old is off: new closer at 1e-3
        new[j][3] = repr(float(lines[j][3]) + 5e-13)  # new is off: old closer at 0.1
        po, pn = os.path.join(d, 'old.txt'), os.path.join(d, 'new.txt')
        write(po, old)
        write(pn, new)
        code, rows, text = judge(po, pn)
        want = {'1e-03': ('1', '1', '0'), '1e-01': ('1', '0', '1')}
        for ba, (changed, new_closer, old_closer) in want.items():
            r = rows.get(ba)
            if code != 0 or r is None or (r[2], r[4], r[5]) != (changed, new_closer, old_closer):
                failures.append(f'b/a = {ba}: expected changed {changed}, new closer {new_closer}, old closer {old_closer}; got:\n' + text)
        if any(r[2] != '0' for ba, r in rows.items() if ba not in want):
            failures.append('rows other than 1e-03 and 1e-01 report changes:\n' + text)

        other = [list(l) for l in lines]
        other[0][2] = repr(float(other[0][2]) * (1 + 1e-12))
        write(pn, other)
        code, _, text = judge(po, pn)
        if code != 1:
            failures.append(f'tables with different phases: expected exit status 1, got {code}:\n' + text)
    for f in failures:
        print('FAIL:', f)
    print('compare_judge:', 'ok' if not failures else f'{len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
