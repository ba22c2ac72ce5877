// The parameter column dz/dp through switches (flow.hpp, FlowRun::dzdp) and
// the Poincare map's dP/dp (shooting.hpp, parameter_derivative), checked
// against an independent computation: Richardson-extrapolated central
// differences of plain runs (no variational rows, no saltation) at tighter
// tolerances. Runs with stick phases, exits and, for the forced oscillator,
// the clock's frequency (theta = Omega t moves the forcing).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "stickslip/flow/flow.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace {

using namespace stickslip;
using Eigen::VectorXd;

FlowOptions Tight() {
  FlowOptions o;
  o.rtol = o.atol = 1e-14;
  return o;
}

// d/dp of f(p) by central differences at h and h/2, Richardson-combined
// (error O(h^4) plus the runs' error over h).
template <class F>
VectorXd Differences(const F& f, double p, double h) {
  const VectorXd d1 = (f(p + h) - f(p - h)) / (2 * h);
  const VectorXd d2 = (f(p + h / 2) - f(p - h / 2)) / h;
  return (4 * d2 - d1) / 3;
}

void ExpectClose(const VectorXd& got, const VectorXd& ref, double tol, const std::string& what) {
  ASSERT_EQ(got.size(), ref.size()) << what;
  const double scale = std::max(1.0, ref.lpNorm<Eigen::Infinity>());
  EXPECT_LE((got - ref).lpNorm<Eigen::Infinity>(), tol * scale)
      << what << ": column " << got.transpose() << ", differences " << ref.transpose();
}

// z(t_max) of a plain run of system s with parameter j at p. A start in
// stick moves with the contact's surface (x' = v), as the column assumes.
VectorXd EndAt(System& s, int j, double p, const FlowPoint& start, double t_max, int* switches) {
  s.SetParameterValue(j, p);
  Flow flow(s, Tight());
  FlowRequest rq;
  rq.t_max = t_max;
  FlowPoint from = start;
  if (from.mode.sticks(0)) from.z[1] = s.Contact(0).speed;
  const FlowRun r = flow.Run(from, rq);
  EXPECT_EQ(r.status, FlowStatus::kTimeLimit);
  if (switches) *switches = r.switches;
  return r.end.z.head(s.tangent_dimension());
}

void CheckColumn(const System& system, const FlowPoint& start, double t_max,
                 const std::vector<std::string>& names, int min_exits = 2) {
  for (const std::string& name : names) {
    const int j = system.ParameterIndex(name);
    ASSERT_GE(j, 0) << name;
    ASSERT_TRUE(system.SupportsParameterColumn(j)) << name;
    Flow flow(system, FlowOptions());
    flow.set_parameter_column(j);
    FlowRequest rq;
    rq.t_max = t_max;
    rq.parameter_column = true;
    const FlowRun r = flow.Run(start, rq);
    ASSERT_EQ(r.status, FlowStatus::kTimeLimit) << name;
    ASSERT_TRUE(r.has_dzdp) << name;
    EXPECT_GE(r.exits, min_exits) << name;  // stick phases entered and left
    const std::unique_ptr<System> s = system.Clone();
    const double p0 = system.ParameterValue(j);
    const double h = 1e-4 * std::max(1.0, std::abs(p0));
    int switches = -1, here = -1;
    auto end = [&](double p) { return EndAt(*s, j, p, start, t_max, &here); };
    const VectorXd ref = Differences(
        [&](double p) {
          const VectorXd z = end(p);
          if (switches < 0) switches = here;
          EXPECT_EQ(here, switches) << name << " at " << p;  // the same sequence
          return z;
        },
        p0, h);
    ExpectClose(r.dzdp, ref, 1e-7, name);
  }
}

TEST(ParameterColumn, BeltThroughStickPhases) {
  Params p;  // the seed set: stick-slip from rest
  FlowPoint start;
  start.z = Eigen::Vector2d(0.1, 0.0);
  start.mode = ModeSet(Mode::kSlipBelow);
  CheckColumn(Model(p), start, 30, {"beta", "v", "mu_s", "mu_m"});
  p.law = LawKind::kStribeck;
  p.mu_k = 0.25;
  CheckColumn(Model(p), start, 30, {"beta", "v", "mu_s", "mu_k"});
}

TEST(ParameterColumn, FromAStickStart) {
  Params p;
  FlowPoint start;
  start.z = Eigen::Vector2d(0.1, p.v);
  start.mode = ModeSet(Mode::kStick);
  CheckColumn(Model(p), start, 30, {"beta", "v", "mu_s", "mu_m"}, 1);
  ForcedBeltParams f;
  f.force = 0.5, f.omega = 1.1;
  start.z = Eigen::Vector3d(0.1, f.base.v, 0.3);
  CheckColumn(ForcedBelt(f), start, 30, {"beta", "v", "mu_s", "force", "omega"}, 1);
}

TEST(ParameterColumn, ForcedThroughStickPhasesAndTheClock) {
  ForcedBeltParams p;  // 13 switches by t = 30, the same on either side of each p
  p.force = 0.5, p.omega = 1.1;
  FlowPoint start;
  start.z = Eigen::Vector3d(0.1, 0.0, 0.3);
  start.mode = ModeSet(Mode::kSlipBelow);
  CheckColumn(ForcedBelt(p), start, 30, {"beta", "v", "mu_s", "force", "omega"});
}

// dP/dp of the residual P(z) - z at a fixed z against differences of the
// plain map.
void CheckMap(const System& system, const FlowPoint& z, const PoincareSection& section,
              const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const int j = system.ParameterIndex(name);
    ShootingOptions o;
    Shooting shooting(system, o);
    shooting.set_parameter_column(j);
    VectorXd r;
    PeriodicOrbit orbit;
    ASSERT_TRUE(shooting.Map(z, section, true, &r, &orbit)) << name << ": " << orbit.message;
    const VectorXd got = shooting.parameter_derivative();
    ShootingOptions tight;
    tight.flow = Tight();
    const std::unique_ptr<System> s = system.Clone();
    Shooting plain(*s, tight);
    const double p0 = system.ParameterValue(j);
    auto map = [&](double p) {
      s->SetParameterValue(j, p);
      plain.set_system(*s);
      // The stroboscopic section's time follows the clock (2 pi m / omega).
      const PoincareSection sec = section.kind == SectionKind::kTime && section.turns > 0
                                      ? PoincareSection::Stroboscopic(*s, z.z, section.turns)
                                      : section;
      VectorXd res;
      PeriodicOrbit o2;
      EXPECT_TRUE(plain.Map(z, sec, false, &res, &o2)) << name << ": " << o2.message;
      EXPECT_EQ(o2.sticks, orbit.sticks) << name << " at " << p;
      return res;
    };
    ExpectClose(got, Differences(map, p0, 1e-4 * std::max(1.0, std::abs(p0))), 1e-7, name);
  }
}

TEST(ParameterColumn, BeltStickExitMap) {
  const Model m{Params()};
  FlowPoint z;
  z.z = Eigen::Vector2d(0.3, 0.05);
  z.mode = ModeSet(Mode::kSlipBelow);
  CheckMap(m, z, PoincareSection::StickExit(0), {"beta", "v", "mu_s", "mu_m"});
}

TEST(ParameterColumn, ForcedStroboscopicAndStickExitMaps) {
  ForcedBeltParams p;
  p.force = 0.3, p.omega = 0.8;
  const ForcedBelt m(p);
  FlowPoint z;
  z.z = Eigen::Vector3d(0.1, 0.0, 0.3);
  z.mode = ModeSet(Mode::kSlipBelow);
  const std::vector<std::string> names = {"beta", "v", "mu_s", "force", "omega"};
  CheckMap(m, z, PoincareSection::Stroboscopic(m, z.z, 2), names);
  CheckMap(m, z, PoincareSection::StickExit(0, 2, 1), names);
}

TEST(ParameterColumn, RefusedWhereTheSystemHasNone) {
  Params p;
  p.law = LawKind::kStribeck;
  Flow flow{Model(p), FlowOptions()};
  EXPECT_THROW(flow.set_parameter_column(Model(p).ParameterIndex("v_s")), InvalidArgument);
  FlowOptions cv;
  cv.integrator = Integrator::kCvode;
  Flow cvode{Model(Params()), cv};
  cvode.set_parameter_column(Model(Params()).ParameterIndex("v"));
  EXPECT_FALSE(cvode.has_parameter_column());  // Taylor only
}

}  // namespace
