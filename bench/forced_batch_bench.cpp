// forced_batch_bench: the forced sweep row of issue 34 (10^5 forced orbits,
// Omega grid x uncertain mu_s, <= 10 s wall on 2 cores): StroboscopicOrbits
// (orbits/system_batch.hpp) on studies/seed_forced.ini's oscillator (cubic
// law, beta 0.05, v 0.25, A 0.3) with Omega on OMEGAS values in [0.5, 1.5] by
// mu_s ~ N(0.4, 0.02^2) draws, from (0, 0) with 20 periods of transient and
// m <= 4, default tolerances (1e-12), on 1 and 2 threads.
//   ./build/bench/forced_batch_bench [DRAWS [OMEGAS [REPEATS]]]   (default 500 x 200, 1)
// Prints wall and process CPU time per row and in all, and what the rows are.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "stickslip/orbits/system_batch.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace ss = stickslip;

namespace {

double CpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace

int main(int argc, char** argv) {
  const int draws = argc > 1 ? std::atoi(argv[1]) : 500;
  const int omegas = argc > 2 ? std::atoi(argv[2]) : 200;
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 1;
  if (draws < 1 || omegas < 2 || repeats < 1) {
    std::fprintf(stderr, "forced_batch_bench: DRAWS >= 1, OMEGAS >= 2, REPEATS >= 1\n");
    return 2;
  }
  ss::ForcedBeltParams p;
  p.base.beta = 0.05, p.base.v = 0.25, p.force = 0.3, p.omega = 0.6;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> mu_s(0.4, 0.02);
  std::vector<double> draw(draws);
  for (double& d : draw) d = mu_s(rng);
  ss::SystemColumn w{ss::ForcedBelt::kOmegaIndex, {}};
  ss::SystemColumn mu{static_cast<int>(ss::Parameter::kMuS), {}};
  for (int i = 0; i < omegas; ++i)
    for (double d : draw) w.values.push_back(0.5 + 1.0 * i / (omegas - 1)), mu.values.push_back(d);
  const double n = static_cast<double>(w.values.size());
  std::printf("forced_batch_bench: %.0f rows (%d Omegas x %d mu_s draws), transient 20, max_m 4\n",
              n, omegas, draws);
  std::printf(
      "  threads   wall s   CPU s   wall us/row  CPU us/row  found  stick-slip  m>1  "
      "aperiodic\n");
  for (int threads : {1, 2}) {
    ss::SystemBatchOptions o;
    o.threads = threads;
    for (int r = 0; r < repeats; ++r) {
      const double c0 = CpuSeconds();
      const auto t0 = std::chrono::steady_clock::now();
      const ss::SystemBatch b = ss::StroboscopicOrbits(ss::ForcedBelt(p), {w, mu}, o);
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double cpu = CpuSeconds() - c0;
      std::size_t slip = 0, multiple = 0, aperiodic = 0;
      for (std::size_t i = 0; i < b.rows(); ++i) {
        slip += b.status[i] == ss::OrbitStatus::kOk && b.sticks[i] > 0;
        multiple += b.m[i] > 1;
        aperiodic += b.status[i] == ss::OrbitStatus::kAperiodic;
      }
      std::printf("  %7d  %7.2f  %6.2f  %11.1f  %10.1f  %.4f  %.4f      %.4f  %.4f\n", b.threads,
                  wall, cpu, 1e6 * wall / n, 1e6 * cpu / n, b.found() / n, slip / n, multiple / n,
                  aperiodic / n);
    }
  }
  return 0;
}
