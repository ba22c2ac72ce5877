"""continue_orbits: the one branch driver from Python, on the forced oscillator's
stroboscopic section (Den Hartog's closed form) and on the belt's x' = 0 section
(its grazing against ss_continue's GR, computed by the belt's own driver)."""
import math
import unittest

import numpy as np

import stickslip


def den_hartog_x(mu, a, w):
    """Den Hartog (1931): the non-stop amplitude of the undamped coulomb floor."""
    v = a / (1 - w * w)
    u = math.sin(math.pi / w) / (w * (1 + math.cos(math.pi / w)))
    return math.sqrt(v * v - (mu * u) ** 2)


class OrbitBranchTest(unittest.TestCase):
    def test_den_hartog_rows_match_the_closed_form(self):
        fp = stickslip.ForcedParams(
            stickslip.Params("coulomb", mu_s=0.3, mu_k=0.3, beta=0.0, v=0.0),
            force=1.0, omega=0.75)
        b = stickslip.continue_orbits(fp, "omega", [1 / (1 - 0.75 ** 2), 0.01, 0.0], 2.5,
                                      max_amplitude=10)
        self.assertEqual(b.status, stickslip.BranchStatus.unbounded, b.message)
        self.assertEqual(b.state.shape, (len(b.p), 3))
        self.assertEqual(b.multipliers.shape, (len(b.p), 2))
        rows = np.flatnonzero(b.sticks == 0)
        self.assertGreater(len(rows), 10)
        for i in rows:
            x = den_hartog_x(0.3, 1.0, b.p[i])
            self.assertAlmostEqual(b.hi[i, 0], x, delta=1e-9 * max(1.0, x))
        for a in (b.p, b.state, b.hi, b.multipliers, b.stable, b.label):
            self.assertFalse(a.flags.writeable)

    def test_belt_grazing_is_the_switching_sequences_change(self):
        b = stickslip.continue_orbits(stickslip.Params(v=0.42), "v", [0.55, 0.0], 0.38,
                                      section="xdot-falling")
        self.assertEqual(b.status, stickslip.BranchStatus.reached_end, b.message)
        self.assertEqual(len(b.special), 1)
        label, p, description = b.special[0]
        self.assertEqual(label, "GR")
        self.assertIn("grazing-sliding", description)
        self.assertIn("sticks 0 -> 1", description)
        r = stickslip.continue_branch(stickslip.Params(v=0.38), "v", 0.38, 0.42)
        gr = [s.p for s in r.special if s.kind == stickslip.SpecialKind.grazing]
        self.assertEqual(len(gr), 1)
        self.assertAlmostEqual(p, gr[0], delta=1e-9)

    def test_bad_input_names_the_argument(self):
        bp = stickslip.Params(v=0.42)
        for kwargs, word in (({"parameter": "nope"}, "parameter"),
                             ({"section": "stroboscopic"}, "section"),
                             ({"section": "sideways"}, "section"),
                             ({"state": [0.5]}, "state"),
                             ({"to": float("nan")}, "to"),
                             ({"max_step": -1.0}, "max_step")):
            args = {"parameter": "v", "state": [0.5, 0.0], "to": 0.38, "section": "xdot-falling"}
            args.update(kwargs)
            with self.assertRaises(ValueError) as e:
                stickslip.continue_orbits(bp, **args)
            self.assertIn(word, str(e.exception))
        with self.assertRaises(TypeError):
            stickslip.continue_orbits("belt", "v", [0.5, 0.0], 0.38)


if __name__ == "__main__":
    unittest.main()
