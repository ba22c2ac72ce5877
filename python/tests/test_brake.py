"""The mode-coupling study (issue 32; examples/python/brake.py): the issue's set
with mu_s = 0.8 (mu_k < mu_s over 0.3..0.7).

References: the flutter threshold's closed form mu_k* (docs/theory.md, "Mode
coupling"); each periodic row of continue_orbits as a fixed point of the
stick-exit map integrated by brake_reference.py (SciPy's DOP853 with its own
events and stick handling, nothing shared with the library's Taylor flow).
"""
import importlib.util
import os
import sys
import unittest

import numpy as np

import stickslip

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "examples", "python"))
import brake  # noqa: E402

HAVE_SCIPY = importlib.util.find_spec("scipy") is not None


class Flutter(unittest.TestCase):
    def test_steady_sliding_hb_is_the_closed_form(self):
        star = brake.system(0.5).flutter_mu_k
        self.assertAlmostEqual(star, 0.515, delta=1e-12)  # 0.618 / 1.2
        self.assertAlmostEqual(brake.hopf(), star, delta=1e-10)
        below, above = brake.max_real(star - 1e-6), brake.max_real(star + 1e-6)
        self.assertLess(below, 0)
        self.assertGreater(above, 0)


class OrbitDiagram(unittest.TestCase):
    def test_values_past_the_fold_lose_contact_and_are_no_failures(self):
        # Right of the chart's LP curve (beta 0.02: mu_k 0.528) no stick-slip orbit exists
        # and the contact opens (docs/systems.md); left of the flutter threshold 0.515
        # steady sliding is stable.
        s = brake.system(0.58)
        d = stickslip.orbit_diagram(s, "mu_k", 0.57, 0.6, n=3, transient=100, keep=20,
                                    down=False)
        self.assertEqual(d["failed"], [])
        self.assertEqual([round(v, 12) for _, v, _, _ in d["contact_lost"]], [0.57, 0.585, 0.6])
        self.assertTrue(all(st == "contact-open" for _, _, st, _ in d["contact_lost"]))
        d = stickslip.orbit_diagram(s, "mu_k", 0.45, 0.48, n=2, transient=100, keep=20,
                                    down=False)
        self.assertEqual((d["failed"], d["contact_lost"]), ([], []))
        self.assertEqual(len(d["columns"]["value"]), 2)


@unittest.skipUnless(HAVE_SCIPY, "python3-scipy is missing (scripts/setup.sh installs it): the "
                     "independent integrator needs it")
class Orbits(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import brake_reference
        cls.ref = brake_reference
        z, _ = brake.stick_exit_of_simulation(brake.MU0)
        cls.orbit = stickslip.system_orbit(brake.system(brake.MU0), z, rtol=1e-12, atol=1e-12)
        cls.branches = [brake.branch(brake.MU0, to, cls.orbit.start) for to in (0.3, 0.7)]

    def reference(self, mu_k):
        s = brake.system(mu_k)
        return self.ref.Brake(s.beta, s.k11, s.k22, s.k12, s.gamma, s.v, s.law.mu_s, mu_k)

    def test_the_simulated_orbit_is_a_fixed_point_of_the_independent_map(self):
        o = self.orbit
        self.assertGreaterEqual(o.sticks, 1)
        dz, dt, status = self.ref.residual(self.reference(brake.MU0), o.start, o.period,
                                           o.exits)
        self.assertEqual(status, "exit")
        self.assertLess(dz, 1e-10)
        self.assertLess(dt, 1e-10)

    def test_every_row_is_a_fixed_point_of_the_independent_map(self):
        rows = 0
        for b in self.branches:
            self.assertGreater(len(b.p), 3, b.message)
            for i in range(len(b.p)):
                dz, dt, status = self.ref.residual(self.reference(b.p[i]), b.state[i],
                                                   b.period[i], b.exits[i])
                msg = "mu_k = %r: %s" % (b.p[i], status)
                self.assertEqual(status, "exit", msg)
                self.assertLess(dz, 1e-10, msg)  # measured worst 7.6e-12
                self.assertLess(dt, 1e-10, msg)
                self.assertGreater(1 - b.hi[i][2], 0, msg)  # the contact stays closed
                rows += 1
        self.assertGreater(rows, 8)

    def test_the_branch_folds_and_ends_where_the_contact_opens(self):
        down, up = self.branches
        self.assertEqual(down.status, stickslip.BranchStatus.reached_end)
        self.assertTrue(np.all(down.stable))  # stick-slip coexists with stable steady sliding
        self.assertTrue(np.all(down.p < brake.system(0.5).flutter_mu_k + 0.01))
        self.assertEqual([lab for lab, _, _ in up.special], ["LP", "CL"])
        self.assertGreater(up.special[0][1], brake.MU0)
        # The branch ends at the orbit whose normal force 1 - gamma y first
        # touches 0, labelled CL; beyond it the contact opens.
        self.assertEqual(up.status, stickslip.BranchStatus.contact_lost)
        self.assertIn("opens (normal force 0)", up.message)
        self.assertEqual(up.label[-1], "CL")
        self.assertLess(1 - up.hi[-1][2], 1e-9)


if __name__ == "__main__":
    unittest.main()
