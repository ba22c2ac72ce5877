// chain_orbit_bench: one two-block stick-slip orbit with its 4 x 4 monodromy
// (systems/chain: two seed blocks, kc = 0.2, started together) by the one
// shooting on contact 0's stick exit, in a loop; its period against a run at
// rtol 1e-14 (the period error), beside the one-block belt orbit by the
// same shooting. Prints the mean time per orbit and the error.
//   ./build/bench/chain_orbit_bench [COUNT]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "chain/chain.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace {
namespace ss = stickslip;

struct Row {
  double us = 0, period = 0;
  bool ok = false;
};

Row Time(const ss::System& s, const ss::FlowPoint& start, double rtol, long n) {
  ss::ShootingOptions so;
  so.flow.rtol = rtol;
  so.flow.atol = rtol * 1e-2;
  ss::Shooting shooting(s, so);
  Row r;
  r.ok = true;
  const auto t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < n; ++i) {
    const ss::PeriodicOrbit o = shooting.Find(start, ss::PoincareSection::StickExit(0));
    r.period = o.period, r.ok = r.ok && o.ok() && o.monodromy.rows() == s.dimension();
  }
  r.us = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / n * 1e6;
  return r;
}
}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 20000;
  if (n < 1) {
    std::fprintf(stderr, "chain_orbit_bench: usage: chain_orbit_bench [COUNT >= 1]\n");
    return 2;
  }
  const ss::Params p;  // the seed set, v = 0.25
  const double x_exit = p.mu_s - 2 * p.beta * p.v;
  const ss::Model belt(p);
  const ss::chain::Chain two(ss::chain::Uniform(2, p, 0.2));
  const ss::FlowPoint one_start{0, Eigen::Vector2d(x_exit, p.v), ss::ModeSet(ss::Mode::kSlipBelow)};
  Eigen::VectorXd z(4);
  z << x_exit, p.v, x_exit, p.v;
  ss::ModeSet below;
  below.set(1, ss::Mode::kSlipBelow);
  const ss::FlowPoint two_start{0, z, below};
  const double ref = Time(two, two_start, 1e-14, 1).period;
  bool ok = true;
  for (double rtol : {1e-10, 1e-12}) {
    const Row b = Time(belt, one_start, rtol, n), c = Time(two, two_start, rtol, n);
    ok = ok && b.ok && c.ok;
    std::printf(
        "rtol %.0e: belt (2x2) %.3f us, two blocks (4x4) %.3f us (ratio %.2f), period "
        "error %.1e\n",
        rtol, b.us, c.us, c.us / b.us, std::abs(c.period - ref));
  }
  return ok ? 0 : 1;
}
