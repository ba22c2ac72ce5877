// Timing, the references and processes of ss_bench.
#include "bench_common.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
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
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/report.hpp"

extern char** environ;

namespace ssbench {

namespace ref = stickslip::reference;

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

// ---------------------------------------------------------------- processes

// One run of argv[0] with stdout and stderr to /dev/null: its wall time and
// its CPU time (user + system), or nan and *status = -1 if it cannot start.
struct SpawnTimes {
  double wall = kNan, cpu = kNan;
};
SpawnTimes RunProcess(const std::vector<std::string>& args, int* status) {
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
  SpawnTimes t;
  if (rc != 0) {
    *status = -1;
    return t;
  }
  int ws = 0;
  struct rusage ru {};
  wait4(pid, &ws, 0, &ru);
  t.wall = Now() - t0;
  *status = WIFEXITED(ws) ? WEXITSTATUS(ws) : -1;
  auto sec = [](const timeval& v) { return v.tv_sec + 1e-6 * v.tv_usec; };
  t.cpu = sec(ru.ru_utime) + sec(ru.ru_stime);
  return t;
}

// Wall time of one run of argv[0] with stdout and stderr to /dev/null.
double TimeProcess(const std::vector<std::string>& args, int* status) {
  return RunProcess(args, status).wall;
}

// CPU time (user + system) of one run of argv[0], output to /dev/null.
double ProcessCpu(const std::vector<std::string>& args, int* status) {
  return RunProcess(args, status).cpu;
}

DenseTimes TimeDenseBranch(int reps) {
  DenseTimes d;
  char dir[] = "/tmp/ss_bench_dense.XXXXXX";
  if (!mkdtemp(dir)) return d;
  std::vector<double> taylor, cvode, ratio;
  for (int i = 0; i < reps; ++i) {
    double t[2];
    int status[2] = {0, 0};
    for (int k = 0; k < 2; ++k)
      t[k] = ProcessCpu({SS_CONTINUE_PATH, "--max_step", "1e-3", "--no_plots", "--no_estimates",
                         "--integrator", k == 0 ? "taylor" : "cvode", "--out", dir},
                        &status[k]);
    if (status[0] != 0 || status[1] != 0) continue;
    taylor.push_back(t[0]);
    cvode.push_back(t[1]);
    ratio.push_back(t[1] / t[0]);
  }
  const int rc = std::system(("rm -rf '" + std::string(dir) + "'").c_str());
  (void)rc;
  if (taylor.empty()) return d;
  d = {Median(taylor), Median(cvode), Median(ratio), static_cast<int>(taylor.size())};
  return d;
}

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

std::string Sci(double x, int digits) {
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

}  // namespace ssbench
