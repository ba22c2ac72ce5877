"""stickslip.System: a model file's system in Python (docs/model_files.md).

The seed belt written as a model file against the built-in one-block chain
(hand-written recurrences): the same trajectory and the same branch; bad
text and bad values are refused by name."""
import os
import unittest

import numpy as np

import stickslip

MODELS = os.path.join(os.path.dirname(__file__), "..", "..", "studies", "models")


class ModelSystem(unittest.TestCase):
    def setUp(self):
        self.belt = stickslip.System.from_file(os.path.join(MODELS, "belt.ini"))
        self.chain = stickslip.ChainParams(blocks=1, law=stickslip.Params(), kc=0.0)

    def test_names_and_parameters(self):
        self.assertEqual(self.belt.name, "belt")
        self.assertEqual(self.belt.state_names, ["x", "x'"])
        self.assertEqual(self.belt.parameters["v_m"], 0.5)
        copy = self.belt.copy()
        copy["v"] = 0.3
        self.assertEqual(copy["v"], 0.3)
        self.assertEqual(self.belt["v"], 0.25)  # the copy is its own

    def test_the_same_trajectory_as_the_built_in_belt(self):
        a = stickslip.simulate(self.belt, [0.1, 0.0], t_end=100.0)
        b = stickslip.simulate(self.chain, [0.1, 0.0], t_end=100.0)
        self.assertEqual(len(a.t), len(b.t))
        self.assertLess(np.max(np.abs(a.z - b.z)), 1e-12)  # 1.5e-13 measured
        self.assertTrue(np.any(a.mode == "stick"))

    def test_the_same_branch_as_the_built_in_belt(self):
        start = [0.4 - 2 * 0.05 * 0.25, 0.25]
        a = stickslip.continue_orbits(self.belt, "v", start, to=0.5, section="stick-exit")
        b = stickslip.continue_orbits(self.chain, "v", start, to=0.5, section="stick-exit")
        self.assertEqual(len(a.p), len(b.p))
        self.assertLess(np.max(np.abs(a.p - b.p)), 1e-12)
        self.assertLess(np.max(np.abs(a.period - b.period)), 1e-12)

    def test_a_forced_file_settles_on_its_stroboscopic_map(self):
        """forced.ini (a clock): settle finds the periodic orbit of the stroboscopic map,
        turns clock turns long, which a plain run at a tighter tolerance closes."""
        forced = stickslip.System.from_file(os.path.join(MODELS, "forced.ini"))
        forced["omega"] = 1.0
        s = stickslip.settle(forced, [0.01, 0.0, 0.0])
        self.assertTrue(s.found, s.message)
        self.assertEqual((s.turns, s.returns), (1, 0))
        self.assertAlmostEqual(s.period, 2 * np.pi, delta=1e-12)
        run = stickslip.simulate(forced, s.start, t_end=s.period, dt=s.period, rtol=1e-13,
                                 atol=1e-13)
        np.testing.assert_allclose(run.z[-1][:2], s.start[:2], atol=1e-9)

    def test_the_drill_strings_steady_rotation_slips_above(self):
        """drill_string.ini (first-order states): steady rotation has the bit slipping above
        its contact velocity 0, at T_m = (c_r + c_b) w + W_ob R_b mu(w)."""
        drill = stickslip.System.from_file(os.path.join(MODELS, "drill_string.ini"))
        self.assertEqual(drill.state_names, ["phi", "w_r", "w_b"])
        rest = stickslip.steady_sliding(drill)
        w = rest.z[2]
        p = drill.parameters
        mu = p["mu_cb"] + (p["mu_sb"] - p["mu_cb"]) * np.exp(-p["gamma_b"] * w)
        self.assertAlmostEqual((p["c_r"] + p["c_b"]) * w + p["W_ob"] * p["R_b"] * mu, p["T_m"],
                               delta=1e-8)
        self.assertGreater(w, 0)

    def test_bad_text_and_values_are_refused_by_name(self):
        with self.assertRaisesRegex(stickslip.InvalidArgument, r"mine.ini:2: .*unknown name \"q\""):
            stickslip.System.from_text("coordinates = x\nx'' = -x + F + q\ncontact F = x'\n"
                                       "law F = 0.3\n", source="mine.ini")
        with self.assertRaisesRegex(stickslip.InvalidArgument, "cannot read"):
            stickslip.System.from_file(os.path.join(MODELS, "none.ini"))
        with self.assertRaisesRegex(TypeError, "v must be a number, not str"):
            self.belt["v"] = "fast"
        with self.assertRaisesRegex(KeyError, "'q' is no parameter of belt"):
            self.belt["q"]
        with self.assertRaisesRegex(stickslip.InvalidArgument, "v_m = 0 divides"):
            self.belt["v_m"] = 0.0
        self.assertEqual(self.belt["v_m"], 0.5)  # unchanged


if __name__ == "__main__":
    unittest.main()
