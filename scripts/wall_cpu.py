#!/usr/bin/env python3
"""Wall against CPU time of short app runs, on a quiet disk and under disk load.

    scripts/wall_cpu.py [--runs N] [--load] [--syncs] -- COMMAND [ARGS...] [-- COMMAND2 ...]

Runs each command N times (default 15), the commands in turn, and prints per
command the median wall time, the median CPU time (user + system of the child,
from getrusage) and their ratio. With --load, a writer fills the same disk
meanwhile: `dd if=/dev/zero of=BIG bs=1M count=4000 conv=fdatasync` in a loop,
BIG beside the first command's --out directory (removed after). With --syncs,
each run is also traced (strace -f -T --seccomp-bpf, fsync, fdatasync and
sync_file_range only) for the time spent inside those calls: on a loaded
machine the wall time mostly waits for a CPU, the time in the calls for the disk.
"""
import re
import tempfile
import os
import resource
import signal
import statistics
import subprocess
import sys
import time


def sync_seconds(cmd):
    with tempfile.NamedTemporaryFile("r") as log:
        subprocess.run(["strace", "-f", "-T", "--seccomp-bpf", "-o", log.name, "-e",
                        "trace=fsync,fdatasync,sync_file_range"] + cmd, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return sum(float(t) for t in re.findall(r"<(\d+\.\d+)>$", log.read(), re.M))


def one_run(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main(argv):
    runs, load, syncs = 15, False, False
    while argv and argv[0] != "--":
        opt = argv.pop(0)
        if opt == "--runs":
            runs = int(argv.pop(0))
        elif opt == "--load":
            load = True
        elif opt == "--syncs":
            syncs = True
        else:
            sys.exit(f"wall_cpu.py: unknown option {opt}")
    cmds = []
    for word in argv:
        if word == "--":
            cmds.append([])
        else:
            cmds[-1].append(word)
    if not cmds or not all(cmds):
        sys.exit(__doc__)
    first = cmds[0]
    out = first[first.index("--out") + 1] if "--out" in first else "."
    big = os.path.join(os.path.dirname(os.path.abspath(out)), "wall_cpu_big")
    writer = None
    if load:
        writer = subprocess.Popen(
            ["bash", "-c", f"while :; do dd if=/dev/zero of='{big}' bs=1M count=4000 "
                           "conv=fdatasync 2>/dev/null; done"], start_new_session=True)
        time.sleep(5)  # the page cache fills and writeback starts
    times = [[] for _ in cmds]
    try:
        for _ in range(runs):
            for i, cmd in enumerate(cmds):
                times[i].append(one_run(cmd) + ((sync_seconds(cmd),) if syncs else ()))
    finally:
        if writer is not None:
            os.killpg(writer.pid, signal.SIGTERM)
            writer.wait()
            if os.path.exists(big):
                os.remove(big)
    for cmd, t in zip(cmds, times):
        wall = statistics.median(r[0] for r in t)
        cpu = statistics.median(r[1] for r in t)
        in_syncs = (f"  in syncs {statistics.median(r[2] for r in t) * 1e3:6.1f} ms"
                    if syncs else "")
        print(f"{'load' if load else 'quiet'}  wall {wall * 1e3:7.1f} ms  CPU {cpu * 1e3:6.1f} ms"
              f"  wall/CPU {wall / cpu:5.1f}{in_syncs}  (median of {runs}; wall range "
              f"{min(r[0] for r in t) * 1e3:.1f}-{max(r[0] for r in t) * 1e3:.1f} ms)  "
              f"{cmd[0]}")


if __name__ == "__main__":
    main(sys.argv[1:])
