// orbit_diagram_bench: the orbit diagram's speed goal (issue 21 item 1: 1000
// parameter values x (500 + 200) forcing periods in <= 3 s on 2 cores), on the
// forced coulomb belt (one stick per period at Omega = 0.8) and on the chaotic
// Stribeck setting of tests/chaos/lyapunov_test.cpp. Wall time and process
// CPU time of ComputeOrbitDiagram, per direction count, and one direction cut
// into 2 pieces (c2: OrbitDiagramOptions::chunks, each piece from rest).
//   build/bench/orbit_diagram_bench [n]
#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "stickslip/chaos/orbit_diagram.hpp"

namespace {

using namespace stickslip;

double Seconds(clockid_t id) {
  timespec ts;
  clock_gettime(id, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

void Measure(const char* name, const ForcedBeltParams& p, double from, double to, int n, bool both,
             int chunks = 1) {
  OrbitDiagramOptions o;
  o.from = from, o.to = to, o.n = n;
  o.down = both;
  o.chunks = chunks;
  const double w0 = Seconds(CLOCK_MONOTONIC), c0 = Seconds(CLOCK_PROCESS_CPUTIME_ID);
  const OrbitDiagram d = ComputeOrbitDiagram(p, o);
  const double wall = Seconds(CLOCK_MONOTONIC) - w0, cpu = Seconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
  const double periods =
      static_cast<double>(d.columns.size()) * (o.iterate.transient + o.iterate.keep);
  std::printf(
      "%-34s %-5s c%d %6zu runs  wall %6.2f s  cpu %6.2f s  %5.2f us cpu/period  failed %d\n", name,
      both ? "both" : "up", chunks, d.columns.size(), wall, cpu, cpu * 1e6 / periods, d.failed);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  ForcedBeltParams belt;
  belt.base.law = LawKind::kCoulomb;
  belt.base.mu_s = 0.4, belt.base.mu_k = 0.25, belt.base.beta = 0.05, belt.base.v = 0.2;
  belt.force = 0.3;
  ForcedBeltParams chaotic = belt;
  chaotic.base.law = LawKind::kStribeck;
  chaotic.base.beta = 0.01, chaotic.base.v = 0.1, chaotic.force = 0.5;
  std::printf("orbit diagram, %d values x (500 + 200) forcing periods, rtol = atol = 1e-12\n", n);
  Measure("coulomb belt, omega 0.5..2.5", belt, 0.5, 2.5, n, false);
  Measure("coulomb belt, omega 0.5..2.5", belt, 0.5, 2.5, n, true);
  Measure("coulomb belt, omega 0.5..2.5", belt, 0.5, 2.5, n, false, 2);
  Measure("stribeck (chaotic), omega 0.2..1.2", chaotic, 0.2, 1.2, n, false);
  Measure("stribeck (chaotic), omega 0.2..1.2", chaotic, 0.2, 1.2, n, true);
  Measure("stribeck (chaotic), omega 0.2..1.2", chaotic, 0.2, 1.2, n, false, 2);
  return 0;
}
