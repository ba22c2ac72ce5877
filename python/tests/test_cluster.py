"""stickslip.sweep on a real Dask cluster (ctest: Python.Cluster): a `dask
scheduler` and two `dask worker` processes on 127.0.0.1 (Debian's
python3-distributed), as on several machines. The sweep through
scheduler="tcp://127.0.0.1:PORT" equals the serial run bit for bit; a worker
killed mid-sweep leaves the same result (its tasks rerun on the other worker,
every point once in the table); with no worker left the sweep stops with an
error naming the points, never waits forever."""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import stickslip
from wall_bound import WallBound

HERE = os.path.dirname(os.path.abspath(__file__))
GRID = {"omega": np.linspace(0.6, 1.4, 12)}
SAMPLE = {"mu_s": np.random.default_rng(11).normal(0.4, 0.02, 10)}


def slow_orbits(columns):
    """forced_orbits at 50 ms a chunk at least: the sweep lasts long enough to
    kill a worker in its middle."""
    time.sleep(0.05)
    return stickslip.forced_orbits(columns)


slow_orbits.batch = True


def dask_executable():
    """`dask` (dask >= 2022.10: dask scheduler, dask worker), else None."""
    for d in (os.path.dirname(sys.executable), "/usr/bin"):
        exe = os.path.join(d, "dask")
        if os.access(exe, os.X_OK):
            return exe
    return shutil.which("dask")


class Cluster:
    """A scheduler and `workers` workers, each one process (--no-nanny: killing
    it kills the worker, nothing restarts it), one thread each."""

    def __init__(self, workers):
        self.dir = tempfile.mkdtemp(prefix="ss-cluster-")
        self.file = os.path.join(self.dir, "scheduler.json")
        env = dict(os.environ, PYTHONPATH=os.pathsep.join(
            [HERE, os.environ.get("PYTHONPATH", "")]))
        self.log = open(os.path.join(self.dir, "log"), "wb")
        exe = dask_executable()
        self.scheduler = subprocess.Popen(
            [exe, "scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
             "--scheduler-file", self.file], env=env, stdout=self.log, stderr=self.log)
        self.address = self.wait_for_file()
        self.workers = [subprocess.Popen(
            [exe, "worker", self.address, "--host", "127.0.0.1", "--nthreads", "1",
             "--no-nanny", "--no-dashboard", "--death-timeout", "30",
             "--local-directory", self.dir], env=env, stdout=self.log, stderr=self.log)
            for _ in range(workers)]
        from dask.distributed import Client
        with Client(self.address, timeout=30) as c:
            c.wait_for_workers(workers, timeout=60)

    def wait_for_file(self):
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            if self.scheduler.poll() is not None:
                raise RuntimeError("dask scheduler exited: " + self.logged())
            try:
                with open(self.file) as f:
                    return json.load(f)["address"]
            except (OSError, ValueError, KeyError):
                time.sleep(0.1)
        raise RuntimeError("dask scheduler did not start in 60 s: " + self.logged())

    def logged(self):
        self.log.flush()
        with open(os.path.join(self.dir, "log"), "rb") as f:
            return f.read()[-2000:].decode(errors="replace")

    def close(self):
        for p in self.workers + [self.scheduler]:
            if p.poll() is None:
                p.terminate()
        for p in self.workers + [self.scheduler]:
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        self.log.close()
        shutil.rmtree(self.dir, ignore_errors=True)


def kill_when(progress_at, workers, done):
    """A progress callback that SIGKILLs `workers` once `progress_at` points are done."""
    def progress(points, total, seconds):
        if points >= progress_at and not done.is_set():
            done.set()
            for w in workers:
                os.kill(w.pid, signal.SIGKILL)
    return progress


@unittest.skipIf(dask_executable() is None, "no dask executable (Debian: python3-distributed)")
class RealCluster(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.serial = stickslip.sweep(slow_orbits, GRID, SAMPLE, scheduler="serial",
                                     chunk_size=4)

    def setUp(self):
        self.cluster = Cluster(2)
        self.addCleanup(self.cluster.close)

    def test_scheduler_and_two_workers_equal_serial_bit_for_bit(self):
        r = stickslip.sweep(slow_orbits, GRID, SAMPLE, scheduler=self.cluster.address,
                            chunk_size=4, timeout=120)
        self.assertEqual(r.columns, self.serial.columns)
        self.assertTrue(np.array_equal(r.data, self.serial.data))
        self.assertEqual(r.meta["workers"], 2)
        self.assertEqual(r.meta["scheduler"], self.cluster.address)

    def test_a_worker_killed_mid_sweep_leaves_the_same_result(self):
        done = threading.Event()
        r = stickslip.sweep(slow_orbits, GRID, SAMPLE, scheduler=self.cluster.address,
                            chunk_size=4, timeout=120,
                            progress=kill_when(20, self.cluster.workers[:1], done))
        self.assertTrue(done.is_set())
        self.assertEqual(self.cluster.workers[0].wait(10), -signal.SIGKILL)  # dead
        self.assertEqual(len(r), len(self.serial))
        self.assertTrue(np.array_equal(r.data, self.serial.data))

    def test_no_worker_left_stops_with_the_points_named(self):
        done = threading.Event()
        bound = WallBound()
        start = time.monotonic()
        with self.assertRaises(stickslip.SweepError) as e:
            stickslip.sweep(slow_orbits, GRID, SAMPLE, scheduler=self.cluster.address,
                            chunk_size=4, timeout=120, worker_timeout=3,
                            progress=kill_when(20, self.cluster.workers, done))
        self.assertTrue(done.is_set())
        self.assertLess(time.monotonic() - start, bound.of(60))
        self.assertRegex(str(e.exception), r"sweep: points \d+ to \d+ \(the first \{'omega'")
        # Either the scheduler reports the tasks the dead workers held as lost, or
        # none is left to run the rest: both name the points.
        self.assertRegex(str(e.exception), r"no worker left for 3 s|task lost \(its worker died")


if __name__ == "__main__":
    unittest.main()
