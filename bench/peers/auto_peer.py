#!/usr/bin/env python3
"""Times AUTO-07p's compiled executable and ss_continue on the smooth part of the seed
branch and prints their accuracy side by side (called by auto_peer.sh, which compiles).

References, none from ss_continue: HB from the closed form sqrt((k1 - 2 beta)/(3 k3)) (seed
3.16); GR and each period at the exact v of the point it checks from the independent
long-double reference integrator (reference/reference_orbit.hpp, RKF78 at tol 1e-17), via
`ss_accuracy --seed_references`; that GR is checked against the published 0.3957902888 first."""
import argparse
import csv
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

BETA, MU_S, MU_M, V_M = 0.05, 0.4, 0.25, 0.5
K1 = 3 * (MU_S - MU_M) / (2 * V_M)
K3 = (MU_S - MU_M) / (2 * V_M**3)
HB_EXACT = math.sqrt((K1 - 2 * BETA) / (3 * K3))
GR_PUBLISHED = 0.3957902888  # 10 digits
V_POINTS = (0.435, 0.42, 0.40)  # the UZR velocities of c.po
RANGE = ["--param", "v", "--from", "0.39", "--to", "0.5", "--no_plots", "--no_estimates"]
# Largest HB error accepted from AUTO: its location tolerance EPSS is 1e-5 by default.
HB_LIMIT = {"default": 1e-4, "tight": 1e-6}


def die(msg):
    print("auto_peer: " + msg, file=sys.stderr)
    sys.exit(1)


def timed(cmd, cwd=None, env=None):
    t0 = time.perf_counter()
    r = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True)
    dt = time.perf_counter() - t0
    if r.returncode != 0:
        die(f"{' '.join(cmd)} failed (exit {r.returncode}): {r.stderr.strip()[-300:]}")
    return dt


def run_auto(work, settings, env):
    """One HB run and one periodic run; returns the wall time of the two executables."""
    total = 0.0
    for stage in ("hb", "po"):
        suffix = "" if settings == "default" else ".tight"
        shutil.copy(os.path.join(work, f"c.{stage}{suffix}"), os.path.join(work, "fort.2"))
        total += timed(["./stickslip.exe"], cwd=work, env=env)
        os.replace(os.path.join(work, "fort.7"), os.path.join(work, f"b.{stage}.{settings}"))
    return total


def parse_b(path):
    """Labelled points of an AUTO b-file (fort.7) as dicts: TY code and named columns."""
    names, points = None, []
    with open(path) as f:
        for line in f:
            tok = line.split()
            if len(tok) > 4 and tok[0] == "0" and tok[1] == "PT":
                names = re.findall(r"PAR\(\d+\)|L2-NORM|MAX U\(\d+\)|MIN U\(\d+\)|U\(\d+\)",
                                   line)
            elif names and tok and tok[0] != "0" and len(tok) == 4 + len(names):
                if int(tok[3]) == 0:
                    continue
                p = dict(zip(names, map(float, tok[4:])))
                p["TY"] = abs(int(tok[2]))
                points.append(p)
    return points


def full(p, coarse, fine):
    """v or T to all its digits: the equation file splits off the part below 1e-5."""
    return round(p[coarse], 5) + p[fine]


def auto_results(work, settings):
    hb = [p for p in parse_b(os.path.join(work, f"b.hb.{settings}")) if p["TY"] == 3]
    if len(hb) != 1:
        die(f"AUTO ({settings}): {len(hb)} Hopf points on steady sliding, expected 1")
    uz = [p for p in parse_b(os.path.join(work, f"b.po.{settings}")) if p["TY"] == 4]
    pts = [(full(p, "PAR(1)", "PAR(7)"), full(p, "PAR(6)", "PAR(8)"), p["PAR(9)"]) for p in uz]
    periods = []
    for v0 in V_POINTS:
        near = [(v, t) for v, t, _ in pts if abs(v - v0) < 1e-6]
        if not near:
            die(f"AUTO ({settings}): no periodic orbit at v = {v0} (branch empty?)")
        periods.append(near[0])
    gr = [v for v, _, g in pts if abs(g) < 1e-6]
    if len(gr) != 1:
        die(f"AUTO ({settings}): {len(gr)} points with max y = v, expected 1")
    hb_v = full(hb[0], "PAR(1)", "PAR(7)")
    if abs(hb_v - HB_EXACT) > HB_LIMIT[settings]:
        die(f"AUTO ({settings}): HB at v = {hb_v!r}, closed form {HB_EXACT!r}: "
            "the equation file is wrong")
    return hb_v, gr[0], periods


def rows(out_dir):
    """branch.tsv rows (v, kind, period) and special points {label: v} of ss_continue."""
    def table(name):  # '# key: value' lines, then a header line (the README's format)
        with open(os.path.join(out_dir, name)) as f:
            return list(csv.DictReader((l for l in f if not l.startswith("#")), delimiter="\t"))
    branch = [(float(r["v"]), r["kind"], float(r["period"])) for r in table("branch.tsv")]
    special = {r["label"]: float(r["v"]) for r in table("special_points.tsv")}
    return branch, special


def references(tool, vs):
    """Reference GR (v, spread) and {v: (period, spread)} from `tool --seed_references`."""
    r = subprocess.run([tool, "--seed_references"] + [repr(v) for v in vs],
                       capture_output=True, text=True)
    if r.returncode != 0:
        die(f"{tool} --seed_references failed (exit {r.returncode}): {r.stderr.strip()}")
    gr, periods = None, {}
    for line in r.stdout.splitlines():
        tok = line.split("\t")
        if tok[0] == "GR":
            gr = (float(tok[1]), float(tok[2]))
        elif tok[0] == "T":
            periods[float(tok[1])] = (float(tok[2]), float(tok[3]))
    if gr is None or abs(gr[0] - GR_PUBLISHED) > 1e-10:
        die(f"reference GR {gr!r} is not the published {GR_PUBLISHED}")
    if sorted(periods) != sorted(set(vs)):
        die(f"{tool} --seed_references gave periods at {sorted(periods)}, asked {sorted(vs)}")
    return gr, periods


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--work", required=True)
    ap.add_argument("--tool", required=True)
    ap.add_argument("--reference", required=True, help="ss_accuracy (--seed_references)")
    ap.add_argument("--reps", type=int, default=7)
    ap.add_argument("--threads", default="1", help="OMP_NUM_THREADS for AUTO (default 1)")
    a = ap.parse_args()
    if a.reps < 1:
        die(f"--reps {a.reps}: must be >= 1")
    env = dict(os.environ, OMP_NUM_THREADS=a.threads)
    scratch = tempfile.mkdtemp(prefix="auto_peer.")
    try:
        report(a, env, scratch)
    finally:
        shutil.rmtree(scratch)


def report(a, env, scratch):
    runs = []  # (tool, settings, ms, HB, GR, [(v, T)])
    for settings in ("default", "tight"):
        ms = statistics.median(run_auto(a.work, settings, env) for _ in range(a.reps)) * 1e3
        hb, gr, periods = auto_results(a.work, settings)
        label = "NTST 20, EPS* defaults" if settings == "default" else \
            "NTST 100, EPSL/EPSU/EPSS 1e-10"
        runs.append((f"AUTO {settings}", ("AUTO-07p (IPS 1 + IPS 4)", label), ms, hb, gr, periods))

    out = os.path.join(scratch, "ours")
    ms = statistics.median(timed([a.tool] + RANGE + ["--out", out])
                           for _ in range(a.reps)) * 1e3
    branch, special = rows(out)
    if "HB" not in special or "GR" not in special:
        die(f"ss_continue found {sorted(special)}, expected GR and HB")
    slip = [(v, t) for v, kind, t in branch if kind == "pure-slip"]
    if not slip:
        die("ss_continue: no pure-slip rows")
    periods = [min(slip, key=lambda r: abs(r[0] - v0)) for v0 in V_POINTS]
    runs.append(("ours default", ("ss_continue", "defaults (rtol 1e-11)"), ms, special["HB"],
                 special["GR"], periods))

    (gr_ref, gr_spread), ref = references(a.reference, [v for r in runs for v, _ in r[5]])
    table = []
    for name, label, ms, hb, gr, periods in runs:
        errs = []
        for v, t in periods:
            t_ref, spread = ref[v]
            errs.append(abs(t - t_ref) / t_ref)
            print(f"{name:12s} v {v:.12f}  T {t:.13f}  reference {t_ref:.13f} (spread "
                  f"{spread:.0e})  rel. error {errs[-1]:.1e}")
        print(f"{name:12s} HB {hb!r}  GR {gr!r}")
        table.append(label + (ms, abs(hb - HB_EXACT), abs(gr - gr_ref), max(errs)))

    print(f"\nReferences (none from ss_continue): HB {HB_EXACT!r} (closed form, seed 3.16); "
          f"GR {gr_ref!r} and the periods at each point's own v from the long-double "
          f"reference integrator (RKF78, tol 1e-17; spread against tol 1e-15: GR "
          f"{gr_spread:.0e}, periods <= {max(s for _, s in ref.values()):.0e} rel.).\n"
          f"Median of {a.reps} runs of the executables (AUTO: OMP_NUM_THREADS={a.threads}, "
          "its HB run plus its periodic run).\n")
    print("| tool | settings | median ms | HB error (closed form) | GR error (long-double ref.) "
          "| max period error (rel., long-double ref.) |")
    print("|---|---|---|---|---|---|")
    for name, label, ms, e_hb, e_gr, e_t in table:
        print(f"| {name} | {label} | {ms:.1f} | {e_hb:.1e} | {e_gr:.1e} | {e_t:.1e} |")


if __name__ == "__main__":
    main()
