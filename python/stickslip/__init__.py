"""Continuation and bifurcation of the stick-slip belt model (seed eq. 3.5).

The compiled part is stickslip._core; everything public is re-exported here.
Results are typed objects whose arrays are read-only NumPy arrays;
result["name"] still reads result.name, as the dicts of earlier versions did.
"""
import sys as _sys

try:
    import numpy as _numpy  # noqa: F401  (the module's arrays need it)
except ImportError as _e:  # pragma: no cover - depends on the interpreter
    raise ImportError(
        "stickslip needs NumPy, which this interpreter (%s) does not have. Use the "
        "Python the module was built for (Debian: /usr/bin/python3 with python3-numpy)"
        % _sys.executable) from _e

from . import _core  # noqa: E402
from ._core import *  # noqa: F401,F403
from ._core import __doc__ as _core_doc  # noqa: F401
from ._core import __version__, git_commit  # noqa: F401
from ._sweep import (SweepError, SweepResult, forced_orbits, group_stats,  # noqa: F401
                     read_sweep, stick_slip_orbit, stick_slip_orbits, sweep)
from ._system_orbits import system_orbits  # noqa: F401
from . import _display as _display_module, plot  # noqa: E402
from ._physical import continue_physical  # noqa: E402,F401

_display_module.install()  # reprs, _repr_html_, to_pandas, to_tsv, save, restart
plot.install(_core)  # Branch.plot, Chart.plot, Basins.plot, AttractorBasins.plot, OrbitBranch.plot
