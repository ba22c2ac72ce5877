// The model seam is real (issue 19): a second system, a spring-block of
// stiffness w^2 and damping 2 zeta w under coulomb friction on a belt,
//   x'' + 2 zeta w x' + w^2 x = sigma mu_k   (slip, sigma = +1 below, -1 above),
//   x' = v while |w^2 x + 2 zeta w v| <= mu_s   (stick),
// runs through the belt's Flow, event driver, Taylor and CVODE steppers and
// OrbitFinder. Each slip phase is a damped linear oscillation about
// sigma mu_k / w^2 in closed form; the test finds its switch times by
// bracketing and bisection in long double, independent of the library.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/system/taylor_field.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"

namespace stickslip {
namespace {

struct Block {
  double w = 1.7, zeta = 0.01, v = 0.2, mu_s = 0.5, mu_k = 0.3;
};

class SpringBlock final : public FrictionSystem {
 public:
  explicit SpringBlock(const Block& b) : b_(b) {}
  const Block& block() const { return b_; }
  std::unique_ptr<System> Clone() const override { return std::make_unique<SpringBlock>(*this); }
  bool Assign(const System& s) override {
    const auto* o = dynamic_cast<const SpringBlock*>(&s);
    if (o) *this = *o;
    return o != nullptr;
  }
  double v() const override { return b_.v; }
  double Sigma(Mode m) const { return m == Mode::kSlipBelow ? 1.0 : -1.0; }
  double Acceleration(Mode m, double x, double xdot) const override {
    return -b_.w * b_.w * x - 2 * b_.zeta * b_.w * xdot + Sigma(m) * b_.mu_k;
  }
  Mat2 Jacobian(Mode m, const Vec2&) const override {
    Mat2 J = Mat2::Zero();
    if (m != Mode::kStick) J << 0, 1, -b_.w * b_.w, -2 * b_.zeta * b_.w;
    return J;
  }
  std::unique_ptr<TaylorField> MakeTaylorField(const TaylorRequest& request) const override;
  // Its parameters w, zeta, v, mu_s, mu_k; the parameter lens: mu_k only,
  // df/dmu_k = (0, sigma).
  static constexpr int kMuK = 4;
  bool SupportsParameterColumn(int j) const override { return j == kMuK; }
  int parameters() const override { return 5; }
  std::string ParameterName(int j) const override {
    static const char* names[] = {"w", "zeta", "v", "mu_s", "mu_k"};
    return names[j];
  }
  double ParameterValue(int j) const override { return *Member(j); }
  void SetParameterValue(int j, double value) override { *Member(j) = value; }
  double* Member(int j) const {
    Block& b = const_cast<Block&>(b_);
    double* m[] = {&b.w, &b.zeta, &b.v, &b.mu_s, &b.mu_k};
    return m[j];
  }
  double StickForce(double x) const override { return b_.w * b_.w * x + 2 * b_.zeta * b_.w * b_.v; }
  double static_limit() const override { return b_.mu_s; }
  Vec2 ExitPoint() const override {
    return Vec2((b_.mu_s - 2 * b_.zeta * b_.w * b_.v) / (b_.w * b_.w), b_.v);
  }
  Equilibrium SteadySliding() const override {
    Equilibrium e;
    e.x = b_.mu_k / (b_.w * b_.w);
    e.damping = 2 * b_.zeta * b_.w;
    const double wd = b_.w * std::sqrt(1 - b_.zeta * b_.zeta);
    e.lambda1 = {-b_.zeta * b_.w, wd};
    e.lambda2 = {-b_.zeta * b_.w, -wd};
    return e;
  }

 private:
  Block b_;
};

// The linear recurrences: x_{k+1} = x'_k / (k+1), x'_{k+1} = (-w^2 x_k -
// 2 zeta w x'_k + [k = 0] sigma mu_k) / (k+1); Phi and dz/dmu_k alike. In
// stick x = x0 + v t, and the auxiliary rows are the stick force w^2 x + 2
// zeta w v and its limit mu_s.
class BlockField final : public TaylorField {
 public:
  bool Bind(const System& s, const ModeSet& m) override {
    const auto* o = dynamic_cast<const SpringBlock*>(&s);
    if (!o) return false;
    const Block& b = o->block();
    w2_ = b.w * b.w, c_ = 2 * b.zeta * b.w, sigma_ = o->Sigma(m[0]), force_ = sigma_ * b.mu_k;
    stick_ = m[0] == Mode::kStick, v_ = b.v, mu_s_ = b.mu_s;
    return true;
  }
  int AuxRows() const override { return stick_ ? 2 : 0; }
  void Coefficients(int order, const TaylorLayout& l, TaylorRow* c) override {
    const int n = l.aux_first();
    if (stick_) {
      for (int i = 0; i < n; ++i)
        for (int k = 1; k <= order; ++k) c[i][k] = 0;
      c[0][1] = v_;
      for (int k = 0; k <= order; ++k) c[n][k] = w2_ * c[0][k], c[n + 1][k] = 0;
      c[n][0] += c_ * v_;
      c[n + 1][0] = mu_s_;
      return;
    }
    for (int k = 0; k < order; ++k) {
      const double inv = 1.0 / (k + 1);
      for (int col = 0; col < n; col += 2) {
        const double f = k > 0 ? 0.0 : (col == 0 ? force_ : (col == 6 ? sigma_ : 0.0));
        c[col][k + 1] = c[col + 1][k] * inv;
        c[col + 1][k + 1] = (-w2_ * c[col][k] - c_ * c[col + 1][k] + f) * inv;
      }
    }
  }

 private:
  double w2_ = 1, c_ = 0, sigma_ = 1, force_ = 0, v_ = 0, mu_s_ = 0;
  bool stick_ = false;
};

std::unique_ptr<TaylorField> SpringBlock::MakeTaylorField(const TaylorRequest& request) const {
  if (request.parameter && !SupportsParameterColumn(*request.parameter))
    throw InvalidArgument("no parameter column for " + ParameterName(*request.parameter));
  return std::make_unique<BlockField>();
}

// ---- The closed form, in long double ----
using LD = long double;
struct State {
  LD x, xd;
};

// u'' + 2 a u' + w^2 u = 0 with a = zeta w, from (u0, u0') after time t.
State Linear(const Block& b, LD t, LD u0, LD up0) {
  const LD a = b.zeta * LD(b.w), w2 = LD(b.w) * b.w, wd = std::sqrt(w2 - a * a);
  const LD e = std::exp(-a * t), c = std::cos(wd * t), s = std::sin(wd * t);
  return {e * (u0 * c + (up0 + a * u0) / wd * s), e * (up0 * c - (a * up0 + w2 * u0) / wd * s)};
}
// Slip in mode sigma from (x0, xd0) after time t: about x = sigma mu_k / w^2.
State Slip(const Block& b, LD sigma, LD t, LD x0, LD xd0) {
  const LD xc = sigma * b.mu_k / (LD(b.w) * b.w);
  const State u = Linear(b, t, x0 - xc, xd0);
  return {xc + u.x, u.xd};
}
// The first t in (0, t_max] where g changes sign (g(0+) != 0), or -1:
// scanned in steps of 1/400 of a half period, then bisected.
LD FirstRoot(const Block& b, const std::function<LD(LD)>& g, LD t_max) {
  const LD dt = std::acos(-1.0L) / b.w / 400;
  LD lo = dt * 1e-3L;
  const bool s0 = g(lo) > 0;
  for (LD hi = lo + dt; lo < t_max; lo = hi, hi += dt) {
    if (hi > t_max) hi = t_max;
    if ((g(hi) > 0) == s0) continue;
    for (int i = 0; i < 200; ++i) {
      const LD mid = (lo + hi) / 2;
      ((g(mid) > 0) == s0 ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  }
  return -1;
}

// The stick-slip orbit from the exit point: slip below to the arrival on
// x' = v, stick back to the exit point.
struct ClosedOrbit {
  LD t_slip, t_stick, x_arrive, x_max, x_min;
  Mat2 monodromy;
};
ClosedOrbit StickSlipOrbit(const Block& b) {
  const LD w2 = LD(b.w) * b.w, x0 = (b.mu_s - 2 * b.zeta * b.w * LD(b.v)) / w2;
  auto at = [&](LD t) { return Slip(b, 1, t, x0, b.v); };
  ClosedOrbit o;
  o.t_slip = FirstRoot(
      b, [&](LD t) { return at(t).xd - b.v; }, 100);
  o.x_arrive = at(o.t_slip).x;
  o.t_stick = (x0 - o.x_arrive) / b.v;
  const LD t_top = FirstRoot(
      b, [&](LD t) { return at(t).xd; }, o.t_slip);
  o.x_max = at(t_top).x;
  auto after_top = [&](LD t) { return at(t_top + t).xd; };
  o.x_min = std::min(o.x_arrive, at(t_top + FirstRoot(b, after_top, o.t_slip - t_top)).x);
  // M = S_out S_in Phi(t_slip): Phi of the linear slip field; S_in = diag(1, 0);
  // S_out = I + (0, mu_k - mu_s) (1, 0) / v (the force jump at the exit).
  const State c0 = Linear(b, o.t_slip, 1, 0), c1 = Linear(b, o.t_slip, 0, 1);
  Mat2 phi, s_in, s_out;
  phi << double(c0.x), double(c1.x), double(c0.xd), double(c1.xd);
  s_in << 1, 0, 0, 0;
  s_out << 1, 0, (b.mu_k - b.mu_s) / b.v, 1;
  o.monodromy = s_out * s_in * phi;
  return o;
}

OrbitOptions TightSeam(Integrator integrator = Integrator::kTaylor) {
  OrbitOptions o;
  o.flow.rtol = integrator == Integrator::kTaylor ? 1e-13 : 1e-12;
  o.flow.atol = 1e-15;
  o.flow.integrator = integrator;
  o.floquet = true;
  return o;
}

TEST(Seam, StickSlipOrbitOfASecondSystemMatchesClosedForm) {
  const Block b;
  const ClosedOrbit c = StickSlipOrbit(b);
  ASSERT_GT(c.t_slip, 0);
  OrbitFinder finder(SpringBlock(b), TightSeam());
  const OrbitResult r = finder.StickSlip();
  ASSERT_TRUE(r.ok()) << r.message;
  const Orbit& o = r.orbit;
  EXPECT_NEAR(o.period, double(c.t_slip + c.t_stick), 1e-10 * o.period);
  EXPECT_NEAR(o.t_stick, double(c.t_stick), 1e-10);
  EXPECT_NEAR(o.extrema.x_max, double(c.x_max), 1e-10);
  EXPECT_NEAR(o.extrema.x_min, double(c.x_min), 1e-10);
  ASSERT_TRUE(o.has_floquet);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(o.monodromy(i), c.monodromy(i), 1e-10) << "entry " << i;
  // Multipliers {1, 0}: the flow direction, and the stick phase's collapse.
  EXPECT_NEAR(o.eigenvalues[0].real(), 1.0, 1e-10);
  EXPECT_NEAR(std::abs(o.eigenvalues[1]), 0.0, 1e-10);
  EXPECT_NEAR(o.multiplier, 0.0, 1e-10);
}

// The one shooting (shooting.hpp) on the stick exit, from a start off the
// exit point: the same orbit, its Poincare map constant (multiplier 0).
TEST(Seam, TheOneShootingFindsTheSecondSystemsOrbit) {
  const Block b;
  const ClosedOrbit c = StickSlipOrbit(b);
  ShootingOptions so;
  so.flow = TightSeam().flow;
  Shooting shooting(SpringBlock(b), so);
  const FlowPoint start{0, Eigen::Vector2d(0.1, b.v), ModeSet(Mode::kSlipBelow)};
  const PeriodicOrbit o = shooting.Find(start, PoincareSection::StickExit(0));
  ASSERT_TRUE(o.ok()) << o.message;
  EXPECT_NEAR(o.start.z[0], (b.mu_s - 2 * b.zeta * b.w * b.v) / (b.w * b.w), 1e-15);
  EXPECT_NEAR(o.period, double(c.t_slip + c.t_stick), 1e-10 * o.period);
  EXPECT_NEAR(o.hi[0], double(c.x_max), 1e-10);
  EXPECT_NEAR(o.lo[0], double(c.x_min), 1e-10);
  ASSERT_EQ(o.multipliers.size(), 1u);
  EXPECT_NEAR(std::abs(o.multipliers[0]), 0.0, 1e-10);
}

TEST(Seam, TheCvodeStepperRunsTheSecondSystemToo) {
  const Block b;
  const ClosedOrbit c = StickSlipOrbit(b);
  OrbitFinder finder(SpringBlock(b), TightSeam(Integrator::kCvode));
  const OrbitResult r = finder.StickSlip();
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.orbit.period, double(c.t_slip + c.t_stick), 1e-8);
  EXPECT_NEAR(r.orbit.monodromy(1, 1), c.monodromy(1, 1), 1e-7);
}

// The whole walk: a start above the belt crosses x' = v into slip below,
// sticks, leaves, sticks again, ... The closed form follows the same rules.
struct Walk {
  LD t = 0, x = 0, xd = 0, t_stick = 0;
  Mode mode = Mode::kSlipAbove;
  int switches = 0, crossings = 0;
};
Walk ClosedWalk(const Block& b, Walk w, LD t_max) {
  const LD w2 = LD(b.w) * b.w, x_exit = (b.mu_s - 2 * b.zeta * b.w * LD(b.v)) / w2;
  while (w.t < t_max) {
    if (w.mode == Mode::kStick) {
      const LD t_exit = w.t + (x_exit - w.x) / b.v;
      const LD t_end = std::min(t_exit, t_max);
      w.t_stick += t_end - w.t;
      w.x += b.v * (t_end - w.t);
      w.t = t_end;
      if (t_exit >= t_max) break;
      w.mode = Mode::kSlipBelow, w.x = x_exit, ++w.switches;
      continue;
    }
    const LD sigma = w.mode == Mode::kSlipBelow ? 1 : -1;
    auto at = [&](LD t) { return Slip(b, sigma, t, w.x, w.xd); };
    const LD ta = FirstRoot(
        b, [&](LD t) { return at(t).xd - b.v; }, t_max - w.t);
    const State s = at(ta < 0 ? t_max - w.t : ta);
    w.t = ta < 0 ? t_max : w.t + ta, w.x = s.x, w.xd = s.xd;
    if (ta < 0) break;
    w.xd = b.v, ++w.switches;
    if (std::abs(w2 * w.x + 2 * b.zeta * b.w * LD(b.v)) <= b.mu_s) {
      w.mode = Mode::kStick;
    } else {
      w.mode = w.mode == Mode::kSlipBelow ? Mode::kSlipAbove : Mode::kSlipBelow;
      ++w.crossings;
    }
  }
  return w;
}

TEST(Seam, FlowWalksTheSecondSystemThroughCrossingAndStick) {
  const Block b;
  Walk start;
  start.xd = 0.7;  // above the belt
  const LD t_max = 40;
  const Walk c = ClosedWalk(b, start, t_max);
  ASSERT_GE(c.crossings, 1);
  ASSERT_GE(c.switches, 5);
  FlowOptions fo;
  fo.rtol = 1e-13;
  fo.atol = 1e-15;
  BeltFlow flow(SpringBlock(b), fo);
  StopRule stop;
  stop.t_max = double(t_max);
  const FlowResult r = flow.Run(0.0, Vec2(0.0, 0.7), stop);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.switches, c.switches);
  EXPECT_EQ(r.crossings, c.crossings);
  EXPECT_EQ(r.mode, c.mode);
  EXPECT_NEAR(r.z[0], double(c.x), 1e-10);
  EXPECT_NEAR(r.z[1], double(c.xd), 1e-10);
  EXPECT_NEAR(r.t_stick, double(c.t_stick), 1e-10);
}

// The parameter lens: dz/dmu_k along one slip phase is
// (1 - Phi_00, -Phi_10) / w^2 (the centre moves by 1 / w^2).
TEST(Seam, ParameterColumnOfTheSecondSystem) {
  const Block b;
  FlowOptions fo;
  fo.rtol = 1e-13;
  fo.atol = 1e-15;
  BeltFlow flow(SpringBlock(b), fo);
  EXPECT_THROW(flow.set_parameter_column(Parameter::kBeta), InvalidArgument);
  flow.set_parameter_column(Parameter::kMuK);
  StopRule stop;
  stop.t_max = 3;
  stop.switching = false;
  const FlowResult r = flow.Run(0.0, Vec2(0.3, -0.1), Mode::kSlipBelow, stop, true);
  ASSERT_TRUE(r.ok() && r.has_dzdp) << r.message;
  const State phi0 = Linear(b, 3, 1, 0);
  const LD w2 = LD(b.w) * b.w;
  EXPECT_NEAR(r.dzdp[0], double((1 - phi0.x) / w2), 1e-11);
  EXPECT_NEAR(r.dzdp[1], double(-phi0.xd / w2), 1e-11);
  EXPECT_THROW(flow.model(), InvalidArgument);  // not the belt
}

}  // namespace
}  // namespace stickslip
