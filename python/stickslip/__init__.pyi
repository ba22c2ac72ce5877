# Type stub of the stickslip package (the compiled stickslip._core),
# written by hand; python/tests/test_api.py checks its names against the module.
import enum
from typing import (Any, Callable, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union,
                    overload)

import numpy as np
import numpy.typing as npt

__version__: str
plot: Any  # the module stickslip.plot: Matplotlib figures
git_commit: str

class Error(RuntimeError): ...
class InvalidArgument(ValueError): ...
class NumericalError(Error): ...

class Law(enum.IntEnum):
    cubic = 0
    coulomb = 1
    stribeck = 2
    leine = 3
class Integrator(enum.IntEnum):
    taylor = 0
    cvode = 1
class Method(enum.IntEnum):
    adams = 0
    bdf = 1
class Mode(enum.IntEnum):
    slip_below = 0
    stick = 1
    slip_above = 2
class FlowStatus(enum.IntEnum):
    time_limit = 0
    stick = 1
    section = 2
    velocity_max = 3
    integrator_failed = 4
    too_many_switches = 5
    cancelled = 6
    stick_exit = 7
    too_much_work = 8
    inconsistent_mode = 9
    ambiguous_mode = 10
    too_many_at_once = 11
    contact_open = 12
class OrbitKind(enum.IntEnum):
    stick_slip = 0
    pure_slip = 1
class OrbitStatus(enum.IntEnum):
    ok = 0
    no_return = 1
    integrator_failed = 2
    sticks = 3
    not_converged = 4
    collapsed = 5
    missed = 6
    cancelled = 7
    singular = 8
    aperiodic = 9
    contact_open = 10
    mode_changed = 11
class PointKind(enum.IntEnum):
    stick_slip = 0
    pure_slip = 1
    equilibrium = 2
class SpecialKind(enum.IntEnum):
    grazing = 0
    hopf = 1
    fold = 2
    period_doubling = 3
    torus = 4
    sliding = 5
    adding = 6
    crossing = 7
    contact_loss = 8
    none = 9
class ContinuationStatus(enum.IntEnum):
    ok = 0
    failed = 1
    cancelled = 2
class CurveKind(enum.IntEnum):
    hopf = 0
    grazing = 1
    fold = 2
    period_doubling = 3
    torus = 4
class ChartStatus(enum.IntEnum):
    ok = 0
    failed = 1
    partial = 2
    cancelled = 3
class Region(enum.IntEnum):
    steady_only = 0
    stick_slip = 1
    pure_slip = 2
    bistable = 3
class Fate(enum.IntEnum):
    steady_sliding = 0
    stick_slip = 1
    pure_slip = 2
    undecided = 3
class OrbitScanStatus(enum.IntEnum):
    ok = 0
    failed = 1
    cancelled = 2
class BasinStatus(enum.IntEnum):
    ok = 0
    failed = 1
    cancelled = 2
class Parameter(enum.IntEnum):
    """A parameter of the oscillators (the one lens); functions take a member or its name."""
    beta = 0
    v = 1
    mu_s = 2
    mu_m = 3
    v_m = 4
    mu_k = 5
    v_s = 6
    delta = 7
    k5 = 8
    force = 9
    omega = 10
class SimulationSection(enum.IntEnum):
    strobe = 0
    exit = 1
    none = 2
class BranchStatus(enum.IntEnum):
    reached_end = 0
    unbounded = 1
    step_too_small = 2
    start_failed = 3
    max_points = 4
    closed = 5
    cancelled = 6
    left_range = 7
    contact_lost = 8
    sequence_ended = 9

LawLike = Union[str, Law]
IntegratorLike = Union[str, Integrator, None]
MethodLike = Union[str, Method, None]
Array = npt.NDArray[Any]  # read-only

class Params:
    law: str
    beta: float
    v: float
    mu_s: float
    mu_m: float
    v_m: float
    mu_k: float
    v_s: float
    delta: float
    k5: float
    def __init__(self, law: LawLike = "cubic", **values: float) -> None: ...
    @staticmethod
    def from_physical(law: LawLike = "cubic", **inputs: float) -> Params: ...
    @property
    def k1(self) -> float: ...
    @property
    def k3(self) -> float: ...
    def validation_error(self) -> str: ...
    def validate(self) -> None: ...
    def to_dict(self) -> Dict[str, Union[str, float]]: ...

class FlowOptions:
    rtol: float
    atol: float
    integrator: Integrator
    method: Method
    max_steps: int
    max_switches: int
    def __init__(self) -> None: ...
    def validation_error(self) -> str: ...
class OrbitOptions:
    flow: FlowOptions
    floquet: bool
    max_return_time: float
    max_newton: int
    newton_tol: float
    def __init__(self) -> None: ...
    def validation_error(self) -> str: ...
class ContinuationOptions:
    param: str
    from_: float
    to: float
    orbit: OrbitOptions
    max_step: float
    min_step: float
    locate_tol: float
    max_points: int
    stick_slip_floquet: bool
    def __init__(self) -> None: ...
    def validation_error(self, params: Params) -> str: ...
class Plane:
    p1: str
    p2: str
    from1: float
    to1: float
    from2: float
    to2: float
    def __init__(self) -> None: ...
    def validation_error(self, params: Params) -> str: ...
class ChartOptions:
    plane: Plane
    orbit: OrbitOptions
    max_step: float
    samples: int
    hopf_curves: bool
    grazing_curves: bool
    fold_curves: bool
    region_n1: int
    region_n2: int
    def __init__(self) -> None: ...
    def validation_error(self, params: Params) -> str: ...
class OrbitScanOptions:
    orbit: OrbitOptions
    samples: int
    a_min: float
    def __init__(self) -> None: ...
    def validation_error(self) -> str: ...
class BasinOptions:
    scan: OrbitScanOptions
    auto_range: bool
    x_lo: float
    x_hi: float
    xdot_lo: float
    xdot_hi: float
    nx: int
    ny: int
    t_cap: float
    settle: float
    def __init__(self) -> None: ...
    def validation_error(self) -> str: ...

class ForcedBeltParams:
    """x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t) (issue 20)."""
    params: Params
    force: float
    omega: float
    def __init__(self, params: Params, force: float = 0.0, omega: float = 1.0) -> None: ...
    def validation_error(self) -> str: ...


class OrbitBranch:
    status: BranchStatus
    message: str
    parameter: str
    p: Array
    state: Array
    period: Array
    sticks: Array
    exits: Array
    crossings: Array
    lo: Array
    hi: Array
    multipliers: Array
    stable: Array
    label: Array
    state_names: List[str]
    special: List[Tuple[str, float, str]]
    special_points: List[SpecialOrbit]
    jumps: int
    evaluations: int
    seconds: float
    def to_pandas(self) -> Any: ...
    def to_tsv(self, path: Any) -> None: ...
    def plot(self, y: Optional[str] = None, ax: Any = None, labels: bool = True) -> Any: ...


class SpecialOrbit:
    label: str
    lab: str
    description: str
    parameter: str
    p: float
    state: Array
    period: float
    sticks: int
    exits: int
    crossings: int
    lo: Array
    hi: Array
    multipliers: Array
    stable: bool
    section: str
    m: int
    turns: int
    contact: int
    run_from: float
    run_to: float
    system: Any

class Trajectory:
    t: Array
    x: Array
    xdot: Array
    mode: Array
    status: FlowStatus
    t_stick: float
    switches: int
    crossings: int
    x_min: float
    x_max: float
    xdot_min: float
    xdot_max: float
    def __getitem__(self, key: str) -> Any: ...
    def to_pandas(self) -> Any: ...
    def to_tsv(self, path: Any) -> None: ...
class Equilibrium:
    x: float
    damping: float
    lambda1: complex
    lambda2: complex
    max_real: float
    stable: bool
    def __getitem__(self, key: str) -> Any: ...
class Orbit:
    kind: OrbitKind
    period: float
    t_stick: float
    x_min: float
    x_max: float
    xdot_min: float
    xdot_max: float
    start: Array
    modes: List[Mode]
    crossings: int
    has_floquet: bool
    monodromy: Array
    eigenvalues: Tuple[complex, complex]
    multiplier: float
    stable: bool
    newton_stalled: bool
    def __getitem__(self, key: str) -> Any: ...
class PeriodicOrbits:
    status: OrbitScanStatus
    message: str
    steady: Equilibrium
    stick_slip: Optional[Orbit]
    pure_slip: List[Orbit]
    a_stick: float
    a_max: float
    returns: int
    def __getitem__(self, key: str) -> Any: ...
class Disturbance:
    x: float
    xdot: float
    energy: float
    def __getitem__(self, key: str) -> Any: ...
class BranchPoints:
    p: Array
    kind: Array
    branch: Array
    period: Array
    x_min: Array
    x_max: Array
    xdot_min: Array
    xdot_max: Array
    t_stick: Array
    multiplier: Array
    stable: Array
    amplitude: Array
    newton_stalled: Array
    pt: Array
    x_start: Array
    xdot_start: Array
    def keys(self) -> List[str]: ...
    def to_pandas(self) -> Any: ...
    def items(self) -> List[Tuple[str, Array]]: ...
    def __len__(self) -> int: ...
    def __getitem__(self, key: str) -> Array: ...
class SpecialPoint:
    kind: SpecialKind
    label: str
    lab: str
    pt: int
    p: float
    period: float
    x_min: float
    x_max: float
    xdot_min: float
    multiplier_before: float
    multiplier_after: float
    x_start: float
    xdot_start: float
    description: str
    def __getitem__(self, key: str) -> Any: ...
class ContinuationCounts:
    orbit_solves: int
    return_maps: int
    newton_iterations: int
    rejected_steps: int
    integrator_steps: int
    def __getitem__(self, key: str) -> Any: ...
class ContinuationTimes:
    equilibrium: float
    stick_slip: float
    pure_slip: float
    switching: float
    discovery: float
    total: float
    def __getitem__(self, key: str) -> Any: ...
class Branch:
    param: str
    status: ContinuationStatus
    message: str
    warnings: List[str]
    points: BranchPoints
    special: List[SpecialPoint]
    counts: ContinuationCounts
    seconds: ContinuationTimes
    params: Params
    options: ContinuationOptions
    partial: bool
    def __getitem__(self, key: str) -> Any: ...
    def tables(self, command: str = ...) -> Dict[str, str]: ...
    def to_pandas(self, mass: Optional[float] = None, stiffness: Optional[float] = None,
                  gravity: float = 9.81) -> Any: ...
    def special_to_pandas(self) -> Any: ...
    def to_tsv(self, path: Any, command: Optional[str] = None) -> None: ...
    def save(self, directory: Any, command: Optional[str] = None) -> str: ...
    def restart(self, point: Union[str, int]) -> LabelledPoint: ...
    def plot(self, y: str = "x_max", ax: Any = None, labels: bool = True,
             legend: bool = True) -> Any: ...
class ChartCurve:
    kind: CurveKind
    label: str
    param1: str
    param2: str
    p1: Array
    p2: Array
    period: Array
    amplitude: Array
    multiplier: Array
    l1: Array
    type: Array
    unphysical: Array
    ends: str
    seconds: float
    evaluations: int
    def __getitem__(self, key: str) -> Any: ...
class ChartPoint:
    label: str
    param1: str
    param2: str
    p1: float
    p2: float
    description: str
    def __getitem__(self, key: str) -> Any: ...
class Chart:
    status: ChartStatus
    message: str
    param1: str
    param2: str
    curves: List[ChartCurve]
    codim2: List[ChartPoint]
    region_p1: Array
    region_p2: Array
    regions: Array
    unphysical_points: int
    seconds: float
    def __getitem__(self, key: str) -> Any: ...
    def to_pandas(self) -> Any: ...
    def to_tsv(self, path: Any) -> None: ...
    def plot(self, ax: Any = None, regions: bool = True, legend: bool = True) -> Any: ...
class Basins:
    status: BasinStatus
    message: str
    orbits: PeriodicOrbits
    x_lo: float
    x_hi: float
    xdot_lo: float
    xdot_hi: float
    nx: int
    ny: int
    x: Array
    xdot: Array
    fate: Array
    orbit: Array
    t_settle: Array
    counts: Dict[Fate, int]
    def __getitem__(self, key: str) -> Any: ...
    def to_pandas(self) -> Any: ...
    def to_tsv(self, path: Any) -> None: ...
    def plot(self, ax: Any = None, legend: bool = True) -> Any: ...
class LabelledPoint:
    label: str
    pt: int
    type: str
    param: str
    p: float
    params: Params
    flow: FlowOptions
    state: Tuple[float, float]
    period: Optional[float]
    forced: bool
    force: float
    omega: float
    m: int
    def forced_params(self) -> ForcedBeltParams: ...
    def options(self, param: Optional[Parameter | str] = None,
                to: Optional[float] = None) -> ContinuationOptions: ...
    def chart_options(self, param2: Parameter | str = "beta", from_: float = 0.05, to: float = 0.6,
                      from2: float = 0.0, to2: float = 0.25) -> ChartOptions: ...

def parameter_names(law: LawLike = "cubic") -> List[str]: ...
def default_range(params: Params, name: Parameter | str) -> Tuple[float, float]: ...
def scales(mass: float, stiffness: float, gravity: float = 9.81) -> Tuple[float, float]: ...
@overload
def simulate(params: Params, x0: float = 0.0, xdot0: float = 0.25, t_end: float = 100.0,
             dt: float = 0.01, max_rows: int = 1000000, rtol: Optional[float] = None,
             atol: Optional[float] = None, integrator: IntegratorLike = None,
             method: MethodLike = None) -> Trajectory: ...
@overload
def simulate(system: SystemLike, state: Any, t_end: float = 100.0, dt: float = 0.01,
             max_rows: int = 1000000, rtol: Optional[float] = None, atol: Optional[float] = None,
             section: SimulationSection = SimulationSection.none,
             period: Optional[float] = None) -> SystemTrajectory: ...
def continue_orbits(system: SystemLike, parameter: Parameter | str, state: Any, to: float,
                    section: Optional[str] = None, m: int = 1, turns: Optional[int] = None,
                    max_amplitude: float = 1e3, max_step: Optional[float] = None,
                    rtol: Optional[float] = None, atol: Optional[float] = None,
                    contact: int = 0) -> OrbitBranch: ...
def continue_doubled(point: SpecialOrbit, lo: Optional[float] = None,
                     hi: Optional[float] = None, max_amplitude: float = 1e3,
                     max_step: Optional[float] = None, rtol: Optional[float] = None,
                     atol: Optional[float] = None) -> OrbitBranch: ...
def stroboscopic(params: ForcedBeltParams, x0: float = 0.0, xdot0: Optional[float] = None,
                 transient: Optional[int] = None, keep: Optional[int] = None,
                 max_amplitude: float = 1e6, rtol: Optional[float] = None,
                 atol: Optional[float] = None) -> Dict[str, Any]: ...
@overload
def orbit_diagram(params: ForcedBeltParams, axis: Parameter | str, from_: float, to: float, n: int = 200,
                  transient: Optional[int] = None, keep: Optional[int] = None, up: bool = True,
                  down: bool = True, chunks: int = 1, max_amplitude: float = 50.0,
                  rtol: Optional[float] = None,
                  atol: Optional[float] = None) -> Dict[str, Any]: ...
@overload
def orbit_diagram(system: Union[ChainParams, CouplingParams], parameter: str, from_: float,
                  to: float, n: int = 200, transient: Optional[int] = None,
                  keep: Optional[int] = None, up: bool = True, down: bool = True, chunks: int = 1,
                  max_amplitude: float = 50.0, rtol: Optional[float] = None,
                  atol: Optional[float] = None) -> Dict[str, Any]: ...
@overload
def periodic_orbit(params: Params, a_guess: Optional[float] = None, floquet: bool = False,
                   rtol: Optional[float] = None, atol: Optional[float] = None,
                   integrator: IntegratorLike = None, method: MethodLike = None) -> Orbit: ...
@overload
def periodic_orbit(system: SystemLike, state: Any, section: Optional[str] = None, m: int = 1,
                   turns: Optional[int] = None, rtol: Optional[float] = None,
                   atol: Optional[float] = None, contact: int = 0) -> SystemOrbit: ...
@overload
def continue_branch(params: Params, param: Optional[Parameter | str] = None, from_: Optional[float] = None,
                    to: Optional[float] = None, max_step: Optional[float] = None,
                    floquet: Optional[bool] = None, rtol: Optional[float] = None,
                    atol: Optional[float] = None, integrator: IntegratorLike = None,
                    method: MethodLike = None,
                    options: Optional[ContinuationOptions] = None,
                    progress: Optional[Callable[[int, float, str, bool], Any]] = None
                    ) -> Branch: ...
@overload
def continue_branch(system: SystemLike, parameter: Parameter | str, state: Any, to: float,
                    section: Optional[str] = None, m: int = 1, turns: Optional[int] = None,
                    max_amplitude: float = 1e3, max_step: Optional[float] = None,
                    rtol: Optional[float] = None, atol: Optional[float] = None,
                    contact: int = 0) -> OrbitBranch: ...
def continue_physical(law: LawLike = "cubic", param: str = "belt_speed",
                      from_: Optional[float] = None, to: Optional[float] = None,
                      progress: Optional[Callable[[int, float, str, bool], Any]] = None,
                      **inputs: float) -> Branch: ...
@overload
def orbits(params: Params, columns: Mapping[str, npt.ArrayLike], threads: int = 0,
           floquet: bool = False, rtol: Optional[float] = None, atol: Optional[float] = None,
           integrator: IntegratorLike = None,
           method: MethodLike = None) -> Dict[str, npt.NDArray[Any]]: ...
@overload
def orbits(params: ForcedBeltParams, columns: Mapping[str, npt.ArrayLike], threads: int = 0,
           x0: float = 0.0, xdot0: float = 0.0, transient: int = 20, max_m: int = 4,
           recurrence: float = 1e-3, rtol: Optional[float] = None, atol: Optional[float] = None,
           integrator: IntegratorLike = None,
           method: MethodLike = None) -> Dict[str, npt.NDArray[Any]]: ...
@overload
def orbits(system: Union[ChainParams, CouplingParams, System], columns: Mapping[str, npt.ArrayLike],
           threads: int = 0, state: Optional[npt.ArrayLike] = None,
           transient: Optional[float] = None, max_m: Optional[int] = None,
           recurrence: float = 1e-3, rtol: Optional[float] = None,
           atol: Optional[float] = None) -> Dict[str, npt.NDArray[Any]]: ...
@overload
def periodic_orbits(system: Union[ForcedBeltParams, ChainParams, CouplingParams, System],
                    max_m: Optional[int] = None, max_sticks: Optional[int] = None,
                    grid: Optional[int] = None, exit_samples: Optional[int] = None,
                    radius: Optional[float] = None, rtol: Optional[float] = None,
                    atol: Optional[float] = None, amplitudes: Optional[Sequence[float]] = None,
                    transient: Optional[float] = None,
                    starts: Optional[Sequence[npt.ArrayLike]] = None,
                    max_returns: Optional[int] = None,
                    scale: Optional[float] = None) -> List[SystemOrbit]: ...
@overload
def periodic_orbits(params: Params, samples: Optional[int] = None, rtol: Optional[float] = None,
                    atol: Optional[float] = None, integrator: IntegratorLike = None,
                    method: MethodLike = None,
                    options: Optional[OrbitScanOptions] = None) -> PeriodicOrbits: ...
@overload
def basins(params: Params, nx: Optional[int] = None, ny: Optional[int] = None,
           x_range: Optional[Tuple[float, float]] = None,
           xdot_range: Optional[Tuple[float, float]] = None, t_cap: Optional[float] = None,
           rtol: Optional[float] = None, atol: Optional[float] = None,
           integrator: IntegratorLike = None, method: MethodLike = None,
           options: Optional[BasinOptions] = None,
           progress: Optional[Callable[[int, int], Any]] = None) -> Basins: ...
@overload
def basins(system: Union[ForcedBeltParams, ChainParams, CouplingParams, System], nx: int = 41,
           ny: int = 41,
           slice: Optional[Tuple[str, str]] = None, base: Optional[Any] = None,
           x_range: Optional[Tuple[float, float]] = None,
           y_range: Optional[Tuple[float, float]] = None, transient: Optional[int] = None,
           keep: Optional[int] = None, max_period: Optional[int] = None, threads: int = 2,
           rtol: Optional[float] = None, atol: Optional[float] = None) -> AttractorBasins: ...
def orbit_curve(params: Params, orbit: Orbit, n: int = 400) -> Array: ...
def smallest_disturbance(params: Params, orbit: Orbit, n: int = 4000) -> Disturbance: ...
@overload
def chart(params: Params, param: Optional[Parameter | str] = None, from_: Optional[float] = None,
          to: Optional[float] = None, param2: Optional[Parameter | str] = None,
          from2: Optional[float] = None, to2: Optional[float] = None,
          max_step: Optional[float] = None, regions: Optional[Tuple[int, int]] = None,
          rtol: Optional[float] = None, atol: Optional[float] = None,
          integrator: IntegratorLike = None, method: MethodLike = None,
          options: Optional[ChartOptions] = None) -> Chart: ...
@overload
def chart(system: Union[ForcedBeltParams, ChainParams, CouplingParams], param: str, from_: float,
          to: float,
          param2: str, from2: float, to2: float, seed_lines: int = 3, max_step: float = 0.01,
          hopf: bool = True, orbits: bool = True, max_m: int = 2, rtol: Optional[float] = None,
          atol: Optional[float] = None, grid: int = 0) -> SystemChart: ...
def restart(dir: str, point: Union[str, int]) -> LabelledPoint: ...

# Sweeps (stickslip._sweep): grid x sample on Dask, serially, or on a cluster.
class SweepError(RuntimeError): ...
class SweepResult:
    columns: List[str]
    data: Array
    meta: Dict[str, Any]
    def __getitem__(self, name: str) -> Array: ...
    def __len__(self) -> int: ...
    def to_tsv(self, path: str) -> None: ...
    def to_hdf5(self, path: str) -> None: ...
def read_sweep(path: str) -> SweepResult: ...
def sweep(fn: Union[Callable[[Dict[str, float]], Dict[str, float]],
                    Callable[[Dict[str, Array]], Dict[str, npt.ArrayLike]]],
          grid: Optional[Mapping[str, Sequence[float]]] = None,
          sample: Optional[Mapping[str, Sequence[float]]] = None, *,
          scheduler: Optional[str] = None, n_workers: int = 2, chunk_size: Optional[int] = None,
          meta: Optional[Mapping[str, Any]] = None, timeout: Optional[float] = None,
          worker_timeout: float = 60.0, batch: Optional[bool] = None, out: Optional[str] = None,
          progress: Union[None, bool, Callable[[int, int, float], Any]] = None) -> SweepResult: ...
def group_stats(result: SweepResult, by: str, value: str,
                quantiles: Sequence[float] = (0.05, 0.5, 0.95),
                where: Optional[str] = None) -> Dict[str, Array]: ...
def stick_slip_orbit(point: Mapping[str, float]) -> Dict[str, float]: ...
def stick_slip_orbits(columns: Mapping[str, Array]) -> Dict[str, Array]: ...
def forced_orbits(columns: Mapping[str, Array]) -> Dict[str, Array]: ...
class system_orbits:
    batch: bool
    def __init__(self, system: Any, **options: Any) -> None: ...
    def __call__(self, columns: Mapping[str, Array]) -> Dict[str, Array]: ...

# The several-mass systems (issue 32): python/py_systems.cpp, py_system_runs.cpp.
class ChainBlock:
    m: float
    c: float
    k: float
    law: Params
    def __init__(self, m: float = 1.0, c: float = 0.1, k: float = 1.0,
                 law: Optional[Params] = None) -> None: ...

class ChainParams:
    v: float
    kc: float
    blocks: List[ChainBlock]
    @property
    def n(self) -> int: ...
    @property
    def parameters(self) -> List[str]: ...
    @property
    def state_names(self) -> List[str]: ...
    def __init__(self, blocks: Union[int, Sequence[ChainBlock]] = 2, law: Optional[Params] = None,
                 kc: Optional[float] = None, v: Optional[float] = None) -> None: ...
    def validate(self) -> None: ...

class CouplingParams:
    beta: float
    k11: float
    k22: float
    k12: float
    gamma: float
    v: float
    law: Params
    @property
    def flutter_mu_k(self) -> float: ...
    @property
    def parameters(self) -> List[str]: ...
    @property
    def state_names(self) -> List[str]: ...
    def __init__(self, beta: float = 0.02, k11: float = 1.0, k22: float = 1.5, k12: float = -0.3,
                 gamma: float = 1.0, v: float = 0.5, law: Optional[Params] = None) -> None: ...
    def validate(self) -> None: ...

class System:
    @staticmethod
    def from_file(path: str) -> System: ...
    @staticmethod
    def from_text(text: str, source: str = "<text>") -> System: ...
    @property
    def name(self) -> str: ...
    @property
    def dimension(self) -> int: ...
    @property
    def contacts(self) -> int: ...
    @property
    def state_names(self) -> List[str]: ...
    @property
    def parameters(self) -> Dict[str, float]: ...
    def copy(self) -> System: ...
    def __getitem__(self, name: str) -> float: ...
    def __setitem__(self, name: str, value: float) -> None: ...

SystemLike = Union[Params, ForcedBeltParams, ChainParams, CouplingParams, System]

class SystemTrajectory:
    t: Array
    z: Array
    mode: Array
    section: SimulationSection
    section_t: Array
    section_z: Array
    names: List[str]
    status: FlowStatus
    message: str
    opened: int
    sticks: int
    exits: int
    crossings: int
    t_stick: float

class SystemOrbit:
    status: OrbitStatus
    message: str
    start: Array
    mode: str
    period: float
    monodromy: Array
    multipliers: Array
    stable: bool
    sticks: int
    exits: int
    crossings: int
    modes: List[str]
    lo: Array
    hi: Array
    iterations: int
    update: float
    points: Array
    turns: int
    from_exit_map: bool
    contact: int
    returns: int
    contact_sticks: List[int]
    origin: Array
    origin_mode: int
    origin_imaginary: bool
    origin_amplitude: float

class SteadyState:
    found: bool
    z: Array
    eigenvalues: Array
    max_real: float
    stable: bool

def simulate_system(system: SystemLike, state: Any, t_end: float = 100.0, dt: float = 0.01,
                    max_rows: int = 1000000, rtol: Optional[float] = None,
                    atol: Optional[float] = None,
                    section: SimulationSection = SimulationSection.none,
                    period: Optional[float] = None) -> SystemTrajectory: ...
def system_orbit(system: SystemLike, state: Any, section: Optional[str] = None, m: int = 1,
                 turns: Optional[int] = None, rtol: Optional[float] = None,
                 atol: Optional[float] = None, contact: int = 0) -> SystemOrbit: ...
def steady_sliding(system: SystemLike) -> SteadyState: ...

class Attractor:
    kind: str
    label: str
    m: int
    sticks: int
    sticks_per_period: float
    lyapunov: float
    starts: int
    z: Array
    cycle: Array

class SystemCurve:
    kind: str
    m: int
    gap: bool
    seed: str
    ends: str
    p1: Array
    p2: Array
    period: Array
    sticks: Array
    crossings: Array
    lo: Array
    hi: Array
    mult_max: Array
    test: Array
    evaluations: int
    seconds: float

class SystemCodim2:
    label: str
    on: str
    curve: int
    p1: float
    p2: float
    description: str
    located: str

class ResponseGrid:
    p1: Array
    p2: Array
    kind: Array
    m: Array
    sticks: Array
    lyapunov: Array
    failed: int
    failure: str
    seconds: float

class SystemChart:
    param: str
    param2: str
    state_names: List[str]
    curves: List[SystemCurve]
    codim2: List[SystemCodim2]
    status: str
    message: str
    seed_runs: int
    failed_seed_runs: int
    seeds_not_traced: int
    cut_curves: int
    duplicates: int
    seconds: float
    response: Optional[ResponseGrid]

class AttractorBasins:
    slice: List[str]
    state_names: List[str]
    u: Array
    w: Array
    attractor: Array
    lyapunov: Array
    attractors: List[Attractor]
    failures: List[str]
    failed: int
    seconds: float
    def plot(self, ax: Any = None) -> Any: ...

def attractor_basins(system: SystemLike, nx: int = 41, ny: int = 41,
                     slice: Optional[Tuple[str, str]] = None, base: Optional[Any] = None,
                     x_range: Optional[Tuple[float, float]] = None,
                     y_range: Optional[Tuple[float, float]] = None,
                     transient: Optional[int] = None, keep: Optional[int] = None,
                     max_period: Optional[int] = None, threads: int = 2,
                     rtol: Optional[float] = None,
                     atol: Optional[float] = None) -> AttractorBasins: ...

class SteadyBranch:
    status: BranchStatus
    message: str
    parameter: str
    p: Array
    z: Array
    max_real: Array
    stable: Array
    label: Array
    special: List[Tuple[str, float, str]]

class SettledOrbit:
    found: bool
    message: str
    contact: int
    returns: int
    turns: int
    stick_exits: int
    start: Array
    period: float
    multipliers: Array
    stable: bool
    sticks: int

def steady_branch(system: SystemLike, parameter: str, to: float,
                  points: int = 101) -> SteadyBranch: ...
def settle(system: SystemLike, state: Any, transient: float = 3000.0, max_returns: int = 32,
           rtol: Optional[float] = None, atol: Optional[float] = None) -> SettledOrbit: ...
