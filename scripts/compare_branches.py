#!/usr/bin/env python3
"""Compare two ss_continue output directories numerically, column by column.

Usage: compare_branches.py BASE_DIR NEW_DIR [--tol 1e-12] [--files A.tsv,B.tsv]
                           [--rename OLD=NEW,...] [--text OLD=NEW,...]

--files names other files to compare the same way (default branch.tsv,
special_points.tsv), e.g. ss_basin's basins.tsv,orbits.tsv.
--rename compares by name across renamed and reordered columns: each of BASE's
columns (OLD renamed NEW) is picked out of NEW wherever it stands, NEW's others
not compared; --text renames BASE's text cells (e.g. the forced tables before
they were the system's: --rename x0=x_0,xdot0=xdot_0 --text non-stop=pure-slip).

For each file: the same header, the same number of
rows, text cells equal, and every numeric cell within tol (absolute, scaled
by max(1, |base|)); a cell that does not apply (empty, or nan as older files
wrote it) must match one that does not apply. NEW may have more columns after
BASE's (new columns appended: pt, lab, x_start, ...): those are not compared,
and the count is reported. Either layout is read: the header as
the first '#' line (before 0.1.0's metadata) or as the first line without '#'.
Comment lines other than the header
(# model, # status) must be equal too, except `# key: value` metadata lines
that BASE does not have, the command, the commit and the timings (seconds_*). Exit 0 if equal, 1 otherwise.
"""
import math
import sys


def read(path):
    header, comments, rows = None, [], []
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("#"):
                if header is None and "\t" in line:  # the old layout: '# col1<TAB>col2...'
                    header = line[1:].strip().split("\t")
                else:
                    comments.append(line)
            elif line and header is None:  # '# key: value' lines, then the header line
                header = line.split("\t")
            elif line:
                rows.append(line.split("\t"))
    return header, comments, rows


def number(s):
    if s == "":  # does not apply: as older files' nan
        return math.nan
    try:
        return float(s)
    except ValueError:
        return None


def pairs(text):
    return dict(item.split("=", 1) for item in text.split(",")) if text else {}


def compare(base, new, tol, rename=None, text=None):
    hb, cb, rb = read(base)
    hn, cn, rn = read(new)
    errors = []
    added = 0
    if rename is not None:  # by name: BASE's columns, renamed, picked out of NEW
        want = [rename.get(c, c) for c in hb]
        missing = [c for c in want if c not in hn]
        if missing:
            return [f"columns not in NEW: {missing}"], 0.0, len(rb), 0
        added = len(hn) - len(want)
        rn = [[r[hn.index(c)] for c in want] for r in rn]
        hn = hb
    if text:  # BASE's text cells renamed, with or without --rename
        rb = [[text.get(x, x) for x in r] for r in rb]
    if hn[:len(hb)] == hb:  # columns appended after BASE's: compare BASE's only
        added = max(added, len(hn) - len(hb))
        rn = [r[:len(hb)] for r in rn]
    else:
        errors.append(f"header differs: {hb} vs {hn}")
    # The command line, the build commit and the timings differ between runs.
    volatile = lambda c: c.startswith(("# command:", "# commit:", "# seconds_"))
    cb = [c for c in cb if not volatile(c)]
    keys = {c.split(":")[0] for c in cb}
    cn = [c for c in cn if c.split(":")[0] in keys]
    if cb != cn:
        errors.append(f"comment lines differ: {cb} vs {cn}")
    if len(rb) != len(rn):
        errors.append(f"{len(rb)} rows vs {len(rn)}")
    worst = 0.0
    for i, (a, b) in enumerate(zip(rb, rn)):
        if len(a) != len(b):
            errors.append(f"row {i}: {len(a)} cells vs {len(b)}")
            continue
        for j, (x, y) in enumerate(zip(a, b)):
            fx, fy = number(x), number(y)
            if fx is None or fy is None:
                if x != y:
                    errors.append(f"row {i} col {hb[j]}: '{x}' vs '{y}'")
                continue
            if math.isnan(fx) or math.isnan(fy):
                if not (math.isnan(fx) and math.isnan(fy)):
                    errors.append(f"row {i} col {hb[j]}: {x} vs {y}")
                continue
            d = abs(fx - fy) / max(1.0, abs(fx))
            worst = max(worst, d)
            if d > tol:
                errors.append(f"row {i} col {hb[j]}: {x} vs {y} (diff {d:.3g})")
    return errors, worst, len(rb), added


def main():
    args = sys.argv[1:]
    tol = 1e-12
    names = ("branch.tsv", "special_points.tsv")
    rename, text = None, None
    try:
        if "--rename" in args:
            k = args.index("--rename")
            rename = pairs(args[k + 1])
            del args[k:k + 2]
        if "--text" in args:
            k = args.index("--text")
            text = pairs(args[k + 1])
            del args[k:k + 2]
        if "--files" in args:
            k = args.index("--files")
            names = tuple(args[k + 1].split(","))
            del args[k:k + 2]
        if "--tol" in args:
            k = args.index("--tol")
            tol = float(args[k + 1])
            del args[k:k + 2]
    except (IndexError, ValueError):
        args = []
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    ok = True
    for name in names:
        errors, worst, n, added = compare(f"{args[0]}/{name}", f"{args[1]}/{name}", tol, rename,
                                          text)
        status = "equal" if not errors else f"{len(errors)} differences"
        if added:
            status += f" ({added} new columns not compared)"
        print(f"{args[1]}/{name}: {n} rows, largest relative difference {worst:.3g}: {status}")
        for e in errors[:10]:
            print("  " + e)
        ok = ok and not errors
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
