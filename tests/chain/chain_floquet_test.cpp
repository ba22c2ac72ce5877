// The transverse Floquet multiplier of two identical synchronized blocks
// (seed law, kc = 0.2) against an independent integrator: Boost.Odeint's
// classical Runge-Kutta in long double with its own events (each step
// checked at its end, the event's time bisected by repeating the step with a
// shorter h) and the chain's stick rules written anew. With both blocks
// stuck, d = x1 - x2 is the only coordinate a stick phase keeps, so the
// return map d -> d' from "both stuck" to "both stuck again" has the
// orbit's one nontrivial multiplier as its slope at d = 0 (central
// differences, extrapolated), the eigenvalue the one shooting's 4 x 4 monodromy carries.
#include <gtest/gtest.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>

#include "chain/chain.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip::chain {
namespace {

using LD = long double;
using State = std::array<LD, 4>;

struct Pair {
  LD v = 0.25L, c = 0.1L, kc = 0.2L, mu_s = 0.4L, k1 = 0.45L, k3 = 0.6L;
  LD Mu(LD s) const { return mu_s - k1 * s + k3 * s * s * s; }
  LD Holding(const State& y, int i) const {
    return c * v + (1 + kc) * y[2 * i] - kc * y[2 * (1 - i)];
  }
};

// Modes: 0 below, 1 stick, 2 above.
struct Rhs {
  const Pair* q;
  const int* m;
  void operator()(const State& y, State& f, LD) const {
    for (int i = 0; i < 2; ++i) {
      if (m[i] == 1) {
        f[2 * i] = q->v, f[2 * i + 1] = 0;
        continue;
      }
      const LD sigma = m[i] == 0 ? 1 : -1, vi = y[2 * i + 1];
      f[2 * i] = vi;
      f[2 * i + 1] = -q->c * vi - (1 + q->kc) * y[2 * i] + q->kc * y[2 * (1 - i)] +
                     sigma * q->Mu(sigma * (q->v - vi));
    }
  }
};

// > 0 once block i's event has happened.
LD Event(const Pair& q, const State& y, const int* m, int i) {
  if (m[i] == 1) return std::abs(q.Holding(y, i)) - q.mu_s;
  return m[i] == 0 ? y[2 * i + 1] - q.v : q.v - y[2 * i + 1];
}

// From both stuck at (a, a - d) to the next instant both are stuck after
// some exit: d' = x1 - x2 there.
LD ReturnMap(const Pair& q, LD a, LD d) {
  namespace ode = boost::numeric::odeint;
  ode::runge_kutta4<State, LD, State, LD> rk;
  State y{a, q.v, a - d, q.v};
  int m[2] = {1, 1};
  bool left = false;
  const LD h = 2.5e-4L;
  LD t = 0;
  for (long step = 0; step < 1000000; ++step) {
    const Rhs rhs{&q, m};
    State y1 = y;
    rk.do_step(rhs, y1, t, h);
    int who = -1;
    for (int i = 0; i < 2 && who < 0; ++i)
      if (Event(q, y1, m, i) > 0) who = i;
    if (who < 0) {
      y = y1, t += h;
      continue;
    }
    LD lo = 0, hi = h;
    for (int it = 0; it < 70; ++it) {
      const LD mid = (lo + hi) / 2;
      State ym = y;
      rk.do_step(rhs, ym, t, mid);
      (Event(q, ym, m, who) > 0 ? hi : lo) = mid;
    }
    rk.do_step(rhs, y, t, hi);
    t += hi;
    if (m[who] == 1) {  // exit, to the side the force points
      m[who] = q.Holding(y, who) > 0 ? 0 : 2;
      left = true;
      continue;
    }
    y[2 * who + 1] = q.v;
    const LD f = q.Holding(y, who);
    m[who] = std::abs(f) <= q.mu_s ? 1 : (f > 0 ? 0 : 2);
    if (left && m[0] == 1 && m[1] == 1) return y[0] - y[2];
  }
  return NAN;
}

// Measured: 1.38740067831435 (the one shooting) against 1.3874006783677
// (Odeint, extrapolated): the synchronized orbit is transversally unstable.
TEST(ChainFloquet, TransverseMultiplierMatchesAnIndependentIntegrator) {
  Params p;  // the seed: cubic law mu_s 0.4, k1 0.45, k3 0.6, beta 0.05, v 0.25
  ShootingOptions so;
  so.flow.rtol = 1e-13;
  so.flow.atol = 1e-15;
  const Chain chain(Uniform(2, p, 0.2));
  Shooting sc(chain, so);
  const LD x_exit = (0.4L - 0.1L * 0.25L);
  Eigen::VectorXd z(4);
  z << double(x_exit), p.v, double(x_exit), p.v;
  ModeSet below;
  below.set(1, Mode::kSlipBelow);
  const PeriodicOrbit o = sc.Find(FlowPoint{0, z, below}, PoincareSection::StickExit(0));
  ASSERT_TRUE(o.ok()) << o.message;
  ASSERT_EQ(o.multipliers.size(), 3u);
  const Pair q;
  // The map is smooth on each side of d = 0 but its second derivative
  // jumps there (which block leaves first), so central differences err by
  // O(delta) (3.8e-7 at 1e-5, 3.8e-8 at 1e-6, 3.9e-9 at 1e-7): Richardson's
  // step removes that term (it leaves 5e-11).
  const LD a = x_exit - 1e-3L;
  auto central = [&](LD delta) {
    return (ReturnMap(q, a, delta) - ReturnMap(q, a, -delta)) / (2 * delta);
  };
  const LD slope = (10 * central(1e-7L) - central(1e-6L)) / 9;
  ASSERT_TRUE(std::isfinite(double(slope)));
  EXPECT_NEAR(o.multipliers[0].real(), double(slope), 1e-9);
  EXPECT_NEAR(o.multipliers[0].imag(), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(o.multipliers[1]), 0.0, 1e-10);
  EXPECT_NEAR(std::abs(o.multipliers[2]), 0.0, 1e-10);
}

}  // namespace
}  // namespace stickslip::chain
