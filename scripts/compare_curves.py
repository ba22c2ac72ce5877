#!/usr/bin/env python3
"""Compare two ss_chart curves.tsv files: is each curve the same curve?

Usage: compare_curves.py OLD/curves.tsv NEW/curves.tsv [--tol 1e-12]

For each curve (type, id) of either file: its point counts; where the counts
agree, the largest relative difference of the numeric cells row by row
(relative to max(1, |old|)) and the number of text or nan cells that differ (an
empty cell, not applicable, matches an older file's nan);
and the largest distance of a NEW point from OLD's polyline of that curve, in
units of the chart's ranges (OLD's `# range:` line; the first two columns are
the chart's axes). A NEW point farther than tol from OLD's end vertices and
projecting past one of them counts apart, as beyond that end (a curve that now
goes further). A continuation places points along a curve by its steps, so
points can slide along the same curve: the distance, not the cells, says
whether the curve moved.
Exit 0 if both files have the same curves and every NEW point not beyond an end
lies within tol of OLD's curve, 1 otherwise, 2 on bad input.
"""
import math
import re
import sys


def read(path):
    header, rows, ranges = None, [], None
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            m = re.match(r"#\s*range:\s*(.*)", line)
            if m:  # '# range: v=[0.02, 0.6] beta=[0, 0.25]'
                ranges = [float(b) - float(a) for a, b in
                          re.findall(r"\[([^,\]]+),\s*([^\]]+)\]", m.group(1))]
            if not line or line.startswith("#"):
                continue
            if header is None:
                header = line.split("\t")
            else:
                rows.append(line.split("\t"))
    return header, rows, ranges


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


def from_polyline(p, line, sx, sy, tol):
    """(distance of p from the polyline, 'first'/'last' if p lies beyond that end, else None)."""
    if len(line) == 1:
        d = math.hypot((p[0] - line[0][0]) / sx, (p[1] - line[0][1]) / sy)
        return d, ("last" if d > tol else None)
    (d, u), i = min((distance(p, line[i], line[i + 1], sx, sy), i) for i in range(len(line) - 1))
    if d > tol and i == 0 and u < 0:
        return d, "first"
    if d > tol and i == len(line) - 2 and u > 1:
        return d, "last"
    return d, None


def cells(old, new):
    """(largest relative numeric difference, count of other differing cells)."""
    worst, other = 0.0, 0
    for ro, rn in zip(old, new):
        for u, w in zip(ro, rn):
            u, w = u or "nan", w or "nan"  # empty: does not apply, as older files' nan
            try:
                a, b = float(u), float(w)
            except ValueError:
                other += u != w
                continue
            if math.isfinite(a) and math.isfinite(b):
                worst = max(worst, abs(a - b) / max(1.0, abs(a)))
            elif u.lower() != w.lower():
                other += 1
    return worst, other


def compare(key, old_rows, new_rows, sx, sy, tol):
    """One curve's report line and whether it passes."""
    line = [(float(r[0]), float(r[1])) for r in old_rows]
    found = [from_polyline((float(r[0]), float(r[1])), line, sx, sy, tol) for r in new_rows]
    inside = [d for d, end in found if end is None]
    text = f"{key[0]} {key[1]}: {len(old_rows)} -> {len(new_rows)} points, "
    if len(old_rows) == len(new_rows):
        worst, other = cells(old_rows, new_rows)
        text += f"cells within {worst:.2e} ({other} text or nan cells differ), "
    else:
        text += "cells not compared (counts differ), "
    far = max(inside) if inside else 0.0
    ok = all(math.isfinite(d) for d, _ in found) and far <= tol
    text += f"largest distance from the old curve {far:.2e}"
    for end in ("first", "last"):
        past = [d for d, e in found if e == end]
        if past:
            text += f"; {len(past)} beyond its {end} end (up to {max(past):.2e} away)"
    return text, ok


def main(argv):
    args, tol = argv[1:], 1e-12
    try:
        if "--tol" in args:
            k = args.index("--tol")
            tol = float(args[k + 1])
            del args[k:k + 2]
        if len(args) != 2:
            raise ValueError("two files expected")
        _, old_rows, ranges = read(args[0])
        _, new_rows, _ = read(args[1])
        if not old_rows:
            raise ValueError(f"no points in {args[0]}")
    except (ValueError, IndexError, OSError) as e:
        print(f"compare_curves: {e}\n" + __doc__.strip().split("\n")[2], file=sys.stderr)
        return 2
    if ranges and len(ranges) == 2 and all(r > 0 for r in ranges):
        sx, sy = ranges
    else:  # no range line: the old points' bounding box
        xs, ys = [float(r[0]) for r in old_rows], [float(r[1]) for r in old_rows]
        sx, sy = (max(xs) - min(xs)) or 1.0, (max(ys) - min(ys)) or 1.0
    old, new = curves(old_rows), curves(new_rows)
    status = 0
    for key in sorted(set(old) | set(new), key=lambda k: (int(k[1]), k[0])):
        if key not in new or key not in old:
            print(f"{key[0]} {key[1]}: only in {args[0] if key in old else args[1]}")
            status = 1
            continue
        text, ok = compare(key, old[key], new[key], sx, sy, tol)
        print(text)
        status = status if ok else 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
