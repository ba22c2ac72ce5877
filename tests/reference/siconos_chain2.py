#!/usr/bin/env python3
"""The two-block chain under Coulomb friction with mu_s = mu_k (a relay),
simulated by Siconos (Debian python3-siconos 4.4: FirstOrderLinearTIDS with a
RelayNSL, Moreau-Jean time stepping, theta = 0.5), as an outside cross-check
of systems/chain (tests/reference/siconos_chain2_check.py, ctest
Reference.SiconosChain2, compares it with stickslip's trajectory):

    x_i'' = -(1 + kc) x_i + kc x_j + lambda_i,   lambda_i in -mu sgn(x_i' - v)

Usage: siconos_chain2.py H T_END [EVERY]  -> prints "t x1 x1' x2 x2'" at t = EVERY,
2 EVERY, ..., T_END (EVERY default 5).
"""
import sys

import numpy as np
import siconos.kernel as sk


def run(h, t_end, mu=0.3, kc=0.5, v=0.2, z0=(0.1, 0.0, -0.25, 0.05), every=5.0):
    a = np.array([[0, 1, 0, 0], [-(1 + kc), 0, kc, 0], [0, 0, 0, 1], [kc, 0, -(1 + kc), 0]], float)
    ds = sk.FirstOrderLinearTIDS(np.array(z0, float), a)
    c = np.array([[0, 1, 0, 0], [0, 0, 0, 1]], float)
    b = np.array([[0, 0], [1, 0], [0, 0], [0, 1]], float)
    rel = sk.FirstOrderLinearTIR(c, b)
    rel.setePtr(np.array([-v, -v], float))
    inter = sk.Interaction(sk.RelayNSL(2, -mu, mu), rel)
    nsds = sk.NonSmoothDynamicalSystem(0.0, t_end)
    nsds.insertDynamicalSystem(ds)
    nsds.link(inter, ds)
    osi = sk.EulerMoreauOSI(0.5)
    sim = sk.TimeStepping(nsds, sk.TimeDiscretisation(0.0, h), osi, sk.Relay())
    out, k, next_t = [], 0, every
    while sim.hasNextEvent():
        sim.computeOneStep()
        k += 1
        t = k * h
        if t >= next_t - h / 2:
            out.append([next_t] + list(ds.x()))
            next_t += every
        sim.nextStep()
    return out


if __name__ == "__main__":
    h, t_end = float(sys.argv[1]), float(sys.argv[2])
    every = float(sys.argv[3]) if len(sys.argv) > 3 else 5.0
    for row in run(h, t_end, every=every):
        print(" ".join("%.17g" % x for x in row))
