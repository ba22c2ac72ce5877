"""The bound types of the module: read-only arrays (issue 23, N17), the branch's
direction (issue 23: continue_branch with from and to swapped), the integrator
choice, the row cap of simulate (N7), basins, and the type stub.

References: HB = sqrt((k1 - 2 beta) / (3 k3)) (seed eq. 3.16); GR and HB from
the C++ app ss_continue (STICKSLIP_SS_CONTINUE, run here); the first stick
phase from (0, v) ends at t = (mu_s - 2 beta v) / v (seed eq. 3.6); basins
against a point-in-polygon test on the unstable orbit's curve (design notes
section 4: that orbit bounds the basin of steady sliding).
"""
import ast
import math
import os
import pathlib
import subprocess
import tempfile
import time
import unittest

import numpy as np

import stickslip
from wall_bound import WallBound

STUB = pathlib.Path(stickslip.__file__).with_name("__init__.pyi")


def hopf(p):
    return math.sqrt((p.k1 - 2 * p.beta) / (3 * p.k3))


def app_special_points(args):
    """Special points of ss_continue as {label: p}, read from special_points.tsv."""
    exe = os.environ.get("STICKSLIP_SS_CONTINUE")
    if not exe:
        raise unittest.SkipTest("STICKSLIP_SS_CONTINUE not set (run through ctest)")
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([exe, *args, "--no_plots", "--no_estimates", "--out", out], check=True,
                       stdout=subprocess.DEVNULL)
        with open(os.path.join(out, "special_points.tsv")) as f:
            rows = [line.rstrip("\n").split("\t") for line in f
                    if line.strip() and not line.startswith("#")]
    head = rows[0]
    # "GR" or, with point labels, "GR1": the kind is the letters.
    return {r[head.index("label")].rstrip("0123456789"): float(r[head.index("v")])
            for r in rows[1:]}


class ReadOnlyArrays(unittest.TestCase):
    def assert_read_only(self, arr, name):
        self.assertIsInstance(arr, np.ndarray, name)
        self.assertFalse(arr.flags.writeable, name)
        with self.assertRaises(ValueError, msg=name):
            arr[0] = arr[0]

    def test_every_result_array_is_read_only(self):
        p = stickslip.Params()
        branch = stickslip.continue_branch(p, "v", from_=0.3, to=0.5)
        for name, arr in branch.points.items():
            self.assert_read_only(arr, "points." + name)
        run = stickslip.simulate(p, t_end=2.0)
        for name in ("t", "x", "xdot", "mode"):
            self.assert_read_only(getattr(run, name), "simulate." + name)
        curve = stickslip.chart(p).curves[0]
        for name in ("p1", "p2", "period", "amplitude", "multiplier", "l1", "type"):
            self.assert_read_only(getattr(curve, name), "chart." + name)
        basins = stickslip.basins(p, nx=3, ny=3)
        for name in ("x", "xdot", "fate", "orbit", "t_settle"):
            self.assert_read_only(getattr(basins, name), "basins." + name)
        self.assert_read_only(stickslip.periodic_orbit(p).start, "orbit.start")


def _arrays(obj, path, seen, depth=0):
    """Every numpy array reachable from obj (attributes, dict values, items), with its path."""
    if isinstance(obj, np.ndarray):
        yield path, obj
        if obj.dtype == object:
            for i, item in enumerate(obj.flat[:3]):
                yield from _arrays(item, "%s[%d]" % (path, i), seen, depth + 1)
        return
    if depth > 5 or id(obj) in seen or isinstance(obj, (str, bytes, int, float, complex, bool)):
        return
    if obj is None or callable(obj) or type(obj).__module__ in ("builtins", "enum"):
        if not isinstance(obj, (dict, list, tuple)):
            return
    seen.add(id(obj))
    if isinstance(obj, dict):
        for k, v in obj.items():
            yield from _arrays(v, "%s[%r]" % (path, k), seen, depth + 1)
    elif isinstance(obj, (list, tuple)):
        for i, v in enumerate(obj[:3]):
            yield from _arrays(v, "%s[%d]" % (path, i), seen, depth + 1)
    else:
        for name in dir(obj):
            if name.startswith("_") or name in ("params",):
                continue
            try:
                v = getattr(obj, name)
            except Exception:  # a property that needs arguments
                continue
            if not callable(v) or isinstance(v, np.ndarray):
                yield from _arrays(v, "%s.%s" % (path, name), seen, depth + 1)


class EveryResultArrayReadOnly(unittest.TestCase):
    """Issue 35 (planted bugs): every array any function returns, at any depth, is
    read-only; a function added to the module without a call here fails."""

    # Functions that return no result arrays of a computation (names, scales, a
    # restart point's parameters) or whose results have their own test (sweep:
    # test_sweep.py, read_sweep too; stick_slip_orbit(s), forced_orbits are sweep's fns; group_stats reads a SweepResult).
    NO_ARRAYS = {"default_range", "parameter_names", "scales", "restart", "sweep",
                 "stick_slip_orbit", "stick_slip_orbits", "forced_orbits", "group_stats",
                 "read_sweep"}

    def calls(self):
        p = stickslip.Params()
        orbit = stickslip.periodic_orbit(p)
        slip = stickslip.Params()
        slip.v = 0.42  # a stable pure-slip orbit inside the stick-slip one
        sp = stickslip.Params("stribeck", mu_s=0.4, mu_k=0.25, v_s=0.2, beta=0.05, v=0.25)
        fp = stickslip.ForcedBeltParams(sp, force=0.3, omega=0.617)
        w = "omega"
        s = stickslip.stroboscopic(fp, 0.0, 0.25, transient=100, keep=2)
        fo = stickslip.periodic_orbit(fp, [s["x"][0], s["xdot"][0], 0.0])
        branch = stickslip.continue_branch(stickslip.ForcedBeltParams(sp, force=0.3, omega=0.62), w,
                                           fo.start, 0.617, max_step=0.02)
        pd = [q for q in branch.special_points if q.label == "PD"][0]
        return {
            "basins": lambda: (stickslip.basins(p, nx=3, ny=3), stickslip.basins(fp, nx=2, ny=2)),
            "chart": lambda: (stickslip.chart(p), stickslip.chart(
                stickslip.CouplingParams(law=stickslip.Params("coulomb", mu_s=0.8, mu_k=0.52)),
                "mu_k", 0.5, 0.55, "beta", 0.015, 0.025, seed_lines=1)),
            "continue_branch": lambda: (stickslip.continue_branch(p, "v", from_=0.3, to=0.5),
                                        branch),
            "continue_doubled": lambda: stickslip.continue_doubled(pd, lo=pd.p - 0.003,
                                                                   hi=pd.p + 0.003),
            "continue_orbits": lambda: stickslip.continue_orbits(
                fp, "omega", fo.start, 0.615, max_step=0.5),
            "continue_physical": lambda: stickslip.continue_physical(
                mass=2.0, stiffness=800.0, damping=4.0, belt_speed=0.1, mu_s=0.4, mu_m=0.25,
                speed_m=0.2, from_=0.1, to=0.12),
            "attractor_basins": lambda: stickslip.attractor_basins(
                stickslip.ChainParams(2, kc=0.2), nx=2, ny=2, transient=20, keep=8),
            "orbits": lambda: (stickslip.orbits(p, {"v": [0.25, 0.47]}, floquet=True),
                               stickslip.orbits(fp, {"omega": [0.6, 0.52]})),
            "orbit_curve": lambda: stickslip.orbit_curve(p, orbit, n=20),
            "orbit_diagram": lambda: stickslip.orbit_diagram(fp, w, 0.61, 0.62, n=3,
                                                             transient=50, keep=4),
            "periodic_orbit": lambda: (orbit, fo),
            "periodic_orbits": lambda: (stickslip.periodic_orbits(p),
                                        stickslip.periodic_orbits(fp, max_m=2, grid=3)),
            "simulate": lambda: (stickslip.simulate(p, t_end=2.0),
                                 stickslip.simulate(fp, [0.0, 0.25, 0.0], t_end=20.0,
                                                    section=stickslip.SimulationSection.strobe)),
            "simulate_system": lambda: stickslip.simulate_system(
                stickslip.ChainParams(2, kc=0.2), [0.0, 0.25, 0.1, 0.25], t_end=2.0),
            "steady_sliding": lambda: stickslip.steady_sliding(stickslip.CouplingParams()),
            "steady_branch": lambda: stickslip.steady_branch(stickslip.ChainParams(2), "v", 0.5,
                                                             points=5),
            "settle": lambda: (stickslip.settle(stickslip.ChainParams(1), [0.3, 0.0],
                                                transient=300.0),
                               stickslip.settle(stickslip.ChainParams(1), [0.3, 0.0],
                                                transient=1.0)),  # not found: arrays too
            "system_orbit": lambda: stickslip.system_orbit(stickslip.ChainParams(1), [0.375, 0.25]),
            "smallest_disturbance": lambda: stickslip.smallest_disturbance(
                slip, stickslip.periodic_orbits(slip).pure_slip[0], n=200),
            "stroboscopic": lambda: s,
        }

    def test_every_function_every_array(self):
        calls = self.calls()
        public = {n for n in dir(stickslip) if not n.startswith("_")
                  and callable(getattr(stickslip, n)) and not isinstance(getattr(stickslip, n), type)}
        self.assertEqual(public - self.NO_ARRAYS - set(calls), set(), "functions without a call")
        found = 0
        for name, call in sorted(calls.items()):
            for path, arr in _arrays(call(), name, set()):
                found += 1
                self.assertFalse(arr.flags.writeable, path)
                if arr.size:
                    with self.assertRaises(ValueError, msg=path):
                        arr.flat[0] = arr.flat[0]
        self.assertGreater(found, 40)


class BranchDirection(unittest.TestCase):
    def test_rows_run_from_from_to_to_with_the_apps_special_points(self):
        p = stickslip.Params()
        branch = stickslip.continue_branch(p, "v", from_=0.05, to=0.5)
        pts = branch.points.p
        self.assertEqual(pts[0], 0.05)
        self.assertEqual(pts[-1], 0.5)
        labels = [s.label for s in branch.special]
        self.assertEqual(labels, ["GR", "HB"])  # in the order the branch meets them
        app = app_special_points(["--from", "0.05", "--to", "0.5"])
        self.assertAlmostEqual(branch.special[0].p, app["GR"], delta=1e-12)
        self.assertAlmostEqual(branch.special[1].p, app["HB"], delta=1e-12)
        self.assertAlmostEqual(branch.special[1].p, hopf(p), delta=1e-10)
        self.assertAlmostEqual(branch.special[1].p, 0.4409585518, delta=1e-10)
        self.assertEqual(len(pts), len(branch.points.kind))

    def test_options_object_gives_the_keyword_result(self):
        o = stickslip.ContinuationOptions()
        o.param, o.from_, o.to = "v", 0.3, 0.5
        a = stickslip.continue_branch(stickslip.Params(), options=o)
        b = stickslip.continue_branch(stickslip.Params(), "v", from_=0.3, to=0.5)
        self.assertTrue(np.array_equal(a.points.p, b.points.p))
        self.assertEqual(a["special"][1]["label"], "HB")  # the dict-style access of 0.x


class Integrators(unittest.TestCase):
    def test_each_integrator_ends_the_first_stick_phase_at_the_closed_form(self):
        p = stickslip.Params()
        expected = (p.mu_s - 2 * p.beta * p.v) / p.v
        for kw in ({}, {"integrator": "taylor"}, {"integrator": "cvode"},
                   {"method": "bdf"}, {"integrator": stickslip.Integrator.cvode,
                                       "method": stickslip.Method.adams}):
            run = stickslip.simulate(p, xdot0=p.v, t_end=3.0, **kw)
            first_slip = run.t[np.argmax(run.mode != "stick")]
            self.assertAlmostEqual(first_slip, expected, delta=1e-9, msg=str(kw))

    def test_stick_slip_period_agrees_across_integrators(self):
        p = stickslip.Params()
        taylor = stickslip.periodic_orbit(p).period
        bdf = stickslip.periodic_orbit(p, integrator="cvode", method="bdf", rtol=1e-12,
                                       atol=1e-14).period
        self.assertAlmostEqual(taylor, bdf, delta=1e-8)

    def test_bad_integrator_choices_name_the_argument(self):
        p = stickslip.Params()
        with self.assertRaisesRegex(ValueError, "integrator = 'rk4'"):
            stickslip.simulate(p, integrator="rk4")
        with self.assertRaisesRegex(ValueError, "method = 'bdf' applies to integrator"):
            stickslip.periodic_orbit(p, integrator="taylor", method="bdf")


class RowCap(unittest.TestCase):
    def test_too_many_rows_raise_up_front_naming_max_rows(self):
        p = stickslip.Params()
        bound = WallBound()
        start = time.monotonic()
        with self.assertRaisesRegex(ValueError, r"max_rows = 1000000 \(raise max_rows or dt\)"):
            stickslip.simulate(p, t_end=1e9, dt=1e-3)
        self.assertLess(time.monotonic() - start, bound.of(1.0))
        with self.assertRaisesRegex(ValueError, "max_rows = 100"):
            stickslip.simulate(p, t_end=100.0, dt=0.01, max_rows=100)
        run = stickslip.simulate(p, t_end=1.0, dt=0.01, max_rows=200)
        self.assertEqual(run.t[-1], 1.0)

    def test_switch_rows_count_against_the_cap(self):
        # 101 grid rows fit; the switches (about 2 per period 6.6) take it past 102.
        with self.assertRaisesRegex(ValueError, "switches took the rows past max_rows = 102"):
            stickslip.simulate(stickslip.Params(), t_end=100.0, dt=1.0, max_rows=102)


def inside(polygon, x, y):
    """Ray casting: is (x, y) inside the closed polygon (rows of x, y)?"""
    xs, ys = polygon[:, 0], polygon[:, 1]
    x2, y2 = np.roll(xs, -1), np.roll(ys, -1)
    crosses = ((ys > y) != (y2 > y)) & (x < xs + (y - ys) * (x2 - xs) / (y2 - ys + 1e-300))
    return bool(np.count_nonzero(crosses) % 2)


class Basins(unittest.TestCase):
    def test_unstable_orbit_bounds_the_basin_of_steady_sliding(self):
        # Stribeck law, bistable (subcritical Hopf): steady sliding and stick-slip.
        p = stickslip.Params(law="stribeck", mu_s=0.4, mu_k=0.25, v_s=0.1, v=0.35)
        b = stickslip.basins(p, nx=21, ny=21)
        self.assertEqual(b.status, stickslip.BasinStatus.ok)
        (unstable,) = b.orbits.pure_slip
        self.assertFalse(unstable.stable)
        curve = stickslip.orbit_curve(p, unstable, n=2000)
        h = max((b.x_hi - b.x_lo) / (b.nx - 1), (b.xdot_hi - b.xdot_lo) / (b.ny - 1))
        checked = 0
        for x, xdot, fate in zip(b.x, b.xdot, b.fate):
            if np.min(np.hypot(curve[:, 0] - x, curve[:, 1] - xdot)) < h:
                continue  # a cell the boundary crosses
            want = "steady-sliding" if inside(curve, x, xdot) else "stick-slip"
            self.assertEqual(fate, want, (x, xdot))
            checked += 1
        self.assertGreater(checked, 300)
        counts = b.counts
        self.assertGreater(counts[stickslip.Fate.steady_sliding], 10)
        self.assertEqual(sum(counts.values()), 21 * 21)


class Stub(unittest.TestCase):
    def test_stub_names_match_the_module(self):
        tree = ast.parse(STUB.read_text())
        stub = {}
        for node in tree.body:
            if isinstance(node, ast.ClassDef):
                stub[node.name] = {n.name if isinstance(n, (ast.FunctionDef, ast.ClassDef))
                                   else (n.target.id if isinstance(n, ast.AnnAssign)
                                         else n.targets[0].id)
                                   for n in node.body
                                   if isinstance(n, (ast.FunctionDef, ast.AnnAssign, ast.Assign))}
            elif isinstance(node, ast.FunctionDef):
                stub[node.name] = None
            elif isinstance(node, ast.AnnAssign):
                stub[node.target.id] = None
        public = {n for n in dir(stickslip) if not n.startswith("_")} | {"__version__"}
        self.assertEqual(set(stub), public)
        for name, members in stub.items():
            obj = getattr(stickslip, name)
            if members is None or issubclass(obj, Exception):
                continue
            actual = {n for n in vars(obj) if not n.startswith("_")}
            if hasattr(obj, "__members__"):  # an enum: its values and the enum machinery
                actual = set(obj.__members__)
            members = {m for m in members if not m.startswith("_")}
            self.assertEqual(members, actual, name)


if __name__ == "__main__":
    unittest.main()
