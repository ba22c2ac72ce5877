#!/usr/bin/env python3
"""The hot code's footprint: distinct 64-byte lines of machine code run often.

Usage: /usr/bin/python3 scripts/hot_lines.py CALLGRIND_OUT MIN [TOP]
CALLGRIND_OUT is written by valgrind --tool=callgrind --dump-instr=yes (the
default positions "instr line" or "instr"; not --collect-jumps). An
instruction is hot when it ran at least MIN times in all (the number of
periods, say, for "run every period"); a line is hot when it holds the start
of a hot instruction. Prints the distinct hot lines (and bytes: compare with
the L1 instruction cache, 32 KiB on this machine) and the TOP functions
(default 30) by their hot lines; a line two functions share counts once in
the total. A loop whose code does not fit the cache fetches it again on every
pass, whatever its instruction count (docs/benchmarks.md, "The one flow's
code footprint").
"""
import collections
import re
import sys

NAMED = re.compile(r"\((\d+)\)(?: (.*))?")
ADDRESS = re.compile(r"^(0x[0-9a-f]+|\+\d+|-\d+|\*)$")


def costs_by_instruction(path):
    """{(object, function): {address: Ir}}: self costs, summed per instruction
    (valgrind may give one instruction several cost lines)."""
    names = {"fn": {}, "ob": {}}
    current = {"fn": None, "ob": None}
    costs = collections.defaultdict(collections.Counter)
    addr, after_calls, columns = 0, False, None

    def name(kind, text):
        m = NAMED.match(text)
        if m.group(2):
            names[kind][m.group(1)] = m.group(2)
        return names[kind][m.group(1)]

    with open(path) as f:
        for line in f:
            if line.startswith("positions:"):
                positions = line.split()[1:]
                if positions[0] != "instr":
                    raise ValueError("its positions are not instructions")
                columns = len(positions)
                continue
            key, _, value = line.rstrip("\n").partition("=")
            if key in ("fn", "ob") and value:
                current[key] = name(key, value)
                continue
            if key in ("cfn", "cob") and value:
                name(key[1:], value)  # compressed names first seen in a call
                continue
            if key in ("jump", "jcnd"):
                raise ValueError("it was collected with --collect-jumps")
            if key == "calls":
                after_calls = True  # the next cost line is the call's inclusive cost
                continue
            fields = line.split()
            if columns is None or len(fields) <= columns or not ADDRESS.match(fields[0]):
                continue
            a = fields[0]
            if a.startswith("0x"):
                addr = int(a, 16)
            elif a[0] in "+-":
                addr += int(a)
            if after_calls:
                after_calls = False
                continue
            costs[(current["ob"], current["fn"])][addr] += int(fields[columns])  # Ir
    if columns is None:
        raise ValueError("it has no positions line")
    return costs


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    try:
        min_ir = int(sys.argv[2])
        top = int(sys.argv[3]) if len(sys.argv) == 4 else 30
    except ValueError:
        sys.exit("hot_lines.py: MIN and TOP are integers, not %s" % " ".join(sys.argv[2:]))
    try:
        costs = costs_by_instruction(sys.argv[1])
    except (OSError, KeyError, AttributeError, IndexError, ValueError) as e:
        sys.exit("hot_lines.py: %s is not a callgrind file with --dump-instr=yes (%s)" %
                 (sys.argv[1], e))
    hot, counts = set(), collections.Counter()
    for (ob, fn), by_addr in costs.items():
        lines = {a >> 6 for a, ir in by_addr.items() if ir >= min_ir}
        if lines:
            counts[(ob.rsplit("/", 1)[-1], fn)] = len(lines)
            hot |= {(ob, line) for line in lines}
    if not costs:
        sys.exit("hot_lines.py: %s holds no instruction costs (callgrind --dump-instr=yes)" %
                 sys.argv[1])
    print("hot lines %d = %.1f KiB" % (len(hot), 64 * len(hot) / 1024))
    for (ob, fn), c in counts.most_common(top):
        print("%5d  %-18s %s" % (c, ob[:18], fn[:120]))


if __name__ == "__main__":
    main()
