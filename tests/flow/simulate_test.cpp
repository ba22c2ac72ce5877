// One streamed trajectory of any system (flow/simulate.hpp): rows from the
// flow's dense output against a closed form, the output grid, both sections,
// the row bound and cancelling; and the forced runs that once stalled.
#include "stickslip/flow/simulate.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "coulomb_damped.hpp"
#include "forced_run.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip {
namespace {

struct Row {
  double t;
  Eigen::VectorXd z;
  ModeSet mode;
};
struct Recorded {
  std::vector<Row> rows, section;
  Simulation r;
};

Recorded Record(const System& s, const FlowPoint& start, const SimulationOptions& o) {
  Recorded out;
  SimulationSink sink;
  const int n = s.dimension();
  sink.row = [&](double t, const double* z, const ModeSet& m) {
    out.rows.push_back({t, Eigen::Map<const Eigen::VectorXd>(z, n), m});
  };
  sink.section = [&](long k, double t, const double* z, const ModeSet& m) {
    EXPECT_EQ(k, static_cast<long>(out.section.size()));
    out.section.push_back({t, Eigen::Map<const Eigen::VectorXd>(z, n), m});
  };
  out.r = Simulate(s, start, o, sink);
  return out;
}

// The Coulomb belt from its exit point x0 = mu_s - 2 beta v, x' = v, slipping
// below until its first return's maximum (coulomb_damped.hpp): every row,
// sampled inside Taylor steps, is the closed form x' = e^{-bt}(v cos wt + D sin wt).
TEST(Simulate, DenseRowsFollowTheCoulombClosedForm) {
  Params p;
  p.law = LawKind::kCoulomb, p.beta = 0.05, p.v = 0.25, p.mu_s = 0.4, p.mu_k = 0.25;
  const Model model(p);
  const double t1 = static_cast<double>(coulomb_damped::FirstMaxTime(p.mu_s, p.mu_k, p.beta, p.v));
  SimulationOptions o;
  o.t_end = 0.9 * t1, o.dt = 0.01, o.extrema = {1};
  const FlowPoint start{0, Eigen::Vector2d(p.mu_s - 2 * p.beta * p.v, p.v),
                        ModeSet(Mode::kSlipBelow)};
  const Recorded rec = Record(model, start, o);
  ASSERT_EQ(rec.r.status, SimulationStatus::kComplete) << rec.r.message;
  EXPECT_EQ(rec.r.sticks, 0);
  ASSERT_EQ(rec.rows.size(), static_cast<size_t>(std::floor(o.t_end / o.dt)) + 2);  // and t_end
  const double w = std::sqrt(1 - p.beta * p.beta);
  const double d = (p.beta * p.v - (p.mu_s - p.mu_k)) / w;
  double vmin = INFINITY;
  for (size_t k = 0; k < rec.rows.size(); ++k) {
    const Row& r = rec.rows[k];
    if (k + 1 < rec.rows.size()) {
      EXPECT_EQ(r.t, k * o.dt);  // origin + k dt, not a running sum
    }
    const double xd = std::exp(-p.beta * r.t) * (p.v * std::cos(w * r.t) + d * std::sin(w * r.t));
    EXPECT_NEAR(r.z[1], xd, 1e-12) << "t = " << r.t;
    vmin = std::min(vmin, r.z[1]);
  }
  EXPECT_EQ(rec.rows.back().t, o.t_end);
  EXPECT_LE(rec.r.lo[0], vmin);  // the extremes are roots, between rows
  EXPECT_GT(rec.r.lo[0], vmin - 1e-3);
}

// The forced Stribeck scene of studies/stribeck_forced.ini at Omega = 0.6,
// past its period-doubling cascade.
ForcedBeltParams StribeckScene() {
  ForcedBeltParams p;
  p.base.law = LawKind::kStribeck;
  p.base.beta = 0.05, p.base.v = 0.25, p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v_s = 0.2;
  p.force = 0.3, p.omega = 0.6;
  return p;
}

SimulationOptions Options(const ForcedBelt& model, double t_end, double dt, SimulationSection s) {
  SimulationOptions o;
  o.flow = ForcedBelt::FlowDefaults();
  o.t_end = t_end, o.dt = dt, o.section = s, o.period = model.period();
  return o;
}

// Before the fix the run stopped at t = 520.6 with "switching does not
// advance t": a stick exit left on the stick line 1e-13 off the band's edge
// gave x'' of either sign at the start of slip, and the flow went straight
// back into stick at the same t (mu(0+) = mu_s: the field is continuous there).
TEST(Simulate, LongStribeckRunCompletesAndEveryExitIsOnTheEdge) {
  const ForcedBeltParams p = StribeckScene();
  const ForcedBelt model(p);
  const Recorded rec = Record(model, ForcedStart(model, 0, 0, p.base.v),
                              Options(model, 3000, 1000, SimulationSection::kExit));
  ASSERT_EQ(rec.r.status, SimulationStatus::kComplete) << rec.r.message;
  ASSERT_GT(rec.section.size(), 100u);
  EXPECT_EQ(static_cast<int>(rec.section.size()), rec.r.exits);
  EXPECT_EQ(rec.r.section_points, rec.r.exits);
  for (const Row& s : rec.section) {
    EXPECT_EQ(s.z[1], p.base.v);
    EXPECT_NE(s.mode[0], Mode::kStick);  // the mode after the exit
    const double phi = model.StickForce(s.t, s.z[0]);
    EXPECT_NEAR(std::abs(phi), p.base.mu_s, 1e-15);
    EXPECT_GT(phi * model.StickForceRate(s.t), 0) << "t = " << s.t;  // leaving the band
  }
}

// Before the fix: a short step (h = 1.4e-3, to the next output row) right
// after a stick exit kept x'' h = 3e-20 (rounding) as the deflated constant
// term, above Deflate's noise relative to the O(h^2) polynomial; its sign
// sent the flow back into stick at the same t ("switching does not advance t").
TEST(Simulate, ShortStepAfterAStickExitLeavesTheSurface) {
  ForcedBeltParams p;  // the seed set, forced: studies/seed_forced.ini
  p.force = 0.3, p.omega = 0.6;
  const ForcedBelt model(p);
  std::vector<FlowSwitch> events;
  FlowRequest rq;
  rq.switches = &events;
  const FlowRun r = testing_util::RunForced(
      model, ForcedStart(model, 70.42, 0.32673483409726917, p.base.v, Mode::kStick), 70.43, rq);
  ASSERT_TRUE(Reached(r)) << r.message;
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, SwitchKind::kStickOut);
  EXPECT_LT(r.end.z[1], p.base.v);  // slipping below the belt
  const Recorded rec = Record(model, ForcedStart(model, 0, 0, p.base.v),
                              Options(model, 1000, 0.01, SimulationSection::kStrobe));
  EXPECT_TRUE(rec.r.ok()) << rec.r.message;
}

// The strobe section stops the flow on t = n T; the rows go on on the same
// grid, every multiple of dt plus one per switch, by time; and they agree
// with a run without the section (no stops) to the flow's tolerance.
TEST(Simulate, StroboscopicPointsAreAtMultiplesOfThePeriod) {
  const ForcedBelt model(StribeckScene());
  const FlowPoint start = ForcedStart(model, 0, 0.1, 0);
  const Recorded rec = Record(model, start, Options(model, 100, 0.3, SimulationSection::kStrobe));
  ASSERT_TRUE(rec.r.ok()) << rec.r.message;
  const double T = model.period();
  ASSERT_EQ(rec.section.size(), static_cast<size_t>(std::floor(100 / T)) + 1);
  for (size_t i = 0; i < rec.section.size(); ++i) EXPECT_EQ(rec.section[i].t, i * T);
  EXPECT_EQ(rec.rows.size(), static_cast<size_t>(std::floor(100 / 0.3 + 1e-9)) + 2 +
                                 static_cast<size_t>(rec.r.sticks + rec.r.exits + rec.r.crossings));
  for (size_t i = 1; i < rec.rows.size(); ++i) EXPECT_GE(rec.rows[i].t, rec.rows[i - 1].t);
  const Recorded plain = Record(model, start, Options(model, 100, 0.3, SimulationSection::kNone));
  ASSERT_EQ(plain.rows.size(), rec.rows.size());
  EXPECT_TRUE(plain.section.empty());
  for (size_t i = 0; i < rec.rows.size(); ++i) {
    EXPECT_NEAR(plain.rows[i].t, rec.rows[i].t, 1e-10);  // switch times move with the steps
    EXPECT_NEAR(plain.rows[i].z[0], rec.rows[i].z[0], 1e-10) << "t = " << rec.rows[i].t;
  }
}

// A start between rows whose next multiple of dt rounds onto it (0.29 / 0.01
// = 28.999...): the first row after the start lies after it, none at it.
TEST(Simulate, StartBetweenRowsRoundsItsFirstBreakpointForward) {
  const ForcedBelt model(StribeckScene());
  const Recorded rec = Record(model, ForcedStart(model, 0.29, 0.1, 0),
                              Options(model, 1, 0.01, SimulationSection::kStrobe));
  ASSERT_TRUE(rec.r.ok()) << rec.r.message;
  ASSERT_GE(rec.rows.size(), 2u);
  EXPECT_EQ(rec.rows[0].t, 0.29);
  EXPECT_GT(rec.rows[1].t, 0.29);  // a switch's row, or the row at 0.30
  EXPECT_LE(rec.rows[1].t, 0.30);
}

// FlowOptions::max_switches bounds the switches within one output interval,
// not within the run: a long run goes on from a run stopped after its
// switches, and integrates as one run would (every switch restarts the
// stepper), row for row and bit for bit. Within one dt it is a failure.
TEST(Simulate, SwitchBoundIsPerOutputIntervalAndContinuesBitForBit) {
  const ForcedBeltParams p = StribeckScene();
  const ForcedBelt model(p);
  const FlowPoint start = ForcedStart(model, 0, 0, p.base.v);
  const SimulationOptions one = Options(model, 600, 1, SimulationSection::kExit);
  SimulationOptions chunked = one;
  chunked.flow.max_switches = 7;
  const Recorded a = Record(model, start, one), b = Record(model, start, chunked);
  ASSERT_EQ(a.r.status, SimulationStatus::kComplete) << a.r.message;
  ASSERT_EQ(b.r.status, SimulationStatus::kComplete) << b.r.message;
  ASSERT_GT(a.r.switches, 10 * chunked.flow.max_switches);
  EXPECT_EQ(b.r.switches, a.r.switches);
  ASSERT_EQ(a.rows.size(), b.rows.size());
  for (size_t i = 0; i < a.rows.size(); ++i) {
    ASSERT_EQ(a.rows[i].t, b.rows[i].t) << i;
    ASSERT_EQ(a.rows[i].z, b.rows[i].z) << "t = " << a.rows[i].t;
  }
  ASSERT_EQ(a.section.size(), b.section.size());
  EXPECT_EQ(static_cast<int>(b.section.size()), b.r.exits);
  SimulationOptions coarse = chunked;
  coarse.dt = 500;  // 7 switches within one output interval: a failure, with where
  const Recorded c = Record(model, start, coarse);
  EXPECT_EQ(c.r.status, SimulationStatus::kFailed);
  EXPECT_NE(c.r.message.find("within one output interval"), std::string::npos) << c.r.message;
}

// A section time that is t_end is a section point; a grid row just before a
// section time (0.9 against T = 0.9000000000000001) is given once, not again
// from the run that starts at T.
TEST(Simulate, SectionAtTheEndAndRowsAtChunkEdgesAreGivenOnce) {
  ForcedBeltParams p = StribeckScene();
  p.omega = 2 * M_PI;  // T = 1 exactly
  const ForcedBelt unit(p);
  ASSERT_EQ(unit.period(), 1.0);
  const Recorded a = Record(unit, ForcedStart(unit, 0, 0.1, 0),
                            Options(unit, 10, 0.25, SimulationSection::kStrobe));
  ASSERT_TRUE(a.r.ok()) << a.r.message;
  ASSERT_EQ(a.section.size(), 11u);
  EXPECT_EQ(a.section.back().t, 10.0);
  p.omega = 20.94395102393195;  // T = 0.3 to rounding: 3 T falls on the row 9 dt
  const ForcedBelt tight(p);
  const Recorded b = Record(tight, ForcedStart(tight, 0, 0.1, 0),
                            Options(tight, 3, 0.1, SimulationSection::kStrobe));
  ASSERT_TRUE(b.r.ok()) << b.r.message;
  EXPECT_EQ(b.rows.size(), 31u + static_cast<size_t>(b.r.switches));
  for (size_t i = 1; i < b.rows.size(); ++i)
    EXPECT_GT(b.rows[i].t - b.rows[i - 1].t, 1e-9) << "t = " << b.rows[i].t;
}

// The row bound counts rows and section points and stops the run there,
// with the rows so far given; a cancel hook stops it with its own status.
TEST(Simulate, RowLimitAndCancelStopWithTheirStatus) {
  const ForcedBelt model(StribeckScene());
  const FlowPoint start = ForcedStart(model, 0, 0.1, 0);
  SimulationOptions o = Options(model, 100, 0.01, SimulationSection::kStrobe);
  o.max_rows = 500;
  const Recorded full = Record(model, start, o);
  EXPECT_EQ(full.r.status, SimulationStatus::kRowLimit);
  EXPECT_EQ(static_cast<long>(full.rows.size() + full.section.size()), o.max_rows);
  EXPECT_NE(full.r.message.find("max_rows = 500"), std::string::npos) << full.r.message;
  o.max_rows = 10000000;
  long polls = 0;
  o.cancelled = [&] { return ++polls > 20; };
  const Recorded cut = Record(model, start, o);
  EXPECT_EQ(cut.r.status, SimulationStatus::kCancelled);
  EXPECT_FALSE(cut.rows.empty());
  EXPECT_LT(cut.rows.back().t, 100);
  o.dt = 0;
  EXPECT_THROW(Record(model, start, o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip
