"""Wall-time bounds in tests that hold on a loaded machine (issue 35).

The Python twin of tests/wall_bound.hpp (without its factor for AddressSanitizer,
which the Python module is never built with): a bound measured on a quiet
machine is stretched by the load per usable CPU seen while the timed call went
(the larger of the 1-minute load averages before and after, over the CPUs this
process may run on, at least 1). docs/reliability.md ("Timed tests") gives the
load at which they were all run.
"""
import os


def load_per_thread():
    """The 1-minute load average per usable CPU (the process's affinity)."""
    return os.getloadavg()[0] / max(1, len(os.sched_getaffinity(0)))


class WallBound:
    """Made before a timed call; of(quiet) after it gives the bound to assert."""

    def __init__(self):
        self.before = load_per_thread()

    def stretch(self):
        return max(1.0, self.before, load_per_thread())

    def of(self, quiet_seconds):
        return quiet_seconds * self.stretch()
