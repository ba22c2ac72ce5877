"""Matplotlib figures of stickslip's results, in the styles of the gnuplot
figures the apps draw (src/io/figure_style.cpp): stable solid, unstable
dashed; stick-slip blue, pure slip vermillion, steady sliding gray (Okabe-Ito);
special points black filled circles with their labels (GR1, HB1).

    import stickslip, stickslip.plot
    b = stickslip.continue_branch(stickslip.Params())
    b.plot(y="x_max")            # or stickslip.plot.branch(b, y="x_max")

Matplotlib (Debian python3-matplotlib) is imported when a figure is drawn.
"""
import math

import numpy as np

from . import _display

KIND_COLOR = {"stick-slip": "#0072b2", "pure-slip": "#d55e00", "equilibrium": "#606060"}
KIND_TITLE = {"stick-slip": "stick-slip", "pure-slip": "pure slip", "equilibrium": "steady sliding"}
LINE_WIDTH = 2.0
UNSTABLE_DASH = (0, (4, 3))  # gnuplot's dt 2
# Region and fate fills (figure_style.cpp kFill*, chart_script.cpp's bistable purple).
REGION_FILL = ["#d9d9d9", "#a6cee3", "#fdbf6f", "#d9b3ef"]  # Region codes 0..3
FATE_FILL = {"steady-sliding": "#d9d9d9", "stick-slip": "#a6cee3", "pure-slip": "#fdbf6f",
             "undecided": "#ffffff"}
# Chart curves (chart_script.cpp): HB black, GR red, LP green; subcritical or
# nonsmooth-fold points dashed.
CURVE_COLOR = {"HB": "black", "GR": "#c00000", "LP": "#009e73"}
DASHED_TYPES = ("subcritical", "nonsmooth fold")

SYMBOLS = {"beta": r"$\beta$", "v": r"$v$", "mu_s": r"$\mu_s$", "mu_m": r"$\mu_m$",
           "v_m": r"$v_m$", "mu_k": r"$\mu_k$", "v_s": r"$v_s$", "delta": r"$\delta$",
           "k5": r"$k_5$", "omega": r"$\Omega$", "force": r"$A$", "x_max": r"$x_{max}$",
           "x_min": r"$x_{min}$", "xdot_min": r"$\dot x_{min}$", "xdot_max": r"$\dot x_{max}$",
           "period": "period", "t_stick": "time in stick", "multiplier": "multiplier",
           "amplitude": "amplitude", "x": r"$x$", "xdot": r"$\dot x$", "x'": r"$\dot x$"}


def label(name):
    """An axis label: parameter and column names as symbols (beta -> β)."""
    return SYMBOLS.get(name, name)


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt
        _, ax = plt.subplots(figsize=(7, 4.8))
    return ax


def _threshold(kind):
    """The multiplier's stability threshold: |mu| = 1 for orbits, Re(lambda) = 0 at rest."""
    return (lambda m: m) if kind == "equilibrium" else (lambda m: abs(m) - 1.0)


def stability_runs(p, y, stable, kind=None, branch=None, multiplier=None, breaks=()):
    """Splits a branch's rows into runs of equal stability.

    Rows i and i + 1 belong to one curve when they have the same kind and
    branch number. Where stability changes between them, both runs end at
    one split point, so the line style changes at the stability change, not a
    row later: at a located special point's parameter value (`breaks`, values
    strictly between the two rows), else where the multiplier crosses its
    threshold (linear in the row index), else half-way. Returns a list of
    (p_values, y_values, stable, kind) with numpy arrays.
    """
    p, y = np.asarray(p, float), np.asarray(y, float)
    stable = np.asarray(stable, bool)
    n = len(p)
    kind = np.asarray(kind if kind is not None else ["?"] * n)
    branch = np.asarray(branch if branch is not None else np.zeros(n, int))
    runs = []
    start_p, start_y = [p[0]] if n else [], [y[0]] if n else []
    for i in range(n):
        last = i == n - 1
        same_curve = not last and kind[i + 1] == kind[i] and branch[i + 1] == branch[i]
        if same_curve and stable[i + 1] == stable[i]:
            start_p.append(p[i + 1]), start_y.append(y[i + 1])
            continue
        if same_curve:  # stability changes between rows i and i + 1
            t = _split(p[i], p[i + 1], i, multiplier, kind[i], breaks)
            ps, ys = p[i] + t * (p[i + 1] - p[i]), y[i] + t * (y[i + 1] - y[i])
            runs.append((np.array(start_p + [ps]), np.array(start_y + [ys]), bool(stable[i]),
                         str(kind[i])))
            start_p, start_y = [ps, p[i + 1]], [ys, y[i + 1]]
        else:
            runs.append((np.array(start_p), np.array(start_y), bool(stable[i]), str(kind[i])))
            start_p, start_y = ([p[i + 1]], [y[i + 1]]) if not last else ([], [])
    return runs


def _split(p0, p1, i, multiplier, kind, breaks):
    """Where in [0, 1] between rows i and i + 1 stability changes."""
    lo, hi = min(p0, p1), max(p0, p1)
    for b in breaks:
        if lo < b < hi:
            return (b - p0) / (p1 - p0)
    if multiplier is not None:
        f = _threshold(kind)
        m0, m1 = multiplier[i], multiplier[i + 1]
        if all(map(math.isfinite, (m0, m1))):
            g0, g1 = f(m0), f(m1)
            if g0 != g1 and g0 * g1 <= 0:
                return min(max(g0 / (g0 - g1), 0.0), 1.0)
    return 0.5


def branch(b, y="x_max", ax=None, labels=True, legend=True):
    """A bifurcation diagram of a Branch: column y against the parameter; stable
    solid, unstable dashed, colour by kind; special points marked and labelled
    (lab, e.g. GR1). Returns the Axes."""
    ax = _axes(ax)
    pts = b.points
    values = getattr(pts, y)
    runs = stability_runs(pts.p, values, pts.stable, pts.kind, pts.branch, pts.multiplier,
                          breaks=[s.p for s in b.special])
    seen = set()
    for ps, ys, st, kind in runs:
        if not np.isfinite(ys).any():
            continue  # e.g. the equilibrium's period
        key = (kind, st)
        ax.plot(ps, ys, color=KIND_COLOR.get(kind, "black"), lw=LINE_WIDTH,
                linestyle="-" if st else UNSTABLE_DASH,
                label=None if key in seen else "%s, %s" % (KIND_TITLE.get(kind, kind),
                                                           "stable" if st else "unstable"))
        seen.add(key)
    special_points(b, y, ax, labels)
    ax.set_xlabel(label(b.param))
    ax.set_ylabel(label(y))
    ax.grid(True, color="#e0e0e0", lw=0.5)
    if legend:
        ax.legend(loc="best", fontsize="small")
    return ax


def special_points(b, y, ax, labels=True):
    """The special points of a Branch on column y (where they have it): black dots, labelled."""
    xs, ys, labs = [], [], []
    for s in b.special:
        v = getattr(s, y, None)
        if v is None:  # a column the special points lack: the row it sits on
            v = getattr(b.points, y)[s.pt - 1] if s.pt >= 1 else float("nan")
        if math.isfinite(v):
            xs.append(s.p), ys.append(v), labs.append(s.lab)
    if xs:
        ax.plot(xs, ys, "o", color="black", ms=5, zorder=5, label="special points")
        if labels:
            for x, v, lab in zip(xs, ys, labs):
                ax.annotate(lab, (x, v), xytext=(4, 4), textcoords="offset points",
                            fontsize="small", zorder=6)
    return ax


def chart(c, ax=None, regions=True, legend=True):
    """A stability chart: regions filled (when computed), HB/GR/LP curves, codim-2 points."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch
    ax = _axes(ax)
    handles = []
    if regions and c.regions.size:
        codes = np.asarray(c.regions).T  # (n2, n1): rows are p2
        ax.pcolormesh(c.region_p1, c.region_p2, codes, cmap=ListedColormap(REGION_FILL),
                      vmin=-0.5, vmax=3.5, shading="nearest", rasterized=True)
        names = ["steady sliding only", "stick-slip", "pure-slip oscillation", "bistable"]
        handles += [Patch(color=REGION_FILL[k], label=names[k]) for k in sorted(set(codes.flat))]
    seen = set()
    for curve in c.curves:
        types = np.asarray(curve.type)
        dashed = np.isin(types, DASHED_TYPES)
        for flag in (False, True):
            p1 = np.where(dashed == flag, curve.p1, np.nan)
            p2 = np.where(dashed == flag, curve.p2, np.nan)
            if np.isnan(p1).all():
                continue
            key = (curve.label, flag)
            ax.plot(p1, p2, color=CURVE_COLOR.get(curve.label, "black"), lw=2.5,
                    linestyle=UNSTABLE_DASH if flag else "-",
                    label=None if key in seen else curve.label + (
                        " (subcritical / nonsmooth fold)" if flag else ""))
            seen.add(key)
    if c.codim2:
        ax.plot([q.p1 for q in c.codim2], [q.p2 for q in c.codim2], "o", color="black", ms=7,
                zorder=5, label="codimension two")
        for q in c.codim2:
            ax.annotate(q.label, (q.p1, q.p2), xytext=(5, 5), textcoords="offset points",
                        fontsize="small")
    ax.set_xlabel(label(c.param1))
    ax.set_ylabel(label(c.param2))
    if legend:
        h, _ = ax.get_legend_handles_labels()
        ax.legend(handles=handles + h, loc="best", fontsize="small")
    return ax


def basins(b, ax=None, legend=True):
    """Basins of attraction (a Basins): each start coloured by its fate."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch
    ax = _axes(ax)
    names = list(FATE_FILL)
    codes = np.array([names.index(str(f)) for f in b.fate]).reshape(b.ny, b.nx)
    ax.pcolormesh(np.asarray(b.x).reshape(b.ny, b.nx), np.asarray(b.xdot).reshape(b.ny, b.nx),
                  codes, cmap=ListedColormap(list(FATE_FILL.values())), vmin=-0.5,
                  vmax=len(names) - 0.5, shading="nearest", rasterized=True)
    ax.set_xlabel(label("x"))
    ax.set_ylabel(label("xdot"))
    if legend:
        present = sorted(set(codes.flat))
        ax.legend(handles=[Patch(color=FATE_FILL[names[k]], label=names[k]) for k in present],
                  loc="best", fontsize="small")
    return ax


def attractor_basins(b, ax=None):
    """basins(system)'s AttractorBasins: each start of the slice coloured by its
    attractor (gray: not run), each attractor's cycle marked and numbered."""
    ax = _axes(ax)
    u, w = np.asarray(b.u), np.asarray(b.w)
    nx = len(np.unique(u))
    ny = u.size // nx
    att = np.asarray(b.attractor).reshape(ny, nx)
    ax.set_facecolor("#d9d9d9")
    ax.pcolormesh(u.reshape(ny, nx), w.reshape(ny, nx), np.ma.masked_less(att, 0), cmap="tab10",
                  vmin=-0.5, vmax=9.5, shading="nearest", rasterized=True)
    i, j = (b.state_names.index(n) for n in b.slice)
    for k, a in enumerate(b.attractors):
        # a periodic attractor's m section points (its cycle), else its one point
        pts = np.asarray(a.cycle) if len(a.cycle) else np.asarray(a.z)[None, :]
        ax.plot(pts[:, i], pts[:, j], "o", color="black", ms=4)
        ax.annotate("%d: %s m=%d" % (k, a.kind, a.m), (a.z[i], a.z[j]), xytext=(4, 4),
                    textcoords="offset points", fontsize="small")
    ax.set_xlabel(label(b.slice[0]))
    ax.set_ylabel(label(b.slice[1]))
    return ax


def orbit_diagram(d, axis="omega", y="x", ax=None):
    """orbit_diagram()'s dict: the kept section points against the swept value,
    sweep up blue, down vermillion."""
    ax = _axes(ax)
    value, ys, direction = np.asarray(d["value"]), np.asarray(d[y]), np.asarray(d["direction"])
    for name, color in (("up", "#0072b2"), ("down", "#d55e00")):
        sel = direction == name
        if sel.any():
            ax.plot(value[sel], ys[sel], ".", ms=3.5 if name == "up" else 2, mew=0, color=color,
                    rasterized=True)
            ax.plot([], [], "o", ms=3, color=color, label="sweep " + name)
    ax.set_xlabel(label(axis))
    ax.set_ylabel(label(y) + " at the section")
    ax.legend(loc="best", fontsize="small")
    return ax


def _special_value(b, q, y):
    """Column y of orbit_columns() at a SpecialOrbit q of the OrbitBranch b."""
    for i, n in enumerate(_display.state_columns(b)):
        if y == n + "0":
            return q.state[i]
        if y in (n + "_min", n + "_max") and i < len(q.hi):
            return (q.lo if y.endswith("_min") else q.hi)[i]
    if y == "mult_max":
        return np.abs(q.multipliers).max() if len(q.multipliers) else math.nan
    return getattr(q, y, math.nan)


def orbit_branch(b, y=None, ax=None, labels=True):
    """An OrbitBranch (continue_branch, continue_doubled; e.g. a resonance
    curve): column y of orbit_columns() (default the first component's
    greatest value, x_max or x1_max: b.hi[:, 0]) against the parameter,
    stable solid, unstable dashed, special points labelled (PD1)."""
    ax = _axes(ax)
    cols = _display.orbit_columns(b)
    if y is None:
        y = _display.state_columns(b)[0] + "_max"
    if y not in cols:
        raise KeyError("y = %r: an OrbitBranch has the columns %s" % (y, ", ".join(cols)))
    runs = stability_runs(b.p, cols[y], b.stable, None, None, cols["mult_max"],
                          breaks=[q.p for q in b.special_points])
    seen = set()
    for ps, ys, st, _ in runs:
        ax.plot(ps, ys, color=KIND_COLOR["stick-slip"], lw=LINE_WIDTH,
                linestyle="-" if st else UNSTABLE_DASH,
                label=None if st in seen else ("stable" if st else "unstable"))
        seen.add(st)
    pts = [(q.p, _special_value(b, q, y), q.lab) for q in b.special_points]
    if pts:
        ax.plot([q[0] for q in pts], [q[1] for q in pts], "o", color="black", ms=5, zorder=5)
        if labels:
            for x, v, lab in pts:
                ax.annotate(lab, (x, v), xytext=(4, 4), textcoords="offset points",
                            fontsize="small")
    ax.set_xlabel(label(b.parameter))
    ax.set_ylabel(label(y))
    ax.legend(loc="best", fontsize="small")
    return ax


def install(core):
    """b.plot(...) on Branch, Chart, Basins, AttractorBasins and OrbitBranch."""
    core.Branch.plot = branch
    core.Chart.plot = chart
    core.Basins.plot = basins
    core.AttractorBasins.plot = attractor_basins
    core.OrbitBranch.plot = orbit_branch
