"""Parameter sweeps that outgrow one machine: stickslip.sweep on Dask.

sweep(fn, grid=..., sample=...) evaluates fn at every point of a parameter grid
(the Cartesian product of named 1-D axes), or of a sample (named columns of
equal length, e.g. draws of uncertain friction coefficients), or of both (each
grid point with every sample row). fn must be picklable (a module-level
function) to run on workers. It is either
  a point function: one point as a dict of floats -> a dict of floats (the same
                    keys at every point), e.g. stick_slip_orbit; or
  a batch function: a chunk's columns {name: 1-D float array} -> {key: 1-D array
                    of as many numbers}, e.g. stick_slip_orbits (stickslip.orbits
                    on the chunk: one C++ call per chunk). batch=True says so;
                    by default a fn with the attribute batch = True is one.

Points are numbered grid-major (the last grid axis fastest, then the sample
row) and never listed: a chunk of points is a range of numbers, and the worker
that runs it generates its columns. Execution, by `scheduler`:
  None           an embedded dask.distributed LocalCluster on this machine
                 (n_workers processes, one thread each, on 127.0.0.1, no dashboard);
  "tcp://h:port" an existing Dask cluster's scheduler (its workers must import
                 stickslip and the module that defines fn);
  "serial"       this process, no Dask (the reference the cluster must equal).
Chunks (one task each) are gathered in order into one preallocated table, so a
result does not depend on the number of workers or the order they finish in.

A point whose fn raises, or returns anything but a non-empty dict of finite
numbers with the first point's keys, stops the sweep with SweepError naming the
point (a batch fn that raises: its chunk's points); so does a worker's death
(naming the points of the tasks it held), no worker left for worker_timeout
seconds, or the whole sweep past `timeout` seconds. No partial result is
returned as data. Ctrl-C cancels the outstanding tasks and raises
KeyboardInterrupt. The result's to_tsv writes one self-describing file:
'# key: value' metadata lines (tool, version, function, axes, sample, scheduler,
workers, time), a header line, then one row per point, as the apps' TSVs.
"""
import asyncio
import math
import time

import numpy as np

from ._sweep_io import SweepResult, _H5Writer, _Progress, read_sweep

__all__ = ["sweep", "SweepResult", "SweepError", "read_sweep", "group_stats", "stick_slip_orbit",
           "stick_slip_orbits", "forced_orbits"]

# Default chunk: about 8 tasks per worker, at most this many points (a batch
# chunk of the belt's orbits is then well under a second of work).
MAX_CHUNK = 100000
# Seconds a finished chunk's result may take to arrive before the sweep looks
# again at the workers (its worker may have died holding it).
GATHER_WAIT = 2.0


class SweepError(RuntimeError):
    """fn failed at a point: the message names the point and the reason."""


class _Axes:
    """The points of grid x sample without listing them: point k is grid point
    k // rows (C order over the grid axes) with sample row k % rows."""

    def __init__(self, grid, sample):
        grid = {k: np.asarray(v, dtype=float).ravel() for k, v in (grid or {}).items()}
        sample = {k: np.asarray(v, dtype=float).ravel() for k, v in (sample or {}).items()}
        if not grid and not sample:
            raise ValueError("sweep: give grid=, sample= or both")
        for k, v in list(grid.items()) + list(sample.items()):
            if v.size == 0:
                raise ValueError(f"sweep: axis '{k}' is empty")
            if not np.all(np.isfinite(v)):
                raise ValueError(f"sweep: axis '{k}' has a value that is not finite")
        overlap = set(grid) & set(sample)
        if overlap:
            raise ValueError(f"sweep: '{sorted(overlap)[0]}' is both a grid axis and a sample "
                             "column")
        lengths = {v.size for v in sample.values()}
        if len(lengths) > 1:
            raise ValueError("sweep: sample columns differ in length: "
                             + ", ".join(f"{k} {v.size}" for k, v in sample.items()))
        self.grid, self.sample = grid, sample
        self.rows = lengths.pop() if lengths else 1
        self.shape = tuple(v.size for v in grid.values())
        self.names = list(grid) + list(sample)
        self.n = int(np.prod(self.shape, dtype=np.int64)) * self.rows

    def columns(self, start, stop):
        """{name: float array} of points start .. stop - 1."""
        g, s = np.divmod(np.arange(start, stop, dtype=np.int64), self.rows)
        out = {}
        if self.grid:
            for (name, v), i in zip(self.grid.items(), np.unravel_index(g, self.shape)):
                out[name] = v[i]
        for name, v in self.sample.items():
            out[name] = v[s]
        return out

    def point(self, k):
        return {name: float(v[0]) for name, v in self.columns(k, k + 1).items()}


def _keys_error(out):
    """Why fn's result is not a non-empty dict with string keys ('' if it is)."""
    if not isinstance(out, dict) or not out or not all(isinstance(k, str) for k in out):
        return (f"fn returned {out!r}, expected a non-empty dict of {{name: number}} with "
                "string names")
    return ""


def _point_rows(fn, axes, start, stop):
    """A point fn over points start .. stop - 1: (keys, values) or (None, failure)."""
    cols = axes.columns(start, stop)
    keys, values = None, np.empty((stop - start, 0))
    for j in range(stop - start):
        point = {name: float(v[j]) for name, v in cols.items()}
        try:
            out = fn(point)
        except Exception as e:  # reported with its point, never passed on as data
            return None, (start + j, start + j, f"{type(e).__name__}: {e}")
        if keys is None:
            why = _keys_error(out)
            if why:
                return None, (start + j, start + j, why)
            keys = list(out)
            values = np.empty((stop - start, len(keys)))
        elif not isinstance(out, dict) or list(out) != keys:
            got = f"a dict with keys {list(out)}" if isinstance(out, dict) else repr(out)
            return None, (start + j, start + j, f"fn returned {got}, expected a dict with the "
                          f"first point's keys {keys}")
        for i, (k, x) in enumerate(out.items()):
            if not isinstance(x, (int, float, np.integer, np.floating)) or not math.isfinite(x):
                return None, (start + j, start + j, f"{k} = {x!r} is not a finite number")
            values[j, i] = x
    return keys, values


def _batch_rows(fn, axes, start, stop):
    """A batch fn over the columns of points start .. stop - 1."""
    n = stop - start
    cols = axes.columns(start, stop)
    for v in cols.values():
        v.setflags(write=False)
    try:
        out = fn(cols)
    except Exception as e:
        return None, (start, stop - 1, f"{type(e).__name__}: {e}")
    why = _keys_error(out)
    if why:
        return None, (start, stop - 1, why.replace("{name: number}", "{name: 1-D array}"))
    keys, values = list(out), np.empty((n, len(out)))
    for i, (k, col) in enumerate(out.items()):
        try:
            col = np.asarray(col, dtype=float)
        except (TypeError, ValueError):
            return None, (start, stop - 1, f"fn returned {k} = {col!r}, not an array of numbers")
        if col.shape != (n,):
            return None, (start, stop - 1, f"fn returned {k} of shape {col.shape}, expected "
                          f"({n},): one number per point")
        bad = np.flatnonzero(~np.isfinite(col))
        if bad.size:
            return None, (start + bad[0], start + bad[0],
                          f"{k} = {col[bad[0]]!r} is not a finite number")
        values[:, i] = col
    return keys, values


def _run_chunk(fn, batch, axes, start, stop):
    """fn over points start .. stop - 1: (keys, values of shape (points, keys), None)
    or (None, None, (first, last, message)) naming the points that failed."""
    keys, rest = (_batch_rows if batch else _point_rows)(fn, axes, start, stop)
    return (keys, rest, None) if keys is not None else (None, None, rest)


class _ChunkFailed(Exception):
    """Tasks failed outside fn (their worker died, no worker left): chunk indices, why."""

    def __init__(self, indices, message):
        super().__init__(message)
        self.indices, self.message = indices, message


def _gather(client, futures, consume, timeout, worker_timeout):
    """Hands each future's result to consume(index, result) in order, as soon as
    it and those before it are done, and releases it; polls every 50 ms. A task
    that erred (KilledWorker: its worker died too often) or was lost raises
    _ChunkFailed with its index; so does the first unfinished task when no worker
    has been connected for worker_timeout seconds, or past `timeout` seconds."""
    start = time.monotonic()
    idle_since, done = None, 0
    while True:
        states = [f.status for f in futures[done:]]
        bad = [done + i for i, st in enumerate(states) if st in ("error", "cancelled", "lost")]
        if bad:
            # A dead worker fails every task it held at once (Dask cannot tell which
            # one killed it): each is named.
            time.sleep(0.5)
            bad = [done + i for i, f in enumerate(futures[done:])
                   if f.status in ("error", "cancelled", "lost")]
            if not bad:  # lost, then rescheduled by the scheduler meanwhile
                continue
            f = futures[bad[0]]
            if f.status == "error":
                e = f.exception()
                raise _ChunkFailed(bad, f"task failed: {type(e).__name__}: {e}")
            raise _ChunkFailed(bad, f"task {f.status} (its worker died?)")
        while done < len(futures) and futures[done].status == "finished":
            try:
                # A result held by a worker that died is not there to gather: the
                # scheduler computes it again (the future goes back to pending),
                # or no worker is left; either way the loop looks again.
                part = futures[done].result(timeout=GATHER_WAIT)
            except (TimeoutError, asyncio.TimeoutError):
                break
            consume(done, part)
            futures[done].release()
            done += 1
        if done == len(futures):
            return
        now = time.monotonic()
        if timeout is not None and now - start > timeout:
            raise _ChunkFailed([done], f"not done after timeout = {timeout} s")
        if len(client.nthreads()) == 0:
            idle_since = idle_since if idle_since is not None else now
            if now - idle_since > worker_timeout:
                raise _ChunkFailed([done], f"no worker left for {worker_timeout} s "
                                   "(worker_timeout)")
        else:
            idle_since = None
        time.sleep(0.05)


def _identity(x):
    return x


def _shared_axes(client, axes, worker_timeout):
    """The axes (grid and sample columns) as one task's result that every chunk
    depends on. Passed to each task, they were pickled per task and held by the
    scheduler, whose memory grew with tasks x sample size (220 MB at 10^7
    points). A task, not client.scatter: scatter needs a worker now and loses
    its data with the worker; a task is computed again. Once computed, it is
    copied to every worker: a chunk then goes to any free worker, not only to
    the one holding the axes (without work stealing all went there)."""
    import warnings
    from dask.distributed import wait
    with warnings.catch_warnings():  # Dask's advice to scatter a large argument
        warnings.filterwarnings("ignore", message="Large object of size", category=UserWarning)
        shared = client.submit(_identity, axes, pure=False)
    try:
        wait(shared, timeout=worker_timeout)
        client.replicate(shared)
    except Exception:  # no worker yet, or one lost: _gather waits and names the points
        pass
    return shared


def _dask(fn, batch, axes, bounds, consume, scheduler, n_workers, timeout, worker_timeout):
    """Runs the chunks on Dask; returns the number of workers."""
    from dask.distributed import Client, LocalCluster  # Debian: python3-distributed

    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(scheduler)
    futures = []
    try:
        n = len(bounds)
        shared = _shared_axes(client, axes, worker_timeout)
        futures = client.map(_run_chunk, [fn] * n, [batch] * n, [shared] * n,
                             [b[0] for b in bounds], [b[1] for b in bounds], pure=False)
        _gather(client, futures, consume, timeout, worker_timeout)
        return len(client.scheduler_info()["workers"])
    except (KeyboardInterrupt, _ChunkFailed):
        client.cancel(futures)
        raise
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _check_arguments(fn, scheduler, n_workers, timeout, worker_timeout):
    if not callable(fn):
        raise TypeError("sweep: fn must be callable")
    if not (isinstance(n_workers, int) and n_workers >= 1):
        raise ValueError(f"sweep: n_workers = {n_workers!r} must be an integer >= 1")
    if scheduler is not None and scheduler != "serial" and not str(scheduler).startswith(
            ("tcp://", "tls://", "inproc://", "ucx://")):
        raise ValueError(f"sweep: scheduler = {scheduler!r} must be None, 'serial' or an "
                         "address such as tcp://host:8786")
    for name, t in (("timeout", timeout), ("worker_timeout", worker_timeout)):
        if t is None and name == "timeout":
            continue
        if not (isinstance(t, (int, float)) and not isinstance(t, bool) and 0 < t < math.inf):
            raise ValueError(f"sweep: {name} = {t!r} must be a finite number of seconds > 0")


class _Table:
    """The result, filled chunk by chunk in order: the axes' columns, then fn's;
    in memory, or streamed to an _H5Writer (memory: one chunk)."""

    def __init__(self, axes, bounds, writer=None):
        self.axes, self.bounds, self.keys, self.data = axes, bounds, None, None
        self.writer, self.done = writer, 0

    def where(self, first, last):
        p = self.axes.point(first)
        return f"point {first} {p}" if first == last else \
            f"points {first} to {last} (the first {p})"

    def __call__(self, index, part):
        keys, values, failure = part
        start, stop = self.bounds[index]
        if failure is not None:
            first, last, message = failure
            raise SweepError(f"sweep: {self.where(first, last)}: {message}")
        if self.keys is None:
            self.keys = keys
            if self.writer is not None:
                self.writer.create(self.axes.names + keys)
            else:
                self.data = np.empty((self.axes.n, len(self.axes.names) + len(keys)))
        elif keys != self.keys:
            raise SweepError(f"sweep: {self.where(start, start)}: fn returned a dict with keys "
                             f"{keys}, expected a dict with the first point's keys {self.keys}")
        rows = np.empty((stop - start, len(self.axes.names) + len(keys)))
        m = len(self.axes.names)
        for i, v in enumerate(self.axes.columns(start, stop).values()):
            rows[:, i] = v
        rows[:, m:] = values
        if self.writer is not None:
            self.writer.write(start, stop, rows)
        else:
            self.data[start:stop] = rows
        self.done = stop


def sweep(fn, grid=None, sample=None, *, scheduler=None, n_workers=2, chunk_size=None,
          meta=None, timeout=None, worker_timeout=60.0, batch=None, out=None, progress=None):
    """Evaluates fn over the points of grid x sample; returns a SweepResult.

    grid: {name: 1-D values}, the Cartesian product in the given order;
    sample: {name: 1-D values of equal length}, rows taken together;
    scheduler: None (LocalCluster of n_workers), "tcp://host:port", or "serial";
    chunk_size: points per task (default: about 8 tasks per worker, at most MAX_CHUNK);
    meta: extra metadata lines {key: value} for the file;
    timeout: seconds the whole Dask run may take (None: no bound);
    worker_timeout: seconds the sweep waits with no worker connected;
    batch: fn takes a chunk's columns (default: getattr(fn, "batch", False));
    out: an HDF5 file (.h5, .hdf5) the rows stream to chunk by chunk (memory
         holds one chunk; the file appears whole when the sweep is done, or not
         at all); the result's columns are then mapped from it (read_sweep);
    progress: True (a line on stderr: points done, rate, time left) or
         fn(points, total, seconds), called after each chunk in order.
    """
    _check_arguments(fn, scheduler, n_workers, timeout, worker_timeout)
    batch = bool(getattr(fn, "batch", False)) if batch is None else batch
    if not isinstance(batch, bool):
        raise ValueError(f"sweep: batch = {batch!r} must be True, False or None")
    axes = _Axes(grid, sample)
    if chunk_size is None:
        chunk_size = max(1, min(MAX_CHUNK, math.ceil(axes.n / (8 * n_workers))))
    if not (isinstance(chunk_size, int) and chunk_size >= 1):
        raise ValueError(f"sweep: chunk_size = {chunk_size!r} must be an integer >= 1")
    bounds = [(a, min(axes.n, a + chunk_size)) for a in range(0, axes.n, chunk_size)]
    if out is not None and not str(out).endswith((".h5", ".hdf5")):
        raise ValueError(f"sweep: out = {out!r} must name an HDF5 file (.h5 or .hdf5); "
                         "SweepResult.to_tsv writes TSV")
    report = _Progress(progress, axes.n)
    writer = _H5Writer(out, axes.n) if out is not None else None
    table = _Table(axes, bounds, writer)

    def consume(index, part):
        table(index, part)
        report(table.done)

    start = time.perf_counter()
    try:
        if scheduler == "serial":
            for i, (a, b) in enumerate(bounds):
                consume(i, _run_chunk(fn, batch, axes, a, b))
            workers = 1
        else:
            try:
                workers = _dask(fn, batch, axes, bounds, consume, scheduler, n_workers, timeout,
                                worker_timeout)
            except _ChunkFailed as e:
                where = [table.where(bounds[c][0], bounds[c][1] - 1) for c in e.indices]
                raise SweepError(f"sweep: {', '.join(where)}: {e.message}") from None
    except BaseException:
        if writer is not None:
            writer.abort()
        raise
    seconds = time.perf_counter() - start
    from . import __version__ as version
    info = {"tool": f"stickslip.sweep {version}",
            "function": f"{getattr(fn, '__module__', '?')}.{getattr(fn, '__qualname__', fn)}",
            "grid": "; ".join(f"{k} {v.size} values [{v.min()}, {v.max()}]"
                              for k, v in axes.grid.items()) or "none",
            "sample": "; ".join(f"{k} {v.size} rows" for k, v in axes.sample.items()) or "none",
            "points": axes.n,
            "scheduler": scheduler or f"LocalCluster({n_workers} workers)",
            "workers": workers, "chunk_size": chunk_size, "seconds": f"{seconds:.3f}"}
    info.update(meta or {})
    if writer is not None:
        writer.finish(info)
        return read_sweep(writer.path)
    return SweepResult(axes.names + table.keys, table.data, info)


def group_stats(result, by, value, quantiles=(0.05, 0.5, 0.95), where=None):
    """Per value of the grid axis `by`: the fraction of rows where `where`
    (a column name, taken as true when non-zero; None: every row) holds, and
    the quantiles of `value` over those rows (nan if none). Returns a dict of
    arrays: by, fraction, count, q<q> for each quantile."""
    keys, group = np.unique(result[by], return_inverse=True)
    order = np.argsort(group, kind="stable")  # each key's rows, contiguous
    bounds = np.searchsorted(group[order], np.arange(keys.size + 1))
    values = result[value][order]
    holds = result[where][order] != 0 if where else None
    out = {by: keys, "fraction": [], "count": []}
    for q in quantiles:
        out[f"q{q:g}"] = []
    for lo, hi in zip(bounds[:-1], bounds[1:]):
        vals = values[lo:hi] if holds is None else values[lo:hi][holds[lo:hi]]
        out["fraction"].append(vals.size / (hi - lo))
        out["count"].append(int(hi - lo))
        for q in quantiles:
            out[f"q{q:g}"].append(float(np.quantile(vals, q)) if vals.size else math.nan)
    return {k: np.asarray(v) for k, v in out.items()}


def stick_slip_orbit(point):
    """A ready-made point fn for sweep: the belt model at the seed set with the
    point's values (any Params field: v, beta, mu_s, mu_m, v_m, ...; 'law' may
    name the law). The stick-slip orbit exists where the slip arc from the stick
    exit returns to the stick set (the return map on it is constant, design
    notes section 1), so one first return decides: stick_slip 1 with the orbit's
    amplitude (x_max - x_min)/2 and period, or stick_slip 0 with both 0. The same
    numbers as stick_slip_orbits (stickslip.orbits on one row)."""
    from . import Params, orbits
    p = Params(**point)
    r = orbits(p, {"v": [p.v]}, threads=1)
    return {"stick_slip": float(r["stick_slip"][0]),
            "amplitude": float((r["x_max"][0] - r["x_min"][0]) / 2),
            "period": float(r["period"][0])}


def stick_slip_orbits(columns):
    """The batch form of stick_slip_orbit (sweep takes it as a batch fn): the
    seed set with the chunk's columns, by stickslip.orbits in one call on one
    thread (a Dask worker is one thread). Every column must name a parameter of
    the cubic law; rows without an orbit give stick_slip, amplitude, period 0."""
    from . import Params, orbits
    r = orbits(Params(), columns, threads=1)
    return {"stick_slip": r["stick_slip"].astype(float),
            "amplitude": (r["x_max"] - r["x_min"]) / 2, "period": r["period"]}


stick_slip_orbits.batch = True


def forced_orbits(columns):
    """A ready-made batch fn for forced sweeps: studies/seed_forced.ini's
    oscillator (cubic law, beta 0.05, v 0.25, A 0.3, Omega 0.6) with the chunk's
    columns (omega, force or a parameter of the law), by stickslip.orbits on a
    ForcedBeltParams in one call on one thread: the attractor after 20 forcing
    periods from rest, its least period m <= 4 and the orbit shot on it.
    found 1 with m, sticks, amplitude (x_max - x_min)/2, period, stable; rows
    with no period up to 4 (aperiodic) give found 0 and zeros."""
    from . import ForcedBeltParams, Params, orbits
    p = ForcedBeltParams(Params(beta=0.05, v=0.25), force=0.3, omega=0.6)
    r = orbits(p, columns, threads=1)
    return {"found": r["found"].astype(float), "stick_slip": r["stick_slip"].astype(float),
            "m": r["m"].astype(float), "sticks": r["sticks"].astype(float),
            "amplitude": (r["x_max"] - r["x_min"]) / 2, "period": r["period"],
            "stable": r["stable"].astype(float)}


forced_orbits.batch = True
