#!/usr/bin/env python3
"""The machine's instruction-fetch cliff: CPU time per 64-byte line of code
against the code run per pass (docs/benchmarks.md, "Where the fetch cliff is").

Usage: /usr/bin/python3 bench/fetch_cliff.py [PROCESSES] [--wide]
Writes a C program to a temporary directory, builds it with gcc -O1 and runs
it PROCESSES times (default 5). For each footprint the program has its own
functions of two lines each: 30 independent 4-byte adds (eight registers, so
the adds do not wait on each other) and a return; with --wide, 7-byte adds,
eight per line and an 8-byte no-op (nine instructions per line, not 16; the
flow's hot code has about ten). Each function is 64-byte aligned, laid out
in a shuffled order and called through a table in another shuffled order,
as a loop's scattered calls are. Each process measures every footprint in the
same run (a process mostly keeps one of the machine's two speeds), the best
of three passes, and prints ns per line. A loop whose hot code is past the cliff
pays the step in every pass, whatever its instruction count.
"""
import os
import random
import subprocess
import sys
import tempfile

KIB = [4, 8, 12, 16, 20, 24, 28, 32, 40, 48, 64, 96]
LINES_PER_FUNCTION = 2
REGISTERS = ["r8", "r9", "r10", "r11", "rcx", "rdx", "rsi", "rdi"]


def program(wide):
    rng = random.Random(1)
    if wide:
        eight = "".join("\\taddq $0x11223344, %%%%%s\\n" % r for r in REGISTERS)
        nop8 = "\\t.byte 0x0f, 0x1f, 0x84, 0, 0, 0, 0, 0\\n"
        adds = (eight + nop8) * (LINES_PER_FUNCTION - 1) + eight
    else:
        adds = "".join("\\taddq $1, %%%%%s\\n" % REGISTERS[i % 8]
                       for i in range(16 * LINES_PER_FUNCTION - 2))
    clobbers = ",".join('"%s"' % r for r in REGISTERS)
    out = ["#include <stdio.h>\n#include <time.h>\ntypedef void (*fp)(void);\n"]
    for kib in KIB:
        n = kib * 1024 // 64 // LINES_PER_FUNCTION
        for f in rng.sample(range(n), n):  # the layout
            out.append('__attribute__((noinline, aligned(64))) void f%d_%d(void) '
                       '{ __asm__ volatile("%s" ::: %s); }\n' % (kib, f, adds, clobbers))
        calls = rng.sample(range(n), n)  # the call order
        out.append("static fp t%d[] = {%s};\n" % (kib, ",".join("f%d_%d" % (kib, c) for c in calls)))
    out.append("""static double Now(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e9 + t.tv_nsec;
}
static double PerLine(fp* t, int n) {
  const long reps = 40000000L / (n * %d);
  double best = 1e300;
  for (int pass = 0; pass < 3; ++pass) {
    const double a = Now();
    for (long r = 0; r < reps; ++r)
      for (int i = 0; i < n; ++i) t[i]();
    const double ns = (Now() - a) / (reps * (double)n * %d);
    if (ns < best) best = ns;
  }
  return best;
}
int main(void) {
""" % (LINES_PER_FUNCTION, LINES_PER_FUNCTION))
    for kib in KIB:
        n = kib * 1024 // 64 // LINES_PER_FUNCTION
        out.append('  printf("%%6.2f", PerLine(t%d, %d));\n' % (kib, n))
    out.append('  printf("\\n");\n  return 0;\n}\n')
    return "".join(out)


def main():
    args = sys.argv[1:]
    wide = "--wide" in args
    args = [a for a in args if a != "--wide"]
    if len(args) > 1 or any(a.startswith("-") for a in args):
        sys.exit("fetch_cliff.py: expected [PROCESSES] [--wide], not %s" % " ".join(sys.argv[1:]))
    try:
        processes = int(args[0]) if args else 5
    except ValueError:
        sys.exit("fetch_cliff.py: PROCESSES must be an integer, not %s" % args[0])
    if not 1 <= processes <= 100:
        sys.exit("fetch_cliff.py: PROCESSES = %d must lie in [1, 100]" % processes)
    with tempfile.TemporaryDirectory() as d:
        src, exe = os.path.join(d, "cliff.c"), os.path.join(d, "cliff")
        with open(src, "w") as f:
            f.write(program(wide))
        try:
            subprocess.run(["gcc", "-O1", src, "-o", exe], check=True)
        except (OSError, subprocess.CalledProcessError) as e:
            sys.exit("fetch_cliff.py: gcc could not build the program (%s)" % e)
        print("ns per 64-byte line; columns: hot code per pass, KiB")
        print("".join("%6d" % k for k in KIB))
        for _ in range(processes):
            sys.stdout.write(subprocess.run([exe], check=True, capture_output=True,
                                            text=True).stdout)


if __name__ == "__main__":
    main()
