"""The forced sweep's goal (issue 34: 10^5 forced orbits in <= 10 s wall on 2 cores):
stickslip.sweep(stickslip.forced_orbits, ...) over 200 values of Omega in [0.5, 1.5] by
500 draws of mu_s ~ N(0.4, 0.02^2) on a 2-worker LocalCluster, its start and stop
included, as docs/library.md's cluster recipe runs it.

    PYTHONPATH=build/python /usr/bin/python3 bench/forced_sweep.py [OMEGAS [DRAWS]]

Prints the wall time of the whole sweep, the CPU of this process and its reaped
children (the workers), the rows found and the rate.
"""
import os
import resource
import sys
import time

import numpy as np

import stickslip


def main():
    omegas = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    draws = int(sys.argv[2]) if len(sys.argv) > 2 else 500
    wall = time.perf_counter()
    r = stickslip.sweep(stickslip.forced_orbits, {"omega": np.linspace(0.5, 1.5, omegas)},
                        {"mu_s": np.random.default_rng(1).normal(0.4, 0.02, draws)})
    wall = time.perf_counter() - wall
    own = resource.getrusage(resource.RUSAGE_SELF)
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime
    n = omegas * draws
    print(f"forced_sweep: {n} forced orbits in {wall:.2f} s wall on 2 workers "
          f"({n / wall:.0f} orbits/s), CPU {cpu:.1f} s, found {np.mean(r['found']):.4f}, "
          f"m > 1 {np.mean(r['m'] > 1):.4f}, load {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
