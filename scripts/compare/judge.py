#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Judge two tables of T (from t_table.cpp) against the 40-digit reference.

  judge.py OLD NEW        (both: lines `b/a q/a theta T scenario`, the same phases in the same order)
  judge.py --errors TABLE (the errors of one table at every mapped phase; ~2 min for 35 315 phases)

Every phase where the two values of T differ is evaluated by tests/precision_reference.py (mpmath,
40 digits, written from the paper alone), with T read as the exact binary value of the printed
double. Per b/a the table gives:
  mapped      phases that both builds map (rows that fail in both are counted apart: failed)
  changed     of those, how many values of T differ, and the largest change in ulp of T
  new closer, old closer, equal
              in how many changed phases each value is closer to the reference (equal: the same
              distance, which two different doubles can have)
  mean and largest error of each among the changed phases.
Phases whose scenario changed, or that one build maps and the other does not, are listed in full.
With --errors, per b/a: the mapped phases, the largest error of T and where (q/a, theta), the
conditioning |dT/dtheta| there (from the reference at theta and theta (1 + 1e-10); a discontinuity
in between would show as a huge value), and the backward error: the error of T divided by
|dT/dtheta|, in ulp of theta (how far theta would have to move for the reference to give the
computed T); and how many errors exceed 2.1e-14 (the largest the CTest precision_reference
measures at its random phases), with the largest backward error among them. Phases where the
reference has no T are counted apart.
Exit status 0 with the table; 2 (one line on stderr) when a file cannot be read, its lines are
not of this form, the two tables do not hold the same phases (the first differing line is named:
a change that moves t2 or t3 moves every phase, which this comparison cannot follow), or the
reference fails.
"""
import collections
import math
import os
import subprocess
import sys

from mpmath import mp, mpf

mp.dps = 40
# --errors: errors above this (the largest the CTest precision_reference measures at its random
# phases, docs/accuracy.md) are each divided by the conditioning |dT/dtheta| there.
LARGE = 2.1e-14
REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tests', 'precision_reference.py')


class BadInput(Exception):
    pass


def value(text):
    """T as a double, or None for a failure (nan, -nan)."""
    x = float(text)
    return None if math.isnan(x) else x


def rows(path):
    try:
        with open(path) as f:
            out = []
            for k, line in enumerate(f, 1):
                if not line.strip():
                    continue
                r = line.split()
                if len(r) != 5:
                    raise BadInput(f'{path}:{k}: expected `b/a q/a theta T scenario`, got {line.strip()!r}')
                try:
                    float(r[0]), float(r[1]), float(r[2]), float(r[3])
                except ValueError:
                    raise BadInput(f'{path}:{k}: not numbers: {line.strip()!r}') from None
                out.append((k, r))
            return out
    except OSError as e:
        raise BadInput(f'{path}: cannot read ({e.strerror})') from None


def ulp_distance(x, y):
    return abs(x - y) / math.ulp(max(abs(x), abs(y)))


def reference_T(b, q, thetas):
    r = subprocess.run(['/usr/bin/python3', REFERENCE, 'eval', '1', b, q] + thetas, capture_output=True, text=True)
    lines = r.stdout.splitlines()[1:]
    if r.returncode != 0 or len(lines) != len(thetas):
        raise BadInput(f'the reference failed for b/a={b} q/a={q}: ' + (r.stderr.strip().splitlines() or ['no output'])[-1])
    out = []
    for line in lines:
        f = line.split('\t')
        try:
            out.append(mpf(f[2]))
        except (IndexError, ValueError):
            out.append(None)  # the reference has no T here (e.g. no return to free flight)
    return out


def error(x, ref):
    """|x - ref| for the double x, as a float."""
    return float(abs(mpf(x) - ref))


def judge(old, new):
    if len(old) != len(new):
        raise BadInput(f'the tables hold {len(old)} and {len(new)} phases')
    for (k, o), (_, n) in zip(old, new):
        if o[:3] != n[:3]:
            raise BadInput(f'the tables differ in their phases from line {k} on: {" ".join(o[:3])} against {" ".join(n[:3])}')
    mapped, failed = collections.Counter(), collections.Counter()
    changed = collections.defaultdict(list)
    listed = []
    for (_, o), (_, n) in zip(old, new):
        vo, vn = value(o[3]), value(n[3])
        if vo is None and vn is None:
            failed[o[0]] += 1
            continue
        if vo is None or vn is None or o[4] != n[4]:
            listed.append((o, n))
        if vo is None or vn is None:
            continue
        mapped[o[0]] += 1
        if vo != vn:
            changed[(o[0], o[1])].append((o, n, vo, vn))
    stats = collections.defaultdict(lambda: {'n': 0, 'ulp': 0.0, 'new': 0, 'old': 0, 'equal': 0, 'en': [], 'eo': [], 'noref': 0})
    for (b, q), group in changed.items():
        refs = reference_T(b, q, [o[2] for o, _, _, _ in group])
        for (o, n, vo, vn), ref in zip(group, refs):
            s = stats[b]
            s['n'] += 1
            s['ulp'] = max(s['ulp'], ulp_distance(vo, vn))
            if ref is None:
                s['noref'] += 1
                continue
            e_old, e_new = error(vo, ref), error(vn, ref)
            s['new' if e_new < e_old else 'old' if e_old < e_new else 'equal'] += 1
            s['en'].append(e_new)
            s['eo'].append(e_old)
    print('b/a\tmapped\tfailed\tchanged\tmax change [ulp]\tnew closer\told closer\tequal\t'
          'mean err new\tmean err old\tmax err new\tmax err old')
    for b in sorted(set(mapped) | set(failed), key=lambda x: -float(x)):
        s = stats.get(b)
        head = f'{float(b):.0e}\t{mapped[b]}\t{failed[b]}'
        if not s:
            print(head + '\t0' + '\t-' * 8)
            continue
        m = len(s['en'])
        errs = (f"{sum(s['en']) / m:.2g}\t{sum(s['eo']) / m:.2g}\t{max(s['en']):.2g}\t{max(s['eo']):.2g}" if m else '-\t-\t-\t-')
        print(f"{head}\t{s['n']}\t{s['ulp']:.0f}\t{s['new']}\t{s['old']}\t{s['equal']}\t{errs}")
        if s['noref']:
            print(f"  ({s['noref']} changed phases at b/a={b} have no reference value: not judged)")
    for o, n in listed:
        print(f'changed scenario or failure: b/a={o[0]} q/a={o[1]} theta={o[2]}: old {o[3]} {o[4]}, new {n[3]} {n[4]}')


def errors(table):
    groups = collections.defaultdict(list)
    for _, r in table:
        if value(r[3]) is not None:
            groups[(r[0], r[1])].append(r)
    worst = {}  # b/a -> (error, q/a, theta)
    large = collections.defaultdict(list)  # b/a -> [(error, q/a, theta)] with error > LARGE
    mapped, noref = collections.Counter(), collections.Counter()
    for (b, q), group in groups.items():
        for r, ref in zip(group, reference_T(b, q, [r[2] for r in group])):
            mapped[b] += 1
            if ref is None:
                noref[b] += 1
                continue
            e = error(float(r[3]), ref)
            if b not in worst or e > worst[b][0]:
                worst[b] = (e, q, r[2])
            if e > LARGE:
                large[b].append((e, q, r[2]))

    def conditioning(b, q, th, e):
        """|dT/dtheta| at theta, and e divided by it in ulp of theta."""
        h = float(th) * 1e-10
        t0, t1 = reference_T(b, q, [th, repr(float(th) + h)])
        slope = float(abs(t1 - t0)) / h if t0 is not None and t1 is not None else float('nan')
        return slope, (e / slope / math.ulp(float(th)) if slope > 0 else float('nan'))

    print('b/a\tmapped\tno reference\tmax error\tq/a\ttheta\t|dT/dtheta|\tbackward error [ulp of theta]\t'
          f'errors above {LARGE:g}\ttheir largest backward error [ulp of theta]')
    for b in sorted(mapped, key=lambda x: -float(x)):
        if b not in worst:
            print(f'{float(b):.0e}\t{mapped[b]}\t{noref[b]}' + '\t-' * 7)
            continue
        e, q, th = worst[b]
        slope, back = conditioning(b, q, th, e)
        big = max((conditioning(b, *x[1:], x[0])[1] for x in large[b]), default=None)
        print(f'{float(b):.0e}\t{mapped[b]}\t{noref[b]}\t{e:.2g}\t{q}\t{th}\t{slope:.2g}\t{back:.2g}\t'
              f'{len(large[b])}\t' + ('-' if big is None else f'{big:.2g}'))


def main(argv):
    if len(argv) != 3 or (argv[1].startswith('-') and argv[1] != '--errors'):
        print('usage: judge.py OLD NEW | judge.py --errors TABLE', file=sys.stderr)
        return 2
    try:
        if argv[1] == '--errors':
            errors(rows(argv[2]))
        else:
            judge(rows(argv[1]), rows(argv[2]))
    except BadInput as e:
        print(f'judge: {e}', file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
