// ss_bench's printed table, TSV, speed-ups and targets.
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "brute_force.hpp"
#include "reference/reference_orbit.hpp"
#include "regularised.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/version.hpp"
namespace ssbench {

namespace ref = stickslip::reference;

void PrintTable(const std::vector<Row>& rows) {
  std::printf("%-15s %5s %5s %4s %9s %7s %8s %6s %7s %5s %7s %8s %7s %7s %8s %5s %4s %6s %7s  %s\n",
              "method", "rtol", "eps", "runs", "t_med[ms]", "cpu", "branch", "eval", "steps", "pts",
              "err_T", "err_xmax", "err_GR", "err_HB", "GR/HB/LP", "kinds", "same", "x8orb",
              "xbranch", "note");
  for (const Row& r : rows) {
    char grhb[16];
    std::snprintf(grhb, sizeof grhb, "%d/%d/%d", r.n_gr, r.n_hb, r.n_lp);
    const std::string pts = r.method.rfind("ours", 0) == 0
                                ? std::to_string(r.points)
                                : std::to_string(r.points) + "/" + std::to_string(kV.size());
    std::printf(
        "%-15s %5s %5s %4d %9s %7s %8s %6s %7ld %5s %7s %8s %7s %7s %8s %5s %4s %6s %7s  %s\n",
        r.method.c_str(), Sci(r.rtol, 0).c_str(), Sci(r.eps, 0).c_str(), r.runs, Ms(r.t).c_str(),
        Ms(r.cpu).c_str(), Ms(r.t_branch).c_str(), Ms(r.t_eval).c_str(), r.steps, pts.c_str(),
        Sci(r.err_period).c_str(), Sci(r.err_xmax).c_str(), Sci(r.err_gr).c_str(),
        Sci(r.err_hb).c_str(), grhb, r.kinds.c_str(), r.same.c_str(),
        Ratio(r.speedup_orbits).c_str(), Ratio(r.speedup_branch).c_str(), r.note.c_str());
  }
}

ss::TsvTable Table(const std::vector<Row>& rows, const Reference& ref, const ProcessTimes& pt) {
  ss::TsvTable t(
      {"method",         "rtol",          "eps",         "runs",           "time_s",
       "cpu_s",          "time_branch_s", "time_eval_s", "steps",          "points",
       "err_period",     "err_xmax",      "err_gr",      "err_hb",         "n_gr",
       "n_hb",           "n_lp",          "kinds",       "same_structure", "speedup_orbits",
       "speedup_branch", "note"});
  std::string vs;
  for (double v : kV) vs += (vs.empty() ? "" : " ") + ss::FormatNumber(v);
  t.AddMeta("tool", std::string("ss_bench ") + ss::Version());
  if (*ss::GitCommit()) t.AddMeta("commit", ss::GitCommit());
  t.AddMeta("setting",
            "seed set (cubic law), orbits at v = " + vs +
                "; err_period relative, err_xmax absolute, max over v; times are medians");
  t.AddMeta("reference",
            "GR v_g = " + ss::FormatNumber(ref.v_gr) + ", HB v_H = " + ss::FormatNumber(ref.v_hb) +
                "; reference spread (tol 1e-16 vs 1e-14): period " + Sci(ref.spread_period) +
                ", x_max " + Sci(ref.spread_x) + ", GR " + Sci(ref.spread_gr));
  t.AddMeta("ss_continue", "process (default rtol 1e-11), medians: --no_plots " + Ms(pt.full) +
                               " ms, --no_plots --no_estimates " + Ms(pt.no_estimates) +
                               " ms, start-up (--help) " + Ms(pt.startup) + " ms");
  using E = ss::TsvTable::Cell;  // NaN: does not apply (an empty cell, never "nan")
  for (const Row& r : rows)
    t.AddRow({r.method,
              E::OrEmpty(r.rtol),
              E::OrEmpty(r.eps),
              r.runs,
              E::OrEmpty(r.t),
              E::OrEmpty(r.cpu),
              E::OrEmpty(r.t_branch),
              E::OrEmpty(r.t_eval),
              r.steps,
              r.points,
              E::OrEmpty(r.err_period),
              E::OrEmpty(r.err_xmax),
              E::OrEmpty(r.err_gr),
              E::OrEmpty(r.err_hb),
              r.n_gr,
              r.n_hb,
              r.n_lp,
              r.kinds,
              r.same,
              E::OrEmpty(r.speedup_orbits),
              E::OrEmpty(r.speedup_branch),
              r.note.empty() ? "-" : r.note});
  return t;
}

// Speed-ups against the fastest ours rows with both errors no larger.
void Speedups(std::vector<Row>& rows) {
  for (Row& r : rows) {
    if (r.method.rfind("ours", 0) == 0 || std::isnan(r.err_period) || std::isnan(r.err_xmax))
      continue;
    const Row* orbits = nullptr;
    const Row* branch = nullptr;
    for (const Row& o : rows) {
      if (o.method.rfind("ours", 0) != 0 || o.same != "yes" || !(o.err_period <= r.err_period) ||
          !(o.err_xmax <= r.err_xmax))
        continue;
      if (!orbits || o.t_eval < orbits->t_eval) orbits = &o;
      if (!branch || o.t < branch->t) branch = &o;
    }
    if (orbits) r.speedup_orbits = r.t / orbits->t_eval;
    if (branch) r.speedup_branch = r.t * branch->points / kV.size() / branch->t;
  }
}

// Least-squares slope of log10(error) against log10(rtol) over [1e-10, 1e-4].
double Slope(const std::vector<Row>& rows, const std::string& method, double Row::*err) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Row& r : rows) {
    if (r.method != method || r.rtol < 0.99e-10 || r.rtol > 1.01e-4 || !(r.*err > 0)) continue;
    const double x = std::log10(r.rtol), y = std::log10(r.*err);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return n < 2 ? kNan : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void PrintTargets(const std::vector<Row>& rows, const ProcessTimes& pt) {
  std::printf("\nTargets (shown, not asserted):\n");
  // 1. Full branch, >= 100 points, GR and HB to 1e-9, period error < 1e-8, < 50 ms.
  const Row* best = nullptr;
  for (const Row& r : rows)
    if (r.method.rfind("ours", 0) == 0 && r.points >= 100 && r.err_gr < 1e-9 && r.err_hb < 1e-9 &&
        r.err_period < 1e-8 && (!best || r.t_branch < best->t_branch))
      best = &r;
  if (best)
    std::printf(
        "  [%s] full branch at err_T < 1e-8, GR/HB < 1e-9, >= 100 points: fastest %s rtol %s: "
        "Continue() %s ms wall, %s ms CPU (+ %s ms for the orbits at the fixed v), %d points, "
        "err_T %s, GR %s, HB %s; ss_continue --no_estimates process %s ms (start-up %s ms)\n",
        best->t_branch < 0.05 ? "met" : "NOT met", best->method.c_str(), Sci(best->rtol, 0).c_str(),
        Ms(best->t_branch).c_str(), Ms(best->cpu_branch).c_str(), Ms(best->t_eval).c_str(),
        best->points, Sci(best->err_period).c_str(), Sci(best->err_gr).c_str(),
        Sci(best->err_hb).c_str(), Ms(pt.no_estimates).c_str(), Ms(pt.startup).c_str());
  else
    std::printf(
        "  [NOT met] no tolerance gives the full branch at err_T < 1e-8 and GR/HB < 1e-9\n");
  // 2. At equal error, >= 100x faster than brute force and than regularised.
  for (const char* m : {"brute-adams", "regularised-bdf"}) {
    double lo_o = kNan, lo_b = kNan;
    int n = 0;
    for (const Row& r : rows) {
      if (r.method != m || std::isnan(r.speedup_orbits)) continue;
      lo_o = std::isnan(lo_o) ? r.speedup_orbits : std::min(lo_o, r.speedup_orbits);
      lo_b = std::isnan(lo_b) ? r.speedup_branch : std::min(lo_b, r.speedup_branch);
      ++n;
    }
    std::printf(
        "  [%s / %s] speed-up over %s at no larger errors, min over %d settings: "
        "same 8 orbits %sx; branch (theirs scaled to the branch's points) %sx\n",
        lo_o >= 100 ? "met" : "NOT met", lo_b >= 100 ? "met" : "NOT met", m, n, Ratio(lo_o).c_str(),
        Ratio(lo_b).c_str());
  }
  // 3. Error proportional to tolerance down to 1e-10.
  for (const char* m : {"ours-taylor", "ours-adams", "ours-bdf"}) {
    const double sp = Slope(rows, m, &Row::err_period), sx = Slope(rows, m, &Row::err_xmax);
    std::printf(
        "  [%s] %s: slope of log err vs log rtol on [1e-10, 1e-4]: period %.2f, x_max "
        "%.2f; err_T/rtol in table order:",
        std::abs(sp - 1) < 0.2 && std::abs(sx - 1) < 0.2 ? "met" : "NOT met", m, sp, sx);
    for (const Row& r : rows)
      if (r.method == m) std::printf(" %s", Sci(r.err_period / r.rtol, 0).c_str());
    std::printf("; err_xmax/rtol:");
    for (const Row& r : rows)
      if (r.method == m) std::printf(" %s", Sci(r.err_xmax / r.rtol, 0).c_str());
    std::printf("\n");
  }
  // 4. Structure at every tolerance.
  int n = 0, same = 0;
  for (const Row& r : rows)
    if (r.method.rfind("ours", 0) == 0) ++n, same += r.same == "yes";
  std::printf(
      "  [%s] same structure (1 GR, 1 HB, 0 LP, stick-slip > pure-slip) at %d of %d "
      "tolerance/method settings\n",
      same == n ? "met" : "NOT met", same, n);
}

}  // namespace ssbench
