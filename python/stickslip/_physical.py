"""continue_physical(): a branch from physical inputs over a physical range, as
ss_continue --mass ... --param belt_speed --from ... --to ... (m/s)."""
import math

from . import _core

# The physical axes of a branch and their dimensionless parameters (seed section 3):
# v = V t0 / L, beta = C / (2 sqrt(K M)).
_AXES = {"belt_speed": "v", "damping": "beta"}


def continue_physical(law="cubic", param="belt_speed", from_=None, to=None, progress=None,
                      **inputs):
    """The branch in belt_speed [m/s] or damping [N s/m] from physical inputs
    (mass, stiffness, damping, belt_speed, gravity=9.81, mu_s, ...: as
    Params.from_physical), from_ to `to` in the same unit (default: the
    dimensionless parameter's default_range). The Branch is dimensionless;
    b.to_pandas(mass=M, stiffness=K) adds the physical columns."""
    if param not in _AXES:
        raise ValueError("param = %r: a physical branch runs in %s" % (param, " or ".join(_AXES)))
    p = _core.Params.from_physical(law, **inputs)
    mass, stiffness = inputs["mass"], inputs["stiffness"]
    L, t0 = _core.scales(mass, stiffness, inputs.get("gravity", 9.81))
    factor = t0 / L if param == "belt_speed" else 1 / (2 * math.sqrt(stiffness * mass))
    name = _AXES[param]
    lo, hi = _core.default_range(p, name)
    return _core.continue_branch(p, name, from_=lo if from_ is None else from_ * factor,
                                 to=hi if to is None else to * factor, progress=progress)
