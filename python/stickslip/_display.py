"""Results that show themselves: short reprs, HTML tables for notebooks,
to_pandas() and to_tsv() for the result classes of stickslip._core.

Installed on the classes by install(); pandas is imported only when to_pandas()
is called (Debian python3-pandas).
"""
import html
import os
import tempfile

import numpy as np

from . import _core


def _name(x):
    """An enum's or any value's short text."""
    return str(x).split(".")[-1] if hasattr(x, "__members__") or type(x).__module__.startswith(
        "stickslip") else str(x)


def _num(x):
    """A number as TSV text: the shortest round-trip form, as the apps write it;
    NaN (does not apply) an empty cell. ValueError for inf: never written."""
    if isinstance(x, float) or hasattr(x, "dtype") and x.dtype.kind == "f":
        v = float(x)
        if v != v:
            return ""
        if v in (float("inf"), float("-inf")):
            raise ValueError("%r is not a finite number" % v)
        return repr(v)
    if isinstance(x, (bool,)) or hasattr(x, "dtype") and x.dtype.kind == "b":
        return "1" if x else "0"
    return str(x)


def _finite_or_text(x):
    """x, or None for a number _num refuses."""
    try:
        _num(x)
        return x
    except ValueError:
        return None


def _status(r):
    s = _name(r.status)
    return s + (": " + r.message if getattr(r, "message", "") else "")


def _specials(branch):
    return ["%s %s=%.6g pt=%d" % (s.lab, branch.param, s.p, s.pt) for s in branch.special]


def _html(title, rows, table=None):
    """A small HTML block: a title, key/value lines, an optional table."""
    out = ["<div><b>%s</b><table>" % html.escape(title)]
    for k, v in rows:
        out.append("<tr><th style='text-align:left'>%s</th><td style='text-align:left'>%s</td>"
                   "</tr>" % (html.escape(str(k)), html.escape(str(v))))
    out.append("</table>")
    if table:
        head, body = table
        out.append("<table><tr>%s</tr>" % "".join("<th>%s</th>" % html.escape(h) for h in head))
        for row in body:
            out.append("<tr>%s</tr>" % "".join("<td>%s</td>" % html.escape(str(c)) for c in row))
        out.append("</table>")
    return "".join(out) + "</div>"


# ---------------------------------------------------------------- Branch

def _branch_summary(b):
    kinds = {}
    for k in b.points.kind:
        kinds[str(k)] = kinds.get(str(k), 0) + 1
    return [("status", _status(b)),
            ("points", "%d (%s)" % (len(b.points), ", ".join("%s %d" % kv for kv in kinds.items()))),
            ("branches", len(set(int(i) for i in b.points.branch))),
            ("special", ", ".join(_specials(b)) or "none")]


def _branch_repr(b):
    p = b.points.p
    rng = " %s in [%.6g, %.6g]" % (b.param, p.min(), p.max()) if len(p) else " " + b.param
    return "<Branch%s: status %s; %d points; special: %s>" % (
        rng, _status(b), len(p), ", ".join(_specials(b)) or "none")


def _branch_html(b):
    head = ["lab", "pt", b.param, "period", "x_max", "description"]
    body = [[s.lab, s.pt, "%.10g" % s.p, "%.6g" % s.period, "%.6g" % s.x_max, s.description]
            for s in b.special]
    return _html("Branch in " + b.param, _branch_summary(b), (head, body) if body else None)


def _branch_pandas(b, mass=None, stiffness=None, gravity=9.81):
    """The rows as a DataFrame. With mass [kg] and stiffness [N/m], also ss_continue's
    physical columns: belt_speed [m/s] (for v) or damping [N s/m] (for beta), x_min_m,
    x_max_m, period_s (scales L = M g / K, t0 = sqrt(M / K), seed section 3)."""
    import pandas as pd
    cols = b.points.keys()
    df = pd.DataFrame({(b.param if c == "p" else c): getattr(b.points, c) for c in cols})
    df.attrs.update({"param": b.param, "status": _status(b)})
    if (mass is None) != (stiffness is None):
        raise TypeError("to_pandas: mass and stiffness go together")
    if mass is not None:
        L, t0 = _core.scales(mass, stiffness, gravity)  # ValueError for bad values
        if b.param == "v":
            df["belt_speed"] = df["v"] * L / t0
        elif b.param == "beta":
            df["damping"] = df["beta"] * 2 * (stiffness * mass) ** 0.5
        df["x_min_m"] = df["x_min"] * L
        df["x_max_m"] = df["x_max"] * L
        df["period_s"] = df["period"] * t0
        df.attrs.update({"L": L, "t0": t0})
    return df


def _special_pandas(b):
    import pandas as pd
    rows = [{"lab": s.lab, "pt": s.pt, "label": s.label, b.param: s.p, "period": s.period,
             "x_min": s.x_min, "x_max": s.x_max, "xdot_min": s.xdot_min,
             "x_start": s.x_start, "xdot_start": s.xdot_start, "description": s.description}
            for s in b.special]
    return pd.DataFrame(rows, columns=["lab", "pt", "label", b.param, "period", "x_min", "x_max",
                                       "xdot_min", "x_start", "xdot_start", "description"])


def _write(path, text):
    """Writes text to path through a temporary file and a rename (never a partial file)."""
    path = os.fspath(path)
    d = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=d)
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def _command(b):
    """The call that makes b again (its solver options aside: they are their own lines)."""
    return "stickslip.continue_branch(%r, %r, from_=%r, to=%r, max_step=%r)" % (
        b.params, b.param, b.options.from_, b.options.to, b.options.max_step)


def _branch_to_tsv(b, path, command=None):
    """Writes branch.tsv's text (ss_continue's columns and '# key: value' metadata) to path."""
    _write(path, b.tables(command or _command(b))["branch.tsv"])


def _branch_save(b, directory, command=None):
    """Writes branch.tsv and special_points.tsv into directory (made if missing), as
    ss_continue does: stickslip.restart(directory, 'GR1') then starts from a point."""
    directory = os.fspath(directory)
    os.makedirs(directory, exist_ok=True)
    for name, text in b.tables(command or _command(b)).items():
        _write(os.path.join(directory, name), text)
    return directory


def _branch_restart(b, point):
    """The LabelledPoint `point` ('GR1', 'HB1' or a pt number) of this branch, as
    restart() reads it from a saved run: point.options(...) starts a new branch there."""
    with tempfile.TemporaryDirectory(prefix="stickslip-") as d:
        _branch_save(b, d)
        return _core.restart(d, point)


# ---------------------------------------------------------------- the others

def _table_tsv(df, path, meta):
    """A DataFrame as the apps' TSV: '# key: value' lines, the header, the rows."""
    lines = ["# tool: stickslip (Python) %s" % _core.__version__]
    if _core.git_commit:
        lines.append("# commit: %s" % _core.git_commit)
    lines += ["# %s: %s" % (k, str(v).replace("\n", " ")) for k, v in meta]
    lines.append("\t".join(df.columns))
    for i, row in enumerate(df.itertuples(index=False), 1):
        try:
            lines.append("\t".join(_num(c) for c in row))
        except ValueError as e:
            bad = next(n for n, c in zip(df.columns, row) if _finite_or_text(c) is None)
            raise ValueError("to_tsv: column '%s', row %d: %s" % (bad, i, e)) from None
    _write(path, "\n".join(lines) + "\n")


def _chart_pandas(c):
    import pandas as pd
    frames = []
    for i, k in enumerate(c.curves, 1):
        frames.append(pd.DataFrame({c.param1: k.p1, c.param2: k.p2, "curve": i, "label": k.label,
                                    "period": k.period, "amplitude": k.amplitude,
                                    "multiplier": k.multiplier, "l1": k.l1, "type": k.type,
                                    "unphysical": k.unphysical}))
    cols = [c.param1, c.param2, "curve", "label", "period", "amplitude", "multiplier", "l1",
            "type", "unphysical"]
    return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=cols)


def _chart_summary(c):
    labels = {}
    for k in c.curves:
        labels[k.label] = labels.get(k.label, 0) + 1
    return [("status", _status(c)), ("plane", "(%s, %s)" % (c.param1, c.param2)),
            ("curves", ", ".join("%s %d" % kv for kv in labels.items()) or "none"),
            ("codim 2", ", ".join("%s (%.4g, %.4g)" % (q.label, q.p1, q.p2) for q in c.codim2)
             or "none"),
            ("regions", "x".join(str(n) for n in c.regions.shape) if c.regions.size else "none")]


def _basins_pandas(b):
    import pandas as pd
    return pd.DataFrame({"x": b.x, "xdot": b.xdot, "fate": b.fate, "orbit": b.orbit,
                         "t_settle": b.t_settle})


def _basins_summary(b):
    return [("status", _status(b)), ("grid", "%d x %d" % (b.nx, b.ny)),
            ("box", "x in [%.4g, %.4g], x' in [%.4g, %.4g]" % (b.x_lo, b.x_hi, b.xdot_lo,
                                                              b.xdot_hi)),
            ("fates", ", ".join("%s %d" % (_name(k), v) for k, v in b.counts.items()))]


def _trajectory_pandas(t):
    import pandas as pd
    return pd.DataFrame({"t": t.t, "x": t.x, "xdot": t.xdot, "mode": t.mode})


def _trajectory_summary(t):
    end = "%.6g" % t.t[-1] if len(t.t) else "-"
    return [("status", _name(t.status)), ("rows", "%d, t up to %s" % (len(t.t), end)),
            ("switches", t.switches), ("x range", "[%.6g, %.6g]" % (t.x_min, t.x_max))]


def _column_name(state_name):
    """A state component's name as a column's: x' is xdot."""
    return state_name.replace("'", "dot")


def state_columns(b):
    """An OrbitBranch's state components as column names (x, xdot, theta, ...)."""
    return [_column_name(n) for n in b.state_names]


def orbit_columns(b):
    """An OrbitBranch's rows by column: the parameter, the section point (x0,
    xdot0, theta0, ...), period, sticks, exits, crossings, each tangent
    component's least and greatest value on the orbit (x_min, x_max, xdot_min,
    ...), stable, label and the largest |multiplier|."""
    names = state_columns(b)
    cols = {b.parameter: b.p}
    cols.update(("%s0" % n, b.state[:, i]) for i, n in enumerate(names))
    cols.update(period=b.period, sticks=b.sticks, exits=b.exits, crossings=b.crossings)
    for i in range(b.hi.shape[1]):
        cols[names[i] + "_min"], cols[names[i] + "_max"] = b.lo[:, i], b.hi[:, i]
    mult = np.abs(b.multipliers)
    cols.update(stable=b.stable, label=b.label,
                mult_max=mult.max(axis=1) if mult.shape[1] else np.full(len(b.p), np.nan))
    return cols


def _orbit_branch_pandas(b):
    import pandas as pd
    df = pd.DataFrame(orbit_columns(b))
    df.insert(df.shape[1], "pt", range(1, len(df) + 1))
    return df


def _orbit_branch_summary(b):
    return [("status", _status(b)), ("parameter", b.parameter), ("points", len(b.p)),
            ("special", ", ".join("%s %s=%.6g" % (q.lab, b.parameter, q.p)
                                  for q in b.special_points) or "none")]


def _orbits_summary(o):
    return [("status", _status(o)), ("steady sliding", "stable" if o.steady.stable else "unstable"),
            ("stick-slip", "period %.6g" % o.stick_slip.period if o.stick_slip else "none"),
            ("pure slip", len(o.pure_slip))]


def _generic(cls, name, summary, pandas=None, meta=None):
    """__repr__, _repr_html_, and with pandas to_pandas() and to_tsv() on cls."""
    cls.__repr__ = lambda r: "<%s: %s>" % (name, "; ".join("%s %s" % kv for kv in summary(r)))
    cls._repr_html_ = lambda r: _html(name, summary(r))
    if pandas:
        cls.to_pandas = pandas
        cls.to_tsv = lambda r, path: _table_tsv(pandas(r), path, (meta or summary)(r))
        cls.to_pandas.__doc__ = "The rows as a pandas.DataFrame (one column per array)."


def install():
    B = _core.Branch
    B.__repr__ = _branch_repr
    B._repr_html_ = _branch_html
    B.to_pandas = _branch_pandas
    B.special_to_pandas = _special_pandas
    B.to_tsv = _branch_to_tsv
    B.save = _branch_save
    B.restart = _branch_restart
    _core.SpecialPoint.__repr__ = lambda s: "<SpecialPoint %s (pt %d) at p = %.10g: %s>" % (
        s.lab, s.pt, s.p, s.description)
    _core.BranchPoints.__repr__ = lambda p: "<BranchPoints: %d rows, columns %s>" % (
        len(p), ", ".join(p.keys()))
    _core.BranchPoints.to_pandas = lambda p: __import__("pandas").DataFrame(dict(p.items()))
    _generic(_core.Chart, "Chart", _chart_summary, _chart_pandas)
    _generic(_core.Basins, "Basins", _basins_summary, _basins_pandas)
    _generic(_core.Trajectory, "Trajectory", _trajectory_summary, _trajectory_pandas)
    _generic(_core.OrbitBranch, "OrbitBranch", _orbit_branch_summary, _orbit_branch_pandas)
    _generic(_core.PeriodicOrbits, "PeriodicOrbits", _orbits_summary)
    _generic(_core.Orbit, "Orbit", lambda o: [
        ("kind", _name(o.kind)), ("period", "%.10g" % o.period),
        ("x range", "[%.6g, %.6g]" % (o.x_min, o.x_max)),
        ("stable", o.stable if o.has_floquet else "not computed")])
    _generic(_core.ChartCurve, "ChartCurve", lambda c: [
        ("label", c.label), ("points", len(c.p1)), ("ends", c.ends)])
