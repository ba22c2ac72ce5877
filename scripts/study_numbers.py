"""The runs behind docs/studies.md and the numbers read from them
(scripts/check_study_numbers.py runs and checks them)."""
import math
import re

CR_FORCED = ["--law", "coulomb", "--mu_s", "0.4", "--mu_k", "0.25", "--v", "0", "--beta", "0.05",
             "--force", "0.5", "--param", "omega", "--from", "0.5", "--to", "2.5"]
DEN_HARTOG_CLI = ["--law", "coulomb", "--mu_s", "0.3", "--mu_k", "0.3", "--beta", "0", "--v", "0",
                  "--force", "1", "--param", "omega", "--from", "0.75", "--to", "2.5"]
STRIBECK_13 = ["--law", "stribeck", "--beta", "0.02"]
LEINE_2 = ["--law", "leine", "--mu_s", "1", "--beta", "0.05"]
PHYSICAL = ["--mass", "2", "--stiffness", "8", "--damping", "0.4", "--belt_speed", "1", "--speed_m",
            "2.4525", "--param", "belt_speed", "--from", "1.5", "--to", "2.4525"]
R2_CHART = ["--law", "stribeck", "--mu_s", "0.4", "--mu_k", "0.25", "--v_s", "0.2", "--v", "0.41",
            "--param", "omega", "--from", "0.6", "--to", "2.4", "--param2", "force", "--from2",
            "0.002", "--to2", "0.16", "--grid", "0"]
COULOMB_BASIN = ["--law", "coulomb", "--mu_s", "0.4", "--mu_k", "0.25", "--beta", "0.05", "--v",
                 "0.2", "--force", "0.3", "--omega", "0.45", "--nx", "61", "--ny", "61"]
SCAN = ["--study", "studies/stribeck_forced.ini", "--orbits", "--max_m", "8", "--omega"]
SEED_SCAN = ["--study", "studies/seed_forced.ini", "--orbits"]
FAST, SLOW = "fast", "slow"


def study(name, *more):
    return ["--study", "studies/%s.ini" % name] + list(more)


# name: (tier, app, arguments, options); in this order ({name}: that run's directory).
# Options: "plots" (draw: chart.gp and regions.tsv need it). The forced charts run with
# --grid 0: the page's numbers are of their curves, not of the response grid.
RUNS = {
    "seed": (FAST, "ss_continue", study("seed"), ""),
    "hb_beta": (FAST, "ss_continue", ["--restart", "{seed}", "--point", "HB1", "--param", "beta"],
                ""),
    "gr_chart": (FAST, "ss_chart", ["--restart", "{seed}", "--point", "GR1", "--param2", "beta"],
                 ""),
    "seed_beta": (FAST, "ss_continue", study("seed_beta"), ""),
    "stribeck": (FAST, "ss_continue", study("stribeck"), ""),
    "coulomb": (FAST, "ss_continue", ["--law", "coulomb"], ""),
    "coulomb_study": (FAST, "ss_continue", study("coulomb"), ""),
    "cr": (FAST, "ss_continue", CR_FORCED, ""),
    "cr_force": (FAST, "ss_continue", ["--restart", "{cr}", "--point", "CR1", "--param", "force"],
                 ""),
    "den_hartog": (FAST, "ss_continue", study("den_hartog"), ""),
    "den_hartog_cli": (FAST, "ss_continue", DEN_HARTOG_CLI, ""),
    "floor_static": (FAST, "ss_continue", study("floor_static"), ""),
    "seed_forced": (FAST, "ss_continue", study("seed_forced"), ""),
    "seed_forced_a05": (FAST, "ss_continue",
                        study("seed_forced", "--force", "0.5", "--from", "1", "--to", "0.3"), ""),
    "stribeck_forced": (FAST, "ss_continue", study("stribeck_forced"), ""),
    "m1": (FAST, "ss_continue", study("stribeck_forced", "--from", "0.7", "--to", "0.6"), ""),
    "m2": (FAST, "ss_continue", ["--restart", "{m1}", "--point", "PD1", "--switch", "--to", "0.6"],
           ""),
    "m4": (FAST, "ss_continue", ["--restart", "{m2}", "--point", "PD1", "--switch", "--to", "0.6"],
           ""),
    "ns_seed": (FAST, "ss_continue", study("forced_ns_seed"), ""),
    "ns_seed_chart": (FAST, "ss_chart", study("forced_ns_seed", "--grid", "0"), ""),
    "strib13_up": (FAST, "ss_continue", STRIBECK_13 + ["--param", "v", "--from", "1.3", "--to",
                                                       "1.31"], ""),
    "strib13_down": (FAST, "ss_continue", STRIBECK_13 + ["--param", "v", "--from", "1.31", "--to",
                                                         "1.3"], ""),
    "leine2_up": (FAST, "ss_continue", LEINE_2 + ["--from", "2.0", "--to", "2.01"], ""),
    "leine2_down": (FAST, "ss_continue", LEINE_2 + ["--from", "2.01", "--to", "2.0"], ""),
    "physical": (FAST, "ss_continue", PHYSICAL, ""),
    "stribeck_basin": (FAST, "ss_basin", study("stribeck_basin"), ""),
    "basin_stability": (FAST, "ss_basin", study("stribeck_basin_stability"), ""),
    "seed_basin": (FAST, "ss_basin", study("seed_basin"), ""),
    "seed_basin_42": (FAST, "ss_basin", study("seed_basin", "--v", "0.42"), ""),
    "basin_strib13": (FAST, "ss_basin", STRIBECK_13 + ["--v", "1.3", "--nx", "21", "--ny", "21"],
                      ""),
    "basin_leine2": (FAST, "ss_basin", LEINE_2 + ["--v", "2", "--nx", "21", "--ny", "21"], ""),
    "seed_chart": (FAST, "ss_chart", study("seed_chart"), ""),
    "stribeck_chart": (FAST, "ss_chart", study("stribeck_chart"), ""),
    "quintic_chart": (FAST, "ss_chart", study("quintic_chart"), "plots"),
    "leine_chart": (FAST, "ss_chart", study("leine_chart"), "plots"),
    # docs/systems.md: the chain studies.
    "chain2": (FAST, "ss_continue", study("chain2"), ""),
    "chain2_kc05": (FAST, "ss_continue", study("chain2", "--set", "kc=0.5"), ""),
    "chain2_list": (FAST, "ss_continue", study("chain2", "--from", "0.3", "--to", "0.302", "--all"),
                    ""),
    "chain2_asym": (FAST, "ss_continue", study("chain2_asym"), ""),
    "chain2_asym_list": (FAST, "ss_continue",
                         study("chain2_asym", "--from", "0.3", "--to", "0.302", "--all"), ""),
    "chain2_asym_kc05": (FAST, "ss_continue", study("chain2_asym", "--set", "kc=0.5"), ""),
    "chain2_coulomb": (FAST, "ss_continue", study("chain2_coulomb"), ""),
    "chain2_coulomb_sim": (FAST, "ss_simulate", study("chain2_coulomb"), ""),
    "chain10": (FAST, "ss_continue", study("chain10"), ""),
    "chain10_sim": (FAST, "ss_simulate", study("chain10"), ""),
}


def gap(run, k):
    return float(re.findall(r"-?\d+\.\d+(?:e[-+]?\d+)?", run.meta("branch.tsv", "gap"))[k])


def counts(r, kind):
    return sum(1 for row in r.table("branch.tsv") if row["kind"] == kind)


def first_of(r, kind, col):
    return float(next(row for row in r.table("branch.tsv") if row["kind"] == kind)[col])


def coulomb_period_error(r):
    """Largest |period - (pi + 2 atan(v/d) + 2 d/v)| over the run's rows (d = mus - muk)."""
    d = 0.4 - 0.25
    return max(abs(float(row["period"]) - (math.pi + 2 * math.atan(float(row["v"]) / d) +
                                           2 * d / float(row["v"])))
               for row in r.table("branch.tsv") if row["kind"] == "stick-slip")


def region_share(r, name):
    """Percent of the (v, beta) rectangle in region `name` (regions.tsv's # face lines)."""
    faces = re.findall(r"^# face \d+: ([^,]+), area ([0-9.e-]+)", r.text("regions.tsv"), re.M)
    return 100 * sum(float(a) for n, a in faces if n == name) / (1.45 * 0.3)


def inset(r, axis, k):
    gp = r.text("chart.gp").split("# the inset")[1]
    m = re.search(r"set %srange \[([-0-9.e]+):([-0-9.e]+)\]" % axis, gp)
    return float(m.group(k))


def scan(r, m, col):
    rows = [row for row in r.table("orbits.tsv") if int(row["m"]) == m and row["point"] == "1"]
    if len(rows) != 1:
        raise KeyError("%d orbits of m = %d" % (len(rows), m))
    return float(rows[0][col])


def S(lab, col):
    return lambda r: r.special(lab, col)


SEED_LINE = "214 points: 87 stick-slip, 25 pure-slip, 102 equilibrium"
GR_HB = "| GR 0.3957902888, HB 0.4409585518 |"
COULOMB_LINE = "GR1  pt 27  v = 0.164713893617  period 6.439475"
DH_ROWS = "writes 1103 rows, gap 0.97661 to 1.02276"
SEED_PD2 = "Ω = 0.58019, just before the grazing point GR1 at Ω = 0.57949"
STRIB_PD2 = "second PD, Ω = 0.58000,\njust before the grazing point GR1 at Ω = 0.57876"
BASIN_LINE = "smallest disturbance 0.441233 in x, 0.453716 in x', 0.0973416 in energy"
STRIB13_ROW = ("| `ss_basin --law stribeck --beta 0.02 --v 1.3 --nx 21 --ny 21` | period 6.28485, "
               "multiplier 1.14484 | 1.10714, 1.13223, 0.612604 |")
LEINE2_ROW = ("| `ss_basin --law leine --mu_s 1 --beta 0.05 --v 2 --nx 21 --ny 21` | period 6.29136, "
              "multiplier 1.53759 | 1.55874, 1.62529, 1.21262 |")
PURE_ROW = ("period 6.284854776, multiplier 1.144838229 and section\namplitude 1.160460219. Its "
            "smallest disturbance is 1.107135 in x, 1.132232 in x' and 0.612604")
LEINE_COUNTS = "101 stick-slip, 52 unstable pure-slip and 101 equilibrium rows"
SEED_CHART = ["| 0 | 0.4498 | 0.5 |", "| 0.05 | 0.3958 | 0.4410 |", "| 0.2 | 0.1491 | 0.1666 |"]
STRIB_CHART = ["| 0.05 | 0.5493 | 0.6520 | 0.103 |", "| 0.1 | 0.2027 | 0.2142 | 0.011 |"]
LEINE_CHART = ["| 0.15 | 0.7208 | 1.1152 |", "| 0.2 | 0.5795 | 0.8444 |", "| 0.3 | 0.4120 | 0.5522 |"]
LEINE_AREAS = "55.5 % is\nstick-slip, 17.6 % bistable and 27.0 % steady sliding only"
NS_LINE = "NS at Ω = 1.13687 and 0.87323. Between them, the locked orbit starts to\nstick (GR at " \
          "Ω = 1.04195 and 0.92745"
NS_TEST = "(Ω = 1.13687139716456, 0.87323194229969)"
R1_LINE = "(Ω 0.984277, A 0.005601 and Ω 1.001890, A 0.003686)"
SCAN_612 = "unstable m = 1 orbit (|μ| = 1.557) and the stable m = 2 orbit (|μ| = 0.772)"


def chart_row(row, k):
    return float(row.strip("| ").split(" | ")[k])


# (passage of the page, the number as printed there, run, measured value[, how]).
CHECKS = [
    (SEED_LINE, "214", "seed", lambda r: r.printed(r"^(\d+) points:")),
    (SEED_LINE, "87", "seed", lambda r: r.printed(r"(\d+) stick-slip,")),
    (SEED_LINE, "25", "seed", lambda r: r.printed(r"(\d+) pure-slip,")),
    (SEED_LINE, "102", "seed", lambda r: r.printed(r"(\d+) equilibrium")),
    ("grazing point v_GR = 0.3957902888", "0.3957902888", "seed", S("GR1", "v")),
    ("jumps to 0.636", "0.636", "seed", lambda r: r.described("GR1", r"([0-9.]+) on the pure-slip")),
    ("Hopf point v_max = 0.4409585518", "0.4409585518", "seed", S("HB1", "v")),
    (GR_HB, "0.3957902888", "seed", S("GR1", "v")),
    (GR_HB, "0.4409585518", "seed", S("HB1", "v")),
    ("v = 0.44095855184409843 written to every digit", "0.44095855184409843", "hb_beta",
     lambda r: float(re.search(r" v=([0-9.]+)", r.meta("branch.tsv", "model")).group(1))),
    ("It finds HB1 at β = 0.05", "0.05", "hb_beta", S("HB1", "beta")),
    ("(v, β) = (0.3957902887978414,\n0.05)", "0.3957902887978414", "gr_chart",
     lambda r: float(next(row["v"] for row in r.table("curves.tsv")
                          if row["curve"] == "GR" and float(row["beta"]) == 0.05))),
    ("GR β = 0.1547673804", "0.1547673804", "seed_beta", S("GR1", "beta")),
    ("HB β = 0.16875", "0.16875", "seed_beta", S("HB1", "beta")),
    ("HB 0.5493061443", "0.5493061443", "stribeck", S("HB1", "v")),
    ("GR = LP 0.6519468583", "0.6519468583", "stribeck", S("GR1", "v")),
    ("GR = LP 0.6519468583", "0.6519468583", "stribeck", S("LP1", "v")),
    ("every period within 1e-8 of π + 2 atan(v/(μs−μk)) + 2(μs−μk)/v", "1e-8", "coulomb_study",
     coulomb_period_error, "le"),
    ("equals v: v = 0.1647138936", "0.1647138936", "coulomb", S("GR1", "v")),
    (COULOMB_LINE, "0.164713893617", "coulomb", S("GR1", "v")),
    (COULOMB_LINE, "6.439475", "coulomb", S("GR1", "period")),
    (COULOMB_LINE, "27", "coulomb", S("GR1", "pt")),
    ("grazing inside the stick band at x = 0.2335286106", "0.2335286106", "coulomb",
     lambda r: r.printed(r"stick band at x = ([0-9.]+)")),
    ("Its period, 6.4394749 = t1 + Δ/v", "6.4394749", "coulomb", S("GR1", "period")),
    ("at CR1's Ω = 0.7167891507042515", "0.7167891507042515", "cr_force",
     lambda r: float(dict(kv.split("=") for kv in r.meta("branch.tsv", "parameters").split(","))
                     ["omega"])),
    ("locates CR again at A = 0.5000000000000168", "0.5000000000000168", "cr_force",
     S("CR1", "force")),
    (DH_ROWS, "1103", "den_hartog", lambda r: r.rows()),
    (DH_ROWS, "0.97661", "den_hartog", lambda r: gap(r, 0)),
    (DH_ROWS, "1.02276", "den_hartog", lambda r: gap(r, 1)),
    ("`max_amplitude` 50) writes 2817", "2817", "den_hartog_cli", lambda r: r.rows()),
    ("compares all 2817 with", "2817", "den_hartog_cli", lambda r: r.rows()),
    ("Ω = 0.63575 (CR1, the located", "0.63575", "floor_static", S("CR1", "omega")),
    ("x_max = 3.194 at Ω = 0.993", "3.194", "floor_static", lambda r: r.argmax("x_max", "omega")[0]),
    ("x_max = 3.194 at Ω = 0.993", "0.993", "floor_static", lambda r: r.argmax("x_max", "omega")[1]),
    ("(LP at Ω = 0.62857 and 0.62849)", "0.62857", "seed_forced", S("LP2", "omega")),
    ("(LP at Ω = 0.62857 and 0.62849)", "0.62849", "seed_forced", S("LP1", "omega")),
    ("a period doubling at\nΩ = 0.61397", "0.61397", "seed_forced", S("PD1", "omega")),
    (SEED_PD2, "0.58019", "seed_forced", S("PD2", "omega")),
    (SEED_PD2, "0.57949", "seed_forced", S("GR1", "omega")),
    ("(LP at Ω = 0.63020 and 0.62374)", "0.63020", "stribeck_forced", S("LP2", "omega")),
    ("(LP at Ω = 0.63020 and 0.62374)", "0.62374", "stribeck_forced", S("LP1", "omega")),
    ("in a PD at Ω = 0.61821", "0.61821", "stribeck_forced", S("PD1", "omega")),
    (STRIB_PD2, "0.58000", "stribeck_forced", S("PD2", "omega")),
    (STRIB_PD2, "0.57876", "stribeck_forced", S("GR1", "omega")),
    ("The m = 2 branch opens from Ω = 0.618208", "0.618208", "m1", S("PD1", "omega")),
    ("doubles again at\nΩ = 0.610558", "0.610558", "m2", S("PD1", "omega")),
    ("the m = 4 branch doubles at Ω = 0.606161", "0.606161", "m4", S("PD1", "omega")),
    ("finds at Ω = 0.392967", "0.392967", "seed_forced_a05", S("LP1", "omega")),
    # The forced seed belt below its Hopf point.
    ("seed set at v = 0.42, just below its supercritical Hopf point (v = 0.441)", "0.441", "seed",
     S("HB1", "v")),
    (NS_LINE, "1.13687", "ns_seed", S("NS1", "omega")),
    (NS_LINE, "0.87323", "ns_seed", S("NS2", "omega")),
    (NS_LINE, "1.04195", "ns_seed", S("GR1", "omega")),
    (NS_LINE, "0.92745", "ns_seed", S("GR2", "omega")),
    (NS_TEST, "1.13687139716456", "ns_seed", S("NS1", "omega")),
    (NS_TEST, "0.87323194229969", "ns_seed", S("NS2", "omega")),
    ("crosses the rectangle (229 points", "229", "ns_seed_chart",
     lambda r: r.printed(r"curve \d+ GR m=1: (\d+) points")),
    (R1_LINE, "0.984277", "ns_seed_chart", lambda r: r.argmax("force", "omega", "codim2.tsv")[1]),
    (R1_LINE, "0.005601", "ns_seed_chart", lambda r: r.argmax("force", "omega", "codim2.tsv")[0]),
    (R1_LINE, "1.001890", "ns_seed_chart", lambda r: r.argmin("force", "omega", "codim2.tsv")[1]),
    (R1_LINE, "0.003686", "ns_seed_chart", lambda r: r.argmin("force", "omega", "codim2.tsv")[0]),
    # Basins of the unforced belt.
    ("(inside the band HB 0.549 < v < LP 0.652)", "0.549", "stribeck", S("HB1", "v")),
    ("(inside the band HB 0.549 < v < LP 0.652)", "0.652", "stribeck", S("LP1", "v")),
    ("steady sliding x̄ = 0.295179 (stable)", "0.295179", "stribeck_basin",
     lambda r: r.printed(r"steady sliding x = ([0-9.]+)")),
    ("stick-slip, period 6.2885;", "6.2885", "stribeck_basin",
     lambda r: r.printed(r"stick-slip orbit: period ([0-9.]+)")),
    ("unstable pure-slip, period 6.28525, multiplier 1.06476", "6.28525", "stribeck_basin",
     lambda r: r.printed(r"pure-slip orbit: period ([0-9.]+)")),
    ("unstable pure-slip, period 6.28525, multiplier 1.06476", "1.06476", "stribeck_basin",
     lambda r: r.printed(r"pure-slip orbit: .*multiplier ([0-9.]+)")),
    (BASIN_LINE, "0.441233", "stribeck_basin", lambda r: r.printed(r"disturbance: x ([0-9.]+)")),
    (BASIN_LINE, "0.453716", "stribeck_basin", lambda r: r.printed(r"disturbance: .* x' ([0-9.]+)")),
    (BASIN_LINE, "0.0973416", "stribeck_basin", lambda r: r.printed(r"energy ([0-9.]+)")),
    ("276 starts end in steady sliding, 1405 in stick-slip", "276", "stribeck_basin",
     lambda r: r.found("basins.tsv", r"^# count: steady-sliding (\d+)")),
    ("276 starts end in steady sliding, 1405 in stick-slip", "1405", "stribeck_basin",
     lambda r: r.found("basins.tsv", r"^# count: stick-slip (\d+)")),
    ("basin stability steady-sliding 0.172602854616", "0.172602854616", "stribeck_basin",
     lambda r: r.printed(r"basin stability steady-sliding ([0-9.]+)")),
    ("basin stability stick-slip 0.827397145384", "0.827397145384", "stribeck_basin",
     lambda r: r.printed(r"basin stability stick-slip ([0-9.]+)")),
    ("the steady-sliding share is 0.308754575361", "0.308754575361", "basin_stability",
     lambda r: r.printed(r"^v = 0\.6: +basin stability steady-sliding ([0-9.]+)")),
    ("from 0.0042 at v = 0.55 to\n0.624 at v = 0.65", "0.0042", "basin_stability",
     lambda r: r.printed(r"^v = 0\.55: +basin stability steady-sliding ([0-9.]+)")),
    ("from 0.0042 at v = 0.55 to\n0.624 at v = 0.65", "0.624", "basin_stability",
     lambda r: r.printed(r"^v = 0\.649+: +basin stability steady-sliding ([0-9.]+)")),
    ("(v < 0.549)", "0.549", "stribeck", S("HB1", "v")),
    ("fold at GR (0.652)", "0.652", "stribeck", S("GR1", "v")),
    ("sends all 1681 starts to stick-slip", "1681", "seed_basin",
     lambda r: r.printed(r"(\d+) stick-slip 0 pure-slip 0 undecided")),
    ("stable pure-slip orbit\n(multiplier 0.810288)", "0.810288", "seed_basin_42",
     lambda r: r.printed(r"pure-slip orbit: .*multiplier ([0-9.]+) \(stable\)")),
]
for row, run in ((STRIB13_ROW, "basin_strib13"), (LEINE2_ROW, "basin_leine2")):
    nums = re.findall(r"\d+\.\d+", row.split("|", 2)[2])
    pats = [r"pure-slip orbit: period ([0-9.]+)", r"pure-slip orbit: .*multiplier ([0-9.]+)",
            r"disturbance: x ([0-9.]+)", r"disturbance: .* x' ([0-9.]+)", r"energy ([0-9.]+)"]
    CHECKS += [(row, q, run, (lambda p: lambda r: r.printed(p))(p)) for q, p in zip(nums, pats)]
for run in ("strib13_up", "strib13_down", "leine2_up", "leine2_down"):
    for q, kind in (("101", "stick-slip"), ("52", "pure-slip"), ("101", "equilibrium")):
        CHECKS.append((LEINE_COUNTS, q, run, (lambda k: lambda r: counts(r, k))(kind)))
for q, col in zip(("6.284854776", "1.144838229", "1.160460219", "1.107135", "1.132232", "0.612604"),
                  ("period", "multiplier", "amplitude", "dist_x", "dist_xdot", "dist_energy")):
    CHECKS.append((PURE_ROW, q, "strib13_up", (lambda c: lambda r: first_of(r, "pure-slip", c))(col)))
CHECKS += [
    ("grows from 0 at HB to 0.196\nat the fold", "0.196", "stribeck",
     lambda r: r.argmax("dist_energy", "v", where=lambda row: row["dist_energy"] not in ("", "nan"))[0]),
]
# The (v, beta) charts: linear interpolation on curves.tsv.
for row in SEED_CHART:
    b = chart_row(row, 0)
    CHECKS.append((row, row.split(" | ")[1], "seed_chart",
                   (lambda b: lambda r: r.crossings("GR", "beta", b, "v")[0])(b)))
    CHECKS.append((row, row.split(" | ")[2].rstrip(" |"), "seed_chart",
                   (lambda b: lambda r: r.crossings("HB", "beta", b, "v")[0])(b)))
for row in STRIB_CHART + LEINE_CHART:
    run = "stribeck_chart" if row in STRIB_CHART else "leine_chart"
    b, cells = chart_row(row, 0), row.strip("| ").split(" | ")
    hb = (lambda b: lambda r: r.crossings("HB", "beta", b, "v")[0])(b)
    gr = (lambda b: lambda r: r.crossings("GR", "beta", b, "v")[0])(b)
    CHECKS += [(row, cells[1], run, hb), (row, cells[2], run, gr)]
    if len(cells) > 3:
        CHECKS.append((row, cells[3], run, (lambda hb, gr: lambda r: gr(r) - hb(r))(hb, gr)))
EDGE = "At the chart's edge v = 0.02, GR is at\nβ = 0.22455 and HB at β = 0.22464"
STRIB_EDGE = "At the chart's edge v = 0.05 the curves\nare at β = 0.1357 (HB) and 0.1359 (GR)"
QUINTIC_LP = "at β = 0.05, v from 0.4769 to 0.4791"
CHECKS += [
    (EDGE, "0.22455", "seed_chart", lambda r: r.crossings("GR", "v", 0.02, "beta")[0]),
    (EDGE, "0.22464", "seed_chart", lambda r: r.crossings("HB", "v", 0.02, "beta")[0]),
    ("with damping above β = 0.2246 no stick-slip", "0.2246", "seed_chart",
     lambda r: r.crossings("GR", "v", 0.02, "beta")[0]),
    (STRIB_EDGE, "0.1357", "stribeck_chart", lambda r: r.crossings("HB", "v", 0.05, "beta")[0]),
    (STRIB_EDGE, "0.1359", "stribeck_chart", lambda r: r.crossings("GR", "v", 0.05, "beta")[0]),
    ("Above β = 0.1359 there is no stick-slip", "0.1359", "stribeck_chart",
     lambda r: r.crossings("GR", "v", 0.05, "beta")[0]),
    ("**GH at v = 0.5, β = 0.0375**", "0.5", "quintic_chart",
     lambda r: r.printed(r"^\s*GH\s+v = ([0-9.]+)")),
    ("**GH at v = 0.5, β = 0.0375**", "0.0375", "quintic_chart",
     lambda r: r.printed(r"^\s*GH\s+.*beta = ([0-9.]+)")),
    ("v = 0.4630979700, β = 0.0561978870", "0.4630979700", "quintic_chart",
     lambda r: r.printed(r"^\s*GR-LP\s+v = ([0-9.]+)")),
    ("v = 0.4630979700, β = 0.0561978870", "0.0561978870", "quintic_chart",
     lambda r: r.printed(r"^\s*GR-LP\s+.*beta = ([0-9.]+)")),
    ("(at β = 0.03, v from 0.5125 to 0.5432)", "0.5125", "quintic_chart",
     lambda r: r.crossings("HB", "beta", 0.03, "v")[0]),
    ("(at β = 0.03, v from 0.5125 to 0.5432)", "0.5432", "quintic_chart",
     lambda r: r.crossings("GR", "beta", 0.03, "v")[0]),
    (QUINTIC_LP, "0.4769", "quintic_chart", lambda r: r.crossings("LP", "beta", 0.05, "v")[0]),
    (QUINTIC_LP, "0.4791", "quintic_chart", lambda r: r.crossings("HB", "beta", 0.05, "v")[0]),
    ("v 0.447–0.516,\nβ 0.031–0.063", "0.447", "quintic_chart", lambda r: inset(r, "x", 1)),
    ("v 0.447–0.516,\nβ 0.031–0.063", "0.516", "quintic_chart", lambda r: inset(r, "x", 2)),
    ("v 0.447–0.516,\nβ 0.031–0.063", "0.031", "quintic_chart", lambda r: inset(r, "y", 1)),
    ("v 0.447–0.516,\nβ 0.031–0.063", "0.063", "quintic_chart", lambda r: inset(r, "y", 2)),
    ("GR leaves the chart's edge v = 1.5 at β = 0.1085", "0.1085", "leine_chart",
     lambda r: r.crossings("GR", "v", 1.5, "beta")[0]),
    (LEINE_AREAS, "55.5", "leine_chart", lambda r: region_share(r, "stick-slip")),
    (LEINE_AREAS, "17.6", "leine_chart", lambda r: region_share(r, "bistable")),
    (LEINE_AREAS, "27.0", "leine_chart", lambda r: region_share(r, "steady sliding only")),
    # Physical units.
    ("HB at `belt_speed` 2.1629016968 m/s", "2.1629016968", "physical", S("HB1", "belt_speed")),
    ("= 0.4409585518 × L/t0", "0.4409585518", "physical", S("HB1", "v")),
    ("GR at 1.9413513666 m/s", "1.9413513666", "physical", S("GR1", "belt_speed")),
]

# The forced scans (ss_simulate --orbits): fast; the cascade's table with --max_m 8: slow.
for name, om, force in (("scan_06", "0.6", "0.3"), ("scan_14", "1.4", "0.1"),
                        ("scan_18", "1.8", "0.3"), ("scan_20", "2.0", "0.3")):
    RUNS[name] = (FAST, "ss_simulate", SEED_SCAN + ["--omega", om, "--force", force], "")
RUNS["scan_612"] = (FAST, "ss_simulate", study("stribeck_forced", "--omega", "0.612", "--orbits"),
                    "")
for om in ("0.617", "0.608", "0.605", "0.603"):
    RUNS["scan_" + om] = (SLOW, "ss_simulate", SCAN + [om], "")


def stable(r, col):
    """Column `col` of the one stable orbit of a scan."""
    rows = [row for row in r.table("orbits.tsv") if row["stable"] == "1" and row["point"] == "1"]
    if len(rows) != 1:
        raise KeyError("%d stable orbits" % len(rows))
    return float(rows[0][col])


SEED_SCAN_06 = "at Ω = 0.6, m = 1, 2 unstable and a stable m = 4 orbit with 4\nsticks"
SEED_SCAN_14 = "at A = 0.1, Ω = 1.4 a stable m = 3 orbit with 2 sticks"
SEED_SCAN_2 = "at A = 0.3, Ω = 1.8 and 2.0 a stable\nm = 2 orbit with 2 sticks"
CHECKS += [
    (SEED_SCAN_06, "1", "scan_06", lambda r: scan(r, 1, "stable") + 1),
    (SEED_SCAN_06, "2", "scan_06", lambda r: scan(r, 2, "stable") + 2),
    (SEED_SCAN_06, "4", "scan_06", lambda r: stable(r, "m")),
    (SEED_SCAN_06, "4", "scan_06", lambda r: stable(r, "sticks")),
    (SEED_SCAN_14, "3", "scan_14", lambda r: stable(r, "m")),
    (SEED_SCAN_14, "2", "scan_14", lambda r: stable(r, "sticks")),
    (SEED_SCAN_2, "2", "scan_18", lambda r: stable(r, "m")),
    (SEED_SCAN_2, "2", "scan_18", lambda r: stable(r, "sticks")),
    (SEED_SCAN_2, "2", "scan_20", lambda r: stable(r, "m")),
    (SEED_SCAN_2, "2", "scan_20", lambda r: stable(r, "sticks")),
    (SCAN_612, "1.557", "scan_612", lambda r: scan(r, 1, "mult_max")),
    (SCAN_612, "0.772", "scan_612", lambda r: scan(r, 2, "mult_max")),
]
CASCADE = {"0.617": "| 0.617 | m = 2 (|μ| = 0.53) | m = 1 (1.12) |",
           "0.608": "| 0.608 | m = 4 (0.28) | m = 1 (1.82), m = 2 (1.29) |",
           "0.605": "| 0.605 | m = 8 (0.50) | m = 1, 2, 4 |",
           "0.603": "| 0.603 | none up to m = 8 | m = 1, 2, 4, 8 (2.48) |"}
for om, row in CASCADE.items():
    run = "scan_" + om
    stable_part, unstable_part = row.strip("| ").split(" | ")[1:]
    m = re.search(r"m = (\d+) \(\|?μ?\|?(?: = )?([0-9.]+)\)", stable_part)
    if m:
        CHECKS.append((row, m.group(1), run, lambda r: stable(r, "m")))
        CHECKS.append((row, m.group(1), run, lambda r: stable(r, "sticks")))
        CHECKS.append((row, m.group(2), run, lambda r: stable(r, "mult_max")))
    else:  # no stable orbit: the unstable ones are 1, 2, 4, 8
        CHECKS.append((row, "8", run, lambda r: sum(
            1 for row in r.table("orbits.tsv") if row["stable"] == "0" and row["point"] == "1") * 2))
    for um, mu in re.findall(r"m = (\d+) \(([0-9.]+)\)", unstable_part):
        CHECKS.append((row, mu, run, (lambda m: lambda r: scan(r, m, "mult_max"))(int(um))))
    last = re.search(r"(\d+) \(2\.48\)", unstable_part)
    if last:
        CHECKS.append((row, "2.48", run, lambda r: scan(r, 8, "mult_max")))

# The forced basins (slow, 81 x 81 and 61 x 61 starts) and the Omega = 0.558 one (fast).
RUNS["coulomb_basin"] = (SLOW, "ss_basin", COULOMB_BASIN, "")
RUNS["seed_forced_basin"] = (SLOW, "ss_basin", study("seed_forced_basin"), "")
RUNS["seed_forced_basin_558"] = (FAST, "ss_basin", study(
    "seed_forced_basin", "--omega", "0.558", "--nx", "9", "--ny", "9", "--max_period", "32"), "")
RUNS["stribeck_forced_basin"] = (SLOW, "ss_basin", study("stribeck_forced_basin"), "")


def attractor(r, k, col):
    return float(r.table("attractors.tsv")[k][col])


def starts(r, kind, col="lyapunov", agg=lambda v: v):
    return agg([float(row[col]) for row in r.table("basins_forced.tsv") if row["kind"] == kind])


def median(v):
    v = sorted(v)
    return 0.5 * (v[(len(v) - 1) // 2] + v[len(v) // 2])


def cycle(r, k, col):
    block = r.text("basins_forced.gp").split("$cycles << EOD\n")[1].split("EOD")[0]
    row = block.splitlines()[1 + k].split("\t")
    return float(row[{"x": 1, "xdot": 2}[col]])


COULOMB_COUNTS = "Of the 3721 starts in [−1.5, 1.5]², 3406 end on the stick-slip orbit and 315 on the pure-slip"
SEED_BASIN = ("Of the 6561 starts, 4393 (67 %)\nend on the period-2 orbit (one stick per period) and "
              "2168 (33 %) on the chaotic attractor\n(0.66 sticks per forcing period")
SEED_558 = "finds it for 36 of 81 starts (43 chaotic, 2 undecided)"
SEED_LAMBDA = "λ₁ = 0.017 per unit time (the median over its 2168 starts in basins_forced.tsv), 0.19 per"
CYCLES = "(0.546, 0.153) and (0.863, 0.096)"
STRIB_BASIN = ("6268 of the 6561 starts (95.5 %) end on the\norbit the down sweep follows (section x = "
               "0.553), 293 (4.5 %) on the up sweep's (x = 0.841)")
CHECKS += [
    (COULOMB_COUNTS, "3721", "coulomb_basin", lambda r: r.rows("basins_forced.tsv")),
    (COULOMB_COUNTS, "3406", "coulomb_basin", lambda r: attractor(r, 0, "starts")),
    (COULOMB_COUNTS, "315", "coulomb_basin", lambda r: attractor(r, 1, "starts")),
    (SEED_BASIN, "6561", "seed_forced_basin", lambda r: r.rows("basins_forced.tsv")),
    (SEED_BASIN, "4393", "seed_forced_basin", lambda r: attractor(r, 0, "starts")),
    (SEED_BASIN, "67", "seed_forced_basin", lambda r: 100 * attractor(r, 0, "fraction"), "rounded"),
    (SEED_BASIN, "2", "seed_forced_basin", lambda r: attractor(r, 0, "m")),
    (SEED_BASIN, "2168", "seed_forced_basin", lambda r: attractor(r, 1, "starts")),
    (SEED_BASIN, "33", "seed_forced_basin", lambda r: 100 * attractor(r, 1, "fraction"), "rounded"),
    (SEED_BASIN, "0.66", "seed_forced_basin", lambda r: attractor(r, 1, "sticks_per_period")),
    ("period-27 orbit (18 sticks)", "27", "seed_forced_basin_558", lambda r: attractor(r, 0, "m")),
    ("period-27 orbit (18 sticks)", "18", "seed_forced_basin_558",
     lambda r: attractor(r, 0, "sticks")),
    (SEED_558, "36", "seed_forced_basin_558", lambda r: attractor(r, 0, "starts")),
    (SEED_558, "81", "seed_forced_basin_558", lambda r: r.rows("basins_forced.tsv")),
    (SEED_558, "43", "seed_forced_basin_558", lambda r: attractor(r, 1, "starts")),
    (SEED_558, "2", "seed_forced_basin_558", lambda r: attractor(r, 2, "starts")),
    (SEED_LAMBDA, "0.017", "seed_forced_basin", lambda r: starts(r, "chaotic", agg=median)),
    (SEED_LAMBDA, "2168", "seed_forced_basin", lambda r: starts(r, "chaotic", agg=len)),
    (SEED_LAMBDA, "0.19", "seed_forced_basin",
     lambda r: starts(r, "chaotic", agg=median) * 2 * math.pi / 0.559),
    ("up to 1024 (attractors.tsv's", "1024", "seed_forced_basin",
     lambda r: r.found("attractors.tsv", r"^# undecided_run_on: .* up to (\d+) periods")),
    ("with x' below −0.4 locks", "0.4", "seed_forced_basin",
     lambda r: -starts(r, "chaotic", "xdot", min), "le"),
    (CYCLES, "0.546", "seed_forced_basin", lambda r: cycle(r, 0, "x")),
    (CYCLES, "0.153", "seed_forced_basin", lambda r: cycle(r, 0, "xdot")),
    (CYCLES, "0.863", "seed_forced_basin", lambda r: cycle(r, 1, "x")),
    (CYCLES, "0.096", "seed_forced_basin", lambda r: cycle(r, 1, "xdot")),
    (STRIB_BASIN, "6268", "stribeck_forced_basin", lambda r: attractor(r, 0, "starts")),
    (STRIB_BASIN, "6561", "stribeck_forced_basin", lambda r: r.rows("basins_forced.tsv")),
    (STRIB_BASIN, "95.5", "stribeck_forced_basin", lambda r: 100 * attractor(r, 0, "fraction")),
    (STRIB_BASIN, "0.553", "stribeck_forced_basin", lambda r: attractor(r, 0, "x")),
    (STRIB_BASIN, "293", "stribeck_forced_basin", lambda r: attractor(r, 1, "starts")),
    (STRIB_BASIN, "4.5", "stribeck_forced_basin", lambda r: 100 * attractor(r, 1, "fraction")),
    (STRIB_BASIN, "0.841", "stribeck_forced_basin", lambda r: attractor(r, 1, "x")),
]

# The forced (Omega, A) charts' curves (slow: about 60 one-parameter runs each).
RUNS["stribeck_forced_chart"] = (SLOW, "ss_chart", study("stribeck_forced", "--grid", "0"), "")
RUNS["seed_forced_chart"] = (SLOW, "ss_chart", study("seed_forced", "--grid", "0"), "")
RUNS["r2_chart"] = (SLOW, "ss_chart", R2_CHART, "")


def upper_gr(r, col):
    """The lowest point of the GR curve above which the m = 1 orbit never sticks."""
    rows = [row for row in r.table("curves.tsv")
            if row["curve"] == "GR" and float(row["omega"]) > 0.7 and float(row["force"]) > 0.3]
    return float(min(rows, key=lambda row: float(row["force"]))[col])


def left_lp(r, end, col):
    """The LP curve that ends near (0.445, 0.19): its lowest or highest point."""
    low = {}
    for row in r.table("curves.tsv"):
        if row["curve"] == "LP":
            low[row["id"]] = min(low.get(row["id"], 1e9), float(row["force"]))
    ids = [i for i, a in low.items() if abs(a - 0.19) < 0.01]
    if len(ids) != 1:
        raise KeyError("%d LP curves end near A = 0.19" % len(ids))
    rows = [row for row in r.table("curves.tsv") if row["id"] == ids[0]]
    return float((min if end == "low" else max)(rows, key=lambda row: float(row["force"]))[col])


def codim2(r, label, k, col):
    rows = sorted((row for row in r.table("codim2.tsv") if row["label"] == label),
                  key=lambda row: float(row["omega"]))
    return float(rows[k][col])


def m2_curves(r):
    return len(re.findall(r"^  curve \d+ \w+ m=2:", r.stdout, re.M))


STRIB_CURVES = "58 one-parameter runs and 15 curves; 84 seeds"
SEED_CURVES = "18 curves from 59\none-parameter runs (6.7 s wall), 8 of them of m = 2"
GG = "Near Ω 0.4867,\nA 0.4935 it has a corner (GG)"
LEFT_LP = "It runs from (Ω 0.445, A 0.19) up to (0.37, 0.6)"
R2 = "two R2 points (Ω 1.981467,\nA 0.111154 and Ω 2.018449, A 0.114634)"
CHECKS += [
    (STRIB_CURVES, "58", "stribeck_forced_chart",
     lambda r: r.printed(r"from (\d+) one-parameter runs")),
    (STRIB_CURVES, "15", "stribeck_forced_chart", lambda r: r.printed(r"^(\d+) curves,")),
    (STRIB_CURVES, "84", "stribeck_forced_chart", lambda r: r.printed(r"(\d+) seeds gave no")),
    ("Its minimum, A ≈ 0.37 near\nΩ ≈ 0.93", "0.37", "stribeck_forced_chart",
     lambda r: upper_gr(r, "force")),
    ("Its minimum, A ≈ 0.37 near\nΩ ≈ 0.93", "0.93", "stribeck_forced_chart",
     lambda r: upper_gr(r, "omega")),
    (SEED_CURVES, "18", "seed_forced_chart", lambda r: r.printed(r"^(\d+) curves,")),
    (SEED_CURVES, "59", "seed_forced_chart", lambda r: r.printed(r"from (\d+) one-parameter runs")),
    (SEED_CURVES, "8", "seed_forced_chart", m2_curves),
    ("starts at A ≈ 0.45 near Ω ≈ 0.98", "0.45", "seed_forced_chart",
     lambda r: upper_gr(r, "force")),
    ("starts at A ≈ 0.45 near Ω ≈ 0.98", "0.98", "seed_forced_chart",
     lambda r: upper_gr(r, "omega")),
    (GG, "0.4867", "seed_forced_chart", lambda r: codim2(r, "GG", 0, "omega")),
    (GG, "0.4935", "seed_forced_chart", lambda r: codim2(r, "GG", 0, "force")),
    (LEFT_LP, "0.445", "seed_forced_chart", lambda r: left_lp(r, "low", "omega")),
    (LEFT_LP, "0.19", "seed_forced_chart", lambda r: left_lp(r, "low", "force")),
    (LEFT_LP, "0.37", "seed_forced_chart", lambda r: left_lp(r, "high", "omega")),
    (LEFT_LP, "0.6", "seed_forced_chart", lambda r: left_lp(r, "high", "force")),
    ("It ends at (0.44522, 0.19133)", "0.44522", "seed_forced_chart",
     lambda r: left_lp(r, "low", "omega")),
    ("It ends at (0.44522, 0.19133)", "0.19133", "seed_forced_chart",
     lambda r: left_lp(r, "low", "force")),
    ("Below A ≈ 0.19 this branch has no fold", "0.19", "seed_forced_chart",
     lambda r: left_lp(r, "low", "force")),
    (R2, "1.981467", "r2_chart", lambda r: codim2(r, "R2", 0, "omega")),
    (R2, "0.111154", "r2_chart", lambda r: codim2(r, "R2", 0, "force")),
    (R2, "2.018449", "r2_chart", lambda r: codim2(r, "R2", -1, "omega")),
    (R2, "0.114634", "r2_chart", lambda r: codim2(r, "R2", -1, "force")),
]

# The orbit diagrams (slow: 800 values, each 500 + 200 forcing periods).
RUNS["stribeck_od"] = (SLOW, "ss_orbit_diagram", study("forced_stribeck_orbit_diagram"), "")


def lyap_range(r, lo, hi, k):
    v = [float(row["lyapunov"]) for row in r.table("lyapunov.tsv") if lo <= float(row["omega"]) <= hi]
    return (min(v), max(v))[k]


def period_one_from(r):
    """The lowest Omega from which every value of both sweeps is a period-1 orbit."""
    pts = {}
    for row in r.table("orbit_diagram.tsv"):
        pts.setdefault(float(row["omega"]), []).append((float(row["x"]), float(row["xdot"])))
    lo = None
    for w in sorted(pts, reverse=True):
        p = pts[w]
        if max(max(abs(a[0] - p[0][0]), abs(a[1] - p[0][1])) for a in p) > 1e-6:
            break
        lo = w
    return lo


def stick_runs(r, lo):
    """[(sticks per period, first Omega, last Omega)] above lo, the same in both sweeps."""
    runs = {}
    for d in ("up", "down"):
        rows = sorted((float(row["omega"]), row["sticks_per_period"])
                      for row in r.table("lyapunov.tsv")
                      if row["direction"] == d and float(row["omega"]) >= lo)
        out = []
        for w, n in rows:
            if out and out[-1][0] == n:
                out[-1][2] = w
            else:
                out.append([n, w, w])
        runs[d] = out
    if runs["up"] != runs["down"]:
        raise KeyError("the sweeps differ above %g" % lo)
    if [n for n, _, _ in runs["up"]] != ["1", "2", "1", "0"]:  # one, two, one, none
        raise KeyError("sticks per period above %g: %s" % (lo, runs["up"]))
    return runs["up"]


STRIB_OD = ("Ω = 0.3604 up the response is a period-1 orbit, with λ₁ between −0.47 and −0.01: one "
            "stick per\nperiod up to Ω = 0.3779, two from 0.3805 to 0.5584, one again from 0.5609 to "
            "0.7188, and none from\n0.7213 on")
STICK_RUNS = [("0.3779", 0, 2), ("0.3805", 1, 1), ("0.5584", 1, 2), ("0.5609", 2, 1),
              ("0.7188", 2, 2), ("0.7213", 3, 1)]
CHECKS += [
    (STRIB_OD, "0.3604", "stribeck_od", period_one_from),
    ("Below 0.3604 come locking windows", "0.3604", "stribeck_od", period_one_from),
    (STRIB_OD, "0.47", "stribeck_od", lambda r: -lyap_range(r, period_one_from(r), 1.2, 0)),
    (STRIB_OD, "0.01", "stribeck_od", lambda r: -lyap_range(r, period_one_from(r), 1.2, 1)),
]
for q, k, j in STICK_RUNS:
    CHECKS.append((STRIB_OD, q, "stribeck_od",
                   (lambda k, j: lambda r: stick_runs(r, period_one_from(r))[k][j])(k, j)))
CHECKS += [
    ("Near Ω = 0.35, λ₁ = 0.021 ±\n0.0006", "0.021", "stribeck_od",
     lambda r: float(r.lyapunov("up", 0.35)["lyapunov"]), "err 0.0006"),
    ("All 800 values complete", "800", "stribeck_od",
     lambda r: r.rows("lyapunov.tsv") if "0 values failed" in r.meta("lyapunov.tsv", "status")
     else -1),
]

# Feigenbaum's table (slow: examples/python/feigenbaum.py, about a minute).
RUNS["feigenbaum"] = (SLOW, "examples/python/feigenbaum.py", ["0.25", "0.27", "0.3"], "")


def cascade_value(r, force, k, ratios=False):
    line = re.search(r"^A = %s: .*$" % re.escape(force), r.stdout, re.M)
    if ratios:
        line = re.search(r"interval ratios (.*?)  \(", r.stdout[line.end():])
        return float(line.group(1).split(", ")[k])
    return float(line.group(0).split("at Omega ")[1].split(", ")[k])


FEIGENBAUM = {
    "0.25": "| 0.25 | 0.652766275042, 0.645080107919, 0.641597595667, 0.640656992599, "
            "0.640439076656 | 2.207, 3.702, 4.316 |",
    "0.27": "| 0.27 | 0.638176968274, 0.630398843049, 0.626564736976, 0.625447537572, "
            "0.625180345458 | 2.029, 3.432, 4.181 |",
    "0.3": "| 0.3 | 0.618208471272, 0.610558022942, 0.606160962290, 0.604563234680, "
           "0.604123613319 | 1.740, 2.752, 3.634 |",
}
for force, row in FEIGENBAUM.items():
    pds, ratios = row.strip("| ").split(" | ")[1:]
    for k, q in enumerate(pds.split(", ")):
        CHECKS.append((row, q, "feigenbaum", (lambda f, k: lambda r: cascade_value(r, f, k))(force, k),
                       "err 1.5e-11"))  # 3e-11: they move by that much between builds
    for k, q in enumerate(ratios.split(", ")):
        CHECKS.append((row, q, "feigenbaum",
                       (lambda f, k: lambda r: cascade_value(r, f, k, True))(force, k)))
RUNS["seed_forced_od"] = (SLOW, "ss_orbit_diagram", study("seed_forced"), "")
RUNS["seed_forced_od_coarse"] = (SLOW, "ss_orbit_diagram",
                                 study("seed_forced", "--n", "300", "--to", "1.2"), "")
RUNS["stribeck_forced_od"] = (SLOW, "ss_orbit_diagram", study("stribeck_forced"), "")


def chaotic(row):
    """ss_basin's test for chaos: above 3 standard errors and 1e-3."""
    lam, err = float(row["lyapunov"]), float(row["lyapunov_err"])
    return lam > 3 * err and lam > 1e-3


def only_chaotic(r, sweeps=("up", "down")):
    """The one Omega where the sweeps `sweeps` are chaotic, and only they."""
    by = {}
    for row in r.table("lyapunov.tsv"):
        by.setdefault(row["omega"], {})[row["direction"]] = chaotic(row)
    hits = [w for w, d in by.items() if all(d.get(s) == (s in sweeps) for s in ("up", "down"))]
    if len(hits) != 1:
        raise KeyError("chaotic in %s at %d values" % (sweeps, len(hits)))
    return float(hits[0])


def chaotic_anywhere(r):
    """The one Omega with a chaotic value in either sweep; it must be chaotic in both."""
    hits = {(row["omega"], row["direction"]) for row in r.table("lyapunov.tsv") if chaotic(row)}
    omegas = {w for w, _ in hits}
    if len(omegas) != 1 or len(hits) != 2:
        raise KeyError("chaotic values: %s" % sorted(hits))
    return float(omegas.pop())


def lam(direction, omega):
    return lambda r: float(r.lyapunov(direction, omega)["lyapunov"])


def lam_err(direction, omega):
    """lambda_1 with its own error bar: the check allows twice the run's standard error."""
    return lambda r: (lam(direction, omega)(r), float(r.lyapunov(direction, omega)["lyapunov_err"]))


def positive_both(r, lo, hi, k):
    """The first (k = 0) or last (k = -1) Omega in [lo, hi] with lambda_1 > 0 in both sweeps."""
    pos = {}
    for row in r.table("lyapunov.tsv"):
        w = float(row["omega"])
        if lo <= w <= hi:
            pos.setdefault(w, []).append(float(row["lyapunov"]) > 0)
    return sorted(w for w, p in pos.items() if p == [True, True])[k]


def zero_both(r, lo, hi):
    """The Omegas in [lo, hi] with |lambda_1| within its error in both sweeps."""
    z = {}
    for row in r.table("lyapunov.tsv"):
        w = float(row["omega"])
        if lo <= w <= hi:
            z.setdefault(w, []).append(abs(float(row["lyapunov"])) <= float(row["lyapunov_err"]))
    return sorted(w for w, p in z.items() if p == [True, True])


def repeats(r, direction, omega, period):
    """Largest change of the section point over `period` forcing periods."""
    rows = [row for row in r.table("orbit_diagram.tsv") if row["direction"] == direction]
    w = min({float(row["omega"]) for row in rows}, key=lambda w: abs(w - omega))
    pts = [(float(row["x"]), float(row["xdot"])) for row in rows if float(row["omega"]) == w]
    return max(max(abs(a[0] - b[0]), abs(a[1] - b[1])) for a, b in zip(pts, pts[period:]))


SEED_OD = "with λ₁ from −0.02 down to −0.88 (near\nΩ = 0.788"
SEED_558 = "Only\nΩ = 0.558 has λ₁ above 3σ and 1e-3 (ss_basin's test for chaos), in both sweeps (0.0099 ± 0.0015\nup, 0.0079 ± 0.0022 down)"
STRIB_6 = "0.0113 ± 0.0022 up and\n0.0128 ± 0.0017 down at Ω = 0.6"
WINDOW = "at Ω = 0.60075 the down sweep lands on a period-20 orbit (λ₁ = −0.0042; its\nsection points repeat after 20 periods to 4e-7) while the up sweep stays chaotic\n(λ₁ = 0.0131)"
ZERO = "at Ω = 0.59774 and 0.60301 λ₁ is within its error of 0 in both sweeps"
BELOW = "Ω = 0.5459 (0.0077) and\n0.5594 (0.0139)"
CHECKS += [
    ("Above Ω ≈ 0.63 the\nsection is one point", "0.63", "seed_forced", S("LP2", "omega")),
    (SEED_OD, "0.02", "seed_forced_od", lambda r: -lyap_range(r, 0.63, 1, 1)),
    (SEED_OD, "0.88", "seed_forced_od", lambda r: -lyap_range(r, 0.63, 1, 0)),
    (SEED_OD, "0.788", "seed_forced_od", lambda r: float(min(
        r.table("lyapunov.tsv"), key=lambda row: float(row["lyapunov"]))["omega"])),
    (SEED_558, "0.558", "seed_forced_od", chaotic_anywhere),
    (SEED_558, "0.0099", "seed_forced_od", lam("up", 0.558), "err 0.0015"),
    (SEED_558, "0.0015", "seed_forced_od", lambda r: float(r.lyapunov("up", 0.558)["lyapunov_err"])),
    (SEED_558, "0.0079", "seed_forced_od", lam("down", 0.558), "err 0.0022"),
    (SEED_558, "0.0022", "seed_forced_od",
     lambda r: float(r.lyapunov("down", 0.558)["lyapunov_err"])),
    ("sweeps part at Ω = 0.559: the up sweep is chaotic", "0.559", "seed_forced_od_coarse",
     lambda r: only_chaotic(r, ("up",))),
    ("the down sweep sits on a period-2 orbit", "2", "seed_forced_od_coarse",
     lambda r: 2 if repeats(r, "down", 0.559, 2) < 1e-6 < repeats(r, "down", 0.559, 1) else 0),
    ("two from the PD at Ω ≈ 0.618", "0.618", "stribeck_forced", S("PD1", "omega")),
    ("positive at most values of 0.5955 ≤ Ω ≤ 0.6038 in both sweeps", "0.5955", "stribeck_forced_od",
     lambda r: positive_both(r, 0.59, 0.61, 0)),
    ("positive at most values of 0.5955 ≤ Ω ≤ 0.6038 in both sweeps", "0.6038", "stribeck_forced_od",
     lambda r: positive_both(r, 0.59, 0.61, -1)),
    (STRIB_6, "0.0113", "stribeck_forced_od", lam("up", 0.6), "err 0.0022"),
    (STRIB_6, "0.0022", "stribeck_forced_od", lambda r: float(r.lyapunov("up", 0.6)["lyapunov_err"])),
    (STRIB_6, "0.0128", "stribeck_forced_od", lam("down", 0.6), "err 0.0017"),
    (STRIB_6, "0.0017", "stribeck_forced_od",
     lambda r: float(r.lyapunov("down", 0.6)["lyapunov_err"])),
    (WINDOW, "0.0042", "stribeck_forced_od", lambda r: -lam("down", 0.60075)(r)),
    (WINDOW, "4e-7", "stribeck_forced_od", lambda r: repeats(r, "down", 0.60075, 20), "le"),
    (WINDOW, "0.0131", "stribeck_forced_od", lam_err("up", 0.60075), "err"),
    (ZERO, "0.59774", "stribeck_forced_od", lambda r: zero_both(r, 0.5955, 0.6038)[0]),
    (ZERO, "0.60301", "stribeck_forced_od", lambda r: zero_both(r, 0.5955, 0.6038)[-1]),
    (BELOW, "0.5459", "stribeck_forced_od", lambda r: only_chaotic_below(r, 0)),
    (BELOW, "0.0077", "stribeck_forced_od", lam_err("up", 0.5459), "err"),
    (BELOW, "0.5594", "stribeck_forced_od", lambda r: only_chaotic_below(r, 1)),
    (BELOW, "0.0139", "stribeck_forced_od", lam_err("up", 0.5594), "err"),
    ("Between the folds (0.624 ≤ Ω ≤ 0.630)", "0.624", "stribeck_forced", S("LP1", "omega")),
    ("Between the folds (0.624 ≤ Ω ≤ 0.630)", "0.630", "stribeck_forced", S("LP2", "omega")),
]


def only_chaotic_below(r, k):
    """The k-th Omega below the cascade (< 0.59) where a sweep is chaotic; exactly two, up only."""
    hits = sorted({(float(row["omega"]), row["direction"]) for row in r.table("lyapunov.tsv")
                   if float(row["omega"]) < 0.59 and chaotic(row)})
    if len(hits) != 2 or any(d != "up" for _, d in hits):
        raise KeyError("chaotic below the cascade: %s" % hits)
    return hits[k][0]

# The output the page quotes verbatim: each number of each quoted line against the same
# number of the run's line that starts alike (the wall time "in 22.8 ms" excepted).
NUM = r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?"


def quoted_line(r, head, k):
    for line in r.stdout.splitlines():
        if line.strip().startswith(head):
            return float(re.findall(NUM, line)[k])
    raise KeyError(head)


SEED_BLOCK = [
    "ss_continue: v from 0.05 to 0.5; law=cubic beta=0.05 v=[0.05, 0.5] mu_s=0.4 mu_m=0.25 v_m=0.5 k5=0",
    "GR1  pt 87  v = 0.395790288798  period 6.367585  x in [-0.065469, 0.730586]  grazing-sliding: "
    "stick phase vanishes; multiplier 0 on the stick-slip side, 0.6359399616 on the pure-slip side",
    "HB1  pt 200  v = 0.440958551844  period 6.283185  x in [0.253014, 0.253014]  Hopf point of "
    "steady sliding (2 beta + mu'(v) = 0), supercritical (mu''' > 0)",
]
COULOMB_FULL = ("GR1  pt 27  v = 0.164713893617  period 6.439475  x in [0.072256, 0.458017]  grazing "
                "inside the stick band at x = 0.2335286106")
for line, run in [(l, "seed") for l in SEED_BLOCK] + [(COULOMB_FULL, "coulomb")]:
    head = line.split(":")[0] if line.startswith("ss_") else line[:4]
    for k, q in enumerate(re.findall(NUM, line)):
        CHECKS.append((line, q, run,
                       (lambda h, k: lambda r: quoted_line(r, h, k))(head, k)))
CHECKS += [
    ("The β = 0.05 row matches the one-parameter run above (0.3957902888, 0.4409585518)",
     "0.3957902888", "seed", S("GR1", "v")),
    ("The β = 0.05 row matches the one-parameter run above (0.3957902888, 0.4409585518)",
     "0.4409585518", "seed", S("HB1", "v")),
    ("agrees with the one-parameter run (0.6519468583)", "0.6519468583", "stribeck",
     S("GR1", "v")),
    ("took 0.4 s (12 one-parameter runs)", "12", "ns_seed_chart",
     lambda r: r.printed(r"from (\d+) one-parameter runs")),
]


# docs/systems.md: the chain studies (two unequal blocks, the Coulomb chain, ten blocks).
def branch_row(r, branch, col, k=0):
    return float([row for row in r.table("branch.tsv") if row["branch"] == branch][k][col])


def in_step_from(r, col):
    """The first stick exit from which x1 = x2 (1e-9) at every exit (section.tsv)."""
    rows = r.table("section.tsv")
    same = [abs(float(q["x1"]) - float(q["x2"])) < 1e-9 for q in rows]
    k = next(i for i in range(len(rows)) if all(same[i:]))
    return float(rows[k][col])


def late_range(r, k, t0=400):
    xs = [float(q["x1"]) for q in r.table("trajectory.tsv") if float(q["t"]) >= t0]
    return (min(xs), max(xs))[k]


def exit_gap(r):
    ts = [float(q["t"]) for q in r.table("section.tsv")]
    return ts[-1] - ts[-3]


CHAIN2 = ("- **Branch 1** ends at GR, v = 0.3952149311, where both stick phases vanish (sticks 2 → 0)")
CHAIN2_T = ("block's extremes are the other's, and both stick once per period. Its period is 5.4337 at\n"
            "  v = 0.3, near the out-of-phase mode's 2π/w = 5.310, w = √(1 + 2kc) = 1.18322")
KC05 = ("HB, with w = √(1 + 2kc) = 1.41421, a stable orbit with the blocks half a period apart, of\n"
        "period 4.5257 at v = 0.3 (near 2π/√2 = 4.443), and branch 1 ending at GR, v = 0.3948974826")
ASYM_HEAD = ["branch 1: 18 rows, sequence-ended", "branch 2: 17 rows, sequence-ended"]
ASYM05_HEAD = ["branch 1: 41 rows, sequence-ended", "branch 2: 62 rows, sequence-ended"]
ASYM = ("- **The attractor at v = 0.3 is long**: period 29.45572, six stick phases a period (three\n"
        "  per block), x1 over [−0.11951, 0.65768] and x2 over [−0.17862, 0.72536], largest multiplier\n"
        "  0.52371 (stable). Its branch is short: up to SL1, v = 0.30585, and down to SL2,\n"
        "  v = 0.29513")
ASYM_ROW = ("its x1 runs over [0.00924, 0.55471], the heavier block's x2 over\n"
            "  [0.15314, 0.42347]. The period is 4.89608")
COULOMB_SIM = ("6307 rows to t = 600 (complete), 153 section points (exit), 153 sticks, 0 crossings; "
               "x1 in [0.06072007950742299, 0.53241128440428]")
CHAIN10_SIM = ("2210 rows to t = 300 (complete), 353 section points (exit), 355 sticks, 1 crossings; "
               "x1 in [-0.13623802826185943, 0.6698721218397475]")
for line, run in ([(l, "chain2_asym") for l in ASYM_HEAD] +
                  [(l, "chain2_asym_kc05") for l in ASYM05_HEAD] +
                  [(COULOMB_SIM, "chain2_coulomb_sim"), (CHAIN10_SIM, "chain10_sim")]):
    for k, q in enumerate(re.findall(NUM, line)):
        CHECKS.append((line, q, run, (lambda h, k: lambda r: quoted_line(r, h, k))(line[:12], k)))
CHECKS += [
    ("1: period 5.433667724740548, sticks 1, 1 (per contact), |multiplier| 0.24463498200056205",
     "5.433667724740548", "chain2_list", lambda r: r.printed(r"1: period ([0-9.]+)")),
    ("1: period 5.433667724740548, sticks 1, 1 (per contact), |multiplier| 0.24463498200056205",
     "0.24463498200056205", "chain2_list", lambda r: r.printed(r"1: period .*\|multiplier\| ([0-9.]+)")),
    ("2: period 6.461249807003621, sticks 1, 1 (per contact), |multiplier| 1.153292062190169",
     "6.461249807003621", "chain2_list", lambda r: r.printed(r"2: period ([0-9.]+)")),
    ("2: period 6.461249807003621, sticks 1, 1 (per contact), |multiplier| 1.153292062190169",
     "1.153292062190169", "chain2_list", lambda r: r.printed(r"2: period .*\|multiplier\| ([0-9.]+)")),
    (CHAIN2, "0.3952149311", "chain2", S("GR1", "v")),
    (CHAIN2_T, "5.4337", "chain2", lambda r: branch_row(r, "1", "period")),
    (CHAIN2_T, "1.18322", "chain2", lambda r: r.described("HB1", r"w = ([0-9.]+)")),
    (KC05, "1.41421", "chain2_kc05", lambda r: r.described("HB1", r"w = ([0-9.]+)")),
    (KC05, "4.5257", "chain2_kc05", lambda r: branch_row(r, "1", "period")),
    (KC05, "0.3948974826", "chain2_kc05", S("GR1", "v")),
    ("d = 0, v = 0.44095855184409716, whatever m2", "0.44095855184409716", "chain2_asym",
     S("HB1", "v")),
    ("w = 1.12169 and 0.86128; the run reports the first", "1.12169", "chain2_asym",
     lambda r: r.described("HB1", r"w = ([0-9.]+)")),
    (ASYM, "29.45572", "chain2_asym", lambda r: branch_row(r, "1", "period")),
    (ASYM, "0.11951", "chain2_asym", lambda r: -branch_row(r, "1", "x1_min")),
    (ASYM, "0.65768", "chain2_asym", lambda r: branch_row(r, "1", "x1_max")),
    (ASYM, "0.17862", "chain2_asym", lambda r: -branch_row(r, "1", "x2_min")),
    (ASYM, "0.72536", "chain2_asym", lambda r: branch_row(r, "1", "x2_max")),
    (ASYM, "0.52371", "chain2_asym", lambda r: branch_row(r, "1", "mult_max")),
    (ASYM, "0.30585", "chain2_asym", S("SL1", "v")),
    ("has a second stable orbit, period 29.38938 with sticks 4 and 2", "29.38938",
     "chain2_asym_list", lambda r: r.printed(r"1: period ([0-9.]+), sticks 4, 2 .*, stable")),
    (ASYM, "0.29513", "chain2_asym", S("SL2", "v")),
    ("- HB at the same v, with w = 1.31481 and 0.87823", "1.31481", "chain2_asym_kc05",
     lambda r: r.described("HB1", r"w = ([0-9.]+)")),
    (ASYM_ROW, "0.00924", "chain2_asym_kc05", lambda r: branch_row(r, "1", "x1_min")),
    (ASYM_ROW, "0.55471", "chain2_asym_kc05", lambda r: branch_row(r, "1", "x1_max")),
    (ASYM_ROW, "0.15314", "chain2_asym_kc05", lambda r: branch_row(r, "1", "x2_min")),
    (ASYM_ROW, "0.42347", "chain2_asym_kc05", lambda r: branch_row(r, "1", "x2_max")),
    (ASYM_ROW, "4.89608", "chain2_asym_kc05", lambda r: branch_row(r, "1", "period")),
    ("a complex pair of modulus 0.92316", "0.92316", "chain2_asym_kc05",
     lambda r: branch_row(r, "1", "mult_max")),
    ("ends at GR1, v = 0.40082", "0.40082", "chain2_asym_kc05", S("GR1", "v")),
    ("ends at GR2, v = 0.14195", "0.14195", "chain2_asym_kc05", S("GR2", "v")),
    ("From section point 75 on, at\n  t = 357.83", "75", "chain2_coulomb_sim",
     lambda r: in_step_from(r, "n")),
    ("From section point 75 on, at\n  t = 357.83", "357.83", "chain2_coulomb_sim",
     lambda r: in_step_from(r, "t")),
    ("(x1 from 0.07639 to 0.52361 after t = 400)", "0.07639", "chain2_coulomb_sim",
     lambda r: late_range(r, 0)),
    ("(x1 from 0.07639 to 0.52361 after t = 400)", "0.52361", "chain2_coulomb_sim",
     lambda r: late_range(r, 1)),
    ("Their exits come 6.3558900892 apart", "6.3558900892", "chain2_coulomb_sim", exit_gap),
    ("steady sliding: 101 rows, reached-end ss_continue: note: no stick-slip orbit: no stick phase",
     "101", "chain2_coulomb", lambda r: r.rows()),
    ("largest real part 0 in every row", "0", "chain2_coulomb",
     lambda r: max(abs(float(q["max_real"])) for q in r.table("branch.tsv"))),
    ("x1 =\n  x2 = μk = 0.3)", "0.3", "chain2_coulomb",
     lambda r: max(float(q[c]) for q in r.table("branch.tsv") for c in ("x1_0", "x2_0"))),
    ("The reported w = 1.51954 is w_6", "1.51954", "chain10",
     lambda r: r.described("HB1", r"w = ([0-9.]+)")),
    ("in 32 exits after 3000 time units (the closest 0.223)", "0.223", "chain10",
     lambda r: float(re.search(r"closest ([0-9.]+)", r.meta("branch.tsv", "orbit")).group(1))),
    ("The blocks stick about 1.2 times per time unit", "1.2", "chain10_sim",
     lambda r: r.printed(r"(\d+) sticks") / 300),
]

# docs/systems.md: the chain's orbit diagram (kc = 0.5, 400 values, seconds).
RUNS["chain2_od"] = (FAST, "ss_orbit_diagram", study(
    "chain2", "--set", "kc=0.5", "--from", "0.05", "--to", "0.45", "--n", "200", "--transient",
    "300", "--keep", "100"), "")


def od_value(r, direction, v, col, table="lyapunov.tsv"):
    """Column col of the first row of that sweep nearest v."""
    rows = [q for q in r.table(table) if q["direction"] == direction]
    return float(min(rows, key=lambda q: abs(float(q["v"]) - v))[col])


CHECKS += [
    ("maximum 0.6494 at v = 0.3, λ₁ = −0.328)", "0.6494", "chain2_od",
     lambda r: od_value(r, "up", 0.3, "x1_max")),
    ("maximum 0.6494 at v = 0.3, λ₁ = −0.328)", "0.328", "chain2_od",
     lambda r: -od_value(r, "up", 0.3, "lyapunov")),
    ("starts at v = 0.05 with the blocks out of step (x1's maximum 0.430, x2", "0.430",
     "chain2_od", lambda r: od_value(r, "up", 0.05, "x1_max")),
    ("0.429 at the section). It falls into step at v = 0.146", "0.429", "chain2_od",
     lambda r: od_value(r, "up", 0.05, "x2", "orbit_diagram.tsv")),
    ("out of step (x1 0.444, x2 0.418 at v = 0.05)", "0.444", "chain2_od",
     lambda r: od_value(r, "down", 0.05, "x1_max")),
    ("out of step (x1 0.444, x2 0.418 at v = 0.05)", "0.418", "chain2_od",
     lambda r: od_value(r, "down", 0.05, "x2", "orbit_diagram.tsv")),
    ("the same λ₁ at each v (−0.51017 at v = 0.05)", "0.51017", "chain2_od",
     lambda r: -od_value(r, "up", 0.05, "lyapunov")),
    ("the same λ₁ at each v (−0.51017 at v = 0.05)", "0.51017", "chain2_od",
     lambda r: -od_value(r, "down", 0.05, "lyapunov")),
    ("+0.0048) lie where the in-step orbit turns unstable", "0.0048", "chain2_od",
     lambda r: max(float(q["lyapunov"]) for q in r.table("lyapunov.tsv"))),
    ("−0.00725 at v = 0.45", "0.00725", "chain2_od", lambda r: -od_value(r, "up", 0.45, "lyapunov")),
]
