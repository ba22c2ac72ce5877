"""stickslip.orbits (ctest: Python.Orbits): the batched stick-slip orbits against
the closed form of the undamped coulomb law (the slip arc is a circle about
x = mu_k of radius R = sqrt(v^2 + (mu_s - mu_k)^2); period
pi + 2 atan(v / (mu_s - mu_k)) + 2 (mu_s - mu_k) / v, stick time
2 (mu_s - mu_k) / v), against periodic_orbit one point at a time, one thread
against two; read-only columns, zeros on rows without an orbit, and bad input
refused with TypeError or ValueError naming it."""
import math
import unittest

import numpy as np

import stickslip

OK, MISSED = int(stickslip.OrbitStatus.ok), int(stickslip.OrbitStatus.missed)
KEYS = ["status", "stick_slip", "period", "t_stick", "x_min", "x_max", "xdot_min", "xdot_max",
        "stable"]


class Orbits(unittest.TestCase):
    def test_undamped_coulomb_matches_the_closed_form(self):
        v = np.array([0.05, 0.1, 0.25, 0.5, 1.0])
        mu_s = np.array([0.3, 0.4, 0.4, 0.5, 0.6])
        p = stickslip.Params("coulomb", beta=0.0)
        r = stickslip.orbits(p, {"v": v, "mu_s": mu_s}, rtol=1e-12, atol=1e-14)
        d = mu_s - p.mu_k
        self.assertTrue(np.all(r["status"] == OK))
        np.testing.assert_allclose(r["period"], np.pi + 2 * np.arctan(v / d) + 2 * d / v,
                                   rtol=0, atol=1e-9)
        np.testing.assert_allclose(r["t_stick"], 2 * d / v, rtol=0, atol=1e-9)
        np.testing.assert_allclose(r["x_max"], p.mu_k + np.hypot(v, d), rtol=0, atol=1e-10)
        np.testing.assert_allclose(r["xdot_min"], -np.hypot(v, d), rtol=0, atol=1e-10)

    def test_rows_agree_with_periodic_orbit_and_missed_rows_hold_zeros(self):
        v = np.linspace(0.05, 0.47, 15)
        r = stickslip.orbits(stickslip.Params(), {"v": v}, threads=2)
        self.assertEqual(list(r), KEYS)
        for k, a in r.items():
            self.assertFalse(a.flags.writeable, k)
            self.assertEqual(a.shape, (15,), k)
        self.assertEqual(r["status"].dtype, np.uint8)
        self.assertEqual(r["stable"].dtype, bool)
        for i, vi in enumerate(v):
            if r["status"][i] == OK:
                o = stickslip.periodic_orbit(stickslip.Params(v=vi))
                self.assertAlmostEqual(r["period"][i], o.period, delta=1e-12)
                self.assertAlmostEqual(r["x_max"][i], o.x_max, delta=1e-12)
                self.assertTrue(r["stick_slip"][i] and r["stable"][i])
            else:  # past the end of the stick-slip branch (v 0.44 at the seed)
                self.assertEqual(r["status"][i], MISSED)
                self.assertGreater(vi, 0.4)
                self.assertFalse(r["stick_slip"][i] or r["stable"][i])
                for k in KEYS[2:-1]:
                    self.assertEqual(r[k][i], 0.0, k)
        self.assertEqual(str(stickslip.OrbitStatus(MISSED)), "missed")

    def test_one_and_two_threads_are_equal_and_floquet_adds_the_multiplier(self):
        rng = np.random.default_rng(3)
        cols = {"v": rng.uniform(0.05, 0.45, 3000), "mu_s": rng.normal(0.4, 0.02, 3000)}
        one = stickslip.orbits(stickslip.Params(), cols, threads=1)
        two = stickslip.orbits(stickslip.Params(), cols, threads=2)
        for k in KEYS:
            self.assertTrue(np.array_equal(one[k], two[k]), k)
        f = stickslip.orbits(stickslip.Params(), cols, threads=2, floquet=True)
        self.assertEqual(list(f), KEYS[:-1] + ["multiplier", "stable"])
        ok = f["status"] == OK
        self.assertTrue(np.array_equal(f["status"], one["status"]))
        self.assertLess(np.abs(f["multiplier"][ok]).max(), 1e-9)  # superstable
        self.assertTrue(np.all(f["multiplier"][~ok] == 0))

    def test_bad_input_names_the_argument(self):
        p = stickslip.Params()
        type_errors = [({"v": ["a", "b"]}, "column 'v' must hold real numbers"),
                       ({"v": np.array([True, False])}, "dtype bool"),
                       ({1: [0.1]}, "column names must be parameter names"),
                       ([("v", [0.1])], "columns must be a dict")]
        for cols, words in type_errors:
            with self.assertRaises(TypeError, msg=words) as e:
                stickslip.orbits(p, cols)
            self.assertIn(words, str(e.exception))
        value_errors = [({"nope": [0.1]}, "nope"),
                        ({"v": [[0.1, 0.2]]}, "column 'v' must be 1-D, not of shape (1, 2)"),
                        ({"v": [0.1, 0.2], "mu_s": [0.4]}, "columns differ in length: v 2, mu_s 1"),
                        ({"v": [0.1, -0.2]}, "row 1: v = -0.2 must be > 0"),
                        ({"v": [0.1, math.nan]}, "row 1: v = nan is not a finite number"),
                        ({"mu_k": [0.1]}, "column 'mu_k': not a parameter of the cubic law"),
                        ({}, "no parameter column")]
        for cols, words in value_errors:
            with self.assertRaises(ValueError, msg=words) as e:
                stickslip.orbits(p, cols)
            self.assertIn(words, str(e.exception))
        with self.assertRaises(ValueError) as e:
            stickslip.orbits(p, {"v": [0.1]}, threads=-1)
        self.assertIn("threads = -1", str(e.exception))
        with self.assertRaises(TypeError):
            stickslip.orbits({"v": 0.1}, {"v": [0.1]})

    def test_zero_rows_give_empty_columns(self):
        r = stickslip.orbits(stickslip.Params(), {"v": []})
        self.assertEqual(list(r), KEYS)
        self.assertTrue(all(a.shape == (0,) for a in r.values()))


FORCED_KEYS = ["status", "found", "stick_slip", "stable", "m", "sticks", "period", "x0", "xdot0",
               "x_min", "x_max", "xdot_min", "xdot_max", "multiplier"]


def seed_forced(omega=0.6):
    """studies/seed_forced.ini's oscillator."""
    return stickslip.ForcedBeltParams(stickslip.Params(beta=0.05, v=0.25), force=0.3, omega=omega)


class ForcedOrbits(unittest.TestCase):
    """stickslip.orbits on a ForcedBeltParams: the stroboscopic orbits of
    orbits/system_batch.hpp, each row against periodic_orbit (the single-orbit
    API) from the row's point, and Den Hartog's non-stop amplitude."""

    def test_rows_agree_with_periodic_orbit(self):
        w = np.repeat(np.linspace(0.5, 1.5, 21), 3)
        mu_s = np.tile([0.38, 0.4, 0.42], 21)
        r = stickslip.orbits(seed_forced(), {"omega": w, "mu_s": mu_s}, threads=2)
        self.assertEqual(list(r), FORCED_KEYS)
        for k, a in r.items():
            self.assertFalse(a.flags.writeable, k)
            self.assertEqual(a.shape, (63,), k)
        found = r["status"] == OK
        self.assertTrue(np.array_equal(found, r["found"]))
        self.assertGreater(found.sum(), 50)
        aperiodic = r["status"] == int(stickslip.OrbitStatus.aperiodic)
        self.assertTrue(np.all(found | aperiodic))
        for k in ("m", "period", "x_max", "multiplier"):
            self.assertTrue(np.all(r[k][~found] == 0), k)
        for i in np.flatnonzero(found):
            p = seed_forced(w[i])
            p.params = stickslip.Params(beta=0.05, v=0.25, mu_s=mu_s[i])
            o = stickslip.periodic_orbit(p, [r["x0"][i], r["xdot0"][i], 0.0], m=int(r["m"][i]))
            self.assertEqual(o.sticks, r["sticks"][i])
            self.assertAlmostEqual(o.period, r["period"][i], delta=1e-12)
            self.assertAlmostEqual(o.hi[0], r["x_max"][i], delta=1e-11)
            self.assertAlmostEqual(o.lo[1], r["xdot_min"][i], delta=1e-11)
            self.assertAlmostEqual(max(abs(o.multipliers)), r["multiplier"][i], delta=1e-8)
            self.assertEqual(r["stick_slip"][i], o.sticks > 0)

    def test_non_stop_rows_match_den_hartog(self):
        w = np.array([1.3, 1.5, 2.0, 2.5])
        p = stickslip.ForcedBeltParams(stickslip.Params("coulomb", mu_s=0.3, mu_k=0.3, beta=0.0,
                                                    v=0.0), force=1.0, omega=1.3)
        r = stickslip.orbits(p, {"omega": w}, x0=-0.5, transient=0, max_m=1, rtol=1e-14,
                             atol=1e-14)
        V = 1 / (1 - w * w)
        U = np.sin(np.pi / w) / (w * (1 + np.cos(np.pi / w)))
        X = np.sqrt(V * V - (0.3 * U) ** 2)  # Den Hartog (1931)
        self.assertTrue(np.all(r["status"] == OK))
        np.testing.assert_allclose(r["x_max"], X, rtol=0, atol=1e-9)
        np.testing.assert_allclose(-r["x_min"], X, rtol=0, atol=1e-9)
        self.assertTrue(np.all(r["sticks"] == 0))

    def test_one_and_two_threads_are_equal(self):
        rng = np.random.default_rng(5)
        cols = {"omega": rng.uniform(0.6, 1.4, 300), "mu_s": rng.normal(0.4, 0.02, 300)}
        one = stickslip.orbits(seed_forced(), cols, threads=1)
        two = stickslip.orbits(seed_forced(), cols, threads=2)
        for k in FORCED_KEYS:
            self.assertTrue(np.array_equal(one[k], two[k]), k)

    def test_bad_input_names_the_argument(self):
        p = seed_forced()
        value_errors = [({"nope": [0.1]}, "column 'nope' is not a parameter of the forced cubic"),
                        ({"mu_k": [0.1]}, "column 'mu_k' is not a parameter"),
                        ({"omega": [0.5, 0.0]}, "row 1 (omega = 0): omega = 0 must be"),
                        ({"force": [0.1, math.nan]}, "row 1: force = nan is not finite"),
                        ({"omega": [0.5], "force": [0.1, 0.2]}, "columns differ in length"),
                        ({}, "no parameter column")]
        for cols, words in value_errors:
            with self.assertRaises(ValueError, msg=words) as e:
                stickslip.orbits(p, cols)
            self.assertIn(words, str(e.exception))
        for kw, words in (({"max_m": 0}, "max_m = 0"), ({"transient": -1}, "transient = -1"),
                          ({"recurrence": 0.0}, "recurrence = 0"), ({"x0": math.inf}, "start")):
            with self.assertRaises(ValueError, msg=words) as e:
                stickslip.orbits(p, {"omega": [0.5]}, **kw)
            self.assertIn(words, str(e.exception))


if __name__ == "__main__":
    unittest.main()
