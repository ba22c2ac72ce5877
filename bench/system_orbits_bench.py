"""Time per row of stickslip.orbits(system, ...) for autonomous model files (C++
SettledOrbits: a 3000-unit settling run and Newton per row): the drill string over
T_m in [9900, 10600] from rest and chain2.ini over v in [0.1, 0.4] from its default start
(steady sliding nudged), 40 rows each, on 1 and 2 threads.

    PYTHONPATH=build/python /usr/bin/python3 bench/system_orbits_bench.py
"""
import os
import time

import numpy as np

import stickslip

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
SCENES = [("drill_string.ini", "T_m", (9900.0, 10600.0), [0.0, 0.0, 0.0]),
          ("chain2.ini", "v", (0.1, 0.4), None)]

for model, name, (lo, hi), state in SCENES:
    system = stickslip.System.from_file(os.path.join(ROOT, "studies", "models", model))
    column = {name: np.linspace(lo, hi, 40)}
    for threads in (1, 2):
        wall, cpu = time.perf_counter(), time.process_time()
        r = stickslip.orbits(system, column, threads=threads, state=state)
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        print(f"{model:18s} threads {threads}: wall {wall / 40 * 1e3:6.2f} ms/row, "
              f"CPU {cpu / 40 * 1e3:6.2f} ms/row, found {np.mean(r['found']):.3f}")
