"""Results that show themselves (repr, _repr_html_, to_pandas, to_tsv), pt and
lab, restarts from a Python branch, Matplotlib figures, Params validation,
TypeErrors and the progress callback.

References: ss_continue's own files for the same branch (STICKSLIP_SS_CONTINUE,
run here): its special points' labels, rows and values, and its branch.tsv
columns; the Hopf point in beta from 2 beta + mu'(v) = 0, mu'(v) = -k1 +
3 k3 v^2 (seed eq. 3.16). The style split is checked against hand-made rows
whose change of stability is known.
"""
import math
import os
import subprocess
import tempfile
import unittest

import numpy as np

import stickslip
from stickslip import plot


def read_tsv(path):
    meta, rows, head = {}, [], None
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("# ") and ": " in line:
                k, v = line[2:].split(": ", 1)
                meta.setdefault(k, v)
            elif line and not line.startswith("#"):
                cells = line.split("\t")
                if head is None:
                    head = cells
                else:
                    rows.append(dict(zip(head, cells)))
    return meta, head, rows


class Seed:
    """The seed branch in v on [0.2, 0.5], once."""
    branch = None

    @classmethod
    def get(cls):
        if cls.branch is None:
            cls.branch = stickslip.continue_branch(stickslip.Params(), "v", from_=0.2, to=0.5)
        return cls.branch


class ShowThemselves(unittest.TestCase):
    def test_branch_repr_and_html_name_status_counts_and_labels(self):
        b = Seed.get()
        text = repr(b)
        self.assertNotIn("object at 0x", text)
        self.assertIn("ok", text)
        self.assertIn("%d points" % len(b.points), text)
        labs = [s.lab for s in b.special]
        self.assertIn("GR1", labs)
        self.assertIn("HB1", labs)
        for lab in labs:
            self.assertIn(lab, text)
            self.assertIn(lab, b._repr_html_())
        self.assertIn("<table>", b._repr_html_())

    def test_every_result_type_has_a_repr_and_html(self):
        p = stickslip.Params()
        results = [Seed.get(), stickslip.simulate(p, t_end=2.0),
                   stickslip.periodic_orbits(p), stickslip.periodic_orbit(p),
                   stickslip.basins(p, nx=4, ny=3)]
        for r in results:
            self.assertNotIn("object at 0x", repr(r), type(r).__name__)
            self.assertIn("status" if hasattr(r, "status") else "period", repr(r))
            self.assertTrue(r._repr_html_().startswith("<div>"), type(r).__name__)

    def test_pt_and_lab_match_ss_continue(self):
        exe = os.environ.get("STICKSLIP_SS_CONTINUE")
        if not exe:
            self.skipTest("STICKSLIP_SS_CONTINUE not set (run through ctest)")
        b = Seed.get()
        np.testing.assert_array_equal(b.points.pt, np.arange(1, len(b.points) + 1))
        with tempfile.TemporaryDirectory() as out:
            subprocess.run([exe, "--param", "v", "--from", "0.2", "--to", "0.5", "--no_plots",
                            "--no_estimates", "--out", out], check=True,
                           stdout=subprocess.DEVNULL)
            _, _, app = read_tsv(os.path.join(out, "special_points.tsv"))
        self.assertEqual([(r["lab"], int(r["pt"])) for r in app],
                         [(s.lab, s.pt) for s in b.special])
        for r, s in zip(app, b.special):
            self.assertEqual(float(r["v"]), s.p)

    def test_to_pandas_has_every_column_and_pt(self):
        b = Seed.get()
        df = b.to_pandas()
        self.assertEqual(len(df), len(b.points))
        self.assertIn("v", df.columns)
        np.testing.assert_array_equal(df["x_max"].to_numpy(), b.points.x_max)
        self.assertEqual(list(df["pt"][:3]), [1, 2, 3])
        sp = b.special_to_pandas()
        self.assertEqual(list(sp["lab"]), [s.lab for s in b.special])
        traj = stickslip.simulate(stickslip.Params(), t_end=2.0).to_pandas()
        self.assertEqual(list(traj.columns), ["t", "x", "xdot", "mode"])

    def test_to_tsv_writes_the_apps_columns_and_metadata(self):
        b = Seed.get()
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "branch.tsv")
            b.to_tsv(path)
            meta, head, rows = read_tsv(path)
        for key in ("tool", "law", "beta", "integrator", "rtol", "continued", "from", "to",
                    "status", "model"):
            self.assertIn(key, meta)
        self.assertEqual(meta["v"], "continued")
        self.assertEqual(meta["continued"], "v")
        self.assertEqual(head[:3], ["v", "kind", "branch"])
        self.assertIn("pt", head)
        self.assertEqual(len(rows), len(b.points))
        self.assertEqual(float(rows[5]["x_max"]), b.points.x_max[5])  # every digit

    def test_other_results_write_tsv_with_metadata(self):
        t = stickslip.simulate(stickslip.Params(), t_end=1.0)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "t.tsv")
            t.to_tsv(path)
            meta, head, rows = read_tsv(path)
        self.assertIn("tool", meta)
        self.assertEqual(head, ["t", "x", "xdot", "mode"])
        self.assertEqual(float(rows[-1]["x"]), t.x[-1])

    def test_tsv_cells_are_empty_where_nan_and_inf_is_refused(self):
        import pandas as pd  # no nan or inf is written: NaN (does not apply) is an empty cell
        from stickslip import _display
        with tempfile.TemporaryDirectory() as d:
            Seed.get().to_tsv(os.path.join(d, "branch.tsv"))
            _, head, rows = read_tsv(os.path.join(d, "branch.tsv"))
            eq = [r for r in rows if r["kind"] == "equilibrium"]
            self.assertTrue(eq)
            self.assertEqual({(r["period"], r["t_stick"]) for r in eq}, {("", "")})
            self.assertFalse([c for r in rows for c in r.values() if c.lower() in ("nan", "inf")])
            path = os.path.join(d, "t.tsv")
            _display._table_tsv(pd.DataFrame({"p": [1, 2], "a": [1.5, math.nan]}), path, [])
            self.assertEqual([r["a"] for r in read_tsv(path)[2]], ["1.5", ""])
            with self.assertRaisesRegex(ValueError, "column 'a', row 2: inf is not a finite"):
                _display._table_tsv(pd.DataFrame({"p": [1, 2], "a": [1.5, math.inf]}), path, [])


class RestartFromPython(unittest.TestCase):
    def test_hopf_point_of_a_python_branch_starts_a_beta_branch(self):
        b = Seed.get()
        with tempfile.TemporaryDirectory() as d:
            b.save(d)
            point = stickslip.restart(d, "HB1")
        hb = [s for s in b.special if s.lab == "HB1"][0]
        self.assertEqual(point.p, hb.p)
        self.assertEqual(point.pt, hb.pt)
        same = b.restart("HB1")
        self.assertEqual(same.p, hb.p)
        # From HB1 in beta: the Hopf point in beta at v = HB1's v (seed eq. 3.16).
        nb = stickslip.continue_branch(point.params, options=point.options("beta"))
        hb_beta = [s.p for s in nb.special if s.label == "HB"]
        p = point.params
        self.assertEqual(len(hb_beta), 1, repr(nb))
        self.assertAlmostEqual(hb_beta[0], (p.k1 - 3 * p.k3 * p.v ** 2) / 2, delta=1e-10)

    def test_unknown_label_names_the_point(self):
        with self.assertRaisesRegex(ValueError, "XX9"):
            Seed.get().restart("XX9")


class StyleSplit(unittest.TestCase):
    def test_change_falls_at_the_special_point_not_a_row_later(self):
        p = [0.0, 1.0, 2.0, 3.0]
        y = [0.0, 1.0, 2.0, 3.0]
        runs = plot.stability_runs(p, y, [True, True, False, False], breaks=[1.25])
        self.assertEqual(len(runs), 2)
        (p0, y0, s0, _), (p1, y1, s1, _) = runs
        self.assertTrue(s0)
        self.assertFalse(s1)
        np.testing.assert_allclose(p0, [0, 1, 1.25])
        np.testing.assert_allclose(p1, [1.25, 2, 3])
        np.testing.assert_allclose(y0[-1], 1.25)

    def test_change_at_the_multiplier_crossing(self):
        # |mu| = 0.8 then 1.4: crosses 1 a third of the way (linear).
        runs = plot.stability_runs([0, 3], [0, 3], [True, False], ["stick-slip"] * 2, [0, 0],
                                   [0.8, 1.4])
        self.assertAlmostEqual(runs[0][0][-1], 1.0)
        self.assertAlmostEqual(runs[1][0][0], 1.0)

    def test_branches_are_never_joined(self):
        runs = plot.stability_runs([0, 1, 2, 3], [0, 1, 2, 3], [True] * 4,
                                   ["stick-slip"] * 2 + ["pure-slip"] * 2, [0, 0, 1, 1])
        self.assertEqual([list(r[0]) for r in runs], [[0, 1], [2, 3]])

    def test_seed_branch_runs_are_uniform_and_meet_at_the_change(self):
        b = Seed.get()
        pts = b.points
        runs = plot.stability_runs(pts.p, pts.x_max, pts.stable, pts.kind, pts.branch,
                                   pts.multiplier, breaks=[s.p for s in b.special])
        rows = {(str(k), float(p), float(y)): bool(s)
                for k, p, y, s in zip(pts.kind, pts.p, pts.x_max, pts.stable)}
        checked = 0
        for ps, ys, st, kind in runs:
            for q, y in zip(ps, ys):  # every original row of a run has the run's stability
                if (kind, float(q), float(y)) in rows:
                    self.assertEqual(rows[(kind, float(q), float(y))], st, (kind, q))
                    checked += 1
        self.assertEqual(checked, len(pts))  # and every row is in a run
        changes = [(a, c) for a, c in zip(runs, runs[1:]) if a[2] != c[2] and a[3] == c[3]]
        self.assertTrue(changes)
        for a, c in changes:
            self.assertEqual(a[0][-1], c[0][0])  # the two styles meet at one point


class Figures(unittest.TestCase):
    def setUp(self):
        import matplotlib
        matplotlib.use("Agg")

    def test_branch_plot_draws_solid_and_dashed_and_labels(self):
        import matplotlib.pyplot as plt
        b = Seed.get()
        ax = b.plot(y="x_max")
        styles = {line.get_linestyle() for line in ax.get_lines()}
        self.assertIn("-", styles)
        self.assertIn("--", styles)
        texts = {t.get_text() for t in ax.texts}
        self.assertTrue({"GR1", "HB1"} <= texts, texts)
        out = os.environ.get("STICKSLIP_FIGURE_OUT")
        if out:
            ax.figure.savefig(out, dpi=100)
        plt.close(ax.figure)

    def test_forced_branch_shows_itself_and_plots(self):
        import matplotlib.pyplot as plt
        # Den Hartog's floor: a resonance curve (test_forced checks its values).
        p = stickslip.ForcedBeltParams(stickslip.Params("coulomb", mu_s=0.3, mu_k=0.3, beta=0.0,
                                                    v=0.0), force=1.0, omega=1.5)
        o = stickslip.periodic_orbit(p, [0.5, 0.0, 0.0])
        b = stickslip.continue_branch(p, stickslip.Parameter.omega, o.start, 2.5,
                                      max_step=0.02)
        self.assertIn("points %d" % len(b.p), repr(b))
        df = b.to_pandas()
        np.testing.assert_array_equal(df["x_max"].to_numpy(), b.hi[:, 0])
        self.assertEqual(list(df["pt"][:2]), [1, 2])
        ax = b.plot()
        self.assertTrue(ax.get_lines())
        plt.close(ax.figure)

    def test_attractor_basins_plot_marks_every_attractor(self):
        import matplotlib.pyplot as plt
        fp = stickslip.ForcedBeltParams(stickslip.Params(), force=0.2, omega=0.8)
        d = stickslip.basins(fp, nx=8, ny=6)
        ax = d.plot()
        self.assertEqual(len(ax.texts), len(d.attractors))
        mesh = ax.collections[0].get_array()
        np.testing.assert_array_equal(np.ma.filled(mesh, -1).ravel(), d.attractor)  # x fastest
        self.assertEqual(ax.get_xlabel(), plot.label("x"))
        plt.close(ax.figure)

    def test_basins_plot(self):
        import matplotlib.pyplot as plt
        ax = stickslip.basins(stickslip.Params(), nx=6, ny=5).plot()
        self.assertEqual(len(ax.collections), 1)
        plt.close(ax.figure)


class ParamsChecks(unittest.TestCase):
    def test_invalid_value_raises_when_built(self):
        with self.assertRaisesRegex(ValueError, "beta"):
            stickslip.Params(beta=-1)
        with self.assertRaises(stickslip.InvalidArgument):
            stickslip.Params(v=-0.1)

    def test_type_errors_name_the_argument(self):
        with self.assertRaisesRegex(TypeError, "law must be .*not Params"):
            stickslip.parameter_names(stickslip.Params())
        with self.assertRaisesRegex(TypeError, "beta must be a number, not str"):
            stickslip.Params(beta="0.1")
        with self.assertRaisesRegex(TypeError, "progress must be a callable"):
            stickslip.continue_branch(stickslip.Params(), progress=3)

    def test_numpy_scalars_are_numbers(self):
        self.assertEqual(stickslip.Params(beta=np.float64(0.1)).beta, 0.1)
        self.assertEqual(stickslip.Params(beta=np.int64(0)).beta, 0.0)

    def test_physical_columns_round_trip_through_from_physical(self):
        M, K = 2.0, 800.0
        df = Seed.get().to_pandas(mass=M, stiffness=K)
        V = df["belt_speed"].iloc[10]
        p = stickslip.Params.from_physical(mass=M, stiffness=K, damping=0.05 * 2 * math.sqrt(K * M),
                                           belt_speed=V)
        self.assertAlmostEqual(p.v, df["v"].iloc[10], places=12)
        self.assertAlmostEqual(df["x_max_m"].iloc[10], df["x_max"].iloc[10] * M * 9.81 / K)
        self.assertAlmostEqual(df["period_s"].iloc[10], df["period"].iloc[10] * math.sqrt(M / K))

    def test_a_branch_in_belt_speed_has_the_seeds_grazing_point(self):
        # The seed set in physical form: C = 2 beta sqrt(K M), mu as the seed's; the GR point
        # in v is ss_continue's 0.39579028879784 (README), in m/s v L / t0 = v g sqrt(M / K).
        M, K = 2.0, 800.0
        speed = 9.81 * math.sqrt(M / K)  # m/s per unit of v
        b = stickslip.continue_physical(mass=M, stiffness=K, damping=0.1 * math.sqrt(K * M),
                                        belt_speed=0.25 * speed, mu_s=0.4, mu_m=0.25,
                                        speed_m=0.5 * speed, param="belt_speed",
                                        from_=0.2 * speed, to=0.5 * speed)
        self.assertEqual(b.param, "v")
        self.assertAlmostEqual(b.points.p[0], 0.2, places=12)
        gr = [s for s in b.special if s.label == "GR"][0]
        self.assertAlmostEqual(gr.p, 0.39579028879784, delta=1e-9)
        df = b.to_pandas(mass=M, stiffness=K)
        self.assertAlmostEqual(df["belt_speed"].iloc[gr.pt - 1], df["v"].iloc[gr.pt - 1] * speed)
        with self.assertRaisesRegex(ValueError, "mass"):
            stickslip.continue_physical(mass=M, param="mass")

    def test_physical_inputs_scale_as_the_seed(self):
        # v = V / (g sqrt(M / K)) and beta = C / (2 sqrt(K M)) (seed section 3).
        M, K, C, V = 2.0, 800.0, 4.0, 0.5
        p = stickslip.Params.from_physical(mass=M, stiffness=K, damping=C, belt_speed=V)
        self.assertAlmostEqual(p.v, V / (9.81 * math.sqrt(M / K)), places=12)
        self.assertAlmostEqual(p.beta, C / (2 * math.sqrt(K * M)), places=12)


class Progress(unittest.TestCase):
    def test_called_once_per_point_in_order(self):
        calls = []
        b = stickslip.continue_branch(stickslip.Params(), "v", from_=0.3, to=0.5,
                                      progress=lambda *a: calls.append(a))
        self.assertEqual([c[0] for c in calls][:3], [1, 2, 3])
        self.assertEqual(len(calls), len(b.points))
        self.assertEqual([c[1] for c in calls], list(b.points.p))

    def test_an_exception_in_the_callback_stops_the_run(self):
        class Stop(Exception):
            pass

        def stop(pt, *_):
            if pt == 5:
                raise Stop("enough")

        with self.assertRaises(Stop):
            stickslip.continue_branch(stickslip.Params(), "v", from_=0.2, to=0.5, progress=stop)

    def test_basins_report_every_start(self):
        calls = []
        stickslip.basins(stickslip.Params(), nx=4, ny=3, progress=lambda d, n: calls.append((d, n)))
        self.assertEqual(sorted(calls), [(d, 12) for d in range(1, 13)])


if __name__ == "__main__":
    unittest.main()
