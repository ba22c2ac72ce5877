#!/usr/bin/env python3
"""The hot code's footprint: distinct 64-byte lines of machine code run often.

Usage: /usr/bin/python3 scripts/hot_lines.py CALLGRIND_OUT MIN [TOP]
CALLGRIND_OUT is written by valgrind --tool=callgrind --dump-instr=yes. A
line counts when one of its instructions ran at least MIN times (the number
of periods, say, for "run every period"). Prints the total (lines and bytes:
compare with the L1 instruction cache, 32 KiB on this machine) and the TOP
functions (default 30) by their lines. A loop whose code does not fit the
cache fetches it again on every pass, whatever its instruction count
(docs/benchmarks.md, "The one flow's code footprint").
"""
import collections
import re
import sys

POSITION = re.compile(r"^(0x[0-9a-f]+|\+\d+|-\d+|\*)\s+\S+\s+(\d+)")
NAMED = re.compile(r"\((\d+)\)(?: (.*))?")


def lines_by_function(path, min_ir):
    names = {"fn": {}, "ob": {}}
    current = {"fn": None, "ob": None}
    lines = collections.defaultdict(set)
    addr, after_calls = 0, False

    def name(kind, text):
        m = NAMED.match(text)
        if m.group(2):
            names[kind][m.group(1)] = m.group(2)
        return names[kind][m.group(1)]

    with open(path) as f:
        for line in f:
            if line.startswith("positions:") and "instr" not in line:
                raise ValueError("its positions are not instructions")
            key, _, value = line.rstrip("\n").partition("=")
            if key in ("fn", "ob") and value:
                current[key] = name(key, value)
                continue
            if key in ("cfn", "cob") and value:
                name(key[1:], value)  # compressed names first seen in a call
                continue
            if key == "calls":
                after_calls = True  # the next position line is the call's inclusive cost
                continue
            m = POSITION.match(line)
            if not m:
                continue
            a = m.group(1)
            if a.startswith("0x"):
                addr = int(a, 16)
            elif a[0] in "+-":
                addr += int(a)
            if after_calls:
                after_calls = False
                continue
            if int(m.group(2)) >= min_ir:
                lines[(current["ob"], current["fn"])].add(addr >> 6)
    return lines


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    try:
        min_ir = int(sys.argv[2])
        top = int(sys.argv[3]) if len(sys.argv) == 4 else 30
    except ValueError:
        sys.exit("hot_lines.py: MIN and TOP are integers, not %s" % " ".join(sys.argv[2:]))
    try:
        lines = lines_by_function(sys.argv[1], min_ir)
    except (OSError, KeyError, AttributeError, ValueError) as e:
        sys.exit("hot_lines.py: %s is not a callgrind file with --dump-instr=yes (%s)" %
                 (sys.argv[1], e))
    if not lines:
        sys.exit("hot_lines.py: %s holds no instruction costs (callgrind --dump-instr=yes)" %
                 sys.argv[1])
    counts = collections.Counter(
        {(ob.rsplit("/", 1)[-1], fn): len(s) for (ob, fn), s in lines.items()})
    total = sum(counts.values())
    print("hot lines %d = %d bytes" % (total, 64 * total))
    for (ob, fn), c in counts.most_common(top):
        print("%5d  %-18s %s" % (c, ob[:18], fn[:120]))


if __name__ == "__main__":
    main()
