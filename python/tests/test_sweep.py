"""stickslip.sweep (ctest: Python.Sweep): a 2-worker Dask LocalCluster gives
exactly the serial result; the ready-made stick_slip_orbit against the closed
form of the undamped coulomb law (design notes section 1: the slip arc is a
circle about x = mu_k of radius sqrt(v^2 + (mu_s - mu_k)^2), period
pi + 2 atan(v / (mu_s - mu_k)) + 2 (mu_s - mu_k) / v); bad input and failing
points are refused with messages that name them."""
import math
import os
import tempfile
import unittest

import numpy as np

import stickslip

GRID = {"v": np.linspace(0.1, 0.45, 6)}
SAMPLE = {"mu_s": np.random.default_rng(7).normal(0.4, 0.02, 12)}


def failing(point):
    if point["v"] > 0.3:
        raise ValueError("no model here")
    return {"y": point["v"]}


def nan_above(point):
    return {"y": math.nan if point["v"] > 0.3 else point["v"]}


def returns_none(point):
    return None


def returns_list(point):
    return [point["v"]]


def returns_empty(point):
    return {}


def keys_change(point):
    return {"y": 1.0} if point["v"] < 0.3 else {"z": 1.0}


def dies_at_third(point):
    if point["v"] == 0.3:
        os._exit(1)  # the worker process dies, as one killed by the OOM killer
    return {"y": point["v"]}


def batch_fails(columns):
    raise ValueError("no model in this chunk")


def batch_nan_above(columns):
    return {"y": np.where(columns["v"] > 0.3, np.nan, columns["v"])}


def batch_short(columns):
    return {"y": columns["v"][:-1]}


def coulomb_orbit(point):
    return stickslip.stick_slip_orbit(dict(point, law="coulomb"))


class Sweep(unittest.TestCase):
    def test_local_cluster_equals_serial_exactly(self):
        serial = stickslip.sweep(stickslip.stick_slip_orbit, GRID, SAMPLE, scheduler="serial")
        dask = stickslip.sweep(stickslip.stick_slip_orbit, GRID, SAMPLE, n_workers=2,
                               chunk_size=5)
        self.assertEqual(dask.meta["workers"], 2)
        self.assertEqual(serial.columns, ["v", "mu_s", "stick_slip", "amplitude", "period"])
        self.assertEqual(len(serial), 72)
        self.assertTrue(np.array_equal(serial.data, dask.data))
        self.assertFalse(serial.data.flags.writeable)
        # Stick-slip at small v for every sample, none past the Hopf point (0.44 at the seed).
        stats = stickslip.group_stats(serial, "v", "amplitude", where="stick_slip")
        self.assertEqual(stats["fraction"][0], 1.0)
        self.assertEqual(stats["fraction"][-1], 0.0)

    def test_batch_fn_equals_the_point_fn_serial_and_on_a_local_cluster(self):
        point = stickslip.sweep(stickslip.stick_slip_orbit, GRID, SAMPLE, scheduler="serial")
        batch = stickslip.sweep(stickslip.stick_slip_orbits, GRID, SAMPLE, scheduler="serial",
                                chunk_size=7)
        dask = stickslip.sweep(stickslip.stick_slip_orbits, GRID, SAMPLE, n_workers=2,
                               chunk_size=7)
        self.assertEqual(batch.columns, point.columns)
        self.assertTrue(np.array_equal(batch.data, point.data))
        self.assertTrue(np.array_equal(dask.data, point.data))
        self.assertFalse(dask.data.flags.writeable)

    def test_points_are_generated_chunk_by_chunk_in_grid_major_order(self):
        seen = []

        def record(columns):
            seen.append({k: v.copy() for k, v in columns.items()})
            self.assertFalse(columns["v"].flags.writeable)
            return {"y": columns["v"] * 0}

        grid = {"v": [0.1, 0.2, 0.3], "beta": [0.01, 0.02]}
        sample = {"mu_s": [0.4, 0.41, 0.42, 0.43]}
        r = stickslip.sweep(record, grid, sample, scheduler="serial", chunk_size=5, batch=True)
        self.assertEqual([len(c["v"]) for c in seen], [5, 5, 5, 5, 4])
        # The last grid axis fastest, then the sample row (itertools.product order).
        import itertools
        want = [(v, b, m) for v, b in itertools.product(grid["v"], grid["beta"])
                for m in sample["mu_s"]]
        got = [t for c in seen for t in zip(c["v"], c["beta"], c["mu_s"])]
        self.assertEqual(got, want)
        self.assertEqual(r.columns, ["v", "beta", "mu_s", "y"])
        self.assertEqual([tuple(row[:3]) for row in r.data], want)

    def test_a_failing_batch_names_its_points(self):
        grid = {"v": [0.1, 0.2, 0.25, 0.4, 0.1]}
        cases = ((batch_fails, "points 3 to 4 (the first {'v': 0.4}): ValueError: no model"),
                 (batch_nan_above, "point 3 {'v': 0.4}: y = nan is not a finite number"),
                 (batch_short, "points 0 to 2 (the first {'v': 0.1}): fn returned y of shape "
                               "(2,), expected (3,)"))
        for fn, words in cases:
            with self.assertRaises(stickslip.SweepError, msg=fn.__name__) as e:
                stickslip.sweep(fn, grid, scheduler="serial", chunk_size=3, batch=True)
            if fn is batch_fails:  # the first chunk fails first
                words = words.replace("points 3 to 4 (the first {'v': 0.4})",
                                      "points 0 to 2 (the first {'v': 0.1})")
            self.assertIn(words, str(e.exception))

    def test_coulomb_orbits_match_the_closed_form(self):
        r = stickslip.sweep(coulomb_orbit, {"v": [0.1, 0.2, 0.3], "mu_s": [0.4, 0.5],
                                            "beta": [0.0]}, scheduler="serial")
        mu_k = stickslip.Params(law="coulomb").mu_k
        for row in r.data:
            v, mu_s, _, stick, amp, period = row
            d = mu_s - mu_k
            self.assertEqual(stick, 1.0)
            self.assertAlmostEqual(amp, math.hypot(v, d), delta=1e-9)
            self.assertAlmostEqual(period, math.pi + 2 * math.atan(v / d) + 2 * d / v, delta=1e-9)

    def test_file_describes_itself(self):
        r = stickslip.sweep(stickslip.stick_slip_orbit, GRID, SAMPLE, scheduler="serial")
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "sweep.tsv")
            r.to_tsv(path)
            lines = open(path).read().splitlines()
            meta = [l for l in lines if l.startswith("# ")]
            self.assertTrue(any(l.startswith("# tool: stickslip.sweep") for l in meta))
            self.assertTrue(any(l == "# points: 72" for l in meta))
            body = [l for l in lines if not l.startswith("#")]
            self.assertEqual(body[0].split("\t"), r.columns)
            back = np.array([[float(x) for x in l.split("\t")] for l in body[1:]])
            self.assertTrue(np.array_equal(back, r.data))
            self.assertEqual(os.stat(path).st_mode & 0o777, 0o644)

    def test_rows_are_written_as_repr_writes_them(self):
        # The rows are formatted in C (std::to_chars); the text must be repr's.
        rng = np.random.default_rng(5)
        data = rng.standard_normal((2000, 4)) * 10.0 ** rng.integers(-30, 30, (2000, 4))
        data[:, 0] = np.round(rng.random(2000) * 1e6)
        data[:13, 1] = [1e-5, 1e-4, 1.1e-4, 9.99999e-5, 123.0, 1e16, 9999999999999998.0, 1e17,
                        -0.0, 0.0, 5e-324, 1.7976931348623157e308, 0.1]
        r = stickslip.SweepResult(["a", "b", "c", "d"], data, {"k": "v"})
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "rows.tsv")
            r.to_tsv(path)
            with open(path) as f:
                lines = f.read().splitlines()
        self.assertEqual(lines[:2], ["# k: v", "a\tb\tc\td"])
        self.assertEqual(lines[2:], ["\t".join(map(repr, row)) for row in data.tolist()])

    def test_nan_is_an_empty_cell_and_inf_is_refused(self):
        # No nan or inf is written: NaN (does not apply) is an empty cell.
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "rows.tsv")
            stickslip.SweepResult(["a", "b"], [[1.0, math.nan]], {}).to_tsv(path)
            self.assertEqual(open(path).read(), "a\tb\n1.0\t\n")
            with self.assertRaisesRegex(ValueError, "inf is not a finite number"):
                stickslip.SweepResult(["a", "b"], [[1.0, math.inf]], {}).to_tsv(path)

    def test_bad_input_names_the_argument(self):
        for kwargs, word in [({"grid": {"v": []}}, "'v' is empty"),
                             ({"grid": {"v": [0.1, float("nan")]}}, "not finite"),
                             ({"sample": {"a": [1, 2], "b": [1]}}, "differ in length"),
                             ({"grid": {"v": [0.1]}, "n_workers": 0}, "n_workers"),
                             ({"grid": {"v": [0.1]}, "scheduler": "localhost"}, "scheduler"),
                             ({}, "grid=")]:
            with self.assertRaises(ValueError) as e:
                stickslip.sweep(stickslip.stick_slip_orbit, **kwargs)
            self.assertIn(word, str(e.exception))

    def test_a_failing_point_is_named_not_returned(self):
        with self.assertRaises(stickslip.SweepError) as e:
            stickslip.sweep(failing, {"v": [0.1, 0.2, 0.4]}, scheduler="serial")
        self.assertIn("point 2 {'v': 0.4}", str(e.exception))
        self.assertIn("no model here", str(e.exception))


    def test_the_error_names_the_point_not_its_index_in_the_chunk(self):
        # Issue 35 (planted bugs): with 2 points per chunk, point 3 is index 1
        # of the second chunk and point 2 index 0 of it.
        grid = {"v": [0.1, 0.2, 0.25, 0.4]}
        for fn, where in ((failing, "point 3 {'v': 0.4}"), (nan_above, "point 3 {'v': 0.4}")):
            for scheduler in ("serial", None):
                with self.assertRaises(stickslip.SweepError, msg=fn.__name__) as e:
                    stickslip.sweep(fn, grid, scheduler=scheduler, chunk_size=2, n_workers=1)
                self.assertIn(where, str(e.exception))
        with self.assertRaises(stickslip.SweepError) as e:
            stickslip.sweep(failing, {"v": [0.1, 0.2, 0.4, 0.1]}, scheduler="serial",
                            chunk_size=3)
        self.assertIn("point 2 {'v': 0.4}", str(e.exception))

    # Issue 35: what fn returns is checked before its keys are taken.
    def test_a_return_that_is_no_dict_of_numbers_is_named(self):
        cases = ((returns_none, "fn returned None"), (returns_list, "fn returned [0.1]"),
                 (returns_empty, "fn returned {}"),
                 (keys_change, "a dict with keys ['z'], expected a dict with the first point's "
                               "keys ['y']"))
        for fn, words in cases:
            with self.assertRaises(stickslip.SweepError) as e:
                stickslip.sweep(fn, {"v": [0.1, 0.2, 0.4]}, scheduler="serial")
            self.assertIn("point 0 {'v': 0.1}" if fn is not keys_change else "point 2", 
                          str(e.exception))
            self.assertIn(words, str(e.exception))

    def test_bad_timeouts_are_refused(self):
        for kw in ({"timeout": 0}, {"timeout": math.nan}, {"worker_timeout": -1},
                   {"worker_timeout": None}):
            with self.assertRaises(ValueError) as e:
                stickslip.sweep(failing, {"v": [0.1]}, scheduler="serial", **kw)
            self.assertIn(list(kw)[0], str(e.exception))

    def test_a_killed_worker_names_its_point(self):
        import dask
        import distributed  # noqa: F401 (its config defaults first)
        with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
            with self.assertRaises(stickslip.SweepError) as e:
                stickslip.sweep(dies_at_third, {"v": [0.1, 0.2, 0.3, 0.4]}, n_workers=2,
                                chunk_size=1, timeout=120)
        # Every task the dead worker held is named (Dask cannot tell which killed it);
        # the one that did is among them.
        self.assertIn("point 2 {'v': 0.3}", str(e.exception))
        self.assertIn("KilledWorker", str(e.exception))

    def test_no_worker_left_is_an_error_not_a_hang(self):
        from dask.distributed import LocalCluster
        with LocalCluster(n_workers=0, host="127.0.0.1", dashboard_address=None) as cluster:
            with self.assertRaises(stickslip.SweepError) as e:
                stickslip.sweep(failing, {"v": [0.1, 0.2]}, scheduler=cluster.scheduler_address,
                                chunk_size=1, worker_timeout=2)
        self.assertIn("point 0 {'v': 0.1}: no worker left for 2 s", str(e.exception))


def cheap(columns):
    """Three numbers per point at NumPy speed: the sweep's own cost shows."""
    v = columns["v"]
    return {"a": v * 2.0, "b": v + columns["mu_s"], "c": np.sqrt(v)}


cheap.batch = True

MEMORY_SCRIPT = """
import resource, sys, numpy as np, stickslip
sys.path.insert(0, {here!r})
from test_sweep import cheap
n = int(sys.argv[1])
grid = {{"v": np.linspace(0.1, 0.4, n // 1000)}}
sample = {{"mu_s": np.linspace(0.35, 0.45, 1000)}}
stickslip.sweep(cheap, grid, sample, scheduler="serial", chunk_size=50000, out=sys.argv[2])
r = stickslip.read_sweep(sys.argv[2])
print(len(r), resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""

# On a LocalCluster (its scheduler lives in this process): 100 tasks over a
# sample of n draws. Passed to every task, the sample was pickled per task and
# held by the scheduler: 100 x 8 MB at n = 1e6.
DASK_MEMORY_SCRIPT = """
import resource, sys, numpy as np, stickslip
sys.path.insert(0, {here!r})
from test_sweep import cheap
n = int(sys.argv[1])
sample = {{"mu_s": np.linspace(0.35, 0.45, n)}}
stickslip.sweep(cheap, {{"v": [0.2]}}, sample, chunk_size=n // 100, out=sys.argv[2])
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""

# Without work stealing the scheduler places a task where its inputs are: the
# chunks, which all take the shared axes, must still spread over both workers.
SPREAD_SCRIPT = """
import os, sys, time, numpy as np
os.environ["DASK_DISTRIBUTED__SCHEDULER__WORK_STEALING"] = "False"
sys.path.insert(0, {here!r})
import stickslip
from test_sweep import which_worker
if __name__ == "__main__":
    r = stickslip.sweep(which_worker, {{"v": np.linspace(0.1, 0.4, 8)}}, chunk_size=2)
    print(len(set(r["pid"].tolist())))
"""


def which_worker(columns):
    """Each chunk's worker process, after half a second of work."""
    import time
    time.sleep(0.5)
    return {"pid": np.full(columns["v"].size, float(os.getpid()))}


which_worker.batch = True


def run_script(template, *args):
    """A script of this file's templates, run by this Python: its stdout's words."""
    import subprocess
    import sys
    script = template.format(here=os.path.dirname(os.path.abspath(__file__)))
    out = subprocess.run([sys.executable, "-c", script, *map(str, args)], capture_output=True,
                         text=True, check=True)
    return out.stdout.split()


class Stream(unittest.TestCase):
    """sweep(out=...) streams to one HDF5 file (python3-h5py); progress."""

    def setUp(self):
        try:
            import h5py  # noqa: F401
        except ImportError:
            self.skipTest("no h5py (Debian: python3-h5py)")
        self.dir = tempfile.mkdtemp(prefix="ss-stream-")

    def tearDown(self):
        import shutil
        shutil.rmtree(self.dir, ignore_errors=True)

    def test_the_file_round_trips_to_the_in_memory_result(self):
        path = os.path.join(self.dir, "s.h5")
        mem = stickslip.sweep(stickslip.stick_slip_orbits, GRID, SAMPLE, scheduler="serial",
                              chunk_size=5, meta={"study": "round trip"})
        calls = []
        f = stickslip.sweep(stickslip.stick_slip_orbits, GRID, SAMPLE, scheduler="serial",
                            chunk_size=5, meta={"study": "round trip"}, out=path,
                            progress=lambda *a: calls.append(a))
        self.assertEqual(f.columns, mem.columns)
        self.assertTrue(np.array_equal(f.data, mem.data))
        for c in mem.columns:
            self.assertFalse(f[c].flags.writeable, c)
            self.assertTrue(np.array_equal(f[c], mem[c]), c)
        self.assertEqual(set(f.meta), set(mem.meta))
        for k in mem.meta:
            if k != "seconds":
                self.assertEqual(f.meta[k], str(mem.meta[k]), k)
        # The same file from the in-memory result, and its TSV from either.
        again = os.path.join(self.dir, "again.h5")
        mem.to_hdf5(again)
        self.assertTrue(np.array_equal(stickslip.read_sweep(again).data, mem.data))
        mem.to_tsv(os.path.join(self.dir, "m.tsv"))
        f.to_tsv(os.path.join(self.dir, "f.tsv"))
        with open(os.path.join(self.dir, "m.tsv")) as a, open(os.path.join(self.dir, "f.tsv")) as b:
            ra = [x for x in a if not x.startswith("# seconds")]
            rb = [x for x in b if not x.startswith("# seconds")]
        self.assertEqual(ra, rb)
        # Progress after each chunk, in order, to the total.
        n = len(mem)
        self.assertEqual([c[0] for c in calls], list(range(5, n, 5)) + [n])
        self.assertTrue(all(c[1] == n for c in calls))
        self.assertEqual(sorted(os.listdir(self.dir)), ["again.h5", "f.tsv", "m.tsv", "s.h5"])

    def test_a_failed_sweep_leaves_no_file(self):
        path = os.path.join(self.dir, "s.h5")
        with self.assertRaises(stickslip.SweepError):
            stickslip.sweep(failing, GRID, SAMPLE, scheduler="serial", chunk_size=5, out=path)
        self.assertEqual(os.listdir(self.dir), [])
        with self.assertRaises(ValueError) as e:
            stickslip.sweep(failing, GRID, scheduler="serial", out=os.path.join(self.dir, "x.csv"))
        self.assertIn("out = ", str(e.exception))
        with self.assertRaises(ValueError) as e:
            stickslip.sweep(failing, GRID, scheduler="serial", progress="yes")
        self.assertIn("progress = 'yes'", str(e.exception))

    def test_the_progress_line(self):
        import contextlib
        import io
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            stickslip.sweep(cheap, {"v": [0.1, 0.2]}, {"mu_s": [0.4, 0.41]}, scheduler="serial",
                            chunk_size=1, progress=True)
        self.assertRegex(err.getvalue(), r"sweep: 4/4 points \(100 %\), [0-9.e+]+ points/s, "
                         r"\d+ s left\n$")

    def test_memory_does_not_grow_with_the_points(self):
        peak = {}
        for n in (200000, 2000000):
            rows, kb = map(int, run_script(MEMORY_SCRIPT, n, os.path.join(self.dir, f"{n}.h5")))
            self.assertEqual(rows, n)
            peak[n] = kb / 1024
        # In memory the 2e6-point table alone is 2e6 x 5 x 8 B = 76 MB.
        print(f"[ measured ] peak RSS {peak[200000]:.1f} MB at 2e5 points, "
              f"{peak[2000000]:.1f} MB at 2e6")
        self.assertLess(peak[2000000] - peak[200000], 20)

    def test_chunks_spread_over_the_workers_without_work_stealing(self):
        self.assertEqual(run_script(SPREAD_SCRIPT)[-1], "2")

    def test_memory_on_dask_does_not_grow_with_tasks_times_the_sample(self):
        peak = {}
        for n in (100000, 1000000):
            kb = run_script(DASK_MEMORY_SCRIPT, n, os.path.join(self.dir, f"d{n}.h5"))[-1]
            peak[n] = int(kb) / 1024
        print(f"[ measured ] LocalCluster, 100 tasks: peak RSS {peak[100000]:.1f} MB with a "
              f"1e5-draw sample, {peak[1000000]:.1f} MB with 1e6 draws")
        # The sample itself is 8 MB; per task it was 800 MB.
        self.assertLess(peak[1000000] - peak[100000], 60)


class _Future:
    """A Dask future's face for _gather: its status follows `states`, one per look."""

    def __init__(self, states, value):
        self.states, self.value = list(states), value

    @property
    def status(self):
        return self.states.pop(0) if len(self.states) > 1 else self.states[0]

    def result(self, timeout=None):
        return self.value

    def release(self):
        pass


class _Client:
    def nthreads(self):
        return {"w": 1}


class Gather(unittest.TestCase):
    def test_a_lost_task_rescheduled_before_the_second_look_is_waited_for(self):
        # A worker's death marks its tasks lost; the scheduler may run them again
        # before _gather looks a second time (0.5 s later). Seen under load: an
        # IndexError instead of the results.
        from stickslip._sweep import _gather
        futures = [_Future(["finished"], "a"),
                   _Future(["lost", "pending", "finished"], "b")]
        got = []
        _gather(_Client(), futures, lambda i, part: got.append((i, part)), None, 60.0)
        self.assertEqual(got, [(0, "a"), (1, "b")])


if __name__ == "__main__":
    unittest.main()

