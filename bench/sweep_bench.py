"""Time per point of the belt's stick-slip orbits through Python, on the points of
examples/python/sweep.py (v on 200 speeds in [0.05, 0.45] by mu_s ~ N(0.4, 0.02^2)):

  stickslip.orbits (the batched call, 1 thread), the point path sweeps used before
  (periodic_orbit per point: a fresh finder, no first_return_only), the point fn
  stick_slip_orbit, stickslip.sweep of the batch fn stick_slip_orbits serially and on a
  running 2-worker LocalCluster (its start not counted).

    PYTHONPATH=build/python /usr/bin/python3 bench/sweep_bench.py [DRAWS [REPEATS]]
                                           (default 500 draws: 10^5 points, 3 repeats)
Prints medians over the repeats of wall and process CPU time per point (the
cluster's row: wall only, the work is in its worker processes).
"""
import statistics
import sys
import time

import numpy as np

import stickslip


def timed(f, repeats):
    wall, cpu = [], []
    for _ in range(repeats):
        w, c = time.perf_counter(), time.process_time()
        f()
        wall.append(time.perf_counter() - w)
        cpu.append(time.process_time() - c)
    return statistics.median(wall), statistics.median(cpu)


def old_point(point):
    """stick_slip_orbit as sweeps called it before (periodic_orbit per point)."""
    try:
        o = stickslip.periodic_orbit(stickslip.Params(**point))
    except stickslip.NumericalError:
        return {"stick_slip": 0.0, "amplitude": 0.0, "period": 0.0}
    return {"stick_slip": 1.0, "amplitude": (o.x_max - o.x_min) / 2, "period": o.period}


def main():
    draws = int(sys.argv[1]) if len(sys.argv) > 1 else 500
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    rng = np.random.default_rng(1)
    grid = {"v": np.linspace(0.05, 0.45, 200)}
    sample = {"mu_s": rng.normal(0.4, 0.02, draws)}
    n = 200 * draws
    cols = {"v": np.repeat(grid["v"], draws), "mu_s": np.tile(sample["mu_s"], 200)}
    points = [{"v": float(v), "mu_s": float(m)} for v, m in zip(cols["v"], cols["mu_s"])]
    rows = []

    def row(name, m, f, cpu=True):
        wall, c = timed(f, repeats)
        rows.append((name, m, 1e6 * wall / m, 1e6 * c / m if cpu else None))

    row("orbits(), 1 thread", n, lambda: stickslip.orbits(stickslip.Params(), cols, threads=1))
    row("periodic_orbit per point (before)", n // 50,
        lambda: [old_point(p) for p in points[::50]])
    row("stick_slip_orbit per point", n // 10,
        lambda: [stickslip.stick_slip_orbit(p) for p in points[::10]])
    row("sweep(stick_slip_orbits), serial", n,
        lambda: stickslip.sweep(stickslip.stick_slip_orbits, grid, sample, scheduler="serial"))
    from dask.distributed import LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster:
        row("sweep(stick_slip_orbits), 2 workers", n,
            lambda: stickslip.sweep(stickslip.stick_slip_orbits, grid, sample,
                                    scheduler=cluster.scheduler_address), cpu=False)
    print(f"sweep_bench: {n} points (200 speeds x {draws} draws), {repeats} repeats, medians")
    print("  path                                  points  wall us/pt  CPU us/pt")
    for name, m, wall, cpu in rows:
        print(f"  {name:36s} {m:7d}  {wall:10.2f}  " + (f"{cpu:9.2f}" if cpu else "        -"))
    base = rows[0][2]
    print(f"  sweep / orbits() per point (wall): serial {rows[3][2] / base:.2f}, "
          f"2 workers {rows[4][2] / base:.2f}")


if __name__ == "__main__":
    main()
