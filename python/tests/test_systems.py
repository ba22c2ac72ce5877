"""The several-mass systems in Python (issue 32): ChainBlock, ChainParams and
CouplingParams validated at construction, and simulate_system, system_orbit,
steady_sliding and continue_orbits on them.

References: the first stick phase from (0, v) ends at t = (mu_s - 2 beta v) / v
(seed eq. 3.6); two identical blocks have the modes s = 1 and 1 + 2 kc, each
with lambda^2 + (2 beta + mu'(v)) lambda + s = 0 (docs/theory.md, "A chain of
blocks"); one block is the belt, whose stick-slip orbit the belt's own
OrbitFinder computes (a separate code path, periodic_orbit); contact loss where
1 - gamma y = 0.
"""
import cmath
import unittest

import numpy as np

import stickslip


class Validation(unittest.TestCase):
    def check(self, call, *words):
        with self.assertRaises(ValueError) as c:
            call()
        for w in words:
            self.assertIn(w, str(c.exception))

    def test_each_field_is_named_with_its_value(self):
        self.check(lambda: stickslip.ChainParams(0), "blocks = 0")
        self.check(lambda: stickslip.ChainParams(100000), "blocks = 100000")
        self.check(lambda: stickslip.ChainParams(2, kc=-0.5), "kc = -0.5")
        self.check(lambda: stickslip.ChainParams(2, v=float("nan")), "v = nan")
        self.check(lambda: stickslip.ChainBlock(m=-1.0), "m = -1.0")
        self.check(lambda: stickslip.ChainBlock(c=-0.1), "c = -0.1")
        self.check(lambda: stickslip.ChainBlock(k=float("inf")), "k = inf")
        bad = stickslip.Params("coulomb", mu_s=0.6, mu_k=0.3)
        bad.mu_k = 0.7  # set later: Params checks itself at construction
        self.check(lambda: stickslip.ChainBlock(law=bad), "law", "mu_k = 0.7")
        self.check(lambda: stickslip.ChainParams(2, law=bad), "mu_k = 0.7")
        self.check(lambda: stickslip.CouplingParams(v=0.0), "v = 0.0")
        self.check(lambda: stickslip.CouplingParams(beta=-1.0), "beta = -1.0")
        self.check(lambda: stickslip.CouplingParams(gamma=-2.0), "gamma = -2.0")
        self.check(lambda: stickslip.CouplingParams(k12=float("nan")), "k12 = nan")
        self.check(lambda: stickslip.CouplingParams(law=bad), "law", "mu_k = 0.7")

    def test_attributes_set_later_are_checked_by_every_computation(self):
        c = stickslip.ChainParams(2)
        c.kc = -1.0
        self.check(lambda: stickslip.steady_sliding(c), "kc = -1.0")
        m = stickslip.CouplingParams()
        m.v = -0.5
        self.check(lambda: stickslip.simulate_system(m, [0, 0, 0, 0], t_end=1), "v = -0.5")
        self.check(lambda: stickslip.simulate_system(stickslip.ChainParams(2), [0, 0, 0]),
                   "state: 3 values", "4")
        self.check(lambda: stickslip.system_orbit(stickslip.ChainParams(2), [0, 0.25, 0, 0.25],
                                                  section="nowhere"), "section = 'nowhere'")
        with self.assertRaises(TypeError):
            stickslip.ChainParams([1, 2])

    def test_names(self):
        c = stickslip.ChainParams([stickslip.ChainBlock(m=1.0), stickslip.ChainBlock(m=1.5)],
                                  kc=0.2, v=0.3)
        self.assertEqual(c.n, 2)
        self.assertEqual(c.blocks[1].m, 1.5)
        self.assertEqual(c.state_names, ["x1", "x1'", "x2", "x2'"])
        self.assertIn("kc", c.parameters)
        m = stickslip.CouplingParams()
        self.assertEqual(m.state_names, ["x", "x'", "y", "y'"])
        self.assertEqual(m.parameters[-2:], ["mu_s", "mu_k"])


class ChainRuns(unittest.TestCase):
    def test_first_stick_phase_ends_at_the_closed_form(self):
        p = stickslip.Params()
        run = stickslip.simulate_system(stickslip.ChainParams(1, law=p), [0.0, p.v], t_end=2.0,
                                        dt=0.5, rtol=1e-13, atol=1e-13)
        i = next(i for i in range(1, len(run.t)) if run.mode[i] != "stick")
        self.assertEqual(run.mode[0], "stick")
        self.assertAlmostEqual(run.t[i], (p.mu_s - 2 * p.beta * p.v) / p.v, delta=1e-12)
        self.assertEqual(run.z.shape, (len(run.t), 2))
        self.assertEqual(run.names, ["x1", "x1'"])

    def test_two_blocks_steady_sliding_has_both_modes_closed_forms(self):
        p = stickslip.Params(v=0.3)
        kc = 0.2
        s = stickslip.steady_sliding(stickslip.ChainParams(2, law=p, kc=kc))
        self.assertTrue(s.found)
        a = 2 * p.beta - p.k1 + 3 * p.k3 * p.v ** 2  # 2 beta + mu'(v)
        expected = []
        for stiff in (1.0, 1.0 + 2 * kc):
            r = cmath.sqrt(a * a / 4 - stiff)
            expected += [-a / 2 + r, -a / 2 - r]
        for e in expected:
            self.assertLess(min(abs(e - x) for x in s.eigenvalues), 1e-12, (e, s.eigenvalues))
        self.assertAlmostEqual(s.max_real, -a / 2, delta=1e-12)
        self.assertEqual(s.stable, -a / 2 < 0)

    def test_one_block_orbit_and_branch_are_the_belts(self):
        p = stickslip.Params()
        belt = stickslip.periodic_orbit(p)
        exit_state = [p.mu_s - 2 * p.beta * p.v, p.v]
        c = stickslip.ChainParams(1, law=p)
        o = stickslip.system_orbit(c, exit_state, rtol=1e-12, atol=1e-12)
        self.assertAlmostEqual(o.period, belt.period, delta=1e-10)
        self.assertEqual(o.sticks, 1)
        self.assertEqual(o.monodromy.shape, (2, 2))
        b = stickslip.continue_orbits(c, "v", o.start, 0.3, section="stick-exit", max_step=0.2)
        self.assertEqual(b.status, stickslip.BranchStatus.reached_end)
        self.assertGreater(len(b.p), 2)
        for v, period in zip(b.p, b.period):
            ref = stickslip.periodic_orbit(stickslip.Params(v=v)).period
            self.assertAlmostEqual(period, ref, delta=1e-9, msg="v = %r" % v)


    def test_two_synchronized_blocks_run_the_seed_orbit(self):
        # Started together at the stick exit, both blocks leave at once (the
        # stick-exit start lets every contact at its limit go) and run the
        # seed's orbit; the transverse multiplier against Boost.Odeint in long
        # double with its own events (docs/theory.md, "A chain of blocks").
        p = stickslip.Params()
        x0 = p.mu_s - 2 * p.beta * p.v
        c = stickslip.ChainParams(2, law=p, kc=0.2)
        o = stickslip.system_orbit(c, [x0, p.v, x0, p.v], rtol=1e-13, atol=1e-13)
        seed = stickslip.periodic_orbit(p, rtol=1e-13, atol=1e-13)
        self.assertAlmostEqual(o.period, seed.period, delta=1e-12)
        self.assertAlmostEqual(abs(o.multipliers[0]), 1.3874006783677, delta=1e-9)
        self.assertFalse(o.stable)
        b = stickslip.continue_orbits(c, "v", o.start, 0.3, section="stick-exit", m=o.exits)
        self.assertEqual(b.status, stickslip.BranchStatus.reached_end)
        for v, period in zip(b.p, b.period):
            ref = stickslip.periodic_orbit(stickslip.Params(v=v)).period
            self.assertAlmostEqual(period, ref, delta=1e-9, msg="v = %r" % v)


class SteadyBranchAndSettle(unittest.TestCase):
    """steady_branch and settle, as ss_continue --system uses them."""

    def brake(self, mu_k):
        law = stickslip.Params("coulomb", mu_s=0.8, mu_k=mu_k)
        return stickslip.CouplingParams(beta=0.02, k11=1.0, k22=1.5, k12=-0.3, gamma=1.0, v=0.5,
                                        law=law)

    def test_steady_branch_hopf_is_the_flutter_closed_form(self):
        b = stickslip.steady_branch(self.brake(0.3), "mu_k", 0.7, points=21)
        self.assertEqual(b.status, stickslip.BranchStatus.reached_end)
        self.assertEqual([lab for lab, _, _ in b.special], ["HB"])
        self.assertAlmostEqual(b.special[0][1], self.brake(0.3).flutter_mu_k, delta=1e-13)
        self.assertEqual(len(b.p), 22)  # the grid and the located point
        self.assertEqual(list(b.label).count("HB"), 1)
        self.assertTrue(np.all(b.stable == (b.max_real < 0)))
        with self.assertRaises(ValueError):
            stickslip.steady_branch(self.brake(0.3), "gamma2", 0.7)
        # A parameter the system does not read: refused, as ss_continue does (a flat line).
        with self.assertRaisesRegex(ValueError, "'mu_m' does not apply to the coulomb law"):
            stickslip.steady_branch(stickslip.Params("coulomb", mu_s=0.4, mu_k=0.3), "mu_m", 0.5)

    def test_chart_hopf_curve_is_the_flutter_closed_form_and_its_fold_has_a_cusp(self):
        """chart(system, ...) as ss_chart --study brake_chart: every HB point at mu_k*(beta);
        the LP curve's largest multiplier 1; its cusp (CP) where two folds merge."""
        c = stickslip.chart(self.brake(0.52), "mu_k", 0.45, 0.6, "beta", 0.01, 0.03,
                            rtol=1e-12, atol=1e-12)
        self.assertEqual(c.status, "ok")
        kinds = [k.kind for k in c.curves]
        self.assertEqual(kinds, ["HB", "LP"])
        hb, lp = c.curves
        for mu, beta in zip(hb.p1, hb.p2):
            closed = stickslip.CouplingParams(beta=beta, k11=1.0, k22=1.5, k12=-0.3, gamma=1.0,
                                              v=0.5, law=self.brake(0.52).law).flutter_mu_k
            self.assertAlmostEqual(mu, closed, delta=1e-12)
        self.assertTrue(np.all(np.abs(lp.mult_max - 1) < 1e-7))
        self.assertEqual(lp.lo.shape, (len(lp.p1), 4))
        self.assertEqual(lp.ends.split(" / ")[0], "border")
        self.assertTrue(lp.ends.split(" / ")[1].startswith("contact-lost: "), lp.ends)
        self.assertEqual((c.failed_seed_runs, c.cut_curves), (0, 0))
        self.assertEqual([q.label for q in c.codim2], ["CP"])
        self.assertAlmostEqual(c.codim2[0].p2, 0.02442, delta=1e-5)
        with self.assertRaises(ValueError):
            stickslip.chart(self.brake(0.52), "zeta", 0.45, 0.6, "beta", 0.01, 0.03)
        with self.assertRaises(ValueError):  # mu_k reaches mu_s on the border
            stickslip.chart(self.brake(0.52), "mu_k", 0.45, 0.9, "beta", 0.01, 0.03)

    def test_chart_grid_rests_below_the_flutter_threshold(self):
        """chart(system, ..., grid=N): every cell more than a cell left of the closed-form
        flutter threshold mu_k*(beta) comes to rest; right of the fold the contact opens."""
        c = stickslip.chart(self.brake(0.52), "mu_k", 0.45, 0.6, "beta", 0.01, 0.03,
                            seed_lines=0, rtol=1e-12, atol=1e-12, grid=8)
        self.assertEqual(c.status, "ok", c.message)
        g = c.response
        self.assertEqual(g.kind.shape, (8, 8))
        self.assertEqual((len(g.p1), len(g.p2), g.failed), (8, 8, 0))
        self.assertFalse(g.kind.flags.writeable)
        width = 0.15 / 8
        rest = 0
        for j, beta in enumerate(g.p2):
            star = stickslip.CouplingParams(beta=beta, k11=1.0, k22=1.5, k12=-0.3, gamma=1.0,
                                            v=0.5, law=self.brake(0.52).law).flutter_mu_k
            for i, mu in enumerate(g.p1):
                if mu < star - width:
                    self.assertEqual(g.kind[j, i], "rest", (mu, beta))
                    rest += 1
        self.assertGreaterEqual(rest, 16)
        self.assertIn("contact-lost", set(g.kind.ravel()))
        self.assertTrue(np.all(np.isfinite(g.lyapunov)))
        self.assertIsNone(stickslip.chart(self.brake(0.52), "mu_k", 0.45, 0.6, "beta", 0.01,
                                          0.03, seed_lines=0).response)
        with self.assertRaises(ValueError):
            stickslip.chart(self.brake(0.52), "mu_k", 0.45, 0.6, "beta", 0.01, 0.03,
                            seed_lines=0, grid=-1)

    def test_settled_orbit_closes_under_the_flow(self):
        """The brake above mu_k*: the orbit settle refines returns to its start after one
        period of a plain run at a tighter tolerance (no Newton)."""
        s0 = self.brake(0.52)
        z0 = np.array(stickslip.steady_sliding(s0).z) + [0.01, 0, 0, 0]
        s = stickslip.settle(s0, z0)
        self.assertTrue(s.found, s.message)
        self.assertEqual((s.contact, s.returns, s.sticks), (0, 1, 1))
        self.assertAlmostEqual(s.period, 5.701384424741, delta=1e-11)
        run = stickslip.simulate_system(s0, s.start, t_end=s.period, dt=s.period, rtol=1e-13,
                                        atol=1e-13)
        np.testing.assert_allclose(run.z[-1], s.start, atol=1e-9)

    def test_a_chain_settles_on_two_exits_and_its_branch_takes_that_section(self):
        law = stickslip.Params("cubic", beta=0.05, v=0.3, mu_s=0.4, mu_m=0.25, v_m=0.5)
        c = stickslip.ChainParams(2, law=law, kc=0.5)
        s = stickslip.settle(c, np.array(stickslip.steady_sliding(c).z) + [0.01, 0, 0, 0])
        self.assertTrue(s.found, s.message)
        self.assertEqual(s.returns, 2)  # the blocks half a period apart: two exits per period
        b = stickslip.continue_orbits(c, "v", s.start, 0.25, section="stick-exit", m=s.returns,
                                      contact=s.contact, max_step=0.2)
        self.assertEqual(b.status, stickslip.BranchStatus.reached_end)
        self.assertAlmostEqual(b.period[0], s.period, delta=1e-10)
        with self.assertRaises(ValueError):
            stickslip.system_orbit(c, s.start, contact=2)
        self.assertFalse(stickslip.settle(c, [0.3, 0, 0.3, 0], transient=1.0).found)


class Basins(unittest.TestCase):
    """basins(system) on a slice of the state, through the one classifier."""

    def chain(self, v):
        law = stickslip.Params("cubic", beta=0.05, mu_s=0.4, mu_m=0.25, v_m=0.5, v=v)
        return stickslip.ChainParams(2, law=law, kc=0.5)

    def test_chain_rests_on_closed_form_steady_sliding_and_orbits_close_under_the_shooting(self):
        b = stickslip.basins(self.chain(0.3), nx=5, ny=5)
        self.assertEqual(b.slice, ["x1", "x1'"])
        self.assertEqual(b.failed, 0)
        self.assertEqual(len(b.u), 25)
        self.assertFalse(b.u.flags.writeable)
        kinds = sorted(a.kind for a in b.attractors)
        self.assertIn("periodic", kinds)
        for a in b.attractors:
            if a.kind != "periodic":
                continue
            self.assertEqual(a.cycle.shape, (a.m, 4))
            # The attractor's section point is a fixed point of the one shooting on
            # the same surface (x1' = 0 falling) that Newton converges to.
            o = stickslip.system_orbit(self.chain(0.3), list(a.z), section="xdot-falling", m=a.m)
            self.assertLess(np.max(np.abs(o.start - a.z)), 1e-6)
            self.assertTrue(o.stable)
        s = 0.45 / 0.5
        mu = 0.4 - 1.5 * 0.15 * (s - s ** 3 / 3)  # the cubic law at v = 0.45
        rest = stickslip.basins(self.chain(0.45), nx=3, ny=2)
        self.assertEqual([a.kind for a in rest.attractors], ["rest"])
        np.testing.assert_allclose(rest.attractors[0].z, [mu, 0, mu, 0], atol=1e-12)

    def test_orbit_diagram_of_blocks_started_together_is_the_single_belts(self):
        # From rest on the belt both blocks stay in step: each section point is
        # the single belt's stick-slip maximum (its own 2-D orbit finder).
        d = stickslip.orbit_diagram(self.chain(0.3), "v", 0.26, 0.34, n=3, transient=200,
                                    keep=5, down=False)
        self.assertEqual(d["names"], ["x1", "x1'", "x2", "x2'"])
        self.assertEqual(d["z"].shape, (15, 4))
        self.assertEqual(d["failed"], [])
        for v, z in zip(d["value"], d["z"]):
            law = stickslip.Params("cubic", beta=0.05, mu_s=0.4, mu_m=0.25, v_m=0.5, v=v)
            self.assertAlmostEqual(z[0], stickslip.periodic_orbit(law).x_max, delta=1e-9)
            self.assertAlmostEqual(z[2], z[0], delta=1e-9)
        with self.assertRaises(ValueError) as c:
            stickslip.orbit_diagram(self.chain(0.3), "q", 0.2, 0.3)
        self.assertIn("'q'", str(c.exception))

    def test_bad_slices_are_refused_by_name(self):
        with self.assertRaises(ValueError) as c:
            stickslip.basins(self.chain(0.3), slice=("x1", "q"))
        self.assertIn("'q'", str(c.exception))
        with self.assertRaises(ValueError) as c:
            stickslip.basins(self.chain(0.3), slice=("x1'", "x1dot"))
        self.assertIn("differ", str(c.exception))


class ContactLoss(unittest.TestCase):
    def test_a_run_stops_where_the_normal_force_reaches_zero(self):
        m = stickslip.CouplingParams(law=stickslip.Params("coulomb", mu_s=0.8, mu_k=0.6))
        run = stickslip.simulate_system(m, [0.0, 0.0, 0.0, 3.0], t_end=50.0, dt=0.1)
        self.assertEqual(run.status, stickslip.FlowStatus.contact_open)
        self.assertEqual(run.opened, 0)
        self.assertLess(run.t[-1], 50.0)
        self.assertAlmostEqual(1 - m.gamma * run.z[-1][2], 0.0, delta=1e-12)
        self.assertTrue(np.all(1 - m.gamma * run.z[:, 2] >= -1e-12))


if __name__ == "__main__":
    unittest.main()
