#!/usr/bin/env python3
"""Child CPU time (user + system, by os.wait4) of ss_continue binaries, interleaved.

Usage: /usr/bin/python3 scripts/cpu_pairs.py REPS EXE[,EXE...] [--cvode] ARGS...
Each rep runs every EXE with ARGS (and --integrator taylor, then cvode with
--cvode) into a scratch --out directory, in turn, so that the binaries see the
same load; prints per binary and integrator the median CPU, and with --cvode
the median of the per-pair ratios cvode / taylor (as ss_bench's dense row).
Used to compare a branch's binary with main's copy on a loaded machine.
"""
import os
import statistics
import sys
import tempfile


def cpu(args):
    pid = os.fork()
    if pid == 0:
        fd = os.open(os.devnull, os.O_WRONLY)
        os.dup2(fd, 1)
        os.dup2(fd, 2)
        os.execv(args[0], args)
    _, status, ru = os.wait4(pid, 0)
    if status != 0:
        sys.exit("%s exited with status %d" % (" ".join(args), status))
    return ru.ru_utime + ru.ru_stime


def main():
    reps, exes, rest = int(sys.argv[1]), sys.argv[2].split(","), sys.argv[3:]
    integrators = ["taylor", "cvode"] if "--cvode" in rest else [None]
    args = [a for a in rest if a != "--cvode"]
    times = {}
    with tempfile.TemporaryDirectory() as out:
        for _ in range(reps):
            for exe in exes:
                for integ in integrators:
                    extra = ["--integrator", integ] if integ else []
                    times.setdefault((exe, integ), []).append(
                        cpu([exe] + args + extra + ["--out", out]))
    for (exe, integ), t in times.items():
        print("%s %s: median %.2f ms CPU over %d runs" %
              (exe, integ or "", 1e3 * statistics.median(t), len(t)))
    for exe in exes:
        if (exe, "cvode") in times:
            ratios = [c / t for t, c in zip(times[(exe, "taylor")], times[(exe, "cvode")])]
            print("%s: cvode / taylor, median of %d pairs: %.1f" %
                  (exe, len(ratios), statistics.median(ratios)))


if __name__ == "__main__":
    main()
