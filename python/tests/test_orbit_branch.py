"""continue_orbits: the one branch driver from Python, on the forced oscillator's
stroboscopic section (Den Hartog's closed form) and on the belt's x' = 0 section
(its grazing against ss_continue's GR, computed by the belt's own driver)."""
import math
import os
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
        fp = stickslip.ForcedBeltParams(
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

    def test_special_orbits_carry_their_run_and_system(self):
        # The GR point whole (SpecialOrbit): its row of the branch, its run,
        # and the run's system at its p, of the type it came as.
        b = stickslip.continue_orbits(stickslip.Params(v=0.42), "v", [0.55, 0.0], 0.38,
                                      section="xdot-falling")
        q, = b.special_points
        self.assertEqual((q.label, q.lab, q.parameter, q.section, q.m, q.turns),
                         ("GR", "GR1", "v", "xdot-falling", 1, 0))
        self.assertEqual((q.run_from, q.run_to), (0.42, 0.38))
        self.assertEqual(b.special[0], (q.label, q.p, q.description))
        row = int(np.flatnonzero(b.label == "GR")[0])
        np.testing.assert_array_equal(q.state, b.state[row])
        np.testing.assert_array_equal(q.hi, b.hi[row])
        self.assertEqual(type(q.system), stickslip.Params)
        self.assertEqual(q.system.v, q.p)
        with self.assertRaisesRegex(ValueError, r"label GR \(GR1\) is not a period doubling"):
            stickslip.continue_doubled(q)
        models = os.path.join(os.path.dirname(__file__), "..", "..", "studies", "models")
        start = [0.4 - 2 * 0.05 * 0.25, 0.25]  # the seed's stick exit
        for system in (stickslip.System.from_file(os.path.join(models, "belt.ini")),
                       stickslip.ChainParams(blocks=1, law=stickslip.Params(), kc=0.0)):
            b = stickslip.continue_orbits(system, "v", start, 0.5, section="stick-exit")
            q, = b.special_points
            self.assertEqual((q.lab, q.section, q.contact, q.m), ("GR1", "stick-exit", 0, 1))
            self.assertEqual(type(q.system), type(system))
            self.assertEqual(q.system["v"] if type(system) is stickslip.System else q.system.v,
                             q.p)

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
