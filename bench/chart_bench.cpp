// chart_bench: the seed (v, beta) stability chart (studies/seed_chart.ini).
// Times the ss_chart process without figures (--no_plots: curves.tsv and
// codim2.tsv only), median wall and CPU time of five runs, against the goal of
// 0.5 s; then the library call (stickslip::Chart) in-process, with the points,
// evaluations and time of every curve.
//
// Usage: chart_bench [--runs N]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "stickslip/chart/chart.hpp"

namespace {

struct Timing {
  double wall = 0, cpu = 0;
  int status = -1;
};

// One ss_chart process, output to a scratch directory; stdout discarded.
Timing RunProcess(const std::string& out_dir) {
  const std::string study = std::string(STICKSLIP_SOURCE_DIR) + "/studies/seed_chart.ini";
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (!std::freopen("/dev/null", "w", stdout)) ::_exit(126);
    ::execl(SS_CHART_PATH, "ss_chart", "--study", study.c_str(), "--out", out_dir.c_str(),
            "--no_plots", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  Timing t;
  int status = 0;
  struct rusage ru;
  if (pid < 0 || ::wait4(pid, &status, 0, &ru) != pid) return t;
  t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.cpu =
      ru.ru_utime.tv_sec + ru.ru_stime.tv_sec + 1e-6 * (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  t.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return t;
}

double Median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  if (argc == 3 && std::strcmp(argv[1], "--runs") == 0) runs = std::max(1, std::atoi(argv[2]));
  char tmpl[] = "/tmp/chart_bench_XXXXXX";
  if (::mkdtemp(tmpl) == nullptr) return 1;
  std::vector<double> wall, cpu;
  for (int i = 0; i < runs; ++i) {
    const Timing t = RunProcess(tmpl);
    if (t.status != 0) {
      std::fprintf(stderr, "chart_bench: ss_chart exited with %d\n", t.status);
      return 1;
    }
    wall.push_back(t.wall);
    cpu.push_back(t.cpu);
  }
  std::printf("ss_chart --study studies/seed_chart.ini --no_plots: median of %d runs\n", runs);
  std::printf("  wall %.3f s, CPU %.3f s (goal <= 0.5 s for the process)\n", Median(wall),
              Median(cpu));

  // The same chart in-process: per curve.
  stickslip::Params base;
  stickslip::ChartOptions o;
  o.plane = stickslip::Plane{stickslip::Parameter::kV, stickslip::Parameter::kBeta, 0.02, 0.6, 0.0, 0.25};
  const stickslip::ChartResult r = stickslip::Chart(base, o);
  std::printf("Chart(): %d curves, %d points in %.3f s (wall)\n", static_cast<int>(r.curves.size()),
              r.points(), r.seconds);
  for (const auto& c : r.curves)
    std::printf("  %s: %zu points, %d evaluations, %.3f s, %.2f ms per point\n",
                stickslip::CurveLabel(c.kind), c.points.size(), c.evaluations, c.seconds,
                1e3 * c.seconds / std::max<size_t>(1, c.points.size()));
  std::system((std::string("rm -rf '") + tmpl + "'").c_str());
  return 0;
}
