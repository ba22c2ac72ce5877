// ss_bench: work-precision benchmark of the seed branch (issue 6).
//
// Same work for every method: the periodic orbits of the seed set (cubic law,
// default Params) at belt speeds kV, and the grazing (GR) and Hopf (HB)
// points. Three methods:
//   ours         stickslip::Continue (v from 0.05 to 0.5, default options)
//                at rtol 1e-3 .. 1e-12, atol = 1e-2 rtol, Taylor (also 1e-13,
//                1e-14), CVODE Adams and BDF;
//   brute force  stickslip::Flow from rest until cycles repeat (brute_force.hpp);
//   regularised  tanh(u / eps) friction, BDF, transient + shooting
//                (regularised.hpp), eps 1e-1 .. 1e-6.
// Errors against references computed here by the independent long-double
// integrator (reference/reference_orbit.hpp) and the closed-form Hopf
// point sqrt((k1 - 2 beta) / (3 k3)) (seed 3.16). Wall times are medians.
//
// Usage: ss_bench [--out DIR] [--quick] [--no_plot]; or scripts/bench.sh, which
// builds it first. The full run takes well under 3 minutes on 2 cores.
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
#include "cli/gnuplot.hpp"
#include "reference/reference_orbit.hpp"
#include "regularised.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/report.hpp"

namespace {

using namespace ssbench;
namespace ref = stickslip::reference;

// The fastest single orbit with period error below 1e-12 (issue 11's goal).
struct OrbitGoal {
  double us = kNan, rtol = kNan, err = kNan;
  const char* integrator = "-";
};

// The orders the Taylor steps used: "19", or "13-19 (18.4)" when they differ
// (min and max over the run, the mean over the orbit's sum / steps).
std::string OrderText(const ss::TaylorOrders& o, long sum, long steps) {
  char text[32];
  if (o.min == o.max)
    std::snprintf(text, sizeof text, "%d", o.max);
  else
    std::snprintf(text, sizeof text, "%d-%d (%.1f)", o.min, o.max,
                  static_cast<double>(sum) / static_cast<double>(steps));
  return text;
}

// One stick-slip orbit of the seed set (v = 0.25), the issue-3 figure: time per
// orbit (median over repeats, solver reused as in continuation) and the period
// error against the reference, at several tolerances.
OrbitGoal SingleOrbit(bool quick) {
  OrbitGoal goal;
  const ss::Params p = Seed(0.25);
  const double t_ref = static_cast<double>(ss::reference::StickSlip(p).period);
  std::printf(
      "\none stick-slip orbit of the seed set at v = 0.25 (atol = rtol/100; "
      "median of repeated calls; order = the Taylor steps' orders, min-max (mean)):\n"
      "  integrator  rtol      us/orbit  steps  order        period error\n");
  for (ss::Integrator in : {ss::Integrator::kTaylor, ss::Integrator::kCvode})
    for (double rtol : {1e-6, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14}) {
      if (in == ss::Integrator::kCvode && rtol < 1e-12) continue;  // CVODE stalls below ~1e-13
      ss::OrbitOptions o;
      o.flow.integrator = in;
      o.flow.rtol = rtol;
      o.flow.atol = rtol * 1e-2;
      ss::OrbitFinder finder{ss::Model(p), o};
      ss::OrbitResult r = finder.StickSlip();
      const long steps0 = finder.flow().total_steps();
      ss::TaylorOrders orders = finder.flow().taylor_orders();
      const long sum0 = orders.sum;
      r = finder.StickSlip();
      const long steps = finder.flow().total_steps() - steps0;
      orders = finder.flow().taylor_orders();  // both calls integrate the same orbit
      const int n = quick ? 50 : 400;
      std::vector<double> us;
      for (int k = 0; k < 9; ++k) {
        const double t0 = Now();
        for (int i = 0; i < n; ++i) r = finder.StickSlip();
        us.push_back((Now() - t0) / n * 1e6);
      }
      const double err = std::abs(r.orbit.period - t_ref), t_us = Median(us);
      const bool taylor = in == ss::Integrator::kTaylor;
      std::printf("  %-10s  %-8.0e  %8.2f  %5ld  %-11s  %.1e\n", taylor ? "taylor" : "cvode-adams",
                  rtol, t_us, steps,
                  taylor ? OrderText(orders, orders.sum - sum0, steps).c_str() : "-", err);
      if (err < 1e-12 && !(t_us >= goal.us))
        goal = {t_us, rtol, err, in == ss::Integrator::kTaylor ? "Taylor" : "CVODE Adams"};
    }
  return goal;
}

// Continue() on the seed branch at the default options (issue 11's goal):
// median wall and CPU time of reps calls.
Times DefaultContinue(int reps, int* points) {
  return Repeat(
      [&] {
        const ss::ContinuationResult r = ss::Continue(ss::Params(), ss::ContinuationOptions());
        *points = static_cast<int>(r.points.size());
      },
      reps, reps, 0.0);
}

int Main(int argc, char** argv) {
  std::string out;
  bool quick = false, plot = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      quick = true;
    } else if (a == "--no_plot") {
      plot = false;
    } else if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--help") {
      std::printf(
          "usage: ss_bench [--out DIR] [--quick] [--no_plot]\n"
          "Work-precision benchmark of the seed branch: exact continuation (Adams, BDF) vs\n"
          "brute-force simulation vs a tanh-regularised model. Prints a table; writes\n"
          "DIR/work_precision.tsv and DIR/work_precision.png (plots/work_precision.gp).\n"
          "--out DIR   output directory (default: the source tree's plots/; with --quick\n"
          "            the build tree's bench/quick/)\n"
          "--quick     reduced set, < 20 s\n"
          "--no_plot   do not run gnuplot\n");
      return 0;
    } else {
      std::fprintf(stderr, "ss_bench: unknown argument '%s' (try --help)\n", a.c_str());
      return 2;
    }
  }
  // The full run writes plots/ (not committed); a quick one stays in the build tree.
  if (out.empty())
    out = quick ? std::string(SS_BENCH_BINARY_DIR) + "/quick"
                : std::string(STICKSLIP_SOURCE_DIR) + "/plots";
  if (!MakeDir(out)) {
    std::fprintf(stderr, "ss_bench: cannot create directory '%s'\n", out.c_str());
    return 2;
  }
  const double t_start = Now();

  // Settings. Full: ~2-3 min on 2 cores; quick: < 20 s.
  std::vector<double> rtols, brute_rtols, epss;
  double t_cap = 20000;
  int min_reps = 7, max_reps = 15, slow_reps = 5;
  if (quick) {
    rtols = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
    brute_rtols = {1e-6, 1e-9};
    epss = {1e-2, 1e-4};
    t_cap = 5000;
    min_reps = 3, max_reps = 5, slow_reps = 1;
  } else {
    for (int k = 3; k <= 12; ++k) rtols.push_back(std::pow(10.0, -k));
    brute_rtols = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
    epss = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  }

  std::printf("ss_bench: %ld cores, load average %s; %s run\n", sysconf(_SC_NPROCESSORS_ONLN),
              LoadAverage().c_str(), quick ? "quick" : "full");
  const Reference ref = ComputeReference();
  std::printf(
      "reference (long double RKF78, tol 1e-16; %.2f s): GR v_g = %.13f, HB v_H = %.13f "
      "(closed form); spread vs tol 1e-14: period %s (rel), x_max %s, GR %s\n",
      ref.seconds, ref.v_gr, ref.v_hb, Sci(ref.spread_period).c_str(), Sci(ref.spread_x).c_str(),
      Sci(ref.spread_gr).c_str());
  std::printf("orbits at v =");
  for (size_t i = 0; i < kV.size(); ++i)
    std::printf(" %.2f (%s, T %.10f, x_max %.10f)%s", kV[i], ref.stick_slip[i] ? "ss" : "ps",
                ref.period[i], ref.x_max[i], i + 1 < kV.size() ? "," : "\n");
  std::fflush(stdout);

  std::vector<Row> rows;
  for (double rtol : rtols)
    rows.push_back(
        RunOurs(ref, ss::Integrator::kTaylor, ss::Method::kAdams, rtol, min_reps, max_reps));
  for (double rtol : {1e-13, 1e-14})
    rows.push_back(
        RunOurs(ref, ss::Integrator::kTaylor, ss::Method::kAdams, rtol, min_reps, max_reps));
  for (ss::Method m : {ss::Method::kAdams, ss::Method::kBdf})
    for (double rtol : rtols)
      rows.push_back(RunOurs(ref, ss::Integrator::kCvode, m, rtol, min_reps, max_reps));
  for (double rtol : brute_rtols) rows.push_back(RunBrute(ref, rtol, t_cap, slow_reps, max_reps));
  for (double eps : epss)
    rows.push_back(RunRegularised(ref, eps, RegularisedRtol(eps), slow_reps, max_reps));
  const ProcessTimes pt = TimeSsContinue(quick ? 3 : 7);
  const DenseTimes dense = TimeDenseBranch(quick ? 3 : 7);
  Speedups(rows);
  const OrbitGoal orbit_goal = SingleOrbit(quick);
  int default_points = 0;
  const Times cont = DefaultContinue(quick ? 15 : 51, &default_points);

  std::printf("\n");
  PrintTable(rows);
  std::printf(
      "\nerr_T: max relative period error over the v set; err_xmax: max absolute x_max error; "
      "err_GR/err_HB: |located - reference| (brute/regularised: from the v set only, GR = "
      "bracket middle, HB = amplitude^2 extrapolated).\nt_med = median wall time of everything "
      "the method does (ours: Continue() of the full branch + the 8 orbits at the fixed v); "
      "steps = CVODE steps for the 8 orbits.\nx8orb = t_med / eval of the fastest ours row with "
      "no larger err_T and err_xmax (same 8 orbits); xbranch = (t_med * pts of that ours row / 8) "
      "/ its t_med (theirs extrapolated to the branch's number of orbits, without GR/HB).\ncpu = "
      "median process CPU time of the same (other load on the machine inflates wall times).\n");
  std::printf(
      "ss_continue process (seed set, default rtol 1e-11, %d runs, medians): "
      "--no_plots %s ms; --no_plots --no_estimates %s ms; start-up alone (--help) %s ms "
      "%s\n",
      pt.runs, Ms(pt.full).c_str(), Ms(pt.no_estimates).c_str(), Ms(pt.startup).c_str(),
      pt.note.c_str());
  PrintTargets(rows, pt);
  std::printf(
      "  [%s] one stick-slip orbit at period error < 1e-12 in <= 3 us: %s us (%s, rtol %s, "
      "error %s)\n",
      orbit_goal.us <= 3 ? "met" : "NOT met", Ratio(orbit_goal.us).c_str(), orbit_goal.integrator,
      Sci(orbit_goal.rtol, 0).c_str(), Sci(orbit_goal.err).c_str());
  std::printf(
      "  [%s] Continue() on the seed branch at the defaults in <= 3 ms: %s ms wall, %s ms CPU "
      "(median of %zu, %d points)\n",
      cont.Wall() <= 3e-3 ? "met" : "NOT met", Ms(cont.Wall()).c_str(), Ms(cont.Cpu()).c_str(),
      cont.wall.size(), default_points);
  std::printf("  [%s] ss_continue --no_plots --no_estimates process in <= 10 ms: %s ms\n",
              pt.no_estimates <= 10e-3 ? "met" : "NOT met", Ms(pt.no_estimates).c_str());
  std::printf(
      "  [%s] dense branch (ss_continue --max_step 1e-3 --no_plots --no_estimates) >= 20x "
      "--integrator cvode, process CPU: taylor %s ms, cvode %s ms, ratio %s (median of %d "
      "interleaved pairs)\n",
      dense.ratio >= 20 ? "met" : "NOT met", Ms(dense.taylor).c_str(), Ms(dense.cvode).c_str(),
      Ratio(dense.ratio).c_str(), dense.runs);

  ss::WriteFileAtomically(out + "/work_precision.tsv", Table(rows, ref, pt).str());
  std::printf("\nwrote %s/work_precision.tsv", out.c_str());
  if (plot) {
    // Render to a temporary name, then rename (as ss_continue does).
    const std::string script = std::string(STICKSLIP_SOURCE_DIR) + "/plots/work_precision.gp";
    const std::string wrapper = out + "/.work_precision.part.gp";
    ss::WriteFileAtomically(wrapper, "suffix = '.part'\nload '" + script + "'\n");
    std::string err;
    const bool ok = stickslip::cli::RunGnuplot(wrapper, out, &err);
    std::remove(wrapper.c_str());
    const std::string png = out + "/work_precision.png";
    if (ok && std::rename((png + ".part").c_str(), png.c_str()) == 0) {
      std::printf(", work_precision.png");
    } else {
      std::remove((png + ".part").c_str());
      std::printf("\nss_bench: gnuplot failed: %s", err.c_str());
    }
  }
  std::printf("\ntotal %.1f s; load average now %s\n", Now() - t_start, LoadAverage().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Main(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ss_bench: %s\n", e.what());
    return 1;
  }
}
