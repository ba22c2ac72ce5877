#!/usr/bin/env python3
"""The seed branch against a SciPy event-driven sweep (issue 19, Speed), in one run.

SciPy: at each belt speed v of the bench's set (0.05 ... 0.44) the exact Filippov
belt model (seed eq. 3.5, cubic law, the seed set) is simulated with
solve_ivp (DOP853, rtol = atol = 1e-11, stickslip's default rtol), one slip
segment at a time, the first v from rest and each next one from the last
maximum of x of the one before (a sweep): a terminal event where x' reaches v (stick, or cross into
slip above the belt) or leaves it from above, the stick phase in closed form
(x' = v until x + 2 beta v = mu_s), and a non-terminal event at every maximum of
x (x' = 0 downwards). It stops when two successive cycles (maximum to maximum)
agree to 1e-9 in period (relative) and x_max (absolute), after at least 3, as
bench/brute_force.cpp does. CPU time per point is time.process_time().
stickslip: `ss_continue --no_plots` (the whole default run: seed branch,
estimates, durable writes), 20 runs in one loop, child CPU time (user + system)
by os.wait4, divided by the rows of its branch.tsv; interleaved with as many
runs with --no_estimates, whose median subtracted gives the estimates phase.
Usage: /usr/bin/python3 bench/peers/scipy_belt.py [BUILD_DIR]   (about a minute)
"""
import math
import os
import statistics
import sys
import tempfile
import time

from scipy.integrate import solve_ivp

TOL = 1e-11
BETA, MU_S, MU_M, V_M = 0.05, 0.4, 0.25, 0.5  # the seed set (Params())
K1 = 1.5 * (MU_S - MU_M) / V_M
K3 = (MU_S - MU_M) / (2 * V_M ** 3)
V_SET = [0.05, 0.1, 0.2, 0.3, 0.35, 0.39, 0.42, 0.44]


def mu(s):
    return MU_S - K1 * s + K3 * s ** 3


def sweep_point(v, start, converge_tol=1e-9, min_cycles=3, t_cap=20000.0):
    """Period, x_max and the last state of the attractor at v, from `start` (x, x' < v)."""
    def below(t, z):  # slip below the belt speed: friction mu(v - x') forwards
        return [z[1], -z[0] - 2 * BETA * z[1] + mu(v - z[1])]

    def above(t, z):  # slip above it: friction backwards
        return [z[1], -z[0] - 2 * BETA * z[1] - mu(z[1] - v)]

    def reach(t, z):
        return z[1] - v
    reach.terminal, reach.direction = True, 1

    def leave(t, z):
        return z[1] - v
    leave.terminal, leave.direction = True, -1

    def maximum(t, z):
        return z[1]
    maximum.direction = -1

    t, z, mode = 0.0, list(start), "below"
    maxima = []  # (t, x) at each maximum of x
    x0 = MU_S - 2 * BETA * v  # stick exit (seed, case 1)
    while t < t_cap:
        f, ev = (below, reach) if mode == "below" else (above, leave)
        r = solve_ivp(f, (t, t_cap), z, method="DOP853", rtol=TOL, atol=TOL,
                      events=[ev, maximum], first_step=1e-6)
        maxima += [(tm, ym[0]) for tm, ym in zip(r.t_events[1], r.y_events[1])]
        if len(maxima) >= min_cycles + 2:
            (ta, xa), (tb, xb), (tc, xc) = maxima[-3:]
            if abs((tc - tb) - (tb - ta)) <= converge_tol * (tc - tb) and \
                    abs(xc - xb) <= converge_tol:
                return tc - tb, xc, [xc, 0.0]
        if r.status != 1:
            break
        t, z = r.t_events[0][0], list(r.y_events[0][0])
        if mode == "below" and abs(z[0] + 2 * BETA * v) <= MU_S:
            t += (x0 - z[0]) / v  # stick: x' = v until x + 2 beta v = mu_s
            z = [x0, v]
        else:
            mode = "above" if mode == "below" else "below"
    return math.nan, math.nan, [0.0, 0.0]


# CPU seconds of one child process, as scripts/cpu_pairs.py measures them.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from cpu_pairs import cpu as child_cpu  # noqa: E402


def ss_continue_cpu(build, runs=20):
    """Medians of --no_plots and (interleaved) --no_plots --no_estimates; rows."""
    exe = os.path.join(build, "ss_continue")
    full, bare = [], []
    with tempfile.TemporaryDirectory() as out:
        for _ in range(runs):
            bare.append(child_cpu([exe, "--no_plots", "--no_estimates", "--out", out]))
            full.append(child_cpu([exe, "--no_plots", "--out", out]))
        with open(os.path.join(out, "branch.tsv")) as f:
            rows = sum(1 for line in f if line.strip() and not line.startswith("#")) - 1
    return statistics.median(full), statistics.median(bare), rows


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    ss, bare, rows = ss_continue_cpu(build)
    print("estimates phase: %.2f ms CPU (median of --no_plots %.2f ms minus median of "
          "--no_plots --no_estimates %.2f ms, 20 runs each, interleaved)" %
          (1e3 * (ss - bare), 1e3 * ss, 1e3 * bare))
    per_point = []
    z = [0.0, 0.0]  # from rest; then each v from the last maximum of the one before
    for v in V_SET:
        c0 = time.process_time()
        period, x_max, z = sweep_point(v, z)
        per_point.append(time.process_time() - c0)
        print("scipy v %.2f: period %.10f x_max %.10f, %.1f ms CPU" %
              (v, period, x_max, 1e3 * per_point[-1]))
    sp = statistics.median(per_point)
    ss_pt = ss / rows
    print("ss_continue --no_plots: %.2f ms CPU (median of 20 runs in one loop), %d points, "
          "%.4f ms per point" % (1e3 * ss, rows, 1e3 * ss_pt))
    print("SciPy event-driven sweep: %.1f ms CPU per point (the sweep's total over its %d "
          "points), median %.1f ms" % (1e3 * statistics.mean(per_point), len(V_SET), 1e3 * sp))
    print("ratio per point (CPU): %.0fx (sweep total / points), %.0fx (median point)" %
          (statistics.mean(per_point) / ss_pt, sp / ss_pt))


if __name__ == "__main__":
    main()
