"""The sweep's cost per point and the parent's memory against the number of
points, streamed to HDF5 (issue 34): belt stick-slip orbits over DRAWS draws of
mu_s ~ N(0.4, 0.02^2) x SPEEDS belt speeds, as examples/python/sweep.py.

    PYTHONPATH=build/python /usr/bin/python3 bench/sweep_scale.py DRAWS SPEEDS \\
        [dask|serial [CHUNK]]

Prints the wall time per point, the steady time per point (the slope of the
seconds against the points done, fitted by least squares over every chunk's
arrival after the first: the cluster's start left out), the parent's peak RSS
and the CPU of the parent and of its reaped workers."""
import os
import resource
import sys
import tempfile
import time

import numpy as np

import stickslip


def main():
    draws, speeds = int(sys.argv[1]), int(sys.argv[2])
    scheduler = sys.argv[3] if len(sys.argv) > 3 and sys.argv[3] != "dask" else None
    chunk = int(sys.argv[4]) if len(sys.argv) > 4 else None
    rng = np.random.default_rng(1)
    grid = {"v": np.linspace(0.05, 0.45, speeds)}
    sample = {"mu_s": rng.normal(0.4, 0.02, draws)}
    arrivals = []

    def progress(points, total, seconds):
        arrivals.append((points, seconds))

    with tempfile.TemporaryDirectory() as d:
        start = time.perf_counter()
        stickslip.sweep(stickslip.stick_slip_orbits, grid, sample, out=os.path.join(d, "s.h5"),
                        progress=progress, scheduler=scheduler, chunk_size=chunk)
        wall = time.perf_counter() - start
    n = draws * speeds
    p, s = np.array(arrivals[1:], dtype=float).reshape(-1, 2).T
    steady = np.polyfit(p, s, 1)[0] if p.size > 1 else float("nan")
    t = os.times()
    print(f"{n} points: wall {wall:.2f} s, {wall / n * 1e6:.3f} us/point; steady "
          f"{steady * 1e6:.3f} us/point; parent peak RSS "
          f"{resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB; CPU parent "
          f"{t.user + t.system:.2f} s, workers {t.children_user + t.children_system:.2f} s")


if __name__ == "__main__":  # Dask starts its workers by re-importing this file
    main()
