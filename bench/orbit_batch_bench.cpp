// orbit_batch_bench: time per point of StickSlipOrbits (orbits/orbit_batch.hpp)
// on the points of examples/python/sweep.py (v on 200 speeds in [0.05, 0.45]
// by mu_s ~ N(0.4, 0.02^2) draws, the seed set otherwise, default tolerances),
// on 1 and 2 threads, against the per-point path sweeps used before: a fresh
// Model and OrbitFinder per point and StickSlip() without first_return_only.
//   ./build/bench/orbit_batch_bench [DRAWS [REPEATS]]   (default 500 draws: 10^5 points, 5)
// Prints medians over the repeats of wall and process CPU time per point.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "stickslip/orbits/orbit_batch.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace ss = stickslip;

namespace {

double CpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Timing {
  std::vector<double> wall, cpu;
  template <typename F>
  void Add(F&& f) {
    const double c0 = CpuSeconds();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    cpu.push_back(CpuSeconds() - c0);
  }
};

}  // namespace

int main(int argc, char** argv) {
  const int draws = argc > 1 ? std::atoi(argv[1]) : 500;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
  if (draws < 1 || repeats < 1) {
    std::fprintf(stderr, "orbit_batch_bench: DRAWS and REPEATS must be >= 1\n");
    return 2;
  }
  std::mt19937_64 rng(1);
  std::normal_distribution<double> mu_s(0.4, 0.02);
  std::vector<double> draw(draws);
  for (double& d : draw) d = mu_s(rng);
  ss::ParameterColumn v{ss::Parameter::kV, {}}, mu{ss::Parameter::kMuS, {}};
  for (int i = 0; i < 200; ++i)
    for (double d : draw) v.values.push_back(0.05 + 0.4 * i / 199), mu.values.push_back(d);
  const double n = static_cast<double>(v.values.size());
  std::printf("orbit_batch_bench: %.0f points (200 speeds x %d draws), %d repeats, medians\n", n,
              draws, repeats);
  std::printf("  path                                   wall us/pt  CPU us/pt  found\n");
  ss::OrbitBatch b;
  for (int threads : {1, 2}) {
    ss::OrbitBatchOptions o;
    o.threads = threads;
    Timing t;
    for (int r = 0; r < repeats; ++r)
      t.Add([&] { b = ss::StickSlipOrbits(ss::Params(), {v, mu}, o); });
    std::printf("  StickSlipOrbits, %d thread%s              %8.2f   %8.2f   %.4f\n", b.threads,
                b.threads == 1 ? " " : "s", 1e6 * Median(t.wall) / n, 1e6 * Median(t.cpu) / n,
                b.found() / n);
  }
  // The per-point path, on every 50th point (it is about 50x slower).
  Timing t;
  int found = 0, m = 0, batch_found = 0;
  for (std::size_t i = 0; i < v.values.size(); i += 50)
    batch_found += b.status[i] == ss::OrbitStatus::kOk;
  for (int r = 0; r < repeats; ++r)
    t.Add([&] {
      found = m = 0;
      for (std::size_t i = 0; i < v.values.size(); i += 50, ++m) {
        ss::Params p;
        p.v = v.values[i], p.mu_s = mu.values[i];
        ss::OrbitFinder finder{ss::Model(p), ss::OrbitOptions()};
        found += finder.StickSlip().ok();
      }
    });
  std::printf(
      "  fresh finder + StickSlip() per point    %8.2f   %8.2f   %.4f  (%d points; the batch "
      "found %.4f of them)\n",
      1e6 * Median(t.wall) / m, 1e6 * Median(t.cpu) / m, double(found) / m, m,
      double(batch_found) / m);
  return 0;
}
