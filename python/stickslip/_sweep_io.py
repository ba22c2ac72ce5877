"""The results of stickslip.sweep: SweepResult in memory or mapped from a file,
its TSV and HDF5 writers, read_sweep, and the progress line.

HDF5 (h5py, Debian: python3-h5py) is the columnar binary format: one file,
one contiguous float64 dataset per column, the metadata as attributes. It was
chosen over netCDF (python3-netcdf4) because h5py needs only NumPy, writes any
row range of a fixed-size dataset (the rows stream in chunk by chunk, in
order), and leaves each column contiguous and uncompressed, so read_sweep maps
it (numpy.memmap) instead of reading it: a 10^8-row result opens at once. A
netCDF-4 file is an HDF5 file, and pandas takes the columns as they are:
pandas.DataFrame({c: f[c][()] for c in f.attrs["columns"]}).
"""
import math
import os
import sys
import tempfile
import time

import numpy as np

# Rows written to a file at a time (its memory, not its content).
TSV_ROWS = 100000


class SweepResult:
    """Rows of a sweep: `columns` (axis names, then fn's keys), `meta` (the
    metadata) and the values, either in memory (`data`, a read-only float array
    of shape (points, columns)) or, for a sweep streamed to a file (out=) or
    opened with read_sweep, as one read-only column per name mapped from the file
    (result[name] reads nothing until used; `data` loads them all)."""

    __slots__ = ("columns", "_data", "_named", "meta")

    def __init__(self, columns, data, meta):
        self.columns = list(columns)
        self.meta = dict(meta)
        if isinstance(data, dict):
            self._data, self._named = None, {k: data[k] for k in self.columns}
        else:
            data = np.asarray(data, dtype=float)
            data.setflags(write=False)
            self._data, self._named = data, None

    @property
    def data(self):
        if self._data is None:
            data = np.column_stack([np.asarray(self._named[k]) for k in self.columns]) \
                if self.columns else np.empty((0, 0))
            data.setflags(write=False)
            self._data = data
        return self._data

    def __getitem__(self, name):
        if self._named is not None:
            return self._named[name]
        return self.data[:, self.columns.index(name)]

    def __len__(self):
        if self._named is not None:
            return len(self._named[self.columns[0]]) if self.columns else 0
        return self.data.shape[0]

    def _rows(self, i, j):
        if self._named is None:
            return self.data[i:j]
        return np.column_stack([np.asarray(self._named[k][i:j]) for k in self.columns])

    def to_tsv(self, path):
        """Writes the whole file under a temporary name, then renames it; rows go
        out TSV_ROWS at a time, each value as repr() writes it (it reads back
        exactly), formatted in C."""
        from ._core import _tsv_rows
        d = os.path.dirname(os.path.abspath(path))
        fd, tmp = tempfile.mkstemp(prefix=".sweep-", dir=d)
        try:
            with os.fdopen(fd, "wb") as f:
                head = "".join(f"# {k}: {v}\n" for k, v in self.meta.items())
                f.write((head + "\t".join(self.columns) + "\n").encode())
                for i in range(0, len(self), TSV_ROWS):
                    f.write(_tsv_rows(self._rows(i, i + TSV_ROWS)))
            os.chmod(tmp, 0o644)
            os.replace(tmp, path)
        except BaseException:
            if os.path.exists(tmp):
                os.unlink(tmp)
            raise

    def to_hdf5(self, path):
        """Writes the result as sweep(out=path) would have (see _H5Writer)."""
        w = _H5Writer(path, len(self))
        try:
            w.create(self.columns)
            for i in range(0, len(self), TSV_ROWS):
                j = min(len(self), i + TSV_ROWS)
                w.write(i, j, self._rows(i, j))
            w.finish(self.meta)
        except BaseException:
            w.abort()
            raise


class _H5Writer:
    """One HDF5 file (h5py, Debian: python3-h5py), written under a temporary
    name in the target's directory and renamed when finished: one contiguous
    1-D float64 dataset per column, in the file's root, written a block of
    rows at a time (memory holds one block); the root's attributes are the
    metadata (each value as the TSV's '# key: value' line writes it, the
    string), plus 'columns', the column names in order."""

    def __init__(self, path, n):
        import h5py  # noqa: F401 (fails here, before any work, if it is missing)
        self.path, self.n = os.path.abspath(path), n
        fd, self.tmp = tempfile.mkstemp(prefix=".sweep-", suffix=".h5",
                                        dir=os.path.dirname(self.path))
        os.close(fd)
        self.file = h5py.File(self.tmp, "w", track_order=True)  # metadata in order
        self.sets = []

    def create(self, columns):
        self.columns = list(columns)
        self.sets = [self.file.create_dataset(c, shape=(self.n,), dtype="f8")
                     for c in self.columns]

    def write(self, start, stop, values):
        for j, ds in enumerate(self.sets):
            ds[start:stop] = values[:, j]

    def finish(self, meta):
        for k, v in meta.items():
            self.file.attrs[k] = str(v)
        self.file.attrs["columns"] = self.columns
        self.file.close()
        with open(self.tmp, "rb+") as f:
            os.fsync(f.fileno())
        os.chmod(self.tmp, 0o644)
        os.replace(self.tmp, self.path)

    def abort(self):
        try:
            self.file.close()
        finally:
            if os.path.exists(self.tmp):
                os.unlink(self.tmp)


def read_sweep(path):
    """A sweep written by sweep(out=path) or SweepResult.to_hdf5 as a
    SweepResult whose columns are read-only arrays mapped from the file (no
    copy in memory); meta holds the metadata strings."""
    import h5py
    with h5py.File(path, "r") as f:
        if "columns" not in f.attrs:
            raise ValueError(f"read_sweep: {path} has no 'columns' attribute: not a sweep file")
        columns = [str(c) for c in f.attrs["columns"]]
        meta = {k: str(v) for k, v in f.attrs.items() if k != "columns"}
        named = {}
        for c in columns:
            ds = f[c]
            offset = ds.id.get_offset()
            if offset is None or ds.shape[0] == 0:  # not allocated (no rows): read
                named[c] = np.array(ds[()], dtype=float)
                named[c].setflags(write=False)
            else:
                named[c] = np.memmap(path, dtype="<f8", mode="r", offset=offset,
                                     shape=ds.shape)
    return SweepResult(columns, named, meta)


class _Progress:
    """Points done, rate and time left after each chunk: to fn(points, total,
    seconds), and with progress=True as one line on stderr (rewritten in place
    on a terminal at most every 0.5 s, else a line every 10 s)."""

    def __init__(self, progress, total):
        if not (progress is None or isinstance(progress, bool) or callable(progress)):
            raise ValueError(f"sweep: progress = {progress!r} must be True, False, None or a "
                             "callable(points, total, seconds)")
        self.fn = progress if callable(progress) and not isinstance(progress, bool) else None
        self.line = progress is True
        self.tty = self.line and sys.stderr.isatty()
        self.total, self.start, self.last = total, time.monotonic(), -math.inf

    def __call__(self, done):
        now = time.monotonic()
        seconds = now - self.start
        if self.fn is not None:
            self.fn(done, self.total, seconds)
        final = done >= self.total
        if self.line and (final or now - self.last >= (0.5 if self.tty else 10)):
            self.last = now
            rate = done / seconds if seconds > 0 else 0.0
            left = (self.total - done) / rate if rate > 0 else math.inf
            text = (f"sweep: {done}/{self.total} points ({100 * done / self.total:.0f} %), "
                    f"{rate:.4g} points/s, {_duration(left)} left")
            sys.stderr.write(("\r" + text + "\x1b[K" if self.tty else text + "\n")
                             + ("\n" if final and self.tty else ""))
            sys.stderr.flush()


def _duration(s):
    if not math.isfinite(s):
        return "?"
    return f"{s:.0f} s" if s < 120 else f"{s / 60:.0f} min" if s < 7200 else f"{s / 3600:.1f} h"
