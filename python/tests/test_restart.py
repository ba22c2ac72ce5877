"""restart(): a labelled point of an ss_continue run (AUTO's IRS) starts a new
branch or chart from Python, as ss_continue --restart and ss_chart --restart do.

References: the Hopf point in beta obeys 2 beta + mu'(v) = 0 with
mu'(v) = -k1 + 3 k3 v^2 (seed eq. 3.16; design notes section 1); the run
directory is written by the C++ app ss_continue (STICKSLIP_SS_CONTINUE).
"""
import math
import os
import shutil
import subprocess
import tempfile
import unittest

import stickslip


def read_tsv(path):
    """(meta, rows as dicts) of a self-describing TSV."""
    meta, rows, head = {}, [], None
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("# ") and ": " in line:
                k, v = line[2:].split(": ", 1)
                meta[k] = v
            elif line and not line.startswith("#"):
                cells = line.split("\t")
                if head is None:
                    head = cells
                else:
                    rows.append(dict(zip(head, cells)))
    return meta, rows


class Restart(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        exe = os.environ.get("STICKSLIP_SS_CONTINUE")
        if not exe:
            raise unittest.SkipTest("STICKSLIP_SS_CONTINUE not set (run through ctest)")
        cls.tmp = tempfile.TemporaryDirectory()
        cls.run_dir = os.path.join(cls.tmp.name, "seed")
        subprocess.run([exe, "--no_plots", "--no_estimates", "--out", cls.run_dir], check=True,
                       stdout=subprocess.DEVNULL)
        _, rows = read_tsv(os.path.join(cls.run_dir, "special_points.tsv"))
        cls.special = {r["lab"]: r for r in rows}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_point_carries_the_run(self):
        lp = stickslip.restart(self.run_dir, "HB1")
        row = self.special["HB1"]
        self.assertEqual((lp.label, lp.type, lp.param, lp.pt), ("HB1", "HB", "v", int(row["pt"])))
        self.assertEqual(lp.p, float(row["v"]))  # every digit of the file's v
        self.assertEqual(lp.params.v, lp.p)
        self.assertEqual(lp.params.beta, 0.05)
        self.assertEqual(lp.flow.rtol, 1e-11)  # the run's solver (the library's default)
        # The Hopf period 2 pi / omega, omega = 1 where the damping 2 beta + mu'(v) vanishes.
        self.assertAlmostEqual(lp.period, 2 * math.pi, delta=1e-12)
        _, branch = read_tsv(os.path.join(self.run_dir, "branch.tsv"))
        last = stickslip.restart(self.run_dir, len(branch))  # steady sliding at v = 0.5
        self.assertEqual(branch[-1]["period"], "")  # does not apply: empty, never nan
        self.assertEqual((last.type, last.p), ("equilibrium", 0.5))
        self.assertIsNone(last.period)
        gr = stickslip.restart(self.run_dir, self.special["GR1"]["pt"])  # by point number
        self.assertEqual(gr.label, self.special["GR1"]["pt"])
        # GR's state is the exit point of stick (mu_s - 2 beta v, v) (seed eq. 3.6).
        self.assertAlmostEqual(gr.state[0], 0.4 - 2 * 0.05 * gr.p, delta=1e-15)
        self.assertGreater(gr.period, 0)

    def test_hopf_point_in_beta_is_the_closed_form(self):
        lp = stickslip.restart(self.run_dir, "HB1")
        opts = lp.options("beta")
        self.assertEqual((opts.param, opts.from_, opts.to), ("beta", 0.05, 0.3))
        branch = stickslip.continue_branch(lp.params, options=opts)
        hb = [s for s in branch.special if s.label == "HB"]
        self.assertEqual(len(hb), 1)
        v = lp.p
        self.assertAlmostEqual(hb[0].p, (0.45 - 3 * 0.6 * v * v) / 2, delta=1e-10)

    def test_chart_starts_its_curve_at_the_point(self):
        for lab in ("GR1", "HB1"):
            lp = stickslip.restart(self.run_dir, lab)
            chart = stickslip.chart(lp.params, options=lp.chart_options("beta"))
            near = min(abs(v - lp.p) for c in chart.curves if c.label == lab[:2]
                       for v, b in zip(c.p1, c.p2) if b == 0.05)
            self.assertLess(near, 1e-9, lab)

    @staticmethod
    def edit(path, what, value="nan"):
        """HB1's period, or the '# from:' line, made nan (or value)."""
        with open(path) as f:
            lines = f.read().splitlines()
        for i, line in enumerate(lines):
            if what == "from" and line.startswith("# from: "):
                lines[i] = "# from: " + value
            if what == "period" and line.startswith("HB\t"):
                cells = line.split("\t")
                cells[2] = value
                lines[i] = "\t".join(cells)
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")

    def test_bad_restarts_raise_value_error_naming_the_cause(self):
        cases = [((os.path.join(self.tmp.name, "none"), "HB1"), "cannot read"),
                 ((self.run_dir, "HB2"), "no point HB2"),
                 ((self.run_dir, 9999), "no point 9999")]
        for args, message in cases:
            with self.assertRaisesRegex(ValueError, message):
                stickslip.restart(*args)
        # Issue 35: a FIFO blocked, /dev/zero grew without bound, a 300 MB file was read
        # whole; period = nan and '# from: nan' were accepted.
        bad = os.path.join(self.tmp.name, "bad")
        sp = os.path.join(bad, "special_points.tsv")
        for name, make, message in (
                ("fifo", lambda: os.mkfifo(sp), "not a regular file"),
                ("zero", lambda: os.symlink("/dev/zero", sp), "not a regular file"),
                ("big", lambda: os.truncate(sp, 65 << 20), "more than 67108864 bytes"),
                ("nan", lambda: self.edit(sp, "period"), "has period = nan"),
                ("empty", lambda: self.edit(sp, "period", ""), r"has period = \(empty\)"),
                ("from", lambda: self.edit(sp, "from"), "'# from: nan'")):
            shutil.rmtree(bad, ignore_errors=True)
            shutil.copytree(self.run_dir, bad)
            if name in ("fifo", "zero"):
                os.unlink(sp)
            make()
            with self.assertRaisesRegex(ValueError, message):
                stickslip.restart(bad, "HB1")
        with self.assertRaisesRegex(ValueError, "a chart starts from a GR or HB point"):
            stickslip.restart(self.run_dir, 3).chart_options()
        with self.assertRaisesRegex(ValueError, "unknown"):
            stickslip.restart(self.run_dir, "HB1").options("gamma")


if __name__ == "__main__":
    unittest.main()


class ForcedRestart(unittest.TestCase):
    """A forced run's labelled point (ss_continue --force) starts continue_branch there.
    Reference: Den Hartog's closed form (1931) of the non-stop orbit, X = sqrt(V^2 - (mu U)^2),
    V = A / (1 - W^2), U = sin(pi / W) / (W (1 + cos(pi / W)))."""

    def test_den_hartog_point_continued_in_force(self):
        exe = os.environ.get("STICKSLIP_SS_CONTINUE")
        if not exe:
            raise unittest.SkipTest("STICKSLIP_SS_CONTINUE not set (run through ctest)")
        with tempfile.TemporaryDirectory() as tmp:
            run = os.path.join(tmp, "dh")
            subprocess.run([exe, "--no_plots", "--law", "coulomb", "--mu_s", "0.3", "--mu_k",
                            "0.3", "--v", "0", "--beta", "0", "--force", "1", "--param", "omega",
                            "--from", "1.5", "--to", "2.5", "--out", run], check=True,
                           stdout=subprocess.DEVNULL)
            lp = stickslip.restart(run, 5)
            self.assertTrue(lp.forced)
            self.assertEqual((lp.force, lp.m), (1.0, 1))
            with self.assertRaises(ValueError):
                lp.options("beta")  # a belt branch from a forced point
            with self.assertRaisesRegex(ValueError, "forced run"):
                lp.chart_options()  # nor a belt chart (its axis is no belt parameter)
            b = stickslip.continue_branch(lp.forced_params(), stickslip.Parameter.force,
                                          (*lp.state, 0.0), 2.0, m=lp.m, max_step=0.02)
        self.assertGreater(len(b.p), 10)
        self.assertAlmostEqual(b.p[0], 1.0, delta=1e-12)
        self.assertAlmostEqual(b.state[0, 0], lp.state[0], delta=1e-9)
        w, mu = lp.omega, 0.3
        u = math.sin(math.pi / w) / (w * (1 + math.cos(math.pi / w)))
        worst = 0.0
        for a, x_max in zip(b.p, b.hi[:, 0]):
            v = a / (1 - w * w)
            worst = max(worst, abs(x_max - math.sqrt(v * v - (mu * u) ** 2)) / x_max)
        self.assertLess(worst, 1e-9)
