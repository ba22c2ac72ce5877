"""Wall-time bounds in tests that hold on a loaded machine (issue 35).

The Python twin of tests/wall_bound.hpp: a bound measured on a quiet machine is
stretched by the load per hardware thread seen while the timed call went (the
larger of the 1-minute load averages before and after, per thread, at least 1).
docs/reliability.md ("Timed tests") gives the margins measured at load 10.
"""
import os


def load_per_thread():
    """The 1-minute load average per hardware thread."""
    return os.getloadavg()[0] / max(1, os.cpu_count() or 1)


class WallBound:
    """Made before a timed call; of(quiet) after it gives the bound to assert."""

    def __init__(self):
        self.before = load_per_thread()

    def stretch(self):
        return max(1.0, self.before, load_per_thread())

    def of(self, quiet_seconds):
        return quiet_seconds * self.stretch()
