#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Test of scripts/compare/judge.py, the verdict of scripts/compare-builds.sh.

  compare_judge.py T_TABLE      (T_TABLE: the driver scripts/compare/t_table.cpp, built against this library)

1. The driver's table: 36 324 phases, failing exactly where q <= 2b (outside the map's domain).
2. The table against itself: no value changed in any row; the failures counted apart.
3. Tables with known answers, made from the driver's table:
   - b/a = 1e-3: OLD moved up by 5e-13 (so NEW, the library's value, is closer);
   - b/a = 0.1: NEW moved down by 5e-13 (so OLD is closer; the smaller T is the worse one here);
   - b/a = 1e-2: the scenario changed, T not; b/a = 1e-4: NEW fails at one phase; b/a = 1e-5:
     both fail (printed -nan) at one phase.
   The judge must count and list each as stated, give the change in ulp and the errors of each
   side, and refuse tables with different phases (exit status 2, naming the line).
4. --errors on two phases, one moved by 1e-12: that error, at that phase, counted above 2.1e-14.
"""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
JUDGE = os.path.join(HERE, '..', 'scripts', 'compare', 'judge.py')
SHIFT = 5e-13


def judge(old, new):
    r = subprocess.run(['/usr/bin/python3', JUDGE, old, new], capture_output=True, text=True)
    rows, listed = {}, []
    for line in r.stdout.splitlines()[1:]:
        f = line.split('\t')
        if len(f) == 12:
            rows[f[0]] = f
        elif line.startswith('changed scenario or failure:'):
            listed.append(line)
    return r.returncode, rows, listed, r.stdout + r.stderr


def write(path, lines):
    with open(path, 'w') as f:
        f.write('\n'.join(' '.join(x) for x in lines) + '\n')


def main():
    table = subprocess.run([sys.argv[1]], capture_output=True, text=True, check=True).stdout
    lines = [l.split() for l in table.splitlines()]
    failures = []

    def check(ok, what, text=''):
        if not ok:
            failures.append(what + ('\n' + text if text else ''))

    check(len(lines) == 36324, f'the driver printed {len(lines)} phases, expected 36324 (12 b/a x 3 q/a x 1009)')
    outside = [float(l[1]) <= 2 * float(l[0]) for l in lines]
    fails = [l[3] == 'nan' for l in lines]
    check(fails == outside and sum(fails) == 1009, f'the driver failed at {sum(fails)} phases; expected exactly the 1009 with q <= 2b')

    with tempfile.TemporaryDirectory() as d:
        same, po, pn = (os.path.join(d, x) for x in ('same.txt', 'old.txt', 'new.txt'))
        write(same, lines)
        code, rows, listed, text = judge(same, same)
        check(code == 0 and len(rows) == 12 and all(r[3] == '0' for r in rows.values()) and not listed,
              'a table against itself: expected 12 rows, none changed, nothing listed', text)
        check(rows.get('3e-01', [None] * 3)[1:3] == ['2018', '1009'], 'a table against itself: b/a = 0.3 should have 2018 mapped, 1009 failed', text)

        def first(ba):
            return next(i for i, l in enumerate(lines) if float(l[0]) == ba and l[3] != 'nan')

        old, new = [list(l) for l in lines], [list(l) for l in lines]
        i, j, k, m, n = first(1e-3), first(0.1), first(1e-2), first(1e-4), first(1e-5)
        ti, tj = float(lines[i][3]), float(lines[j][3])
        old[i][3] = repr(ti + SHIFT)
        new[j][3] = repr(tj - SHIFT)
        new[k][4] = 'X'
        new[m][3:5] = ['nan', 'err']
        old[n][3:5] = new[n][3:5] = ['-nan', 'err']
        write(po, old)
        write(pn, new)
        code, rows, listed, text = judge(po, pn)
        check(code == 0, f'known answers: exit status {code}', text)
        for ba, t, moved, closer in (('1e-03', ti, 'old', (1, 0)), ('1e-01', tj, 'new', (0, 1))):
            r = rows.get(ba)
            if r is None:
                check(False, f'b/a = {ba}: no row', text)
                continue
            ulps = SHIFT / math.ulp(t)
            check(r[3] == '1' and (int(r[5]), int(r[6])) == closer and r[7] == '0',
                  f'b/a = {ba}: expected 1 changed, new/old closer {closer}, 0 equal', text)
            check(abs(float(r[4]) - ulps) <= 1, f'b/a = {ba}: change {r[4]} ulp, expected {ulps:.0f}', text)
            e_moved, e_kept = (float(r[10]), float(r[11])) if moved == 'new' else (float(r[11]), float(r[10]))
            check(0.8 * SHIFT < e_moved < 1.2 * SHIFT and e_kept < 0.2 * SHIFT,
                  f'b/a = {ba}: the moved value ({moved}) should be off by about {SHIFT}, the other by far less', text)
        check(rows.get('1e-02', [None] * 4)[3] == '0', 'b/a = 1e-2: a changed scenario with T unchanged counts no changed value', text)
        check(rows.get('1e-04', [None] * 3)[1:3] == ['3026', '0'], 'b/a = 1e-4: one side failing is not mapped, and not failed in both', text)
        check(rows.get('1e-05', [None] * 3)[1:3] == ['3026', '1'], 'b/a = 1e-5: -nan in both counts as failed', text)
        want = {f'b/a={lines[x][0]} q/a={lines[x][1]} theta={lines[x][2]}' for x in (k, m)}
        check(len(listed) == 2 and all(any(w in l for l in listed) for w in want),
              'the changed scenario (1e-2) and the one-sided failure (1e-4), and only they, should be listed', text)
        check(all(r[3] == '0' for ba, r in rows.items() if ba not in ('1e-03', '1e-01')), 'other rows report changes', text)

        # --errors on a small table: one value moved by 1e-12 at b/a = 1e-3 (T flat there or not,
        # 1e-12 is far above the library's error), one left as computed.
        small = [list(lines[i]), list(lines[i + 1])]
        small[1][3] = repr(float(small[1][3]) + 1e-12)
        ps = os.path.join(d, 'small.txt')
        write(ps, small)
        r = subprocess.run(['/usr/bin/python3', JUDGE, '--errors', ps], capture_output=True, text=True)
        f = r.stdout.splitlines()[1].split('\t') if r.returncode == 0 and len(r.stdout.splitlines()) == 2 else []
        check(len(f) == 10 and f[1] == '2' and 0.9e-12 < float(f[3]) < 1.1e-12 and f[5] == small[1][2] and f[8] == '1',
              '--errors: expected 2 mapped, the largest error about 1e-12 at the moved phase, 1 error above 2.1e-14',
              r.stdout + r.stderr)

        other = [list(l) for l in lines]
        other[7][2] = repr(float(other[7][2]) * (1 + 1e-12))
        write(pn, other)
        code, _, _, text = judge(same, pn)
        check(code == 2 and 'line 8' in text, f'tables with different phases: expected exit status 2 naming line 8, got {code}', text)
    for f in failures:
        print('FAIL:', f)
    print('compare_judge:', 'ok' if not failures else f'{len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
