"""The forced oscillator in the module (issue 20, item 6), against Den Hartog's
(1931) closed form X = sqrt(V^2 - (mu U)^2), V = A / (1 - W^2),
U = sin(pi / W) / (W (1 + cos(pi / W))), computed here on its own; and Ctrl-C in
its long calls."""
import math
import os
import signal
import subprocess
import sys
import time
import unittest

import numpy as np

import stickslip
from wall_bound import WallBound


def den_hartog(mu, a, w):
    V = a / (1 - w * w)
    U = math.sin(math.pi / w) / (w * (1 + math.cos(math.pi / w)))
    return math.sqrt(V * V - (mu * U) ** 2)


def den_hartog_params(w):
    return stickslip.ForcedBeltParams(stickslip.Params("coulomb", mu_s=0.3, mu_k=0.3, beta=0.0, v=0.0),
                                  force=1.0, omega=w)


class Forced(unittest.TestCase):
    def test_orbit_and_scan_give_den_hartogs_amplitude(self):
        for w in (0.8, 1.5, 2.2):
            p = den_hartog_params(w)
            o = stickslip.periodic_orbit(p, [0.5, 0.0, 0.0])  # the clock's section by default
            self.assertEqual(type(o), stickslip.SystemOrbit)
            self.assertAlmostEqual(o.hi[0], den_hartog(0.3, 1, w), delta=1e-9)
            self.assertEqual((o.turns, o.sticks), (1, 0))
            self.assertAlmostEqual(o.period, 2 * math.pi / w, delta=1e-12)
            orbits = stickslip.periodic_orbits(p)
            nonstop = [q for q in orbits if q.turns == 1 and q.sticks == 0]
            self.assertEqual(len(nonstop), 1)
            self.assertAlmostEqual(nonstop[0].hi[0], den_hartog(0.3, 1, w), delta=1e-9)
            self.assertEqual(nonstop[0].points.shape, (1, 3))
            np.testing.assert_allclose(nonstop[0].points[0], o.start, rtol=0, atol=1e-9)

    def test_simulation_settles_on_den_hartogs_orbit(self):
        w = 1.5
        T = 2 * math.pi / w
        tr = stickslip.simulate(den_hartog_params(w), [0.0, 0.0, 0.0], t_end=300.0, dt=0.001,
                                section=stickslip.SimulationSection.strobe)
        n = len(tr.section_t)
        self.assertEqual(n, int(300 / T) + 1)
        np.testing.assert_allclose(tr.section_t, T * np.arange(n), rtol=1e-12, atol=1e-12)
        self.assertEqual(tr.names, ["x", "x'", "theta"])
        last = tr.t >= 300 - T
        self.assertAlmostEqual(tr.z[last, 0].max(), den_hartog(0.3, 1, w), delta=1e-5)
        self.assertTrue(set(tr.mode) <= {"slip-below", "slip-above", "stick"})
        exits = stickslip.simulate(den_hartog_params(w), [0.0, 0.0, 0.0], t_end=30.0,
                                   section=stickslip.SimulationSection.exit)
        self.assertEqual(len(exits.section_t), exits.exits)

    def test_one_simulate_takes_any_system(self):
        # The strobe's points are the rows' states at n T: the same run at the
        # forced oscillator's tolerances, the section points on t = n T exactly.
        p = den_hartog_params(1.5)
        T = 2 * math.pi / 1.5
        new = stickslip.simulate(p, [0.2, 0.0, 0.0], t_end=40.0, dt=T / 8,
                                 section=stickslip.SimulationSection.strobe)
        n = len(new.section_t)
        np.testing.assert_array_equal(new.section_t, T * np.arange(n))
        on_grid = [np.argmin(abs(new.t - t)) for t in new.section_t]
        np.testing.assert_allclose(new.section_z[:, :2], new.z[on_grid, :2], rtol=0, atol=1e-12)
        turn = new.section_z[:, 2] / (2 * math.pi)  # the phase at whole turns
        np.testing.assert_allclose(turn, np.round(turn), rtol=0, atol=1e-12)
        self.assertEqual(new.section, stickslip.SimulationSection.strobe)
        plain = stickslip.simulate(p, [0.2, 0.0, 0.0], t_end=40.0, dt=T / 8)
        self.assertEqual(plain.section_z.shape, (0, 3))
        np.testing.assert_allclose(plain.z, new.z, rtol=0, atol=1e-10)
        chain = stickslip.ChainParams(2)
        a = stickslip.simulate(chain, [0.1, 0.0, 0.0, 0.0], t_end=20.0,
                               section=stickslip.SimulationSection.exit)
        b = stickslip.simulate_system(chain, [0.1, 0.0, 0.0, 0.0], t_end=20.0)
        np.testing.assert_array_equal(a.z, b.z)
        self.assertEqual(len(a.section_t), a.exits)
        with self.assertRaisesRegex(ValueError, "give period"):
            stickslip.simulate(chain, [0.1, 0, 0, 0], section=stickslip.SimulationSection.strobe)
        with self.assertRaisesRegex(ValueError, "rows and section points is more than max_rows"):
            stickslip.simulate(p, [0.2, 0.0, 0.0], t_end=100.0, dt=0.01, max_rows=10002,
                               section=stickslip.SimulationSection.strobe)
        with self.assertRaisesRegex(ValueError, "dt = inf must be a finite number > 0"):
            stickslip.simulate(chain, [0.1, 0, 0, 0], dt=float("inf"))
        with self.assertRaisesRegex(ValueError, "period = -1"):
            stickslip.simulate(chain, [0.1, 0, 0, 0], period=-1.0,
                               section=stickslip.SimulationSection.strobe)
        # The belt's own signature stays.
        self.assertEqual(stickslip.simulate(stickslip.Params(), t_end=1.0).t[-1], 1.0)

    def test_continuation_matches_den_hartog_on_every_row(self):
        p = den_hartog_params(1.5)
        o = stickslip.periodic_orbit(p, [0.5, 0.0, 0.0])
        b = stickslip.continue_branch(p, stickslip.Parameter.omega, o.start,
                                      2.5, max_step=0.02)
        self.assertEqual(b.status, stickslip.BranchStatus.reached_end)
        self.assertGreater(len(b.p), 20)
        self.assertAlmostEqual(b.p[-1], 2.5, delta=1e-12)
        X = np.array([den_hartog(0.3, 1, w) for w in b.p])
        np.testing.assert_allclose(b.hi[:, 0], X, atol=1e-9, rtol=0)
        # m = 1: one forcing period per row
        self.assertTrue(np.all(b.sticks == 0) and np.allclose(b.period, 2 * math.pi / b.p))
        self.assertEqual(b.multipliers.shape, (len(b.p), 2))

    def test_any_parameter_by_member_or_name_is_the_axis(self):
        # The one lens: the Den Hartog branch in mu_k at Omega = 2 (mu_s = 0.3
        # held), its axis by name, against his closed form X(mu_k) on every row.
        p = den_hartog_params(2.0)
        V = 1 / (1 - 4.0)
        b = stickslip.continue_branch(p, "mu_k", [V, 0.01, 0.0], 0.05, max_step=0.02)
        self.assertEqual(b.status, stickslip.BranchStatus.reached_end)
        self.assertEqual(b.parameter, stickslip.Parameter.mu_k.name)
        X = np.array([den_hartog(mu, 1, 2.0) for mu in b.p])
        np.testing.assert_allclose(b.hi[:, 0], X, atol=1e-9, rtol=0)
        with self.assertRaisesRegex(ValueError, "'mu_m' does not apply"):
            stickslip.continue_branch(p, stickslip.Parameter.mu_m, [V, 0.01, 0.0], 0.1)
        with self.assertRaisesRegex(ValueError, "unknown parameter 'gamma'"):
            stickslip.continue_branch(p, "gamma", [V, 0.01, 0.0], 0.1)
        # The belt's functions take the same lens, and refuse the forcing's.
        belt = stickslip.Params()
        self.assertEqual(stickslip.default_range(belt, stickslip.Parameter.v), (0.05, 0.5))
        with self.assertRaisesRegex(ValueError, "'omega' does not apply to the cubic law"):
            stickslip.default_range(belt, "omega")
        with self.assertRaisesRegex(ValueError, "'force' does not apply to the cubic law"):
            stickslip.continue_branch(belt, stickslip.Parameter.force)

    def test_periodic_orbit_and_continue_branch_take_any_system(self):
        # The belt's names with a system and its state (issue 31 item 8): the
        # one shooting and the one branch driver, against Den Hartog's X.
        p = den_hartog_params(2.0)
        o = stickslip.periodic_orbit(p, [-1 / 3, 0.01, 0.0], section="stroboscopic")
        self.assertEqual(type(o), stickslip.SystemOrbit)
        self.assertAlmostEqual(o.hi[0], den_hartog(0.3, 1, 2.0), delta=1e-9)
        b = stickslip.continue_branch(p, "omega", o.start, 2.5)
        self.assertEqual(b.status, stickslip.BranchStatus.reached_end)
        self.assertAlmostEqual(b.p[-1], 2.5, delta=1e-12)
        X = np.array([den_hartog(0.3, 1, w) for w in b.p])
        np.testing.assert_allclose(b.hi[:, 0], X, atol=1e-9, rtol=0)
        # periodic_orbits and basins on the forced oscillator are its scan and basins.
        found = stickslip.periodic_orbits(p, max_m=1)
        self.assertEqual(len(found), 1)
        self.assertAlmostEqual(found[0].hi[0], den_hartog(0.3, 1, 2.0), delta=1e-9)
        d = stickslip.basins(p, nx=3, ny=3, transient=60, keep=16)
        self.assertEqual(type(d), stickslip.AttractorBasins)
        self.assertEqual(d.slice, ["x", "x'"])
        self.assertEqual(list(d.attractor), [0] * 9)  # every start on Den Hartog's orbit
        a = d.attractors[0]
        self.assertEqual((a.kind, a.m, a.starts), ("periodic", 1, 9))
        np.testing.assert_allclose(a.z[:2], o.start[:2], rtol=0, atol=1e-8)
        # The belt's own signatures stay.
        self.assertEqual(type(stickslip.periodic_orbit(stickslip.Params())), stickslip.Orbit)
        self.assertEqual(type(stickslip.periodic_orbits(stickslip.Params())),
                         stickslip.PeriodicOrbits)

    def test_chart_of_the_tongue_ends_its_ns_curves_at_r1(self):
        """chart(ForcedBeltParams, ...) as studies/forced_ns_seed.ini's [chart]: the 1:1 tongue's
        NS curves end where the pair turns real, each at an R1 refined on the curve next to
        its last point; the GR curve of the pure-slip orbits follows their gap to x' = v."""
        p = stickslip.ForcedBeltParams(stickslip.Params("cubic", beta=0.05, v=0.42, mu_s=0.4,
                                                    mu_m=0.25, v_m=0.5), force=0.05, omega=1.3)
        c = stickslip.chart(p, "omega", 0.6, 1.6, "force", 0.002, 0.1)
        self.assertEqual(c.status, "ok", c.message)
        self.assertEqual(sorted(k.kind for k in c.curves), ["GR", "NS", "NS"])
        self.assertTrue(all(k.m == 1 for k in c.curves))
        gr = [k for k in c.curves if k.kind == "GR"][0]
        self.assertTrue(gr.gap)
        r1 = [q for q in c.codim2 if q.label == "R1"]
        self.assertEqual(len(r1), 2)
        for q in r1:
            self.assertEqual((q.on, q.located), ("NS", "refined"))
            ns = c.curves[q.curve]
            self.assertIn("stopped: no complex pair", ns.ends)
            # next to the curve's end there, within a step (1e-2 of the rectangle)
            end = 0 if ns.ends.startswith("stopped") else -1
            self.assertLess(math.hypot(q.p1 - ns.p1[end], (q.p2 - ns.p2[end]) / 0.098), 1e-2)
            self.assertLess(abs(ns.mult_max[end] - 1), 1e-7)

    def test_arrays_are_read_only_and_bad_input_raises(self):
        tr = stickslip.simulate(den_hartog_params(1.5), [0.0, 0.0, 0.0], t_end=5.0,
                                section=stickslip.SimulationSection.strobe)
        for a in (tr.t, tr.z, tr.section_z, tr.mode):
            with self.assertRaises(ValueError):
                a[0] = a[0]
        o = stickslip.periodic_orbit(den_hartog_params(1.5), [0.5, 0.0, 0.0])
        for a in (o.multipliers, o.start, o.points):
            with self.assertRaises(ValueError):
                a[0] = 0
        with self.assertRaisesRegex(stickslip.InvalidArgument, "omega"):
            stickslip.periodic_orbit(den_hartog_params(-1.0), [0.5, 0.0, 0.0])
        with self.assertRaisesRegex(stickslip.InvalidArgument, "max_m"):
            stickslip.periodic_orbits(den_hartog_params(1.5), max_m=0)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "grid is an option of a system with"):
            stickslip.periodic_orbits(stickslip.ChainParams(2), grid=3)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "dt"):
            stickslip.simulate(den_hartog_params(1.5), [0.0, 0.0, 0.0], dt=0.0)


CHILD = r"""
import sys, time, stickslip
p = stickslip.ForcedBeltParams(stickslip.Params("coulomb", mu_s=0.3, mu_k=0.3, beta=0.0, v=0.0),
                           force=1.0, omega=1.5)
calls = {
    "simulate": lambda: stickslip.simulate(p, [0.0, 0.0, 0.0], t_end=1e7, dt=1.0,
                                           max_rows=10000001),
    "periodic_orbits": lambda: stickslip.periodic_orbits(p, max_m=64, grid=100),
}
print("ready", flush=True)
try:
    calls[sys.argv[1]]()
    print("finished", flush=True)
except KeyboardInterrupt:
    print("interrupted %.6f" % time.time(), flush=True)
"""


class CtrlC(unittest.TestCase):
    def test_long_forced_calls_stop_on_sigint(self):
        for name in ("simulate", "periodic_orbits"):
            child = subprocess.Popen([sys.executable, "-c", CHILD, name], stdout=subprocess.PIPE,
                                     text=True, env=os.environ)
            try:
                self.assertEqual(child.stdout.readline().strip(), "ready")
                time.sleep(1.0)
                self.assertIsNone(child.poll(), name + " finished before the signal")
                bound = WallBound()
                sent = time.time()
                child.send_signal(signal.SIGINT)
                out, _ = child.communicate(timeout=10)
            finally:
                if child.poll() is None:
                    child.kill()
                    child.wait()
            self.assertTrue(out.startswith("interrupted"), name + ": " + out)
            self.assertLess(float(out.split()[1]) - sent, bound.of(0.5), name)


if __name__ == "__main__":
    unittest.main()
