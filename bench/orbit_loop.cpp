// orbit_loop: one stick-slip orbit of the seed set at v = 0.25 (rtol 1e-10,
// atol 1e-12, ss_bench's goal row), called in a loop, to profile:
//   perf record ./build/bench/orbit_loop 500000 && perf report
// With `shooting`, the same orbit by the one shooting (orbits/shooting.hpp)
// on its stick-exit section, the stick phase integrated instead of closed.
// Prints the mean time per call and the period.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/belt/model.hpp"

int main(int argc, char** argv) {
  namespace ss = stickslip;
  ss::Params p;
  p.v = 0.25;
  ss::OrbitOptions o;
  o.flow.rtol = 1e-10;
  o.flow.atol = 1e-12;
  const ss::Model model(p);
  ss::OrbitFinder finder{model, o};
  ss::ShootingOptions so;
  so.flow = o.flow;
  ss::Shooting shooting{model, so};
  const ss::FlowPoint exit{0, Eigen::Vector2d(model.ExitPoint()[0], p.v),
                           ss::ModeSet(ss::Mode::kSlipBelow)};
  const long n = argc > 1 ? std::atol(argv[1]) : 200000;
  const bool one = argc > 2 && std::strcmp(argv[2], "shooting") == 0;
  if (n < 1 || (argc > 2 && !one)) {
    std::fprintf(stderr, "orbit_loop: usage: orbit_loop COUNT [shooting]\n");
    return 2;
  }
  double period = 0;
  bool ok = true;
  const auto t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < n; ++i) {
    if (one) {
      const ss::PeriodicOrbit r = shooting.Find(exit, ss::PoincareSection::StickExit(0));
      period = r.period, ok = r.ok();
    } else {
      const ss::OrbitResult r = finder.StickSlip();
      period = r.orbit.period, ok = r.ok();
    }
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%.3f us per orbit, period %.15f\n", s / n * 1e6, period);
  return ok ? 0 : 1;
}
