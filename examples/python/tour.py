"""A five-minute tour of the stickslip Python package (run as a test: Python.Tour).

    /usr/bin/python3 examples/python/tour.py    # after installing, or with
    PYTHONPATH=build/python /usr/bin/python3 examples/python/tour.py
"""
import math
import os
import shutil
import subprocess
import tempfile

import stickslip

# 1. The seed set (beta 0.05, v 0.25, mu_s 0.4, mu_m 0.25, v_m 0.5) and one trajectory.
p = stickslip.Params()
run = stickslip.simulate(p, xdot0=p.v, t_end=20.0)
print("simulate: %d rows, %d switches, %.3f time units in stick" %
      (len(run.t), run.switches, run.t_stick))

# 2. The stick-slip orbit (one slip integration from the exit point of stick).
orbit = stickslip.periodic_orbit(p)
print("stick-slip orbit: period %.6f, x in [%.4f, %.4f]" % (orbit.period, orbit.x_min, orbit.x_max))

# 3. The branch in v: grazing (GR) and Hopf (HB) points, located.
branch = stickslip.continue_branch(p, "v", from_=0.05, to=0.5)
for s in branch.special:
    print("%s at v = %.10f: %s" % (s.label, s.p, s.description))
hb = next(s.p for s in branch.special if s.label == "HB")
print("HB closed form sqrt((k1 - 2 beta) / (3 k3)) = %.10f" % math.sqrt((p.k1 - 2 * p.beta) / (3 * p.k3)))

# 4. The same with CVODE's BDF instead of the Taylor integrator.
bdf = stickslip.continue_branch(p, "v", from_=0.3, to=0.5, integrator="cvode", method="bdf")
print("HB with cvode/bdf: %.10f" % next(s.p for s in bdf.special if s.label == "HB"))

# 5. The stability chart in (v, beta): HB and GR curves.
chart = stickslip.chart(p, "v", 0.05, 0.6, "beta", 0.0, 0.25)
for c in chart.curves:
    print("%s curve: %d points, ends %s" % (c.label, len(c.p1), c.ends))

# 6. Basins of a bistable Stribeck point: the unstable orbit splits the plane.
st = stickslip.Params(law="stribeck", mu_s=0.4, mu_k=0.25, v_s=0.1, v=0.35)
basins = stickslip.basins(st, nx=21, ny=21)
print("basins: " + ", ".join("%s %d" % (f, n) for f, n in basins.counts.items() if n))
unstable = basins.orbits.pure_slip[0]
d = stickslip.smallest_disturbance(st, unstable)
print("smallest disturbance of steady sliding: %.6f in x, %.6f in x'" % (d.x, d.xdot))

# 7. A restart from a labelled point of an ss_continue run (AUTO's IRS), as
#    `ss_continue --restart DIR --point HB1 --param beta` does.
exe = os.environ.get("STICKSLIP_SS_CONTINUE") or shutil.which("ss_continue")
if exe:
    with tempfile.TemporaryDirectory() as run:
        subprocess.run([exe, "--no_plots", "--no_estimates", "--out", run], check=True,
                       stdout=subprocess.DEVNULL)
        hb1 = stickslip.restart(run, "HB1")
        in_beta = stickslip.continue_branch(hb1.params, options=hb1.options("beta"))
    hb_beta = next(s.p for s in in_beta.special if s.label == "HB")
    print("%r -> HB in beta at %.10f (closed form (k1 - 3 k3 v^2) / 2 = %.10f)" %
          (hb1, hb_beta, (p.k1 - 3 * p.k3 * hb1.p ** 2) / 2))
else:
    print("restart: no ss_continue on PATH (or STICKSLIP_SS_CONTINUE) to write a run")

# Results are read-only NumPy arrays; Ctrl-C interrupts any call.
assert not branch.points.p.flags.writeable
assert abs(hb - 0.4409585518) < 1e-9
