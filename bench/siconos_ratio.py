#!/usr/bin/env python3
"""Time at equal accuracy against Siconos on the two-block relay chain of
tests/reference/siconos_chain2.py (mu_s = mu_k = 0.3, beta = 0, kc = 0.5,
v = 0.2, from (0.1, 0, -0.25, 0.05), to t = 3: a crossing, a stick and its
exit). Errors are the largest |z - z_ref| at t = 1, 2, 3 against stickslip at
rtol = atol = 1e-13; times are process CPU seconds, medians of REPEATS runs.
For each Siconos step h (Moreau-Jean, theta 0.5) it prints the loosest
stickslip tolerance whose error is at most Siconos's, and the time ratio.
stickslip's time is one simulate_system call from Python, its set-up and
arrays included (at these tolerances they are most of it).

    PYTHONPATH=build/python /usr/bin/python3 bench/siconos_ratio.py [REPEATS]

Needs python3-siconos (Debian); exits 77 without it.
"""
import os
import statistics
import sys
import time

import numpy as np

try:
    import siconos.kernel  # noqa: F401
except ImportError:
    print("siconos_ratio: python3-siconos is not installed; apt-get install python3-siconos")
    sys.exit(77)

import stickslip

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests",
                                "reference"))
import siconos_chain2  # noqa: E402

Z0 = (0.1, 0.0, -0.25, 0.05)
T_END = 3.0
POINTS = (10, 20, 30)  # t = 1, 2, 3 in tenths


def ours(tol):
    law = stickslip.Params("leine", mu_s=0.3, delta=0.0, beta=0.0, v=0.2)  # mu(s) = 0.3
    chain = stickslip.ChainParams(2, law=law, kc=0.5)
    run = stickslip.simulate_system(chain, Z0, t_end=T_END, dt=0.1, rtol=tol, atol=tol)
    rows = {}
    for t, z in zip(run.t, run.z):
        if abs(t * 10 - round(t * 10)) < 1e-7:
            rows[round(t * 10)] = np.array(z)
    return rows


def timed(fn, repeats):
    times, out = [], None
    for _ in range(repeats):
        t0 = time.process_time()
        out = fn()
        times.append(time.process_time() - t0)
    return statistics.median(times), out


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    ref = ours(1e-13)
    siconos_chain2.run(1e-3, 0.1)  # the first call's set-up, not timed
    err = lambda rows: max(np.max(np.abs(rows[k] - ref[k])) for k in POINTS)  # noqa: E731
    mine = []
    for tol in (1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-10):
        t, rows = timed(lambda: ours(tol), repeats * 20)
        mine.append((tol, t, err(rows)))
        print("stickslip rtol = atol = %.0e: %.3e s, error %.2e" % mine[-1])
    for h in (1e-4, 5e-5, 2.5e-5):
        t, out = timed(lambda: siconos_chain2.run(h, T_END, every=0.1), repeats)
        rows = {round(r[0] * 10): np.array(r[1:]) for r in out}
        e = err(rows)
        best = max((m for m in mine if m[2] <= e), key=lambda m: m[0], default=None)
        line = "Siconos h = %.1e: %.3e s, error %.2e" % (h, t, e)
        if best:
            line += "; stickslip at rtol %.0e: %.2e, %.0fx less time" % (best[0], best[2],
                                                                        t / best[1])
        print(line)


if __name__ == "__main__":
    main()
