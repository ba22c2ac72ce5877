# The period-doubling cascade of studies/stribeck_forced.ini, from the orbit scan:
#   PYTHONPATH=build/python /usr/bin/python3 docs/figures/stribeck_forced/cascade.py
import stickslip as s

base = s.Params("stribeck", beta=0.05, v=0.25, mu_s=0.4, mu_k=0.25, v_s=0.2)
for w in (0.617, 0.612, 0.608, 0.605, 0.603, 0.6):
    orbs = s.periodic_orbits(s.ForcedBeltParams(base, force=0.3, omega=w), max_m=8, grid=4)
    print("w=%.3f: " % w + "; ".join(
        "m%d s%d %s |mu|=%.3f" % (o.turns, o.sticks, "S" if o.stable else "u",
                                  max(abs(o.multipliers))) for o in orbs))
