"""The period-doubling cascade of the forced Stribeck scene (studies/stribeck_forced.ini)
located by branch switching: the m = 1 branch in Omega, then at each PD the doubled branch
(continue_doubled, AUTO-07p's ISW = -1) and its own PD, as deep as the switch starts.
Prints the PD points and the ratios of successive intervals, which Feigenbaum's
delta = 4.6692... bounds for a smooth cascade (issue 21).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/feigenbaum.py [A ...]
"""
import sys

import stickslip


def scene(force, omega):
    p = stickslip.Params("stribeck", mu_s=0.4, mu_k=0.25, v_s=0.2, beta=0.05, v=0.25)
    return stickslip.ForcedBeltParams(p, force=force, omega=omega)


def cascade(force, hi=0.8, lo=0.5, depth=6):
    """The Omegas of the first PD of the m = 1, 2, 4, ... branches below hi."""
    s = stickslip.stroboscopic(scene(force, hi), 0.0, 0.25, transient=200, keep=1)
    b = stickslip.continue_branch(scene(force, hi), "omega", [s["x"][0], s["xdot"][0], 0.0], lo,
                                  max_step=0.01, rtol=1e-13, atol=1e-13)
    pds, m = [], 1
    for _ in range(depth):
        pd = next((q for q in b.special_points if q.label == "PD" and q.m == m), None)
        if pd is None:
            print(f"  m = {m}: no PD ({b.status}: {b.message})")
            break
        pds.append(pd.p)
        # The 2m branch's first step shrinks as 1/m^2 (p - p_PD ~ h^2 on a
        # pitchfork whose Newton basin narrows with m).
        b = stickslip.continue_doubled(pd, lo=lo, hi=hi, max_step=min(0.01, 0.25 / m**2),
                                       rtol=1e-13, atol=1e-13)
        m *= 2
    return pds


if __name__ == "__main__":
    for force in [float(a) for a in sys.argv[1:]] or [0.25]:
        pds = cascade(force)
        print(f"A = {force}: PD of m = 1, 2, 4, ... at Omega " +
              ", ".join(f"{w:.12f}" for w in pds))
        d = [pds[k] - pds[k + 1] for k in range(len(pds) - 1)]
        print("  interval ratios " + ", ".join(f"{d[k] / d[k + 1]:.3f}"
                                               for k in range(len(d) - 1)) +
              "  (Feigenbaum's delta 4.669)")
