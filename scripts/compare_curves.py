#!/usr/bin/env python3
"""Compare two ss_chart curves.tsv files: is each curve the same curve?

Usage: compare_curves.py OLD/curves.tsv NEW/curves.tsv

For each curve (type, id) of NEW: its point counts, the largest relative cell
difference row by row (relative to max(1, |old|); only where the counts agree),
and the largest distance of a NEW point from OLD's polyline of that curve, in
units of OLD's chart ranges (the first two columns are the chart's axes), with
the points beyond the old curve's ends counted apart (a curve that now goes
further). A
continuation places points along a curve by its steps, so points can slide along
the same curve: the distance, not the cells, says whether the curve moved.
Exit 0 if every curve of NEW is in OLD, 1 otherwise.
"""
import math
import sys


def read(path):
    header, rows = None, []
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            if header is None:
                header = line.split("\t")
            else:
                rows.append(line.split("\t"))
    return header, rows


def curves(rows):
    out = {}
    for r in rows:
        out.setdefault((r[2], r[3]), []).append(r)
    return out


def distance(p, a, b, sx, sy):
    """Distance of p from segment a-b, in units of the ranges sx, sy, and the
    unclamped projection parameter (< 0 before a, > 1 past b)."""
    px, py, ax, ay = p[0] / sx, p[1] / sy, a[0] / sx, a[1] / sy
    dx, dy = b[0] / sx - ax, b[1] / sy - ay
    length2 = dx * dx + dy * dy
    u = 0.0 if length2 == 0 else ((px - ax) * dx + (py - ay) * dy) / length2
    t = max(0.0, min(1.0, u))
    return math.hypot(px - ax - t * dx, py - ay - t * dy), u


def from_polyline(p, line, sx, sy):
    """(distance of p from the polyline, whether p lies beyond one of its ends)."""
    if len(line) == 1:
        return math.hypot((p[0] - line[0][0]) / sx, (p[1] - line[0][1]) / sy), True
    best = min((distance(p, line[i], line[i + 1], sx, sy), i) for i in range(len(line) - 1))
    (d, u), i = best
    beyond = (i == 0 and u < 0) or (i == len(line) - 2 and u > 1)
    return d, beyond


def cell_difference(old, new):
    worst = 0.0
    for ro, rn in zip(old, new):
        for u, w in zip(ro, rn):
            try:
                a, b = float(u), float(w)
            except ValueError:
                continue
            if math.isfinite(a) and math.isfinite(b):
                worst = max(worst, abs(a - b) / max(1.0, abs(a)))
    return worst


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().split("\n")[2], file=sys.stderr)
        return 2
    _, old_rows = read(argv[1])
    _, new_rows = read(argv[2])
    old, new = curves(old_rows), curves(new_rows)
    xy = lambda rows: [(float(r[0]), float(r[1])) for r in rows]
    every = xy(old_rows)
    sx = (max(p[0] for p in every) - min(p[0] for p in every)) or 1.0
    sy = (max(p[1] for p in every) - min(p[1] for p in every)) or 1.0
    status = 0
    for key, rows in new.items():
        if key not in old:
            print(f"{key[0]} {key[1]}: not in {argv[1]}")
            status = 1
            continue
        line = xy(old[key])
        found = [from_polyline(p, line, sx, sy) for p in xy(rows)]
        inside = [d for d, beyond in found if not beyond]
        beyond = [d for d, b in found if b]
        cells = (f"cells within {cell_difference(old[key], rows):.2e}"
                 if len(rows) == len(old[key]) else "cells not compared (counts differ)")
        far = f"{max(inside):.2e}" if inside else "-"
        print(f"{key[0]} {key[1]}: {len(old[key])} -> {len(rows)} points, {cells}, "
              f"largest distance from the old curve {far}" +
              (f"; {len(beyond)} points beyond its ends (up to {max(beyond):.2e} away)"
               if beyond else ""))
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
