#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Check that a PNG drawn by matplotlib has the expected size and that something was drawn in it.

    check_png.py FILE.png --size WIDTHxHEIGHT [--panels N] [--min-ink F] [--min-colours K]

Fails (exit 1, one line per problem) unless
  - FILE is a PNG of exactly WIDTH x HEIGHT pixels;
  - at least N plot areas are found: rectangles framed by dark lines (the axes' spines), found as
    horizontal and vertical runs of dark pixels at least 40 pixels long that close a rectangle;
    a frame inside another one (a dark line across a plot) is part of the outer one;
  - inside every plot area (its frame and 2 pixels of it left out), at least a fraction F of the
    pixels is ink (differs from white: luminance below 0.85, or a colour with chroma above 0.15)
    and at least K distinct colours occur.
A plot whose data went missing keeps little ink in its plot area, from its reference lines and
legend: 0.0 to 1.5% in the figures of examples/ with their data left out, against 2% and more (3 to
90%) when drawn; a plot filled with one colour (every value masked) has too few colours. Dark means
luminance below 0.5, so a light grid, a grey reference line or a legend's frame does not split a
plot area, and a drawing entirely in one dark colour can hide its own frame (then no area is found).
Prints one line per plot area (position, ink fraction, colours) on success.
"""
import argparse
import sys

import numpy as np
from matplotlib import image

MIN_RUN = 40  # pixels: shorter dark runs are text, ticks, markers
SLACK = 2     # pixels: how far ends of the lines of one frame may disagree


def runs(mask):
    """Maximal runs of True in each row of a 2-D bool array: list of (row, start, stop)."""
    out = []
    padded = np.pad(mask, ((0, 0), (1, 1))).astype(np.int8)
    d = np.diff(padded, axis=1)
    for row in np.flatnonzero(d.any(axis=1)):
        starts, stops = np.flatnonzero(d[row] == 1), np.flatnonzero(d[row] == -1)
        out += [(row, a, b) for a, b in zip(starts, stops) if b - a >= MIN_RUN]
    return out


def lines(mask):
    """Long dark lines along the rows: runs of adjacent rows with the same extent (within SLACK)
    merged into one line (first_row, last_row, start, stop)."""
    merged = []
    for row, a, b in runs(mask):
        for m in merged:
            if m[1] == row - 1 and abs(m[2] - a) <= SLACK and abs(m[3] - b) <= SLACK:
                m[1] = row
                break
        else:
            merged.append([row, row, a, b])
    return merged


def frames(dark):
    """Rectangles closed by two horizontal and two vertical dark lines, each line reaching the two
    lines across it (a tick at a corner may lengthen a line): (top, bottom, left, right) of the
    interior, outermost ones only."""
    hs, vs = lines(dark), lines(dark.T)  # hs: (first_row, last_row, start_col, stop_col); vs transposed
    found = []
    for i, top in enumerate(hs):
        for bottom in hs[i + 1:]:
            x0, x1 = max(top[2], bottom[2]), min(top[3], bottom[3])
            if bottom[0] - top[1] < MIN_RUN or x1 - x0 < MIN_RUN:
                continue
            across = sorted(v for v in vs if x0 - SLACK <= v[0] and v[1] < x1 + SLACK
                            and v[2] <= top[0] + SLACK and v[3] >= bottom[1] + 1 - SLACK)
            if len(across) >= 2 and across[-1][0] - across[0][1] >= MIN_RUN:
                found.append((top[1] + 1, bottom[0], across[0][1] + 1, across[-1][0]))
    def inside(f, g):
        return g != f and g[0] <= f[0] and g[1] >= f[1] and g[2] <= f[2] and g[3] >= f[3]
    return [f for f in found if not any(inside(f, g) for g in found)]


def size(text):
    """'WIDTHxHEIGHT' -> (width, height), both positive."""
    try:
        width, height = (int(x) for x in text.split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not WIDTHxHEIGHT") from None
    if width < 1 or height < 1:
        raise argparse.ArgumentTypeError(f"'{text}': both must be positive")
    return width, height


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("png")
    ap.add_argument("--size", required=True, type=size, help="WIDTHxHEIGHT in pixels")
    ap.add_argument("--panels", type=int, default=1, help="plot areas expected at least [1]")
    ap.add_argument("--min-ink", type=float, default=0.02, help="ink fraction of each plot area [0.02]")
    ap.add_argument("--min-colours", type=int, default=4, help="distinct colours in each plot area [4]")
    args = ap.parse_args(argv)
    name = args.png
    try:
        with open(name, "rb") as f:
            if f.read(8) != b"\x89PNG\r\n\x1a\n":
                print(f"{name}: not a PNG")
                return 1
        img = image.imread(name)
    except (OSError, ValueError, SyntaxError) as e:
        print(f"{name}: cannot read: {e}")
        return 1
    width, height = args.size
    if img.shape[:2] != (height, width):
        print(f"{name}: {img.shape[1]}x{img.shape[0]} pixels, expected {width}x{height}")
        return 1
    rgb = img[..., :3].astype(float)
    if img.ndim == 3 and img.shape[2] == 4:  # over white, as a viewer shows it
        rgb = rgb * img[..., 3:] + (1 - img[..., 3:])
    lum = rgb @ np.array([0.299, 0.587, 0.114])
    ink = (lum < 0.85) | (rgb.max(axis=2) - rgb.min(axis=2) > 0.15)
    areas = frames(lum < 0.5)
    problems = []
    if len(areas) < args.panels:
        problems.append(f"{len(areas)} plot areas found, expected at least {args.panels}")
    report = []
    for top, bottom, left, right in areas:
        t, b, l, r = top + SLACK, bottom - SLACK, left + SLACK, right - SLACK
        if b - t < 4 or r - l < 4:
            continue
        fraction = ink[t:b, l:r].mean()
        colours = len(np.unique((rgb[t:b, l:r] * 255).round().astype(np.uint32) @ np.array([65536, 256, 1])))
        where = f"plot area x {left}..{right}, y {top}..{bottom}"
        report.append(f"{name}: {where}: ink {fraction:.3f}, {colours} colours")
        if fraction < args.min_ink:
            problems.append(f"{where}: ink {fraction:.4f} < {args.min_ink} (nothing drawn?)")
        if colours < args.min_colours:
            problems.append(f"{where}: {colours} distinct colours < {args.min_colours} (nothing drawn?)")
    for line in problems:
        print(f"{name}: {line}")
    if problems:
        return 1
    print("\n".join(report))
    return 0


if __name__ == "__main__":
    sys.exit(main())
