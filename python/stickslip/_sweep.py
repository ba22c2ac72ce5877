"""Parameter sweeps that outgrow one machine: stickslip.sweep on Dask.

sweep(fn, grid=..., sample=...) evaluates fn at every point of a parameter grid
(the Cartesian product of named 1-D axes), or of a sample (named columns of
equal length, e.g. draws of uncertain friction coefficients), or of both (each
grid point with every sample row). fn takes one point as a dict of floats and
returns a dict of floats (the same keys at every point); it must be picklable
(a module-level function) to run on workers.

Execution, by `scheduler`:
  None           an embedded dask.distributed LocalCluster on this machine
                 (n_workers processes, one thread each, on 127.0.0.1, no dashboard);
  "tcp://h:port" an existing Dask cluster's scheduler (its workers must import
                 stickslip and the module that defines fn);
  "serial"       this process, no Dask (the reference the cluster must equal).
Points are sent in chunks (one task each) and gathered in order, so a result
does not depend on the number of workers or the order they finish in.

A point whose fn raises, or returns anything but a non-empty dict of finite
numbers with the first point's keys, stops the sweep with SweepError naming the
point; so does a worker's death (naming the points of the tasks it held), no worker left for
worker_timeout seconds, or the whole sweep past `timeout` seconds. No partial
result is returned as data. Ctrl-C cancels the outstanding tasks and
raises KeyboardInterrupt. The result's to_tsv writes one self-describing file:
'# key: value' metadata lines (tool, version, function, axes, sample, scheduler,
workers, time), a header line, then one row per point, as the apps' TSVs.
"""
import itertools
import math
import os
import tempfile
import time

import numpy as np

__all__ = ["sweep", "SweepResult", "SweepError", "group_stats", "stick_slip_orbit"]


class SweepError(RuntimeError):
    """fn failed at a point: the message names the point and the reason."""


def _points(grid, sample):
    """The list of point dicts, grid-major, then the axis names in order."""
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
        raise ValueError(f"sweep: '{sorted(overlap)[0]}' is both a grid axis and a sample column")
    lengths = {v.size for v in sample.values()}
    if len(lengths) > 1:
        raise ValueError("sweep: sample columns differ in length: "
                         + ", ".join(f"{k} {v.size}" for k, v in sample.items()))
    n_sample = lengths.pop() if lengths else 1
    names = list(grid) + list(sample)
    points = []
    for g in itertools.product(*grid.values()) if grid else [()]:
        for i in range(n_sample):
            point = dict(zip(grid, (float(x) for x in g)))
            point.update({k: float(v[i]) for k, v in sample.items()})
            points.append(point)
    return names, points


def _run_chunk(fn, points):
    """Evaluates fn at each point; returns (rows, None) or (None, (index, message))."""
    rows = []
    for i, point in enumerate(points):
        try:
            out = fn(dict(point))
        except Exception as e:  # reported with its point, never passed on as data
            return None, (i, f"{type(e).__name__}: {e}")
        rows.append(out)
    return rows, None


class SweepResult:
    """Rows of a sweep: `columns` (axis names, then fn's keys) and `data`, a
    read-only float array of shape (points, columns); `meta` is the metadata."""

    __slots__ = ("columns", "data", "meta")

    def __init__(self, columns, data, meta):
        self.columns = list(columns)
        data = np.asarray(data, dtype=float)
        data.setflags(write=False)
        self.data = data
        self.meta = dict(meta)

    def __getitem__(self, name):
        return self.data[:, self.columns.index(name)]

    def __len__(self):
        return self.data.shape[0]

    def to_tsv(self, path):
        """Writes the whole file under a temporary name, then renames it."""
        lines = [f"# {k}: {v}" for k, v in self.meta.items()]
        lines.append("\t".join(self.columns))
        lines += ["\t".join(repr(float(x)) for x in row) for row in self.data]
        d = os.path.dirname(os.path.abspath(path))
        fd, tmp = tempfile.mkstemp(prefix=".sweep-", dir=d)
        try:
            with os.fdopen(fd, "w") as f:
                f.write("\n".join(lines) + "\n")
            os.chmod(tmp, 0o644)
            os.replace(tmp, path)
        except BaseException:
            if os.path.exists(tmp):
                os.unlink(tmp)
            raise


def _chunks(points, chunk_size):
    return [points[i:i + chunk_size] for i in range(0, len(points), chunk_size)]


def _keys_of(row, point, index):
    """The keys of fn's first result: a non-empty dict with string keys."""
    if not isinstance(row, dict) or not row or not all(isinstance(k, str) for k in row):
        raise SweepError(f"sweep: point {index} {point}: fn returned {row!r}, expected a "
                         "non-empty dict of {name: number} with string names")
    return list(row)


def _check_values(names, keys, rows, points, offset):
    for j, (row, point) in enumerate(zip(rows, points)):
        if not isinstance(row, dict) or list(row) != keys:
            got = f"a dict with keys {list(row)}" if isinstance(row, dict) else repr(row)
            raise SweepError(f"sweep: point {offset + j} {point}: fn returned "
                             f"{got}, expected a dict with the first point's keys {keys}")
        for k, v in row.items():
            if not isinstance(v, (int, float, np.integer, np.floating)) or not math.isfinite(v):
                raise SweepError(f"sweep: point {offset + j} {point}: {k} = {v!r} "
                                 "is not a finite number")


def _serial(fn, chunks):
    return [_run_chunk(fn, c) for c in chunks]


class _ChunkFailed(Exception):
    """Tasks failed outside fn (their worker died, no worker left): chunk indices, why."""

    def __init__(self, indices, message):
        super().__init__(message)
        self.indices, self.message = indices, message


def _gather(client, futures, timeout, worker_timeout):
    """The futures' results in order, polling twice a second: a task that erred
    (KilledWorker: its worker died too often) or was lost raises _ChunkFailed
    with its index; so does the first unfinished task when no worker has been
    connected for worker_timeout seconds, or past `timeout` seconds."""
    start = time.monotonic()
    idle_since = None
    while True:
        states = [f.status for f in futures]
        bad = [i for i, st in enumerate(states) if st in ("error", "cancelled", "lost")]
        if bad:
            # A dead worker fails every task it held at once (Dask cannot tell which
            # one killed it): each is named.
            time.sleep(0.5)
            bad = [i for i, f in enumerate(futures) if f.status in ("error", "cancelled", "lost")]
            f = futures[bad[0]]
            if f.status == "error":
                e = f.exception()
                raise _ChunkFailed(bad, f"task failed: {type(e).__name__}: {e}")
            raise _ChunkFailed(bad, f"task {f.status} (its worker died?)")
        if all(st == "finished" for st in states):
            return client.gather(futures)
        first = states.index(next(st for st in states if st != "finished"))
        now = time.monotonic()
        if timeout is not None and now - start > timeout:
            raise _ChunkFailed([first], f"not done after timeout = {timeout} s")
        if len(client.nthreads()) == 0:
            idle_since = idle_since if idle_since is not None else now
            if now - idle_since > worker_timeout:
                raise _ChunkFailed([first], f"no worker left for {worker_timeout} s "
                                   "(worker_timeout)")
        else:
            idle_since = None
        time.sleep(0.5)


def _dask(fn, chunks, scheduler, n_workers, timeout, worker_timeout):
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
        futures = client.map(_run_chunk, [fn] * len(chunks), chunks, pure=False)
        parts = _gather(client, futures, timeout, worker_timeout)
        return parts, len(client.scheduler_info()["workers"])
    except (KeyboardInterrupt, _ChunkFailed):
        client.cancel(futures)
        raise
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def sweep(fn, grid=None, sample=None, *, scheduler=None, n_workers=2, chunk_size=None,
          meta=None, timeout=None, worker_timeout=60.0):
    """Evaluates fn over the points of grid x sample; returns a SweepResult.

    grid: {name: 1-D values}, the Cartesian product in the given order;
    sample: {name: 1-D values of equal length}, rows taken together;
    scheduler: None (LocalCluster of n_workers), "tcp://host:port", or "serial";
    chunk_size: points per task (default: about 8 tasks per worker);
    meta: extra metadata lines {key: value} for the file;
    timeout: seconds the whole Dask run may take (None: no bound);
    worker_timeout: seconds the sweep waits with no worker connected.
    """
    if not callable(fn):
        raise TypeError("sweep: fn must be callable")
    if not (isinstance(n_workers, int) and n_workers >= 1):
        raise ValueError(f"sweep: n_workers = {n_workers!r} must be an integer >= 1")
    if scheduler is not None and scheduler != "serial" and not str(scheduler).startswith(
            ("tcp://", "tls://", "inproc://", "ucx://")):
        raise ValueError(f"sweep: scheduler = {scheduler!r} must be None, 'serial' or an "
                         "address such as tcp://host:8786")
    names, points = _points(grid, sample)
    if chunk_size is None:
        chunk_size = max(1, math.ceil(len(points) / (8 * n_workers)))
    if not (isinstance(chunk_size, int) and chunk_size >= 1):
        raise ValueError(f"sweep: chunk_size = {chunk_size!r} must be an integer >= 1")
    for name, t in (("timeout", timeout), ("worker_timeout", worker_timeout)):
        if t is None and name == "timeout":
            continue
        if not (isinstance(t, (int, float)) and not isinstance(t, bool) and 0 < t < math.inf):
            raise ValueError(f"sweep: {name} = {t!r} must be a finite number of seconds > 0")
    chunks = _chunks(points, chunk_size)
    start = time.perf_counter()
    if scheduler == "serial":
        parts, workers = _serial(fn, chunks), 1
    else:
        try:
            parts, workers = _dask(fn, chunks, scheduler, n_workers, timeout, worker_timeout)
        except _ChunkFailed as e:
            where = []
            for c in e.indices:
                first, last = c * chunk_size, c * chunk_size + len(chunks[c]) - 1
                where.append(f"point {first} {chunks[c][0]}" if first == last else
                             f"points {first} to {last} (the first {chunks[c][0]})")
            raise SweepError(f"sweep: {', '.join(where)}: {e.message}") from None
    seconds = time.perf_counter() - start
    rows, keys, offset = [], None, 0
    for chunk, (chunk_rows, failure) in zip(chunks, parts):
        if failure is not None:
            i, message = failure
            raise SweepError(f"sweep: point {offset + i} {chunk[i]}: {message}")
        if keys is None:
            keys = _keys_of(chunk_rows[0], chunk[0], offset)
        _check_values(names, keys, chunk_rows, chunk, offset)
        rows += [[p[n] for n in names] + [float(r[k]) for k in keys]
                 for p, r in zip(chunk, chunk_rows)]
        offset += len(chunk)
    from . import __version__ as version
    info = {"tool": f"stickslip.sweep {version}",
            "function": f"{getattr(fn, '__module__', '?')}.{getattr(fn, '__qualname__', fn)}",
            "grid": "; ".join(f"{k} {len(np.ravel(v))} values [{min(v)}, {max(v)}]"
                              for k, v in (grid or {}).items()) or "none",
            "sample": "; ".join(f"{k} {len(np.ravel(v))} rows"
                                for k, v in (sample or {}).items()) or "none",
            "points": len(points),
            "scheduler": scheduler or f"LocalCluster({n_workers} workers)",
            "workers": workers, "chunk_size": chunk_size, "seconds": f"{seconds:.3f}"}
    info.update(meta or {})
    return SweepResult(names + keys, rows, info)


def group_stats(result, by, value, quantiles=(0.05, 0.5, 0.95), where=None):
    """Per value of the grid axis `by`: the fraction of rows where `where`
    (a column name, taken as true when non-zero; None: every row) holds, and
    the quantiles of `value` over those rows (nan if none). Returns a dict of
    arrays: by, fraction, count, q<q> for each quantile."""
    keys = np.unique(result[by])
    out = {by: keys, "fraction": [], "count": []}
    for q in quantiles:
        out[f"q{q:g}"] = []
    for k in keys:
        rows = result[by] == k
        mask = rows & (result[where] != 0) if where else rows
        out["fraction"].append(mask.sum() / rows.sum())
        out["count"].append(int(rows.sum()))
        vals = result[value][mask]
        for q in quantiles:
            out[f"q{q:g}"].append(float(np.quantile(vals, q)) if vals.size else math.nan)
    return {k: np.asarray(v) for k, v in out.items()}


def stick_slip_orbit(point):
    """A ready-made fn for sweep: the belt model at the seed set with the point's
    values (any Params field: v, beta, mu_s, mu_m, v_m, ...; 'law' is not a number
    and cannot be swept). The stick-slip orbit exists where the slip arc from the
    stick exit returns to the stick set (the return map on it is constant, design
    notes section 1), so one first return decides: stick_slip 1 with the orbit's
    amplitude (x_max - x_min)/2 and period, or stick_slip 0 with both 0."""
    from . import NumericalError, Params, periodic_orbit
    try:
        o = periodic_orbit(Params(**point))
    except NumericalError:
        return {"stick_slip": 0.0, "amplitude": 0.0, "period": 0.0}
    return {"stick_slip": 1.0, "amplitude": (o.x_max - o.x_min) / 2, "period": o.period}
