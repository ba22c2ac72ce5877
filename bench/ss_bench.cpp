// ss_bench: work-precision benchmark of the seed branch (issue 6).
//
// Same work for every method: the periodic orbits of the seed set (cubic law,
// default Params) at belt speeds kV, and the grazing (GR) and Hopf (HB)
// points. Three methods:
//   ours         stickslip::Continue (v from 0.05 to 0.5, default options)
//                at rtol 1e-3 .. 1e-12, atol = 1e-2 rtol, CVODE Adams and BDF;
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

#include "brute_force.hpp"
#include "reference/reference_orbit.hpp"
#include "regularised.hpp"
#include "stickslip/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/numbers.hpp"
#include "stickslip/report.hpp"
#include "stickslip/version.hpp"

extern char** environ;

namespace {

namespace ss = stickslip;
namespace ref = stickslip::reference;
using ss::kNan;

// The fixed belt speeds: stick-slip up to 0.39 (< GR ~ 0.3958), pure slip at
// 0.42 and 0.44 (HB ~ 0.44096, multiplier ~0.993: slow transients there).
const std::vector<double> kV = {0.05, 0.1, 0.2, 0.3, 0.35, 0.39, 0.42, 0.44};

ss::Params Seed(double v) {
  ss::Params p;
  p.v = v;
  return p;
}

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double Median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  const size_t n = x.size();
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

double CpuNow() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// Wall and CPU seconds of repeated runs.
struct Times {
  std::vector<double> wall, cpu;
  double Wall() const { return Median(wall); }
  double Cpu() const { return Median(cpu); }
  int runs() const { return static_cast<int>(wall.size()); }
};

// Runs f at least min_reps times, then more (up to max_reps) while the total
// wall time stays under budget seconds.
Times Repeat(const std::function<void()>& f, int min_reps, int max_reps, double budget) {
  Times t;
  double total = 0;
  while (t.runs() < max_reps && (t.runs() < min_reps || total < budget)) {
    const double w0 = Now(), c0 = CpuNow();
    f();
    t.wall.push_back(Now() - w0);
    t.cpu.push_back(CpuNow() - c0);
    total += t.wall.back();
  }
  return t;
}

// ---------------------------------------------------------------- references

struct Reference {
  std::vector<double> period, x_max;
  std::vector<bool> stick_slip;
  double v_gr = kNan, v_hb = kNan;
  // |tol 1e-16 - tol 1e-14|: an estimate of the references' own error.
  double spread_period = 0, spread_x = 0, spread_gr = 0;
  double seconds = 0;
};

Reference ComputeReference() {
  Reference r;
  const double t0 = Now();
  const ss::Params base = Seed(0.25);
  r.v_hb = static_cast<double>(ref::CubicHopfSpeed(base));  // seed (3.16)
  r.v_gr = static_cast<double>(ref::GrazingSpeed(base, 0.3L, 0.44L));
  r.spread_gr =
      std::abs(r.v_gr - static_cast<double>(ref::GrazingSpeed(base, 0.3L, 0.44L, 1e-13L, 1e-14L)));
  for (double v : kV) {
    const ss::Params p = Seed(v);
    ref::Real period[2], x_max[2];
    const ref::Real tols[2] = {1e-16L, 1e-14L};
    const bool stick = v < r.v_gr;
    for (int k = 0; k < 2; ++k) {
      if (stick) {
        const ref::StickSlipOrbit o = ref::StickSlip(p, tols[k]);
        if (!o.found)
          throw ss::Error("reference stick-slip orbit not found at v = " + std::to_string(v));
        period[k] = o.period, x_max[k] = o.x_max;
      } else {
        // Guess: steady sliding + first-harmonic amplitude (Thomsen & Fidlin 2003).
        const ref::Real k1 = ref::CubicK1(p), k3 = ref::CubicK3(p), vv = v;
        const ref::Real xbar = p.mu_s - k1 * vv + k3 * vv * vv * vv;
        const ref::Real a =
            2 * std::sqrt((k1 - 2 * ref::Real(p.beta) - 3 * k3 * vv * vv) / (3 * k3));
        const ref::PureSlipOrbit o = ref::PureSlip(p, xbar + a, tols[k]);
        if (!o.found)
          throw ss::Error("reference pure-slip orbit not found at v = " + std::to_string(v));
        period[k] = o.period, x_max[k] = o.x_max;
      }
    }
    r.period.push_back(static_cast<double>(period[0]));
    r.x_max.push_back(static_cast<double>(x_max[0]));
    r.stick_slip.push_back(stick);
    r.spread_period =
        std::max(r.spread_period, static_cast<double>(std::abs(period[0] - period[1]) / period[0]));
    r.spread_x = std::max(r.spread_x, static_cast<double>(std::abs(x_max[0] - x_max[1])));
  }
  r.seconds = Now() - t0;
  return r;
}

// ---------------------------------------------------------------- rows

struct Row {
  std::string method;  // ours-adams, ours-bdf, brute-adams, regularised-bdf
  double rtol = kNan, eps = kNan;
  int runs = 0;
  double t = kNan;         // median wall time of the whole computation [s]
  double cpu = kNan;       // the same in process CPU time (robust to other load)
  double t_branch = kNan;  // ours: the Continue() call alone
  double cpu_branch = kNan;
  double t_eval = kNan;  // ours: the orbits at kV by OrbitFinder
  long steps = 0;        // CVODE steps for the orbits at kV
  int points = 0;        // ours: periodic branch points; others: orbits found
  double err_period = kNan, err_xmax = kNan, err_gr = kNan, err_hb = kNan;
  int n_gr = 0, n_hb = 0, n_lp = 0;
  std::string kinds = "-";  // ours: kinds along the periodic branch
  std::string same = "-";   // ours: same structure as the reference
  std::string note;
  // Others: speed-up of the fastest ours row with no larger errors, on the
  // same 8 orbits (ours: t_eval) and on the branch (ours: t; others: t scaled
  // to as many orbits as ours' branch has points, an extrapolation).
  double speedup_orbits = kNan, speedup_branch = kNan;
};

// Largest relative period error and absolute x_max error over kV; NaN
// entries (orbit not found) make the error NaN.
void Errors(const Reference& ref, const std::vector<double>& period,
            const std::vector<double>& x_max, Row* row) {
  double ep = 0, ex = 0;
  for (size_t i = 0; i < kV.size(); ++i) {
    const double a = std::abs(period[i] - ref.period[i]) / ref.period[i];
    const double b = std::abs(x_max[i] - ref.x_max[i]);
    ep = std::isnan(a) || std::isnan(ep) ? kNan : std::max(ep, a);
    ex = std::isnan(b) || std::isnan(ex) ? kNan : std::max(ex, b);
  }
  row->err_period = ep;
  row->err_xmax = ex;
}

// GR and HB as a user with orbits at kV only can place them: GR at the middle
// of the bracket where the cycle stops touching the belt; HB where amplitude^2,
// linear in v near a supercritical Hopf point, extrapolates to zero from the
// last two pure-slip speeds.
void SampledSpecialPoints(const Reference& ref, const std::vector<bool>& touches,
                          const std::vector<double>& amplitude, Row* row) {
  for (size_t i = 0; i + 1 < kV.size(); ++i)
    if (touches[i] && !touches[i + 1]) {
      row->err_gr = std::abs(0.5 * (kV[i] + kV[i + 1]) - ref.v_gr);
      row->n_gr = 1;
    }
  const size_t n = kV.size();
  if (!touches[n - 2] && !touches[n - 1] && !std::isnan(amplitude[n - 2] + amplitude[n - 1])) {
    const double a0 = amplitude[n - 2] * amplitude[n - 2], a1 = amplitude[n - 1] * amplitude[n - 1];
    if (a0 != a1) {
      row->err_hb = std::abs(kV[n - 2] + a0 * (kV[n - 1] - kV[n - 2]) / (a0 - a1) - ref.v_hb);
      row->n_hb = 1;
    }
  }
}

// ---------------------------------------------------------------- ours

// Pure-slip section amplitude at v, linear between the branch's neighbours.
double AmplitudeOnBranch(const ss::ContinuationResult& res, double v) {
  const ss::BranchPoint* lo = nullptr;
  const ss::BranchPoint* hi = nullptr;
  for (const auto& pt : res.points) {
    if (pt.kind != ss::PointKind::kPureSlip) continue;
    if (pt.p <= v && (!lo || pt.p > lo->p)) lo = &pt;
    if (pt.p >= v && (!hi || pt.p < hi->p)) hi = &pt;
  }
  if (!lo || !hi) return kNan;
  if (hi->p == lo->p) return lo->amplitude;
  return lo->amplitude + (hi->amplitude - lo->amplitude) * (v - lo->p) / (hi->p - lo->p);
}

ss::PointKind KindOnBranch(const ss::ContinuationResult& res, double v) {
  // The kind of the periodic point nearest to v.
  const ss::BranchPoint* best = nullptr;
  for (const auto& pt : res.points)
    if (pt.kind != ss::PointKind::kEquilibrium &&
        (!best || std::abs(pt.p - v) < std::abs(best->p - v)))
      best = &pt;
  return best ? best->kind : ss::PointKind::kEquilibrium;
}

Row RunOurs(const Reference& ref, ss::Method method, double rtol, int min_reps, int max_reps) {
  Row row;
  row.method = std::string("ours-") + ss::MethodName(method);
  row.rtol = rtol;
  ss::ContinuationOptions co;  // param v, 0.05 -> 0.5, max_step 0.01
  co.orbit.flow.rtol = rtol;
  co.orbit.flow.atol = 1e-2 * rtol;
  co.orbit.flow.method = method;
  const ss::Params base = Seed(0.25);

  ss::ContinuationResult res;
  const Times tb = Repeat([&] { res = ss::Continue(base, co); }, min_reps, max_reps, 1.5);
  row.t_branch = tb.Wall();
  row.runs = tb.runs();

  // Period and x_max at kV: the branch's own orbit code (OrbitFinder, the
  // same options) evaluated at exactly those v, since the adaptive steps do
  // not land on them. Kind and pure-slip start amplitude come from the branch.
  std::vector<double> period(kV.size(), kNan), x_max(kV.size(), kNan);
  long steps = 0;
  auto eval = [&] {
    ss::OrbitFinder finder(ss::Model(Seed(kV[0])), co.orbit);
    for (size_t i = 0; i < kV.size(); ++i) {
      finder.set_model(ss::Model(Seed(kV[i])));
      ss::OrbitResult o;
      if (KindOnBranch(res, kV[i]) == ss::PointKind::kStickSlip) {
        o = finder.StickSlip(/*first_return_only=*/true);
      } else {
        const double a = AmplitudeOnBranch(res, kV[i]);
        if (std::isnan(a) || a <= 0) continue;
        o = finder.PureSlip(a);
      }
      if (o.ok()) period[i] = o.orbit.period, x_max[i] = o.orbit.x_max;
    }
    steps = finder.flow().total_steps();
  };
  const Times te = Repeat(eval, min_reps, max_reps, 0.5);
  row.t_eval = te.Wall();
  row.t = row.t_branch + row.t_eval;
  row.cpu = tb.Cpu() + te.Cpu();
  row.cpu_branch = tb.Cpu();
  row.steps = steps;
  Errors(ref, period, x_max, &row);

  // Structure: special points, and the kinds along the periodic branch.
  for (const auto& sp : res.special) {
    if (sp.kind == ss::SpecialKind::kGrazing) {
      ++row.n_gr;
      row.err_gr = std::abs(sp.p - ref.v_gr);
    } else if (sp.kind == ss::SpecialKind::kHopf) {
      ++row.n_hb;
      row.err_hb = std::abs(sp.p - ref.v_hb);
    } else {
      ++row.n_lp;
    }
  }
  if (row.n_gr != 1) row.err_gr = kNan;
  if (row.n_hb != 1) row.err_hb = kNan;
  std::string kinds;
  ss::PointKind last = ss::PointKind::kEquilibrium;
  for (const auto& pt : res.points) {
    if (pt.kind == ss::PointKind::kEquilibrium) continue;
    ++row.points;
    if (pt.kind == last) continue;
    kinds += std::string(kinds.empty() ? "" : ">") +
             (pt.kind == ss::PointKind::kStickSlip ? "ss" : "ps");
    last = pt.kind;
  }
  row.kinds = kinds.empty() ? "-" : kinds;
  // The reference structure (GrazingSpeed, closed-form Hopf point, cubic law
  // supercritical): stick-slip up to one GR, pure slip down to one HB, no LP.
  const bool same =
      !res.partial() && row.n_gr == 1 && row.n_hb == 1 && row.n_lp == 0 && row.kinds == "ss>ps";
  row.same = same ? "yes" : "NO";
  if (res.partial())
    row.note = std::string("continuation ") + ss::ContinuationStatusName(res.status);
  return row;
}

// ---------------------------------------------------------------- brute force

Row RunBrute(const Reference& ref, double rtol, double t_cap, int min_reps, int max_reps) {
  Row row;
  row.method = "brute-adams";
  row.rtol = rtol;
  bench::BruteOptions bo;
  bo.flow.rtol = rtol;
  bo.flow.atol = 1e-2 * rtol;
  bo.converge_tol = 10 * rtol;  // as tight as the integration allows
  bo.t_cap = t_cap;
  std::vector<bench::BruteCycle> cycles;
  auto run = [&] {
    cycles.clear();
    for (double v : kV) cycles.push_back(bench::BruteForce(Seed(v), bo));
  };
  const Times t = Repeat(run, min_reps, max_reps, 2.0);
  row.t = t.Wall();
  row.cpu = t.Cpu();
  row.runs = t.runs();
  std::vector<double> period, x_max, amplitude;
  std::vector<bool> touches;
  int capped = 0;
  for (const auto& c : cycles) {
    row.steps += c.steps;
    row.points += c.ok;
    capped += c.ok && !c.converged;
    period.push_back(c.ok ? c.period : kNan);
    x_max.push_back(c.ok ? c.x_max : kNan);
    amplitude.push_back(c.ok ? 0.5 * (c.x_max - c.x_min) : kNan);
    touches.push_back(c.ok && c.t_stick > 0);
  }
  Errors(ref, period, x_max, &row);
  SampledSpecialPoints(ref, touches, amplitude, &row);
  char buf[96];
  std::snprintf(buf, sizeof buf, "t_end %.0f at v=%.2f%s", cycles.back().t_end, kV.back(),
                capped ? " (t_cap hit)" : "");
  row.note = buf;
  return row;
}

// ---------------------------------------------------------------- regularised

// Integration tolerance for a given eps, from a pilot sweep (rtol 1e-4 ..
// 1e-10 at each eps): the loosest decade at which both max errors are within
// ~10% of their rtol = 1e-10 values. The regularisation error is ~10 eps in
// period (v = 0.05 dominates); looser rtol at eps <= 1e-5 fails or is worse.
double RegularisedRtol(double eps) { return std::clamp(1e-2 * eps, 1e-10, 1e-6); }

Row RunRegularised(const Reference& ref, double eps, double rtol, int min_reps, int max_reps) {
  Row row;
  row.method = "regularised-bdf";
  row.eps = eps;
  row.rtol = rtol;
  bench::SmoothOptions so;
  so.eps = eps;
  so.rtol = rtol;
  so.atol = 1e-2 * rtol;
  std::vector<bench::SmoothCycle> cycles;
  auto run = [&] {
    cycles.clear();
    for (double v : kV) cycles.push_back(bench::RegularisedCycle(Seed(v), so));
  };
  const Times t = Repeat(run, min_reps, max_reps, 2.0);
  row.t = t.Wall();
  row.cpu = t.Cpu();
  row.runs = t.runs();
  std::vector<double> period, x_max, amplitude;
  std::vector<bool> touches;
  std::string failed;
  for (size_t i = 0; i < cycles.size(); ++i) {
    const auto& c = cycles[i];
    row.steps += c.steps;
    row.points += c.ok;
    if (!c.ok)
      failed += (failed.empty() ? "no cycle at v=" : ",") + std::to_string(kV[i]).substr(0, 4);
    period.push_back(c.ok ? c.period : kNan);
    x_max.push_back(c.ok ? c.x_max : kNan);
    amplitude.push_back(c.ok ? 0.5 * (c.x_max - c.x_min) : kNan);
    touches.push_back(c.ok && c.touches);
  }
  Errors(ref, period, x_max, &row);
  SampledSpecialPoints(ref, touches, amplitude, &row);
  row.note = failed;
  return row;
}

// ---------------------------------------------------------------- processes

// Wall time of one run of argv[0] with stdout and stderr to /dev/null.
double TimeProcess(const std::vector<std::string>& args, int* status) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const double t0 = Now();
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    *status = -1;
    return kNan;
  }
  int ws = 0;
  waitpid(pid, &ws, 0);
  const double t = Now() - t0;
  *status = WIFEXITED(ws) ? WEXITSTATUS(ws) : -1;
  return t;
}

struct ProcessTimes {
  double full = kNan;          // ss_continue --no_plots --out DIR (as a user runs it)
  double no_estimates = kNan;  // the same with --no_estimates, if the app has it
  double startup = kNan;       // ss_continue --help: exec, static init, option parsing
  int runs = 0;
  std::string note;
};

// Median wall times of the ss_continue process (default study: seed set,
// v from 0.05 to 0.5, rtol 1e-11), fork/exec + wait, output to /dev/null.
ProcessTimes TimeSsContinue(int reps) {
  ProcessTimes p;
  const std::string exe = SS_CONTINUE_PATH;
  char dir[] = "/tmp/ss_bench.XXXXXX";
  if (!mkdtemp(dir)) {
    p.note = "mkdtemp failed";
    return p;
  }
  std::vector<double> full, no_est, startup;
  for (int i = 0; i < reps; ++i) {
    int s1 = 0, s2 = 0, s3 = 0;
    full.push_back(TimeProcess({exe, "--no_plots", "--out", dir}, &s1));
    const double t = TimeProcess({exe, "--no_plots", "--no_estimates", "--out", dir}, &s2);
    if (s2 == 0) no_est.push_back(t);
    startup.push_back(TimeProcess({exe, "--help"}, &s3));
    if (s1 != 0 || s3 != 0) p.note = "(ss_continue exited with status " + std::to_string(s1) + ")";
  }
  // Whatever the app wrote (branch.tsv, special_points.tsv, bifurcation.gp, ...).
  const int rc = std::system(("rm -rf '" + std::string(dir) + "'").c_str());
  (void)rc;
  p.full = Median(full);
  if (!no_est.empty()) p.no_estimates = Median(no_est);
  p.startup = Median(startup);
  p.runs = reps;
  return p;
}

// ---------------------------------------------------------------- output

std::string Sci(double x, int digits = 1) {
  if (std::isnan(x)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*e", digits, x);
  return buf;
}
std::string Ms(double s) {
  if (std::isnan(s)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 0.1 ? "%.2f" : (s < 10 ? "%.1f" : "%.0f"), 1e3 * s);
  return buf;
}

std::string Ratio(double x) {
  if (std::isnan(x)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, x < 10 ? "%.1f" : "%.0f", x);
  return buf;
}

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
  for (const Row& r : rows)
    t.AddRow({r.method,
              r.rtol,
              r.eps,
              r.runs,
              r.t,
              r.cpu,
              r.t_branch,
              r.t_eval,
              r.steps,
              r.points,
              r.err_period,
              r.err_xmax,
              r.err_gr,
              r.err_hb,
              r.n_gr,
              r.n_hb,
              r.n_lp,
              r.kinds,
              r.same,
              r.speedup_orbits,
              r.speedup_branch,
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
  for (const char* m : {"ours-adams", "ours-bdf"}) {
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

// The first three fields of /proc/loadavg: other work on a shared machine
// inflates wall times.
std::string LoadAverage() {
  std::FILE* f = std::fopen("/proc/loadavg", "r");
  if (!f) return "?";
  double a = 0, b = 0, c = 0;
  const int n = std::fscanf(f, "%lf %lf %lf", &a, &b, &c);
  std::fclose(f);
  if (n != 3) return "?";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f %.2f %.2f", a, b, c);
  return buf;
}

bool MakeDir(const std::string& d) {
  struct stat st;
  if (stat(d.c_str(), &st) == 0) return S_ISDIR(st.st_mode);
  return mkdir(d.c_str(), 0777) == 0;
}

// One stick-slip orbit of the seed set (v = 0.25), the issue-3 figure: time per
// orbit (median over repeats, solver reused as in continuation) and the period
// error against the reference, at several tolerances.
void SingleOrbit(bool quick) {
  const ss::Params p = Seed(0.25);
  const double t_ref = static_cast<double>(ss::reference::StickSlip(p).period);
  std::printf(
      "\none stick-slip orbit of the seed set at v = 0.25 (Adams, atol = rtol/100; "
      "median of repeated calls):\n  rtol      us/orbit  steps  period error\n");
  for (double rtol : {1e-6, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}) {
    ss::OrbitOptions o;
    o.flow.rtol = rtol;
    o.flow.atol = rtol * 1e-2;
    ss::OrbitFinder finder{ss::Model(p), o};
    ss::OrbitResult r = finder.StickSlip();
    const long steps0 = finder.flow().total_steps();
    r = finder.StickSlip();
    const long steps = finder.flow().total_steps() - steps0;
    const int n = quick ? 50 : 400;
    std::vector<double> us;
    for (int k = 0; k < 9; ++k) {
      const double t0 = Now();
      for (int i = 0; i < n; ++i) r = finder.StickSlip();
      us.push_back((Now() - t0) / n * 1e6);
    }
    std::printf("  %-8.0e  %8.1f  %5ld  %.1e\n", rtol, Median(us), steps,
                std::abs(r.orbit.period - t_ref));
  }
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
  // The full run updates the figure the README shows; a quick one stays in the build tree.
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
  for (ss::Method m : {ss::Method::kAdams, ss::Method::kBdf})
    for (double rtol : rtols) rows.push_back(RunOurs(ref, m, rtol, min_reps, max_reps));
  for (double rtol : brute_rtols) rows.push_back(RunBrute(ref, rtol, t_cap, slow_reps, max_reps));
  for (double eps : epss)
    rows.push_back(RunRegularised(ref, eps, RegularisedRtol(eps), slow_reps, max_reps));
  const ProcessTimes pt = TimeSsContinue(quick ? 3 : 7);
  Speedups(rows);
  SingleOrbit(quick);

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

  ss::WriteFileAtomically(out + "/work_precision.tsv", Table(rows, ref, pt).str());
  std::printf("\nwrote %s/work_precision.tsv", out.c_str());
  if (plot) {
    // Render to a temporary name, then rename (as ss_continue does).
    const std::string script = std::string(STICKSLIP_SOURCE_DIR) + "/plots/work_precision.gp";
    const std::string wrapper = out + "/.work_precision.part.gp";
    ss::WriteFileAtomically(wrapper, "suffix = '.part'\nload '" + script + "'\n");
    std::string err;
    const bool ok = ss::RunGnuplot(wrapper, out, &err);
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
