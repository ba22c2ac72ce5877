"""The Python module against closed forms and the seed (ctest: Python.*).

References: HB = sqrt((k1 - 2 beta) / (3 k3)) (seed eq. 3.16); at GR the stick
phase of the stick-slip orbit vanishes (t_stick -> 0); the first stick phase
from (0, v) ends where x + 2 beta v = mu_s (seed eq. 3.6), at t = (mu_s - 2 beta v) / v.
"""
import math
import unittest
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import stickslip


def hopf(p):
    return math.sqrt((p.k1 - 2 * p.beta) / (3 * p.k3))


def special(result, label):
    return [s["p"] for s in result["special"] if s["label"] == label]


class SeedBranch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.seed = stickslip.Params()
        cls.branch = stickslip.continue_branch(cls.seed, "v", from_=0.05, to=0.5)

    def test_hopf_point_is_the_closed_form(self):
        (hb,) = special(self.branch, "HB")
        self.assertAlmostEqual(hb, hopf(self.seed), delta=1e-9)
        self.assertAlmostEqual(hb, 0.4409585518, delta=1e-10)

    def test_grazing_point_is_where_the_stick_phase_vanishes(self):
        (gr,) = special(self.branch, "GR")
        self.assertAlmostEqual(gr, 0.3957902888, delta=1e-9)  # README, seed.ini
        # GR is located to ~1e-12: just below it the stick phase is ~sqrt(GR - v) short
        # (at GR itself the orbit may already have become pure slip, no return).
        at_gr = stickslip.periodic_orbit(stickslip.Params(v=gr - 1e-12))
        before = stickslip.periodic_orbit(stickslip.Params(v=gr - 0.01))
        self.assertLess(at_gr["t_stick"], 1e-5)
        self.assertGreater(before["t_stick"], 0.1)

    def test_points_are_numpy_arrays_of_one_length(self):
        pts = self.branch["points"]
        self.assertEqual(self.branch.status, stickslip.ContinuationStatus.ok)
        self.assertEqual(str(self.branch.status), "ok")
        n = len(pts["p"])
        self.assertGreater(n, 100)
        for key, arr in pts.items():
            self.assertIsInstance(arr, np.ndarray, key)
            self.assertEqual(len(arr), n, key)
        self.assertTrue(np.all(np.isfinite(pts["x_max"])))
        self.assertEqual(set(pts["kind"]), {"stick-slip", "pure-slip", "equilibrium"})


class Simulation(unittest.TestCase):
    def test_first_stick_phase_ends_at_the_closed_form_time(self):
        p = stickslip.Params()
        run = stickslip.simulate(p, x0=0.0, xdot0=p.v, t_end=3.0, dt=0.01)
        stick = run["mode"] == "stick"
        self.assertTrue(np.all(run["xdot"][stick] == p.v))
        first_slip = run["t"][np.argmax(~stick)]
        self.assertAlmostEqual(first_slip, (p.mu_s - 2 * p.beta * p.v) / p.v, delta=1e-9)


class Errors(unittest.TestCase):
    def test_invalid_model_raises_with_the_apps_message(self):
        with self.assertRaises(stickslip.InvalidArgument) as cm:
            stickslip.Params(mu_m=0.5).validate()
        self.assertEqual(str(cm.exception), "mu_m = 0.5 must be < mu_s = 0.4")
        self.assertIsInstance(cm.exception, ValueError)

    def test_unknown_parameter_raises(self):
        with self.assertRaises(ValueError):
            stickslip.continue_branch(stickslip.Params(), "nope")
        with self.assertRaises(ValueError):
            stickslip.Params(nope=1.0)


class Physical(unittest.TestCase):
    def test_unit_scales_give_the_seed_set(self):
        p = stickslip.Params.from_physical(mass=1, stiffness=1, gravity=1, damping=0.1,
                                           belt_speed=0.25, speed_m=0.5)
        self.assertEqual(p.to_dict(), stickslip.Params().to_dict())
        self.assertEqual(stickslip.scales(2, 8, 9.81), (2.4525, 0.5))
        with self.assertRaises(ValueError):
            stickslip.Params.from_physical(mass=-1)


class Sweep(unittest.TestCase):
    def test_beta_sweep_in_threads_matches_the_closed_form(self):
        betas = [0.02, 0.05, 0.08]

        def hb(beta):
            r = stickslip.continue_branch(stickslip.Params(beta=beta), "v", from_=0.3, to=0.5)
            return special(r, "HB")

        with ThreadPoolExecutor(max_workers=3) as pool:
            found = list(pool.map(hb, betas))
        for beta, points in zip(betas, found):
            self.assertEqual(len(points), 1)
            self.assertAlmostEqual(points[0], hopf(stickslip.Params(beta=beta)), delta=1e-9)

    def test_chart_hopf_curve_is_the_closed_form(self):
        # Seed chart in (v, beta): every HB point on v = sqrt((k1 - 2 beta) / (3 k3)).
        chart = stickslip.chart(stickslip.Params(), "v", 0.05, 0.6, "beta", 0.0, 0.25)
        hb = [c for c in chart["curves"] if c["label"] == "HB"]
        self.assertEqual(len(hb), 1)
        self.assertGreater(len(hb[0]["v"]), 20)
        for v, beta in zip(hb[0]["v"], hb[0]["beta"]):
            k1, k3 = 0.45, 0.6
            self.assertAlmostEqual(v, math.sqrt((k1 - 2 * beta) / (3 * k3)), delta=1e-10)
        self.assertEqual([c["label"] for c in chart["curves"]].count("GR"), 1)
        with self.assertRaises(ValueError):
            stickslip.chart(stickslip.Params(), "v", 0.05, 0.6, "v", 0.0, 0.25)

    def test_version(self):
        self.assertRegex(stickslip.__version__, r"^\d+\.\d+\.\d+$")


if __name__ == "__main__":
    unittest.main()
