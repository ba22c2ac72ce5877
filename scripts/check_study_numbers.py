#!/usr/bin/env python3
"""Checks the numbers of docs/studies.md and docs/systems.md against the runs that print them.

Usage: check_study_numbers.py BUILD_DIR [--slow | --all] [--list] [--keep DIR [--reuse]]
       check_study_numbers.py --self-test

The runs and the checks are in scripts/study_numbers.py. Each check names a
passage of docs/studies.md, a number in it, and the run and the value of its
output the number was read from (stdout or one of the TSV files it writes).
By default the fast runs are rerun (a few seconds: continuation runs, the
(v, beta) charts, the basins of the unforced belt, the forced charts' curves of
the small study); --slow reruns the others (the forced orbit diagrams, forced
basins, the forced (Omega, A) charts' curves and Feigenbaum's cascade: minutes),
--all both. Every run writes into a temporary directory (--keep DIR: there;
with --reuse, a run whose output is already there is not rerun).

A number passes when it equals the measured value at its printed precision
(half a unit of its last digit; integers exactly); a check marked "le" passes
when the measured value is at most the quoted bound, "rounded" a percentage
rounded to an integer; "err S" checks a Lyapunov exponent of a chaotic
attractor, which moves with any change of rounding, to twice its quoted error
bar S, and "err" to twice the run's own standard error. Every passage of every check must still be in the
page, whichever runs are selected, so an edit of the page must update its check.
Wall and CPU times are not checked (they depend on the machine), nor numbers
that a named test prints (the test asserts them).
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

import study_numbers

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = os.path.join(ROOT, "docs", "studies.md")
PAGES = [PAGE, os.path.join(ROOT, "docs", "systems.md")]


class Run:
    def __init__(self, out_dir, stdout):
        self.dir, self.stdout = out_dir, stdout

    def text(self, name):
        with open(os.path.join(self.dir, name)) as f:
            return f.read()

    def table(self, name):
        with open(os.path.join(self.dir, name)) as f:
            return list(csv.DictReader((l for l in f if not l.startswith("#")), delimiter="\t"))

    def meta(self, name, key):
        for line in self.text(name).splitlines():
            if line.startswith("# " + key + ": "):
                return line[len(key) + 4:].strip()
        raise KeyError(key)

    def found(self, name, pattern, group=1):
        """A number matched in file `name` (stdout for None)."""
        m = re.search(pattern, self.stdout if name is None else self.text(name), re.M)
        if not m:
            raise KeyError(pattern)
        return float(m.group(group))

    def printed(self, pattern, group=1):
        return self.found(None, pattern, group)

    def special(self, lab, col):
        for r in self.table("special_points.tsv"):
            if r["lab"] == lab:
                return float(r[col])
        raise KeyError(lab)

    def described(self, lab, pattern):
        for r in self.table("special_points.tsv"):
            if r["lab"] == lab:
                return float(re.search(pattern, r["description"]).group(1))
        raise KeyError(lab)

    def rows(self, name="branch.tsv"):
        return len(self.table(name))

    def first(self, col):
        return float(self.table("branch.tsv")[0][col])

    def argmax(self, col, other, name="branch.tsv", where=lambda r: True):
        rows = [r for r in self.table(name) if where(r)]
        best = max(rows, key=lambda r: float(r[col]))
        return float(best[col]), float(best[other])

    def argmin(self, col, other, name="branch.tsv", where=lambda r: True):
        rows = [r for r in self.table(name) if where(r)]
        best = min(rows, key=lambda r: float(r[col]))
        return float(best[col]), float(best[other])

    def crossings(self, curve, axis, value, other, name="curves.tsv"):
        """`other` interpolated linearly where the curves of kind `curve`
        (curves.tsv's `curve` column) cross `axis` = value, in file order."""
        out, prev = [], None
        for r in self.table(name):
            if r["curve"] != curve:
                prev = None
                continue
            if prev is not None and prev["id"] == r["id"]:
                a0, a1 = float(prev[axis]), float(r[axis])
                if a0 != a1 and (a0 - value) * (a1 - value) <= 0:
                    s = (value - a0) / (a1 - a0)
                    out.append(float(prev[other]) + s * (float(r[other]) - float(prev[other])))
            prev = r
        if not out:
            raise KeyError("%s does not cross %s = %g" % (curve, axis, value))
        return out

    def lyapunov(self, direction, omega):
        """The row of lyapunov.tsv nearest to omega in the sweep `direction`."""
        rows = [r for r in self.table("lyapunov.tsv") if r["direction"] == direction]
        return min(rows, key=lambda r: abs(float(r["omega"]) - omega))


def agrees(quoted, measured, how):
    if how == "le":
        return measured <= float(quoted)
    if how == "err":  # measured is (value, its standard error): within twice that error
        return abs(measured[0] - float(quoted)) <= 2 * measured[1]
    if how.startswith("err"):  # "err SIGMA": within twice the quoted error bar
        return abs(measured - float(quoted)) <= 2 * float(how.split()[1])
    if how == "rounded" and re.fullmatch(r"-?\d+", quoted):  # a rounded percentage
        return abs(measured - int(quoted)) <= 0.5
    if re.fullmatch(r"-?\d+", quoted):
        return measured == int(quoted)
    decimals = len(quoted.split(".")[1])
    return abs(measured - float(quoted)) <= 0.5 * 10 ** -decimals * (1 + 1e-9)


def module_python(build):
    """The interpreter the build's Python module is for (CMakeCache.txt), else this one."""
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as f:
            m = re.search(r"^_Python3_EXECUTABLE:INTERNAL=(.+)$", f.read(), re.M)
        return m.group(1).strip() if m else sys.executable
    except OSError:
        return sys.executable


def run_all(build, tmp, tiers, reuse):
    runs = {}
    for name, (tier, app, args, opts) in study_numbers.RUNS.items():
        if tier not in tiers:
            continue
        out = os.path.join(tmp, name)
        if reuse and os.path.exists(os.path.join(out, "stdout.txt")):
            with open(os.path.join(out, "stdout.txt")) as f:
                runs[name] = Run(out, f.read())
            continue
        fill = {k: v.dir for k, v in runs.items()}
        fill["out"] = out
        args = [a.format(**fill) for a in args]
        if app.endswith(".py"):
            argv = [module_python(build), os.path.join(ROOT, app)] + args
            env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
        else:
            argv = [os.path.join(build, app)] + args + ["--out", out]
            argv += [] if "plots" in opts else ["--no_plots"]
            env = None
        p = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, timeout=1800, env=env)
        if p.returncode not in (0, 1) or (app.endswith(".py") and p.returncode):
            sys.exit("check_study_numbers: %s failed (exit %d): %s" %
                     (" ".join(argv), p.returncode, p.stderr.strip()[-2000:]))
        os.makedirs(out, exist_ok=True)
        with open(os.path.join(out, "stdout.txt"), "w") as f:
            f.write(p.stdout)
        runs[name] = Run(out, p.stdout)
    return runs


def check(runs, flat, tiers, listing):
    bad = done = 0
    for passage, quoted, run, value, *how in study_numbers.CHECKS:
        how = how[0] if how else "digits"
        where = re.sub(r"\s+", " ", passage)
        if where not in flat or quoted not in where:
            print("docs: passage not found (or number not in it): %r" % passage)
            bad += 1
            continue
        if study_numbers.RUNS[run][0] not in tiers:
            continue
        done += 1
        try:
            measured = value(runs[run])
        except (KeyError, ValueError, AttributeError, IndexError, OSError) as e:
            print("BAD %s: no value in run %s (%r)" % (where[:60], run, e))
            bad += 1
            continue
        ok = agrees(quoted, measured, how)
        if not ok or listing:
            print("%s %s: quoted %s, measured %s (run %s%s)" %
                  ("ok " if ok else "BAD", where[:60], quoted,
                   ", ".join("%.17g" % m for m in (measured if how == "err" else [measured])), run,
                   "" if how == "digits" else ", " + how))
        bad += 0 if ok else 1
    return done, bad


def self_test():
    """agrees() on each kind of check, and an edited number of the page is reported."""
    cases = [("0.3958", 0.39578887, "digits", True), ("0.3958", 0.39574, "digits", False),
             ("214", 214.0, "digits", True), ("214", 213.0, "digits", False),
             ("1e-8", 5e-9, "le", True), ("1e-8", 2e-8, "le", False),
             ("0.0113", 0.0150, "err 0.0022", True), ("0.0113", 0.0160, "err 0.0022", False),
             ("0.0131", (0.0150, 0.001), "err", True), ("0.0131", (0.0160, 0.001), "err", False),
             ("67", 66.96, "rounded", True), ("67", 66.4, "rounded", False)]
    bad = [c for c in cases if agrees(c[0], c[1], c[2]) != c[3]]
    flat = " ".join(re.sub(r"\s+", " ", open(p).read()) for p in PAGES)
    edited = flat.replace("v_GR = 0.3957902888", "v_GR = 0.3957902889")
    if check({}, flat, set(), False)[1] != 0 or check({}, edited, set(), False)[1] != 1:
        bad.append("the edited page")
    print("check_study_numbers --self-test: %d cases, %d wrong %s" % (len(cases) + 1, len(bad), bad))
    return 1 if bad else 0


def main():
    if "--self-test" in sys.argv:
        return self_test()
    if len(sys.argv) < 2 or sys.argv[1].startswith("-"):
        sys.exit(__doc__)
    tiers = {"slow"} if "--slow" in sys.argv else {"fast"}
    tiers = {"fast", "slow"} if "--all" in sys.argv else tiers
    flat = " ".join(re.sub(r"\s+", " ", open(p).read()) for p in PAGES)
    keep = sys.argv[sys.argv.index("--keep") + 1] if "--keep" in sys.argv else None
    if keep:
        os.makedirs(keep, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        runs = run_all(sys.argv[1], keep or tmp, tiers, keep and "--reuse" in sys.argv)
        done, bad = check(runs, flat, tiers, "--list" in sys.argv)
    print("check_study_numbers (%s): %d numbers checked against %d runs, %d wrong" %
          ("+".join(sorted(tiers)), done, len(runs), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
