// orbit_loop: one stick-slip orbit of the seed set at v = 0.25 (rtol 1e-10,
// atol 1e-12, ss_bench's goal row), called in a loop, to profile:
//   perf record ./build/bench/orbit_loop 500000 && perf report
// Prints the mean time per call and the period.
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "stickslip/model/model.hpp"
#include "stickslip/orbits/orbit.hpp"

int main(int argc, char** argv) {
  namespace ss = stickslip;
  ss::Params p;
  p.v = 0.25;
  ss::OrbitOptions o;
  o.flow.rtol = 1e-10;
  o.flow.atol = 1e-12;
  ss::OrbitFinder finder{ss::Model(p), o};
  ss::OrbitResult r = finder.StickSlip();
  const long n = argc > 1 ? std::atol(argv[1]) : 200000;
  if (n < 1) {
    std::fprintf(stderr, "orbit_loop: the count must be >= 1\n");
    return 2;
  }
  const auto t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < n; ++i) r = finder.StickSlip();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%.3f us per orbit, period %.15f\n", s / n * 1e6, r.orbit.period);
  return r.status == ss::OrbitStatus::kOk ? 0 : 1;
}
