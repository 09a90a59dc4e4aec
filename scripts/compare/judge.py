#!/usr/bin/python3
"""Judge two tables of T (from t_table.cpp) against the 40-digit reference.

  judge.py OLD NEW        (both: lines `b/a q/a theta T scenario`, the same phases in the same order)

Every phase where the two values of T differ is evaluated by tests/precision_reference.py (mpmath,
40 digits, written from the paper alone); per b/a the table gives how many phases changed, the
largest change in ulp of T, in how many the new or the old value is closer to the reference, and
the mean and largest error of each among the changed phases. A changed scenario, or a phase that
one build maps and the other does not, is listed in full. Exit status 1 when the tables do not
hold the same phases, 0 otherwise (the verdict is for the reader: this prints evidence).
"""
import collections
import math
import os
import subprocess
import sys

from mpmath import mp, mpf

mp.dps = 40
REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tests', 'precision_reference.py')


def rows(path):
    with open(path) as f:
        return [line.split() for line in f if line.strip()]


def ulp_distance(x, y):
    return abs(x - y) / math.ulp(max(abs(x), abs(y)))


def main(argv):
    if len(argv) != 3:
        print('usage: judge.py OLD NEW', file=sys.stderr)
        return 2
    old, new = rows(argv[1]), rows(argv[2])
    if len(old) != len(new) or any(o[:3] != n[:3] for o, n in zip(old, new)):
        print('judge: the two tables do not hold the same phases', file=sys.stderr)
        return 1
    total = collections.Counter(o[0] for o in old)
    changed = collections.defaultdict(list)
    listed = []
    for o, n in zip(old, new):
        if o[3] == n[3] and o[4] == n[4]:
            continue
        if o[4] != n[4] or o[3] == 'nan' or n[3] == 'nan':
            listed.append((o, n))
        if o[3] != 'nan' and n[3] != 'nan' and o[3] != n[3]:
            changed[(o[0], o[1])].append((o, n))
    stats = collections.defaultdict(lambda: {'n': 0, 'ulp': 0.0, 'new': 0, 'old': 0, 'en': [], 'eo': []})
    for (b, q), pairs in changed.items():
        out = subprocess.run(['/usr/bin/python3', REFERENCE, 'eval', '1', b, q] + [o[2] for o, _ in pairs],
                             capture_output=True, text=True, check=True).stdout.splitlines()[1:]
        for (o, n), line in zip(pairs, out):
            ref = mpf(line.split('\t')[2])
            e_old, e_new = float(abs(mpf(o[3]) - ref)), float(abs(mpf(n[3]) - ref))
            s = stats[b]
            s['n'] += 1
            s['ulp'] = max(s['ulp'], ulp_distance(float(o[3]), float(n[3])))
            if e_new < e_old:
                s['new'] += 1
            elif e_old < e_new:
                s['old'] += 1
            s['en'].append(e_new)
            s['eo'].append(e_old)
    print('b/a\tphases\tchanged\tmax change [ulp]\tnew closer\told closer\tmean err new\tmean err old\tmax err new\tmax err old')
    for b in sorted(total, key=lambda x: -float(x)):
        s = stats.get(b)
        if not s:
            print(f'{float(b):.0e}\t{total[b]}\t0\t-\t-\t-\t-\t-\t-\t-')
            continue
        print(f"{float(b):.0e}\t{total[b]}\t{s['n']}\t{s['ulp']:.0f}\t{s['new']}\t{s['old']}\t"
              f"{sum(s['en']) / s['n']:.2g}\t{sum(s['eo']) / s['n']:.2g}\t{max(s['en']):.2g}\t{max(s['eo']):.2g}")
    for o, n in listed:
        print(f'changed scenario or failure: b/a={o[0]} q/a={o[1]} theta={o[2]}: old {o[3]} {o[4]}, new {n[3]} {n[4]}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
