#!/usr/bin/env python3
"""The forced oscillator against SciPy (issue 20, Speed), measured in one run.

Runs build/bench/forced_bench (stickslip's medians), then the same two jobs with
SciPy's event-driven solve_ivp (DOP853) and prints the medians and ratios:
  1. one stick-slip orbit's return of the coulomb belt (A 0.3, Omega 0.8): from
     its stick exit, slip until x' = v (a terminal event), then stick until
     |x + 2 beta v - A cos Omega t| = mu_s (a terminal event); the orbit closes
     after one forcing period, so the period error is |t' - t_e - 2 pi / Omega|;
  2. a 500-point resonance curve of Den Hartog's oscillator (Omega in [1.2, 2.5]):
     each orbit by Newton on the stroboscopic map (finite-difference Jacobian)
     from the previous one; each map a chain of solve_ivp segments with a
     terminal event at every reversal x' = 0; error against his closed form.
Usage: /usr/bin/python3 bench/peers/scipy_forced.py [BUILD_DIR]   (about a minute)
"""
import math
import re
import statistics
import subprocess
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

TOL = 1e-12  # rtol = atol, as stickslip's runs


def stickslip_numbers(build):
    out = subprocess.run([build + "/bench/forced_bench"], capture_output=True, text=True,
                         check=True).stdout
    line = [l for l in out.splitlines() if l.startswith("stick-slip orbit") and "rtol 1e-12" in l][0]
    ret = float(re.search(r"one return ([0-9.]+) us", line).group(1))
    err = float(re.search(r"period error ([0-9.e+-]+)", line).group(1))
    te = float(re.search(r"exit t_e ([0-9.e+-]+)", line).group(1))
    xe = float(re.search(r"x_e ([0-9.e+-]+)", line).group(1))
    sweep = [l for l in out.splitlines() if l.startswith("resonance sweep")][0]
    ms = float(re.search(r"\): ([0-9.]+) ms", sweep).group(1))
    serr = float(re.search(r"error ([0-9.e+-]+)", sweep).group(1))
    return ret, err, te, xe, ms, serr


# 1. The coulomb belt (tests/forced/forced_exit_map_test.cpp): beta 0.05, v 0.2,
# mu_s 0.4, mu_k 0.25, A 0.3, Omega 0.8; slip below the belt: F = +mu_k.
B, V, MUS, MUK, A, W = 0.05, 0.2, 0.4, 0.25, 0.3, 0.8


def belt_return(te, xe):
    def slip(t, z):
        return [z[1], -z[0] - 2 * B * z[1] + MUK + A * math.cos(W * t)]

    def arrive(t, z):
        return z[1] - V
    arrive.terminal, arrive.direction = True, 1
    T = 2 * math.pi / W
    # The start is on x' = v: step off it before the event is armed.
    r = solve_ivp(slip, (te, te + 3 * T), [xe, V], method="DOP853", rtol=TOL, atol=TOL,
                  events=arrive, first_step=1e-6)
    ta, xa = r.t_events[0][0], r.y_events[0][0][0]

    def stick(t, z):
        return [V]

    def leave(t, z):
        return z[0] + 2 * B * V - A * math.cos(W * t) - MUS
    leave.terminal, leave.direction = True, 1
    s = solve_ivp(stick, (ta, te + 3 * T), [xa], method="DOP853", rtol=TOL, atol=TOL,
                  events=leave)
    return s.t_events[0][0]


# 2. Den Hartog: coulomb mu = 0.3, beta 0, v 0, A 1: F = -mu sgn(x').
MU = 0.3


def strobe(x, xd, w):
    """(x, x') after one forcing period from (x, x') at t = 0."""
    T, t, z = 2 * math.pi / w, 0.0, [x, xd]
    for _ in range(20):
        sgn = 1.0 if z[1] > 0 or (z[1] == 0 and -z[0] + math.cos(w * t) > MU) else -1.0

        def f(tt, zz):
            return [zz[1], -zz[0] - sgn * MU + math.cos(w * tt)]

        def rev(tt, zz):
            return zz[1]
        rev.terminal, rev.direction = True, -sgn
        r = solve_ivp(f, (t, T), z, method="DOP853", rtol=TOL, atol=TOL, events=rev,
                      first_step=1e-6 if t > 0 else None)
        if r.status == 1:
            t, z = r.t_events[0][0], [r.y_events[0][0][0], 0.0]
            continue
        return np.array(r.y[:, -1])
    raise RuntimeError("more than 20 reversals in a period")


def x_max_of(x, xd, w):
    """The largest x over the period: at the reversals (x' = 0 from above)."""
    T, t, z, best = 2 * math.pi / w, 0.0, [x, xd], x
    for _ in range(20):
        sgn = 1.0 if z[1] > 0 else -1.0

        def f(tt, zz):
            return [zz[1], -zz[0] - sgn * MU + math.cos(w * tt)]

        def rev(tt, zz):
            return zz[1]
        rev.terminal, rev.direction = True, -sgn
        r = solve_ivp(f, (t, T), z, method="DOP853", rtol=TOL, atol=TOL, events=rev,
                      first_step=1e-6 if t > 0 else None)
        if r.status != 1:
            return max(best, r.y[0, -1])
        t, z = r.t_events[0][0], [r.y_events[0][0][0], 0.0]
        best = max(best, z[0])
    return best


def sweep():
    z = np.array([-1.4, 0.01])
    worst = 0.0
    for i in range(500):
        w = 1.2 + 1.3 * i / 499
        for _ in range(30):  # Newton, Jacobian by central differences
            r = strobe(z[0], z[1], w) - z
            J = np.empty((2, 2))
            for k in range(2):
                d = np.zeros(2)
                d[k] = 1e-6
                J[:, k] = (strobe(*(z + d), w) - strobe(*(z - d), w)) / 2e-6
            dz = np.linalg.solve(J - np.eye(2), -r)
            z = z + dz
            if np.max(np.abs(dz)) <= 1e-11 * (1 + np.max(np.abs(z))):
                break
        V_ = 1 / (1 - w * w)
        U = math.sin(math.pi / w) / (w * (1 + math.cos(math.pi / w)))
        worst = max(worst, abs(x_max_of(z[0], z[1], w) - math.sqrt(V_ * V_ - (MU * U) ** 2)))
    return worst


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    ret, err, te, xe, ms, serr = stickslip_numbers(build)
    T = 2 * math.pi / W
    times = []
    for _ in range(101):
        a = time.thread_time()
        tp = belt_return(te, xe)
        times.append(time.thread_time() - a)
    sret = statistics.median(times) * 1e6
    print("stick-slip orbit return, rtol 1e-12: stickslip %.2f us (period error %.1e), "
          "SciPy DOP853 + events %.0f us (period error %.1e): SciPy / stickslip = %.0f"
          % (ret, err, sret, abs(tp - te - T), sret / ret))
    times = []
    for _ in range(3):
        a = time.thread_time()
        worst = sweep()
        times.append(time.thread_time() - a)
    sms = statistics.median(times) * 1e3
    print("500-point resonance curve, rtol 1e-12: stickslip %.2f ms (max x_max error %.1e), "
          "SciPy %.0f ms (max x_max error %.1e): SciPy / stickslip = %.0f"
          % (ms, serr, sms, worst, sms / ms))


if __name__ == "__main__":
    main()
