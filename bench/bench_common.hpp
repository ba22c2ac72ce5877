// ss_bench's shared pieces: timing, the references, one row per method and
// tolerance, and the printed and written results.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "numerics/numbers.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/io/report.hpp"

namespace ssbench {

namespace ss = stickslip;
using ss::kNan;

// The fixed belt speeds: stick-slip up to 0.39 (< GR ~ 0.3958), pure slip at
// 0.42 and 0.44 (HB ~ 0.44096, multiplier ~0.993: slow transients there).
extern const std::vector<double> kV;

ss::Params Seed(double v);
double Now();
double Median(std::vector<double> x);
double CpuNow();

// Wall and CPU seconds of repeated runs.
struct Times {
  std::vector<double> wall, cpu;
  double Wall() const { return Median(wall); }
  double Cpu() const { return Median(cpu); }
  int runs() const { return static_cast<int>(wall.size()); }
};

// Runs f at least min_reps times, then more (up to max_reps) while the total
// wall time stays under budget seconds.
Times Repeat(const std::function<void()>& f, int min_reps, int max_reps, double budget);

struct Reference {
  std::vector<double> period, x_max;
  std::vector<bool> stick_slip;
  double v_gr = kNan, v_hb = kNan;
  // |tol 1e-16 - tol 1e-14|: an estimate of the references' own error.
  double spread_period = 0, spread_x = 0, spread_gr = 0;
  double seconds = 0;
};

Reference ComputeReference();

struct Row {
  std::string method;  // ours-taylor, ours-adams, ours-bdf, brute-adams, regularised-bdf
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

Row RunOurs(const Reference& ref, ss::Integrator integrator, ss::Method method, double rtol,
            int min_reps, int max_reps);
Row RunBrute(const Reference& ref, double rtol, double t_cap, int min_reps, int max_reps);
// Integration tolerance of the regularised model for a given eps.
double RegularisedRtol(double eps);
Row RunRegularised(const Reference& ref, double eps, double rtol, int min_reps, int max_reps);

// Wall time of one run of argv[0] with stdout and stderr to /dev/null.
double TimeProcess(const std::vector<std::string>& args, int* status);
struct ProcessTimes {
  double full = kNan;          // ss_continue --no_plots --out DIR (as a user runs it)
  double no_estimates = kNan;  // the same with --no_estimates, if the app has it
  double startup = kNan;       // ss_continue --help: exec, static init, option parsing
  int runs = 0;
  std::string note;
};
ProcessTimes TimeSsContinue(int reps);
// The dense branch (issue 19): ss_continue --max_step 1e-3 --no_plots --no_estimates with
// Taylor and with --integrator cvode, interleaved; medians of the child's CPU time (user +
// system, wait4) and of the per-run ratio cvode / taylor.
struct DenseTimes {
  double taylor = kNan, cvode = kNan, ratio = kNan;
  int runs = 0;
};
DenseTimes TimeDenseBranch(int reps);

std::string Sci(double x, int digits = 1);
std::string Ms(double s);
std::string Ratio(double x);
void PrintTable(const std::vector<Row>& rows);
ss::TsvTable Table(const std::vector<Row>& rows, const Reference& ref, const ProcessTimes& pt);
void Speedups(std::vector<Row>& rows);
double Slope(const std::vector<Row>& rows, const std::string& method, double Row::*err);
void PrintTargets(const std::vector<Row>& rows, const ProcessTimes& pt);
std::string LoadAverage();
bool MakeDir(const std::string& d);

}  // namespace ssbench
