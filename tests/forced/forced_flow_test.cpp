// The forced oscillator on the one flow (issue 20, item 1) against the coulomb closed form and an
// independent long-double RKF78 integrator (tests/forced_reference.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip {
namespace {

namespace ref = forced_reference;
using ref::Real;

using ref::Coulomb;

ref::Setup SetupOf(const ForcedBeltParams& p) {
  return {reference::Law(p.base), p.base.beta, p.base.v, p.force, p.omega};
}

struct Case {
  ForcedBeltParams p;
  double x0, xdot0, t_end;
};

// Runs both and compares every event time and x, and the end state.
template <class Piece>
void CompareWithReference(const Case& c, double tol, int min_events, double rtol = 1e-13) {
  const ForcedBelt m(c.p);
  FlowOptions o = ForcedBelt::FlowDefaults();
  o.rtol = o.atol = rtol;
  std::vector<FlowSwitch> events;
  FlowRequest rq;
  rq.switches = &events;
  const FlowRun run = testing_util::RunForced(m, ForcedStart(m, 0, c.x0, c.xdot0), c.t_end, rq, o);
  ASSERT_TRUE(Reached(run)) << run.message;

  ref::PieceSim<Piece> sim(SetupOf(c.p));
  Real t = 0, x = c.x0, y = c.xdot0;
  sim.Run(t, x, y, c.t_end);
  std::vector<FlowSwitch> lib;  // touches are no switch in the reference
  for (const auto& e : events)
    if (e.kind != SwitchKind::kTouch) lib.push_back(e);
  ASSERT_EQ(lib.size(), sim.events.size());
  EXPECT_GE(static_cast<int>(lib.size()), min_events);
  double worst = 0;
  for (size_t i = 0; i < lib.size(); ++i) {
    const int kind = lib[i].kind == SwitchKind::kStickIn    ? 0
                     : lib[i].kind == SwitchKind::kStickOut ? 1
                                                            : 2;
    ASSERT_EQ(kind, sim.events[i].kind) << "event " << i << " at t = " << lib[i].t;
    worst = std::max(worst, std::abs(lib[i].t - static_cast<double>(sim.events[i].t)));
    worst = std::max(worst, std::abs(lib[i].z[0] - static_cast<double>(sim.events[i].x)));
  }
  worst = std::max(worst, std::abs(run.end.z[0] - static_cast<double>(x)));
  worst = std::max(worst, std::abs(run.end.z[1] - static_cast<double>(y)));
  EXPECT_LT(worst, tol) << lib.size() << " events";
  std::printf("[ measured ] %zu events (%d sticks, %d crossings), %ld steps: max error %.2e\n",
              lib.size(), run.sticks, run.crossings, run.steps, worst);
}

// Den Hartog's floor (v = 0): reversals (saltation by 2 mu_k) and stops with
// time-dependent exits, every piece in closed form.
TEST(ForcedFlow, FloorReversalsMatchCoulombClosedForm) {
  CompareWithReference<ref::CoulombPiece>({Coulomb(0.4, 0.3, 0.05, 0, 0.8, 0.7), 0, 0, 100}, 1e-11,
                                          20);
}
TEST(ForcedFlow, FloorWithStopsMatchesCoulombClosedForm) {
  CompareWithReference<ref::CoulombPiece>({Coulomb(0.4, 0.3, 0.05, 0, 0.7, 0.6), 0, 0, 100}, 1e-11,
                                          20);
}

// Den Hartog's non-stop regime (mu_s = mu_k, beta = 0), crossings only after the transient.
TEST(ForcedFlow, DenHartogNonStopMatchesCoulombClosedForm) {
  CompareWithReference<ref::CoulombPiece>({Coulomb(0.3, 0.3, 0, 0, 1, 1.3), 0.5, 0, 60}, 1e-11, 10);
}

// A moving belt (v > 0) with forcing: stick phases whose exit phase varies.
TEST(ForcedFlow, ForcedBeltMatchesCoulombClosedForm) {
  CompareWithReference<ref::CoulombPiece>({Coulomb(0.4, 0.25, 0.05, 0.2, 0.3, 0.8), 0, 0.2, 100},
                                          1e-11, 8);
}

// The seed's cubic law on the forced belt, against the long-double RKF78.
TEST(ForcedFlow, ForcedSeedBeltMatchesLongDoubleReference) {
  ForcedBeltParams p;  // the seed set
  p.force = 0.3, p.omega = 0.8;
  CompareWithReference<ref::OdeintPiece>({p, 0.3, 0.25, 80}, 1e-11, 6);
}

// Stribeck on the floor: reversals and stops where the law is smooth (mu(0+) = mu_s).
TEST(ForcedFlow, StribeckFloorMatchesLongDoubleReference) {
  ForcedBeltParams p;
  p.base.law = LawKind::kStribeck;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v_s = 0.3, p.base.beta = 0.05, p.base.v = 0;
  p.force = 0.9, p.omega = 0.6;
  CompareWithReference<ref::OdeintPiece>({p, 0, 0, 80}, 1e-11, 6);
}

// The state transition matrix with saltation (crossings, stick in, stick out)
// against central differences of the closed-form simulation in long double.
TEST(ForcedFlow, JacobianMatchesClosedFormDifferences) {
  for (const ForcedBeltParams& p : {Coulomb(0.4, 0.3, 0.05, 0.1, 0.6, 0.9),  // sticks on a belt
                                    Coulomb(0.3, 0.2, 0.02, 0, 1, 1.3)}) {   // reversals on a floor
    const ForcedBelt m(p);
    FlowOptions o = ForcedBelt::FlowDefaults();
    o.rtol = o.atol = 1e-14;
    FlowRequest rq;
    rq.variational = true;
    const double x0 = 0.7, y0 = -0.3, t_end = 12;
    const FlowRun run = testing_util::RunForced(m, ForcedStart(m, 0, x0, y0), t_end, rq, o);
    ASSERT_TRUE(Reached(run)) << run.message;
    EXPECT_GE(run.sticks + run.crossings, 2);
    const Real d = 1e-6L;
    for (int col = 0; col < 2; ++col) {
      Real end[2][2];
      for (int sgn = 0; sgn < 2; ++sgn) {
        ref::PieceSim<ref::CoulombPiece> sim(SetupOf(p));
        Real t = 0, x = x0 + (col == 0 ? (sgn ? d : -d) : 0),
             y = y0 + (col == 1 ? (sgn ? d : -d) : 0);
        sim.Run(t, x, y, t_end);
        end[sgn][0] = x, end[sgn][1] = y;
      }
      for (int row = 0; row < 2; ++row) {
        const double fd = static_cast<double>((end[1][row] - end[0][row]) / (2 * d));
        EXPECT_NEAR(run.jacobian(row, col), fd, 1e-8 * (1 + std::abs(fd)))
            << "row " << row << " col " << col << " (" << run.sticks << " sticks, " << run.crossings
            << " crossings)";
      }
    }
  }
}

// A = 0: the seed's belt. From the exit point (x0, v) to the next exit is the
// belt's stick-slip orbit (long-double reference, reference/reference_orbit.hpp).
TEST(ForcedFlow, WithoutForcingTheSeedOrbitComesBack) {
  for (const LawKind law : {LawKind::kCubic, LawKind::kStribeck, LawKind::kCoulomb}) {
    ForcedBeltParams p;  // the seed set
    p.base.law = law;
    if (law == LawKind::kCoulomb) p.base.beta = 0;  // damped, its slip spirals into x = mu_k
    const ForcedBelt m(p);
    FlowOptions o = ForcedBelt::FlowDefaults();
    o.rtol = o.atol = 1e-13;
    FlowRequest rq;
    rq.stop_at_exit = 1;
    const double x0 = p.base.mu_s - 2 * p.base.beta * p.base.v;
    const FlowRun run =
        testing_util::RunForced(m, ForcedStart(m, 0, x0, p.base.v, Mode::kSlipBelow), 100, rq, o);
    const Extrema e = RunExtrema(run);
    ASSERT_EQ(run.exits, 1) << Name(law) << ": " << run.message << " t = " << run.end.t;
    const reference::StickSlipOrbit ref = reference::StickSlip(p.base);
    ASSERT_TRUE(ref.found);
    EXPECT_NEAR(run.end.t, static_cast<double>(ref.period), 1e-11) << Name(law);
    if (law == LawKind::kCoulomb) {  // the closed form
      EXPECT_NEAR(run.end.t, static_cast<double>(reference::CoulombPeriodBeta0(0.4L, 0.25L, 0.25L)),
                  1e-12);
    }
    EXPECT_NEAR(e.x_max, static_cast<double>(ref.x_max), 1e-11) << Name(law);
    EXPECT_NEAR(e.x_min, static_cast<double>(ref.x_min), 1e-11) << Name(law);
    EXPECT_NEAR(e.xdot_min, static_cast<double>(ref.xdot_min), 1e-11) << Name(law);
  }
}

// v = 0 and |x| + A < mu_s: the block never leaves stick.
TEST(ForcedFlow, HeldBlockStaysPut) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb, p.base.v = 0, p.base.mu_s = 0.4, p.base.mu_k = 0.3;
  p.force = 0.2, p.omega = 1.7;
  const ForcedBelt m(p);
  const FlowRun run = testing_util::RunForced(m, ForcedStart(m, 0, 0.1, 0), 50);
  EXPECT_EQ(run.end.mode[0], Mode::kStick);
  EXPECT_EQ(run.end.z[0], 0.1);
  EXPECT_EQ(run.end.t, 50);
  EXPECT_EQ(run.exits, 0);
}

// A stick band edge reached for 1e-4 of a period only (max |phi| = mu_s + 1e-9):
// the exit is still found, at its closed-form time acos(-(mu_s - x) / A) / Omega.
TEST(ForcedFlow, BarelyReachedBandEdgeEndsTheStick) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb, p.base.v = 0, p.base.mu_s = 0.4, p.base.mu_k = 0.3;
  p.force = 0.3 + 1e-9, p.omega = 1.7;
  const ForcedBelt m(p);
  FlowRequest rq;
  rq.stop_at_exit = 1;
  const FlowRun run = testing_util::RunForced(m, ForcedStart(m, 0, 0.1, 0), 10, rq);
  ASSERT_EQ(run.exits, 1);
  EXPECT_NEAR(run.end.t, std::acos(-0.3 / p.force) / p.omega, 1e-9);
  EXPECT_EQ(run.end.mode[0], Mode::kSlipBelow);
}

// A slip arc that rises above x' = v by 1e-10 only (coulomb, beta = 0, A = 0:
// a circle of radius r = v + 1e-10 about (mu_k, 0)) arrives at
// t = pi + asin(v / r): the touch is found inside a step.
TEST(ForcedFlow, BarelyReachedSurfaceEndsTheSlip) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb, p.base.beta = 0, p.base.v = 0.25;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25;
  p.force = 0;
  const ForcedBelt m(p);
  const double r = 0.25 + 1e-10;
  const std::vector<FlowSwitch> events =
      testing_util::RunSwitches(m, ForcedStart(m, 0, 0.25 + r, 0), 10);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events[0].kind, SwitchKind::kStickIn);
  EXPECT_NEAR(events[0].t, M_PI + std::asin(0.25 / r), 1e-9);
}

TEST(ForcedFlow, InvalidInputIsNamed) {
  ForcedBeltParams p;
  p.force = -1;
  EXPECT_NE(ValidationError(p).find("force"), std::string::npos);
  p.force = 0.5, p.omega = 0;
  EXPECT_NE(ValidationError(p).find("omega"), std::string::npos);
  p.omega = 1, p.base.v = -0.1;
  EXPECT_NE(ValidationError(p).find("v = "), std::string::npos);
  EXPECT_THROW(ForcedBelt{p}, InvalidArgument);
  p.base.v = 0;
  EXPECT_EQ(ValidationError(p), "");
  FlowOptions o = ForcedBelt::FlowDefaults();
  o.rtol = 0;
  EXPECT_THROW(Flow(ForcedBelt(p), o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip
