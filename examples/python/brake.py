"""The mode-coupling brake model (Hoffmann, Fischer, Sepehri & Gaul 2002;
systems/mode_coupling, docs/theory.md "Mode coupling") in mu_k: the issue's set
(beta 0.02, k11 1, k22 1.5, k12 -0.3, gamma 1, v 0.5, Coulomb friction) with
mu_s = 0.8, since mu_k must stay below mu_s over 0.3 <= mu_k <= 0.7.

1. Steady sliding's eigenvalues along mu_k, and its Hopf (flutter) point HB,
   where the largest real part crosses 0, found by bisection and compared
   with the closed form mu_k* (CouplingParams.flutter_mu_k).
2. A stick-slip orbit found by simulation above mu_k*, refined by shooting on
   the stick-exit section and continued in mu_k both ways (continue_orbits).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/brake.py
"""
import math

import numpy as np

import stickslip

MU_S = 0.8
MU0 = 0.52  # just above mu_k*: a run settles on stick-slip (from ~0.53 on the contact opens)


def system(mu_k):
    law = stickslip.Params("coulomb", mu_s=MU_S, mu_k=mu_k)
    return stickslip.CouplingParams(beta=0.02, k11=1.0, k22=1.5, k12=-0.3, gamma=1.0, v=0.5,
                                    law=law)


def max_real(mu_k):
    return stickslip.steady_sliding(system(mu_k)).max_real


def hopf(lo=0.3, hi=0.7, tol=1e-14):
    """mu_k where steady sliding's largest real part crosses 0 (bisection)."""
    assert max_real(lo) < 0 < max_real(hi)
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if max_real(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def stick_exit_of_simulation(mu_k, t_end=3000.0):
    """The state at the last stick exit of a run from near steady sliding."""
    s = system(mu_k)
    z = np.array(stickslip.steady_sliding(s).z) + [0.01, 0, 0, 0]
    run = stickslip.simulate_system(s, z, t_end=t_end, dt=0.1)
    exits = [i for i in range(1, len(run.t)) if run.mode[i - 1] == "stick"
             and run.mode[i] != "stick"]
    if not exits:
        raise RuntimeError("no stick exit in %g time units (%s)" % (t_end, run.status))
    return np.array(run.z[exits[-1]]), run


def branch(mu_k, to, state):
    return stickslip.continue_orbits(system(mu_k), "mu_k", state, to, section="stick-exit",
                                     max_step=0.05, rtol=1e-12, atol=1e-12)


def main():
    star = system(0.5).flutter_mu_k
    hb = hopf()
    print("flutter threshold: closed form mu_k* = %.15f, steady sliding's HB %.15f "
          "(difference %.1e)" % (star, hb, hb - star))
    print("\nsteady sliding's eigenvalues (the largest real part first):")
    for mu in (0.3, 0.4, 0.5, star, 0.55, 0.6, 0.7):
        ev = [e for e in stickslip.steady_sliding(system(mu)).eigenvalues if e.imag >= 0]
        print("  mu_k = %.4f  %s" % (mu, "  ".join("%+.5f%+.5fi" % (e.real, e.imag)
                                                   for e in ev)))
    mu0 = MU0
    z, run = stick_exit_of_simulation(mu0)
    orbit = stickslip.system_orbit(system(mu0), z, section="stick-exit", rtol=1e-12,
                                   atol=1e-12)
    print("\nmu_k = %g: simulation (%s, %d sticks) -> orbit of period %.12f, %d stick(s), "
          "multipliers %s" % (mu0, run.status.name, run.sticks, orbit.period, orbit.sticks,
                              np.round(np.abs(orbit.multipliers), 6)))
    for to in (0.3, 0.7):
        b = branch(mu0, to, orbit.start)
        print("\ncontinued to mu_k = %g: %s, %d rows, %s" % (to, b.status.name, len(b.p),
                                                              b.message or "no message"))
        for label, p, what in b.special:
            print("  %s at mu_k = %.10f: %s" % (label, p, what))
        for i in sorted(set(range(0, len(b.p), max(1, len(b.p) // 8))) | {len(b.p) - 1}):
            print("  mu_k %.5f  T %.6f  sticks %d  y max %.5f  N min %.2e  |mu|max %.3g" % (
                b.p[i], b.period[i], b.sticks[i], b.hi[i][2], 1 - b.hi[i][2],
                np.max(np.abs(b.multipliers[i])) if b.multipliers.shape[1] else math.nan))


if __name__ == "__main__":
    main()
