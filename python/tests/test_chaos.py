"""The forced oscillator's chaos tools and branch switching in the module
(issues 20 and 21): each result is checked against a path computed otherwise in
the same test -- the doubled branch against the plain stroboscopic map it must
attract, the Lyapunov exponent against ln|mu| / T from the orbit's own Floquet
multipliers, the orbit diagram's and basins' attractors against Newton's orbit."""
import math
import unittest

import numpy as np

import stickslip


def stribeck(omega):
    """The forced Stribeck scene of studies/stribeck_forced.ini."""
    p = stickslip.Params("stribeck", mu_s=0.4, mu_k=0.25, v_s=0.2, beta=0.05, v=0.25)
    return stickslip.ForcedBeltParams(p, force=0.3, omega=omega)


def settled_orbit(omega, m=1):
    """The attracting m-orbit at omega: from the map's iterate, closed by Newton."""
    s = stickslip.stroboscopic(stribeck(omega), 0.0, 0.25, transient=300, keep=1)
    return stickslip.periodic_orbit(stribeck(omega), [s["x"][0], s["xdot"][0], 0.0], m=m)


class Switch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        o = settled_orbit(0.7)
        cls.branch = stickslip.continue_branch(stribeck(0.7), "omega", o.start, 0.6,
                                               max_step=0.04, rtol=1e-13, atol=1e-13)

    def test_doubled_branch_is_the_attractor_of_the_map(self):
        pds = [q for q in self.branch.special_points if q.label == "PD"]
        self.assertTrue(pds, [q.label for q in self.branch.special_points])
        pd = pds[0]
        self.assertEqual((pd.m, pd.run_from, pd.run_to), (1, 0.7, 0.6))
        self.assertEqual((pd.section, pd.lab, pd.parameter), ("stroboscopic", "PD1", "omega"))
        self.assertAlmostEqual(pd.system.omega, pd.p, delta=0)
        self.assertAlmostEqual(pd.multipliers[0].real, -1, delta=1e-6)
        d = stickslip.continue_doubled(pd, lo=pd.p - 0.006, hi=pd.p + 0.006, max_step=0.33,
                                       rtol=1e-13, atol=1e-13)
        self.assertEqual(d.status, stickslip.BranchStatus.reached_end, d.message)
        self.assertTrue(all(q.m == 2 for q in d.special_points))
        self.assertTrue(np.allclose(d.period, 2 * 2 * math.pi / d.p, rtol=1e-12))  # m = 2
        self.assertLess(d.p[0], pd.p)  # supercritical: it opens toward lower Omega
        # A stable row away from the PD: 300 periods of the plain map from a
        # point off the orbit end on the row's 2-cycle.
        k = int(np.argmax(np.abs(d.p - pd.p) * d.stable))
        self.assertTrue(d.stable[k])
        x0, xdot0 = d.state[k, 0], d.state[k, 1]
        s = stickslip.stroboscopic(stribeck(d.p[k]), x0 + 1e-3, xdot0, transient=300, keep=2)
        gap = min(math.hypot(x - x0, xd - xdot0) for x, xd in zip(s["x"], s["xdot"]))
        self.assertLess(gap, 1e-8)
        self.assertGreater(abs(s["x"][0] - s["x"][1]), 1e-4)  # two points: a 2-cycle

    def test_only_a_period_doubling_switches(self):
        others = [q for q in self.branch.special_points if q.label != "PD"]
        pd = [q for q in self.branch.special_points if q.label == "PD"][0]
        self.assertTrue(others)  # a CR and two LP before the PD
        for q in others:
            with self.assertRaisesRegex(stickslip.InvalidArgument, r"label %s \(%s\) is not a "
                                        r"period doubling" % (q.label, q.lab)):
                stickslip.continue_doubled(q)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "must bracket"):
            stickslip.continue_doubled(pd, lo=pd.p + 0.001, hi=pd.p + 0.01)


class Chaos(unittest.TestCase):
    def test_exponent_on_a_periodic_orbit_is_floquets(self):
        o = settled_orbit(0.7)
        mu = max(abs(z) for z in o.multipliers)
        s = stickslip.stroboscopic(stribeck(0.7), o.start[0], o.start[1], transient=100, keep=200)
        self.assertAlmostEqual(s["lyapunov"], math.log(mu) / o.period, delta=1e-3)
        self.assertTrue(np.all(s["sticks"] == o.sticks))
        np.testing.assert_allclose(s["x"], o.start[0], atol=1e-9)

    def test_orbit_diagram_settles_on_newtons_orbit(self):
        d = stickslip.orbit_diagram(stribeck(0.7), stickslip.Parameter.omega, 0.69, 0.71, n=3,
                                    transient=300, keep=8)
        self.assertEqual(d["failed"], [])
        self.assertEqual(len(d["columns"]["value"]), 6)  # 3 up, 3 down
        self.assertEqual(len(d["x"]), 6 * 8)
        np.testing.assert_allclose(sorted(set(d["value"])), [0.69, 0.7, 0.71], rtol=1e-15)
        at = np.isclose(d["value"], 0.7, rtol=0, atol=1e-15)
        o = settled_orbit(0.7)
        np.testing.assert_allclose(d["x"][at], o.start[0], atol=1e-9)
        np.testing.assert_allclose(d["xdot"][at], o.start[1], atol=1e-9)
        self.assertTrue(np.all(d["columns"]["lyapunov"] < 0))

    def test_basin_attractors_are_newtons_orbits(self):
        b = stickslip.basins(stribeck(0.7), nx=3, ny=3, transient=300, keep=16)
        self.assertEqual(len(b.attractor), 9)
        self.assertEqual(b.failed, 0)
        periodic = [a for a in b.attractors if a.kind == "periodic"]
        self.assertTrue(periodic)
        self.assertEqual(sum(a.starts for a in b.attractors), 9)
        for a in periodic:
            o = stickslip.periodic_orbit(stribeck(0.7), [a.z[0], a.z[1], 0.0], m=a.m)
            self.assertLess(math.hypot(o.start[0] - a.z[0], o.start[1] - a.z[1]), 1e-8)
            self.assertEqual(o.sticks, a.sticks)
            # its cycle: m section points, the first the attractor's own
            self.assertEqual(a.cycle.shape[0], a.m)
            np.testing.assert_array_equal(a.cycle[0], a.z)

    def test_bad_input_names_the_option(self):
        with self.assertRaisesRegex(stickslip.InvalidArgument, "keep"):
            stickslip.stroboscopic(stribeck(0.7), keep=0)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "n"):
            stickslip.orbit_diagram(stribeck(0.7), stickslip.Parameter.omega, 0.6, 0.7, n=0)


class Bounds(unittest.TestCase):
    """Issue 35: every argument is bounded as the apps bound it, and a bad one is
    InvalidArgument (a ValueError) naming it, never a made-up result."""

    def test_periods_past_the_apps_bound_are_refused_not_overflowed(self):
        big = 2**31 - 1  # transient + keep overflowed: 0 points and a nan exponent
        with self.assertRaisesRegex(stickslip.InvalidArgument, r"transient = 2147483647 must lie "
                                    r"in \[0, 1000000\]"):
            stickslip.stroboscopic(stribeck(0.7), transient=big, keep=10)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "transient"):
            stickslip.orbit_diagram(stribeck(0.7), stickslip.Parameter.omega, 0.6, 0.7, n=2,
                                    transient=big)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "transient"):
            stickslip.basins(stribeck(0.7), nx=1, ny=1, transient=big)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "keep"):
            stickslip.stroboscopic(stribeck(0.7), keep=10**6 + 1)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "section points"):
            stickslip.orbit_diagram(stribeck(0.7), stickslip.Parameter.omega, 0.6, 0.7,
                                    n=100000, keep=1000)

    def test_a_short_transient_aligns_over_all_of_it(self):
        # align (50) was not exposed and had to be <= transient; now min(50, transient),
        # as the apps. Newton's orbit is the reference, as above.
        o = settled_orbit(0.7)
        s = stickslip.stroboscopic(stribeck(0.7), o.start[0], o.start[1], transient=10, keep=20)
        np.testing.assert_allclose(s["x"], o.start[0], atol=1e-9)
        s0 = stickslip.stroboscopic(stribeck(0.7), o.start[0], o.start[1], transient=0, keep=20)
        np.testing.assert_allclose(s0["x"], o.start[0], atol=1e-9)

    def test_a_box_must_be_finite_and_bounded(self):
        for box in ((-math.inf, math.inf), (-1e308, 1e308), (0, math.nan)):
            with self.assertRaisesRegex(stickslip.InvalidArgument, "box"):
                stickslip.basins(stribeck(0.7), nx=2, ny=2, x_range=box)
        with self.assertRaisesRegex(stickslip.InvalidArgument, r"base\[2\] = nan must be finite"):
            stickslip.basins(stribeck(0.7), nx=2, ny=2, base=[0.0, 0.0, math.nan])
        with self.assertRaisesRegex(stickslip.InvalidArgument, "base: 2 values, the system has 3"):
            stickslip.basins(stribeck(0.7), nx=2, ny=2, base=[0.0, 0.0])

    def test_threads_are_capped_by_the_hardware(self):
        # threads=5000 started 5000 threads (under a memory limit: abort); now a pool
        # of at most os.cpu_count() threads classifies the same starts.
        a = stickslip.basins(stribeck(0.7), nx=2, ny=2, transient=50, keep=16, threads=5000)
        b = stickslip.basins(stribeck(0.7), nx=2, ny=2, transient=50, keep=16, threads=1)
        np.testing.assert_array_equal(a.attractor, b.attractor)
        np.testing.assert_array_equal(a.lyapunov, b.lyapunov)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "threads"):
            stickslip.basins(stribeck(0.7), nx=2, ny=2, threads=-1)

    def test_non_finite_starts_and_options_name_the_argument(self):
        with self.assertRaisesRegex(stickslip.InvalidArgument, "x0 = nan"):
            stickslip.stroboscopic(stribeck(0.7), math.nan)
        with self.assertRaisesRegex(stickslip.InvalidArgument, "xdot0 = inf"):
            stickslip.stroboscopic(stribeck(0.7), 0.0, math.inf)
        cases = (({"m": 0}, r"m = 0 must lie in \[1, 1000\]"),
                 ({"max_amplitude": 0}, "max_amplitude = 0"),
                 ({"max_amplitude": math.nan}, "max_amplitude = nan"),
                 ({"state": [math.nan, 0.25, 0.0]}, r"state = \(nan, 0.25, 0.0\)"))
        for kw, message in cases:
            kw = {"state": [0.0, 0.25, 0.0], **kw}
            with self.assertRaisesRegex(stickslip.InvalidArgument, message):
                stickslip.continue_branch(stribeck(0.7), "omega", to=0.6, **kw)


if __name__ == "__main__":
    unittest.main()
