#!/usr/bin/env python3
"""Checks the numbers of docs/studies.md against the runs that print them.

Usage: check_study_numbers.py BUILD_DIR [--list]

Each check names a passage of docs/studies.md, a number in it, and the run and
the value of its output the number was read from (stdout, special_points.tsv or
branch.tsv). The runs are the continuation runs of the page's commands (each
well under a second); every check runs against them once, in a temporary
directory. A number passes when it equals the measured value at its printed
precision (half a unit of its last digit; integers exactly). A passage that is
no longer in the page fails too, so an edit of the page must update its check.
The charts, basins, orbit diagrams, Feigenbaum's table and wall times are not
checked here (their runs take minutes; timings depend on the machine).
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = os.path.join(ROOT, "docs", "studies.md")

CR_FORCED = ["--law", "coulomb", "--mu_s", "0.4", "--mu_k", "0.25", "--v", "0", "--beta", "0.05",
             "--force", "0.5", "--param", "omega", "--from", "0.5", "--to", "2.5"]
DEN_HARTOG_CLI = ["--law", "coulomb", "--mu_s", "0.3", "--mu_k", "0.3", "--beta", "0", "--v", "0",
                  "--force", "1", "--param", "omega", "--from", "0.75", "--to", "2.5"]

# name: (app, arguments, the run it restarts from or None); in this order.
RUNS = {
    "seed": ("ss_continue", ["--study", "studies/seed.ini"], None),
    "hb_beta": ("ss_continue", ["--restart", "{seed}", "--point", "HB1", "--param", "beta"], None),
    "seed_beta": ("ss_continue", ["--study", "studies/seed_beta.ini"], None),
    "stribeck": ("ss_continue", ["--study", "studies/stribeck.ini"], None),
    "coulomb": ("ss_continue", ["--law", "coulomb"], None),
    "cr": ("ss_continue", CR_FORCED, None),
    "cr_force": ("ss_continue", ["--restart", "{cr}", "--point", "CR1", "--param", "force"], None),
    "den_hartog": ("ss_continue", ["--study", "studies/den_hartog.ini"], None),
    "den_hartog_cli": ("ss_continue", DEN_HARTOG_CLI, None),
    "floor_static": ("ss_continue", ["--study", "studies/floor_static.ini"], None),
    "seed_forced": ("ss_continue", ["--study", "studies/seed_forced.ini"], None),
    "stribeck_forced": ("ss_continue", ["--study", "studies/stribeck_forced.ini"], None),
    "m1": ("ss_continue", ["--study", "studies/stribeck_forced.ini", "--from", "0.7", "--to", "0.6"],
           None),
    "m2": ("ss_continue", ["--restart", "{m1}", "--point", "PD1", "--switch", "--to", "0.6"], None),
    "m4": ("ss_continue", ["--restart", "{m2}", "--point", "PD1", "--switch", "--to", "0.6"], None),
}


class Run:
    def __init__(self, out_dir, stdout):
        self.dir, self.stdout = out_dir, stdout

    def table(self, name):
        with open(os.path.join(self.dir, name)) as f:
            return list(csv.DictReader((l for l in f if not l.startswith("#")), delimiter="\t"))

    def meta(self, name, key):
        with open(os.path.join(self.dir, name)) as f:
            for line in f:
                if line.startswith("# " + key + ": "):
                    return line[len(key) + 4:].strip()
        raise KeyError(key)

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

    def rows(self):
        return len(self.table("branch.tsv"))

    def first(self, col):
        return float(self.table("branch.tsv")[0][col])

    def argmax(self, col, other):
        rows = self.table("branch.tsv")
        best = max(rows, key=lambda r: float(r[col]))
        return float(best[col]), float(best[other])

    def printed(self, pattern, group=1):
        m = re.search(pattern, self.stdout, re.M)
        if not m:
            raise KeyError(pattern)
        return float(m.group(group))


def gap(run, k):
    return float(re.findall(r"-?\d+\.\d+(?:e[-+]?\d+)?", run.meta("branch.tsv", "gap"))[k])


# (passage of the page, the number as printed there, run, measured value).
CHECKS = [
    ("214 points: 87 stick-slip, 25 pure-slip, 102 equilibrium", "214", "seed",
     lambda r: r.printed(r"^(\d+) points:")),
    ("214 points: 87 stick-slip, 25 pure-slip, 102 equilibrium", "87", "seed",
     lambda r: r.printed(r"(\d+) stick-slip,")),
    ("214 points: 87 stick-slip, 25 pure-slip, 102 equilibrium", "25", "seed",
     lambda r: r.printed(r"(\d+) pure-slip,")),
    ("214 points: 87 stick-slip, 25 pure-slip, 102 equilibrium", "102", "seed",
     lambda r: r.printed(r"(\d+) equilibrium")),
    ("grazing point v_GR = 0.3957902888", "0.3957902888", "seed", lambda r: r.special("GR1", "v")),
    ("jumps to 0.636", "0.636", "seed", lambda r: r.described("GR1", r"([0-9.]+) on the pure-slip side")),
    ("Hopf point v_max = 0.4409585518", "0.4409585518", "seed", lambda r: r.special("HB1", "v")),
    ("| GR 0.3957902888, HB 0.4409585518 |", "0.3957902888", "seed",
     lambda r: r.special("GR1", "v")),
    ("| GR 0.3957902888, HB 0.4409585518 |", "0.4409585518", "seed",
     lambda r: r.special("HB1", "v")),
    ("v = 0.44095855184409843 written to every digit", "0.44095855184409843", "hb_beta",
     lambda r: float(re.search(r" v=([0-9.]+)", r.meta("branch.tsv", "model")).group(1))),
    ("It finds HB1 at β = 0.05", "0.05", "hb_beta", lambda r: r.special("HB1", "beta")),
    ("GR β = 0.1547673804", "0.1547673804", "seed_beta", lambda r: r.special("GR1", "beta")),
    ("HB β = 0.16875", "0.16875", "seed_beta", lambda r: r.special("HB1", "beta")),
    ("HB 0.5493061443", "0.5493061443", "stribeck", lambda r: r.special("HB1", "v")),
    ("GR = LP 0.6519468583", "0.6519468583", "stribeck", lambda r: r.special("GR1", "v")),
    ("GR = LP 0.6519468583", "0.6519468583", "stribeck", lambda r: r.special("LP1", "v")),
    ("equals v: v = 0.1647138936", "0.1647138936", "coulomb", lambda r: r.special("GR1", "v")),
    ("GR1  pt 27  v = 0.164713893617  period 6.439475", "0.164713893617", "coulomb",
     lambda r: r.special("GR1", "v")),
    ("GR1  pt 27  v = 0.164713893617  period 6.439475", "6.439475", "coulomb",
     lambda r: r.special("GR1", "period")),
    ("GR1  pt 27  v = 0.164713893617  period 6.439475", "27", "coulomb",
     lambda r: r.special("GR1", "pt")),
    ("at CR1's Ω = 0.7167891507041263", "0.7167891507041263", "cr_force",
     lambda r: float(r.meta("branch.tsv", "omega"))),
    ("locates CR again at A = 0.5000000000002144", "0.5000000000002144", "cr_force",
     lambda r: r.special("CR1", "force")),
    ("writes 1103 rows, gap 0.97661 to 1.02276", "1103", "den_hartog", lambda r: r.rows()),
    ("writes 1103 rows, gap 0.97661 to 1.02276", "0.97661", "den_hartog", lambda r: gap(r, 0)),
    ("writes 1103 rows, gap 0.97661 to 1.02276", "1.02276", "den_hartog", lambda r: gap(r, 1)),
    ("`max_amplitude` 50) writes 2817", "2817", "den_hartog_cli", lambda r: r.rows()),
    ("Ω = 0.63575 (CR1, the located", "0.63575", "floor_static", lambda r: r.special("CR1", "omega")),
    ("x_max = 3.194 at Ω = 0.993", "3.194", "floor_static", lambda r: r.argmax("x_max", "omega")[0]),
    ("x_max = 3.194 at Ω = 0.993", "0.993", "floor_static", lambda r: r.argmax("x_max", "omega")[1]),
    ("(LP at Ω = 0.62857 and 0.62849)", "0.62857", "seed_forced", lambda r: r.special("LP2", "omega")),
    ("(LP at Ω = 0.62857 and 0.62849)", "0.62849", "seed_forced", lambda r: r.special("LP1", "omega")),
    ("a period doubling at\nΩ = 0.61397", "0.61397", "seed_forced",
     lambda r: r.special("PD1", "omega")),
    ("Ω = 0.58019, just before the grazing point GR1 at Ω = 0.57949", "0.58019", "seed_forced",
     lambda r: r.special("PD2", "omega")),
    ("Ω = 0.58019, just before the grazing point GR1 at Ω = 0.57949", "0.57949", "seed_forced",
     lambda r: r.special("GR1", "omega")),
    ("(LP at Ω = 0.63020 and 0.62374)", "0.63020", "stribeck_forced",
     lambda r: r.special("LP2", "omega")),
    ("(LP at Ω = 0.63020 and 0.62374)", "0.62374", "stribeck_forced",
     lambda r: r.special("LP1", "omega")),
    ("in a PD at Ω = 0.61821", "0.61821", "stribeck_forced", lambda r: r.special("PD1", "omega")),
    ("second PD, Ω = 0.58000,\njust before the grazing point GR1 at Ω = 0.57876", "0.58000",
     "stribeck_forced", lambda r: r.special("PD2", "omega")),
    ("second PD, Ω = 0.58000,\njust before the grazing point GR1 at Ω = 0.57876", "0.57876",
     "stribeck_forced", lambda r: r.special("GR1", "omega")),
    ("The m = 2 branch opens from Ω = 0.618208", "0.618208", "m1",
     lambda r: r.special("PD1", "omega")),
    ("doubles again at\nΩ = 0.610558", "0.610558", "m2", lambda r: r.special("PD1", "omega")),
    ("the m = 4 branch doubles at Ω = 0.606161", "0.606161", "m4",
     lambda r: r.special("PD1", "omega")),
]


def agrees(quoted, measured):
    if re.fullmatch(r"-?\d+", quoted):
        return measured == int(quoted)
    decimals = len(quoted.split(".")[1])
    return abs(measured - float(quoted)) <= 0.5 * 10 ** -decimals * (1 + 1e-9)


def run_all(build, tmp):
    runs = {}
    for name, (app, args, _) in RUNS.items():
        out = os.path.join(tmp, name)
        argv = [os.path.join(build, app)]
        argv += [a.format(**{k: v.dir for k, v in runs.items()}) for a in args]
        argv += ["--out", out, "--no_plots"]
        p = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, timeout=300)
        if not os.path.exists(os.path.join(out, "branch.tsv")):
            sys.exit("check_study_numbers: %s wrote nothing (exit %d): %s" %
                     (" ".join(argv), p.returncode, p.stderr.strip()))
        runs[name] = Run(out, p.stdout)
    return runs


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    page = open(PAGE).read()
    flat = re.sub(r"\s+", " ", page)
    with tempfile.TemporaryDirectory() as tmp:
        runs = run_all(sys.argv[1], tmp)
        bad = 0
        for passage, quoted, run, value in CHECKS:
            where = re.sub(r"\s+", " ", passage)
            if where not in flat or quoted not in where:
                print("studies.md: passage not found (or number not in it): %r" % passage)
                bad += 1
                continue
            try:
                measured = value(runs[run])
            except (KeyError, ValueError, AttributeError, IndexError) as e:
                print("BAD %s: no value in run %s (%r)" % (where[:60], run, e))
                bad += 1
                continue
            ok = agrees(quoted, measured)
            if not ok or "--list" in sys.argv:
                print("%s %s: quoted %s, measured %.17g (run %s)" %
                      ("ok " if ok else "BAD", where[:60], quoted, measured, run))
            bad += 0 if ok else 1
    print("check_study_numbers: %d numbers checked against %d runs, %d wrong" %
          (len(CHECKS), len(RUNS), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
