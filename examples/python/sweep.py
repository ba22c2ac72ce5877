"""A sweep on Dask: P(stick-slip) and the median amplitude over mu_s ~ N(0.4, 0.02^2) x v.

    python3 examples/python/sweep.py [DRAWS [SPEEDS]]   (default 500 draws x 20 speeds;
                                                         5000 200: 10^6 orbits)
"""
import os
import resource
import sys

import numpy as np

import stickslip


def main():
    draws = int(sys.argv[1]) if len(sys.argv) > 1 else 500
    speeds = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    rng = np.random.default_rng(1)
    grid = {"v": np.linspace(0.05, 0.45, speeds)}
    sample = {"mu_s": rng.normal(0.4, 0.02, draws)}
    # LocalCluster, 2 workers; each chunk of points is one stickslip.orbits call
    r = stickslip.sweep(stickslip.stick_slip_orbits, grid, sample)
    r.to_tsv("sweep.tsv")  # one self-describing file
    s = stickslip.group_stats(r, "v", "amplitude", where="stick_slip")
    seconds = float(r.meta["seconds"])  # with the LocalCluster's start and stop
    print(f"{len(r)} orbits in {r.meta['seconds']} s on {r.meta['workers']} workers: "
          f"{len(r) / seconds:.0f} orbits/s")
    t = os.times()  # the workers are reaped children once the cluster closed
    print(f"CPU {t.user + t.system + t.children_user + t.children_system:.1f} s (workers "
          f"{t.children_user + t.children_system:.1f} s), parent peak RSS "
          f"{resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB")
    for v, f, q in zip(s["v"], s["fraction"], s["q0.5"]):
        median = f"{q:.4f}" if f > 0 else "none (no stick-slip orbit)"
        print(f"v = {v:.3f}  P(stick-slip) = {f:.3f}  median amplitude = {median}")

if __name__ == "__main__":  # Dask starts its workers by re-importing this file
    main()
