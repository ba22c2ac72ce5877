"""stickslip.orbits(system, columns) and system_orbits (ctest: Python.SystemOrbits):
the settled stick-slip orbits of a model file's undamped coulomb belt against the
closed form (slip arc a circle about x = mu_k of radius sqrt(v^2 + d^2), d =
mu_s - mu_k; period pi + 2 atan(v / d) + 2 d / v), the drill string's row at
T_m = 10000 against reference/drill_string_reference.py (mpmath Taylor, 40
digits: 5.092532911302433), rows equal to settle() one at a time, a clocked
model on the stroboscopic batch, System pickling, a sweep through a
LocalCluster equal to the serial one, and bad input refused by name."""
import os
import pickle
import unittest

import numpy as np

import stickslip

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
COULOMB = """name = coulomb_belt
coordinates = x
parameter v = 0.2
parameter mu_s = 0.4
parameter mu_k = 0.25
x'' = -x + F
contact F = x' - v
law F = mu_k
static F = mu_s
"""
OK, NO_RETURN = int(stickslip.OrbitStatus.ok), int(stickslip.OrbitStatus.no_return)


class SystemOrbits(unittest.TestCase):
    def test_undamped_coulomb_model_matches_the_closed_form(self):
        s = stickslip.System.from_text(COULOMB)
        v = np.array([0.05, 0.1, 0.15, 0.2, 0.24])  # from rest x' reaches mu_k = 0.25 > v
        mu_s = np.array([0.3, 0.4, 0.35, 0.5, 0.6])
        r = stickslip.orbits(s, {"v": v, "mu_s": mu_s}, state=[0.0, 0.0], transient=200,
                             rtol=1e-12, atol=1e-14)
        d = mu_s - 0.25
        np.testing.assert_array_equal(r["status"], OK)
        np.testing.assert_allclose(r["period"], np.pi + 2 * np.arctan(v / d) + 2 * d / v,
                                   rtol=1e-11, atol=0)
        np.testing.assert_allclose(r["x_max"], 0.25 + np.hypot(v, d), rtol=0, atol=1e-10)
        np.testing.assert_allclose(r["x'_min"], -np.hypot(v, d), rtol=0, atol=1e-10)
        np.testing.assert_allclose(r["x"], mu_s, rtol=0, atol=1e-12)  # the stick exit x = mu_s
        np.testing.assert_array_equal(r["m"], 1)
        np.testing.assert_array_equal(r["contact"], 0)
        np.testing.assert_array_equal(r["sticks"], 1)
        for k, a in r.items():
            self.assertFalse(a.flags.writeable, k)
            self.assertEqual(a.shape, (5,), k)

    def test_drill_row_matches_the_mpmath_reference_and_settle(self):
        drill = stickslip.System.from_file(os.path.join(ROOT, "studies/models/drill_string.ini"))
        t_m = np.array([9900.0, 10000.0, 10300.0])
        # From rest (the default start, steady rotation nudged, stays there:
        # it is stable and coexists with stick-slip).
        r = stickslip.orbits(drill, {"T_m": t_m}, threads=2, state=np.zeros(3))
        self.assertTrue(np.all(r["stick_slip"]))
        steady = stickslip.orbits(drill, {"T_m": t_m})
        np.testing.assert_array_equal(steady["status"], NO_RETURN)
        self.assertAlmostEqual(r["period"][1], 5.092532911302433, delta=1e-11)
        for i, t in enumerate(t_m):
            one = drill.copy()
            one["T_m"] = t
            s = stickslip.settle(one, np.zeros(3))
            self.assertTrue(s.found, s.message)
            self.assertEqual(s.period, r["period"][i])
            self.assertEqual(s.returns, r["m"][i])
            self.assertEqual(s.stable, bool(r["stable"][i]))
            np.testing.assert_array_equal(s.start, [r["phi"][i], r["w_r"][i], r["w_b"][i]])

    def test_steady_sliding_rows_have_no_return_and_zeros(self):
        s = stickslip.System.from_text(COULOMB.replace("x'' = -x + F", "x'' = -0.1*x' - x + F"))
        r = stickslip.orbits(s, {"v": [0.1, 3.0]}, state=[0.0, 0.0], transient=300)
        self.assertEqual(r["status"][0], OK)
        self.assertEqual(r["status"][1], NO_RETURN)  # slides on: the flow never meets the belt
        self.assertEqual(r["period"][1], 0)
        self.assertEqual(r["contact"][1], -1)

    def test_a_chain_of_like_blocks_starts_off_step_by_default(self):
        # From steady sliding nudged (the default), not the origin, where two
        # like blocks would move in step and miss their attractor.
        r = stickslip.orbits(stickslip.ChainParams(), {"v": np.linspace(0.05, 0.35, 7)})
        np.testing.assert_array_equal(r["status"], OK)
        self.assertTrue(np.all(r["stick_slip"]))

    def test_a_clocked_model_takes_the_stroboscopic_batch(self):
        forced = stickslip.System.from_file(os.path.join(ROOT, "studies/models/forced.ini"))
        r = stickslip.orbits(forced, {"omega": [0.8, 1.2]})
        np.testing.assert_array_equal(r["contact"], -1)
        ok = r["status"] == OK
        self.assertTrue(np.any(ok))
        np.testing.assert_allclose(r["period"][ok], r["m"][ok] * 2 * np.pi / np.array([0.8, 1.2])[ok],
                                   rtol=1e-13)

    def test_a_system_pickles_with_its_parameters(self):
        s = stickslip.System.from_text(COULOMB, "mine.ini")
        s["v"] = 0.3
        t = pickle.loads(pickle.dumps(s))
        self.assertEqual(t["v"], 0.3)
        self.assertEqual(repr(t), repr(s))

    def test_sweep_on_a_local_cluster_equals_the_serial_one(self):
        s = stickslip.System.from_text(COULOMB)
        fn = stickslip.system_orbits(s, state=[0.0, 0.0], transient=200)
        grid = {"v": np.linspace(0.05, 0.24, 12)}
        serial = stickslip.sweep(fn, grid, scheduler="serial")
        dask = stickslip.sweep(fn, grid, n_workers=2, chunk_size=3)
        self.assertIn("period", serial.columns)
        for c in serial.columns:
            np.testing.assert_array_equal(serial[c], dask[c], c)
        self.assertTrue(np.all(serial["stick_slip"] == 1))

    def test_bad_input_is_refused_by_name(self):
        s = stickslip.System.from_text(COULOMB)
        with self.assertRaisesRegex(ValueError, "column 'w' is no parameter"):
            stickslip.orbits(s, {"w": [1.0]})
        with self.assertRaisesRegex(TypeError, "columns must be a dict"):
            stickslip.orbits(s, [1.0])
        with self.assertRaisesRegex(ValueError, r"state must be 2 numbers \(x, x'\)"):
            stickslip.orbits(s, {"v": [0.2]}, state=[0, 0, 0])
        with self.assertRaisesRegex(TypeError, "state must hold real numbers"):
            stickslip.orbits(s, {"v": [0.2]}, state="abc")
        with self.assertRaisesRegex(TypeError, "threads must be an integer"):
            stickslip.orbits(s, {"v": [0.2]}, threads=1.5)
        with self.assertRaisesRegex(ValueError, "max_m = 0 must be >= 1"):
            stickslip.orbits(s, {"v": [0.2]}, max_m=0)
        with self.assertRaisesRegex(ValueError, "recurrence applies to a system with a clock"):
            stickslip.orbits(s, {"v": [0.2]}, recurrence=1e-3)
        with self.assertRaisesRegex(ValueError, r"row 0 \(mu_s = -1\): the static coefficient"):
            stickslip.orbits(s, {"mu_s": [-1.0]})
        with self.assertRaisesRegex(ValueError, "threads"):
            stickslip.system_orbits(s, threads=2)
        # The belt's and the forced oscillator's own overloads: a keyword of
        # this one given to them is refused, not run on another path.
        with self.assertRaisesRegex(TypeError, "orbits\\(Params"):
            stickslip.orbits(stickslip.Params(), {"v": [0.2]}, transient=100)
        fp = stickslip.ForcedBeltParams(stickslip.Params(), force=0.3, omega=0.8)
        with self.assertRaisesRegex(TypeError, "orbits\\(ForcedBeltParams"):
            stickslip.orbits(fp, {"omega": [0.8]}, state=[0, 0, 0])
        with self.assertRaisesRegex(TypeError, "transient must be an integer, not 20.5"):
            stickslip.orbits(fp, {"omega": [0.8]}, transient=20.5)
        # NumPy integers reach the forced overload's own rows (x0, xdot0 columns).
        r = stickslip.orbits(fp, {"omega": [0.8]}, transient=np.int64(20), threads=np.int64(1))
        self.assertIn("xdot0", r)


class AutonomousScan(unittest.TestCase):
    """periodic_orbits(system) of two identical seed blocks at v = 0.3 (C++
    FindAutonomousOrbits): the synchronized orbit is the belt's own (its
    periodic_orbits(params)), the alternating one has x2(t) = x1(t + T/2) at
    the period ss_continue gives (ss_continue --study chain2 --set kc=0.5)."""

    def chain(self, kc):
        law = stickslip.Params("cubic", beta=0.05, mu_s=0.4, mu_m=0.25, v_m=0.5, v=0.3)
        return law, stickslip.ChainParams(2, law=law, kc=kc)

    def test_synchronized_orbit_is_the_belts_and_the_alternating_one_is_found(self):
        law, chain = self.chain(0.5)
        belt = stickslip.periodic_orbits(law).stick_slip
        orbits = stickslip.periodic_orbits(chain)
        sync = [o for o in orbits if abs(o.start[0] - o.start[2]) < 1e-9]
        self.assertEqual(len(sync), 1)
        o = sync[0]
        self.assertAlmostEqual(o.period, belt.period, delta=1e-9)
        self.assertAlmostEqual(o.lo[0], belt.x_min, delta=1e-9)
        self.assertAlmostEqual(o.hi[0], belt.x_max, delta=1e-9)
        self.assertEqual(o.contact_sticks, [1, 1])
        self.assertEqual(len(o.multipliers), 3)
        self.assertEqual(o.origin.shape, (4,))
        alt = [o for o in orbits if abs(o.period - 4.525710084704488) < 1e-8]
        self.assertEqual(len(alt), 1)
        a = alt[0]
        self.assertTrue(a.stable)
        # Its section points: block 1's exit, then block 2's with the blocks swapped.
        self.assertEqual(list(a.points.shape), [2, 4])
        swapped = a.points[1][[2, 3, 0, 1]]
        np.testing.assert_allclose(swapped, a.points[0], atol=1e-8)
        # Its repr reads back the period, sticks, largest |multiplier| and stability.
        self.assertEqual(repr(a), "<SystemOrbit ok: period %r, sticks %d, largest |multiplier| %r, "
                         "stable>" % (a.period, a.sticks, max(abs(m) for m in a.multipliers)))

    def test_given_starts_and_bad_options(self):
        law, chain = self.chain(0.5)
        # No modal starts: one given start with the blocks in step stays in step.
        found = stickslip.periodic_orbits(chain, amplitudes=[], starts=[[0.6, 0.0, 0.6, 0.0]],
                                          transient=100.0)
        self.assertEqual(len(found), 1)
        self.assertEqual(found[0].origin_mode, -1)
        np.testing.assert_array_equal(found[0].origin, [0.6, 0.0, 0.6, 0.0])
        self.assertAlmostEqual(found[0].period, stickslip.periodic_orbits(law).stick_slip.period,
                               delta=1e-9)
        with self.assertRaisesRegex(ValueError, "amplitudes"):
            stickslip.periodic_orbits(chain, amplitudes=[0.0])
        with self.assertRaisesRegex(ValueError, "transient"):
            stickslip.periodic_orbits(chain, transient=-1.0)
        with self.assertRaisesRegex(ValueError, "grid"):
            stickslip.periodic_orbits(chain, grid=3)
        with self.assertRaisesRegex(ValueError, "starts"):
            stickslip.periodic_orbits(chain, starts=[[0.0, 0.0]])
        with self.assertRaisesRegex(ValueError, "transient"):
            stickslip.periodic_orbits(stickslip.ForcedBeltParams(law, force=0.1, omega=1.0),
                                      transient=10.0)

    def test_an_empty_scan_says_why(self):
        # The brake model at its defaults: steady sliding is stable (every
        # eigenvalue's real part < 0), so every run from it decays and no
        # stick exit recurs: no orbit, and a RuntimeWarning with the counts.
        system = stickslip.CouplingParams()
        self.assertLess(max(e.real for e in stickslip.steady_sliding(system).eigenvalues), 0)
        with self.assertWarnsRegex(RuntimeWarning, r"no periodic orbit found \(\d+ starts"):
            orbits = stickslip.periodic_orbits(system)
        self.assertEqual(orbits, [])


if __name__ == "__main__":
    unittest.main()
