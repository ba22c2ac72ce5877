// First-order states in a model file (`states = w`, `w' = ...`;
// docs/model_files.md): the belt written as two first-order states equals
// belt.ini, and the drill string (studies/models/drill_string.ini) has the
// stick-slip orbit an independent integrator finds: Boost.Odeint's
// Dormand-Prince 5(4) with dense output in long double at 1e-18, the bit's
// arrival at w_b = 0 and its stick exit at k_t phi + c_t w_r = mu_sb W_ob R_b
// found by bisection on the dense output, the orbit by iterating the return
// map (the orbit is stable). Shares no code with the library.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop

#include "model_file/model_file.hpp"
#include "stickslip/chaos/orbit_diagram.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/equilibria/steady_branch.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip::model_file {
namespace {

namespace odeint = boost::numeric::odeint;
using LReal = long double;
using DrillState = std::array<LReal, 3>;  // phi, w_r, w_b

const std::string kModelDir = STICKSLIP_SOURCE_DIR "/studies/models/";  // NOLINT

TEST(ModelFileStates, TheBeltAsFirstOrderStatesIsBeltIni) {
  const std::unique_ptr<System> a = ReadModel(kModelDir + "belt.ini");
  const std::unique_ptr<System> b = ParseModel(
      "states = x, u\nparameter v = 0.25\nparameter beta = 0.05\nparameter mu_s = 0.4\n"
      "parameter mu_m = 0.25\nparameter v_m = 0.5\nx' = u\nu' = -2*beta*u - x + F\n"
      "contact F = u - v\n"
      "law F = mu_s - 3*(mu_s - mu_m)/(2*v_m)*s + (mu_s - mu_m)/(2*v_m^3)*s^3\n",
      "first_order_belt.ini");
  ASSERT_EQ(b->dimension(), 2);
  EXPECT_EQ(b->StateName(1), "u");
  EXPECT_EQ(b->DerivativeOf(0), -1);  // a state, not a coordinate with its rate
  ShootingOptions o;
  o.flow.rtol = o.flow.atol = 1e-12;
  const FlowPoint exit{0, Eigen::Vector2d(0.4 - 2 * 0.05 * 0.25, 0.25), ModeSet(Mode::kSlipBelow)};
  const PeriodicOrbit pa = Shooting(*a, o).Find(exit, PoincareSection::StickExit(0));
  const PeriodicOrbit pb = Shooting(*b, o).Find(exit, PoincareSection::StickExit(0));
  ASSERT_TRUE(pa.ok() && pb.ok()) << pa.message << pb.message;
  EXPECT_EQ(pa.period, pb.period);  // the same tape: equal, measured
  EXPECT_EQ(pa.hi[0], pb.hi[0]);
  ASSERT_EQ(pa.multipliers.size(), pb.multipliers.size());
  EXPECT_EQ(pa.multipliers[0], pb.multipliers[0]);
}

TEST(ModelFileStates, AStateAndACoordinateAreWrittenAsDeclared) {
  auto refusal = [](const std::string& text) {
    try {
      ParseModel(text, "bad.ini");
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("read");
  };
  const std::string law = "contact F = u\nlaw F = 0.3\n";
  EXPECT_EQ(refusal("states = u\nu'' = -u + F\n" + law),
            "bad.ini:2: u'' = ...: u is a first-order state: write u' = ...");
  EXPECT_EQ(refusal("coordinates = u\nu' = -u + F\n" + law),
            "bad.ini:2: u' = ...: u is a coordinate: write u'' = ...");
  EXPECT_EQ(refusal("states = u, w\nu' = -u + F\n" + law),
            "bad.ini:1: no equation w' = ... for state w (2 coordinates and states, 1 equations)");
  EXPECT_EQ(refusal("states = u\nstates = w\nu' = F\n" + law),
            "bad.ini:2: a second states line (the first: line 1)");
  EXPECT_EQ(refusal("states = u\nu' = -u + F\n" + law),
            "bad.ini:1: one state component: a model needs at least two (a coordinate x, or two "
            "states)");
  EXPECT_EQ(refusal("states = u, w,\nu' = -u + F\nw' = -w\n" + law), "bad.ini:1: '' is not a name");
  EXPECT_EQ(refusal("coordinates = u\nstates = udot\nu'' = -u + F\nudot' = -udot\n" + law),
            "bad.ini:2: the name 'udot' is the column of u' in the tables: choose another");
  EXPECT_EQ(refusal("states = u, w\nu' = -u' + F\nw' = -w\n" + law),
            "bad.ini:2: u' = '-u' + F': unknown name \"u'\" (not a coordinate, a rate x', a "
            "state, a parameter, a contact force)");
}

// The drill string's parameters, read from the file.
struct Drill {
  LReal J_r, J_b, k_t, c_t, c_r, c_b, torque_limit, rock, mu_c, mu_s, gamma, T_m, W_ob;
  explicit Drill(const System& s) {
    auto p = [&](const char* name) { return LReal(s.ParameterValue(s.ParameterIndex(name))); };
    J_r = p("J_r"), J_b = p("J_b"), k_t = p("k_t"), c_t = p("c_t"), c_r = p("c_r");
    c_b = p("c_b"), mu_c = p("mu_cb"), mu_s = p("mu_sb"), gamma = p("gamma_b"), T_m = p("T_m");
    W_ob = p("W_ob"), rock = W_ob * p("R_b");
    torque_limit = mu_s * rock;
  }
  void Slip(const DrillState& z, DrillState& dz) const {  // the bit turning forward, w_b > 0
    const LReal mu = mu_c + (mu_s - mu_c) * std::exp(-gamma * z[2]);
    dz[0] = z[1] - z[2];
    dz[1] = (T_m - c_t * (z[1] - z[2]) - k_t * z[0] - c_r * z[1]) / J_r;
    dz[2] = (c_t * (z[1] - z[2]) + k_t * z[0] - c_b * z[2] - rock * mu) / J_b;
  }
  void Stick(const DrillState& z, DrillState& dz) const {  // the bit at rest
    dz[0] = z[1];
    dz[1] = (T_m - (c_t + c_r) * z[1] - k_t * z[0]) / J_r;
    dz[2] = 0;
  }
};

// From z at time 0, the time where event(z) first turns >= 0, and z there.
template <class Field, class Event>
LReal Until(const Field& field, const Event& event, DrillState& z) {
  auto stepper = odeint::make_dense_output(LReal(1e-18), LReal(1e-18),
                                           odeint::runge_kutta_dopri5<DrillState, LReal>());
  stepper.initialize(z, 0, LReal(1e-4));
  auto f = [&](const DrillState& y, DrillState& dy, LReal) { field(y, dy); };
  do stepper.do_step(f);
  while (event(stepper.current_state()) < 0);
  LReal lo = stepper.previous_time(), hi = stepper.current_time();
  for (int i = 0; i < 200 && hi - lo > 1e-19L * hi; ++i) {
    const LReal mid = (lo + hi) / 2;
    stepper.calc_state(mid, z);
    (event(z) < 0 ? lo : hi) = mid;
  }
  stepper.calc_state(hi, z);
  return hi;
}

// The reference's stable stick-slip orbit: the return map from a stick exit
// (w_b = 0, k_t phi + c_t w_r at the limit) iterated until it stops moving;
// its exit and period; *moved the last step.
DrillState SettledExit(const Drill& d, LReal* period, LReal* moved) {
  DrillState exit{(d.torque_limit - d.c_t * 3) / d.k_t, 3, 0};
  *moved = 1;
  for (int n = 0; n < 200 && *moved > 1e-17L; ++n) {
    DrillState z = exit;
    const LReal slip = Until([&](const DrillState& y, DrillState& dy) { d.Slip(y, dy); },
                             [](const DrillState& y) { return -y[2]; }, z);
    z[2] = 0;
    const LReal stick =
        Until([&](const DrillState& y, DrillState& dy) { d.Stick(y, dy); },
              [&](const DrillState& y) { return d.k_t * y[0] + d.c_t * y[1] - d.torque_limit; }, z);
    *moved = std::abs(z[1] - exit[1]);
    exit = z, *period = slip + stick;
  }
  return exit;
}

TEST(ModelFileStates, TheDrillStringsStickSlipOrbitMatchesAnIndependentIntegrator) {
  const std::unique_ptr<System> s = ReadModel(kModelDir + "drill_string.ini");
  ASSERT_EQ(s->dimension(), 3);
  const Drill d(*s);
  LReal period = 0, moved = 1;
  const DrillState exit = SettledExit(d, &period, &moved);
  ASSERT_LE(moved, 1e-15L) << "the reference did not settle";
  ShootingOptions o;
  o.flow.rtol = o.flow.atol = 1e-13;
  const FlowPoint guess{0, Eigen::Vector3d(double(exit[0]), double(exit[1]) + 1e-3, 0),
                        ModeSet(Mode::kSlipAbove)};
  const PeriodicOrbit orbit = Shooting(*s, o).Find(guess, PoincareSection::StickExit(0));
  ASSERT_TRUE(orbit.ok()) << orbit.message;
  EXPECT_EQ(orbit.sticks, 1);
  EXPECT_TRUE(orbit.stable);
  EXPECT_NEAR(orbit.period, double(period), 1e-11 * double(period));
  EXPECT_NEAR(orbit.start.z[1], double(exit[1]), 1e-11);
  EXPECT_NEAR(orbit.start.z[0], double(exit[0]), 1e-11);
  // Steady rotation, the bit slipping above: T_m = (c_r + c_b) w + W R mu(w).
  const SteadyState rest = SteadySliding(*s);
  ASSERT_TRUE(rest.found);
  EXPECT_EQ(rest.mode[0], Mode::kSlipAbove);
  const LReal w = rest.z[2];
  const LReal mu = d.mu_c + (d.mu_s - d.mu_c) * std::exp(-d.gamma * w);
  EXPECT_NEAR(double((d.c_r + d.c_b) * w + d.rock * mu), double(d.T_m), 1e-9 * double(d.T_m));
  EXPECT_NEAR(rest.z[1], rest.z[2], 1e-12 * (1 + rest.z[2]));  // w_r = w_b
}

// The Hopf point of steady rotation in closed form. The Jacobian in
// (phi, w_r, w_b) reads the speed w only through d = c_b + W_ob R_b mu'(w);
// its characteristic polynomial x^3 + a1 x^2 + a2 x + a3 has a pair on the
// imaginary axis where a1 a2 = a3 (Routh-Hurwitz), a quadratic in d (its
// coefficients from three d). Its larger root d* on the fast
// rotation (the other lies on the slow, saddle one) gives
// exp(-gamma w*) = (c_b - d*) / (gamma (mu_sb - mu_cb) W R)
// and T_m* = (c_r + c_b) w* + W R mu(w*): 9268.897787273090 N m
// (an mpmath check at 30 digits agreed to 25).
TEST(ModelFileStates, TheDrillStringsHopfPointIsTheClosedForm) {
  const std::unique_ptr<System> s = ReadModel(kModelDir + "drill_string.ini");
  const Drill d(*s);
  // J = [[0, 1, -1], [-a, -b, c], [e, f, -g]]: a1 = -trace, a2 = the sum of
  // the principal 2x2 minors, a3 = -det.
  auto hurwitz = [&](LReal damping) {
    const LReal a = d.k_t / d.J_r, b = (d.c_t + d.c_r) / d.J_r, c = d.c_t / d.J_r;
    const LReal e = d.k_t / d.J_b, f = d.c_t / d.J_b, g = (d.c_t + damping) / d.J_b;
    const LReal a1 = b + g, a2 = a + e + b * g - c * f, a3 = a * g - c * e - a * f + b * e;
    return a1 * a2 - a3;
  };
  const LReal f0 = hurwitz(0), f1 = hurwitz(1), fm = hurwitz(-1);
  const LReal qa = (f1 + fm - 2 * f0) / 2, qb = (f1 - fm) / 2, qc = f0;
  const LReal root = std::sqrt(qb * qb - 4 * qa * qc);
  const LReal d1 = (-qb + root) / (2 * qa), d2 = (-qb - root) / (2 * qa);
  const LReal dstar = std::max(d1, d2);  // -277.09: the fast rotation's (the other is a saddle's)
  EXPECT_NEAR(double(dstar), -277.08630707087289, 1e-9);
  const LReal w = -std::log((d.c_b - dstar) / (d.gamma * (d.mu_s - d.mu_c) * d.rock)) / d.gamma;
  const LReal t_hopf =
      (d.c_r + d.c_b) * w + d.rock * (d.mu_c + (d.mu_s - d.mu_c) * std::exp(-d.gamma * w));
  std::unique_ptr<System> at = s->Clone();
  const int j = at->ParameterIndex("T_m");
  at->SetParameterValue(j, 12000);
  SteadyBranchOptions o;
  o.points = 61;
  const SteadyBranch b = ContinueSteadySliding(*at, j, 9240, o);  // the fold: 9236.34
  int hopf = 0;
  for (const SteadyRow& r : b.special)
    if (r.label == SpecialKind::kHopf) {
      ++hopf;
      EXPECT_NEAR(r.p, double(t_hopf), 1e-12 * double(t_hopf));  // 5.4e-15 measured
    }
  EXPECT_EQ(hopf, 1);
  EXPECT_NEAR(double(t_hopf), 9268.897787273090, 1e-8);
}

// The Hopf curve in (T_m, W_ob) (ChartSystem): d* does not depend on W_ob,
// so every point lies on T_m*(W_ob) of the closed form above. It followed
// one steady rotation only once the curve's samples took the last one's rest
// point as Newton's guess: before, the test jumped between the fast and the
// slow rotation, and 26271 points crawled 4e-6 off the curve.
TEST(ModelFileStates, TheDrillStringsHopfCurveIsTheClosedForm) {
  const std::unique_ptr<System> s = ReadModel(kModelDir + "drill_string.ini");
  const Drill d(*s);
  SystemChartOptions o;
  o.plane = {s->ParameterIndex("T_m"), s->ParameterIndex("W_ob"), 9240, 10685, 80000, 110000};
  o.orbit_curves = false;
  const SystemChart c = ChartSystem(*s, o);
  const double d_star = -277.08630707087289;  // the closed form's root, as above
  int points = 0;
  double worst = 0;
  for (const SystemCurve& curve : c.curves) {
    if (curve.kind != CurveKind::kHopf) continue;
    for (const SystemCurvePoint& q : curve.points) {
      const LReal rock = d.rock / d.W_ob * q.p2;  // W_ob R_b at this W_ob
      const LReal w = -std::log((d.c_b - d_star) / (d.gamma * (d.mu_s - d.mu_c) * rock)) / d.gamma;
      const LReal t =
          (d.c_r + d.c_b) * w + rock * (d.mu_c + (d.mu_s - d.mu_c) * std::exp(-d.gamma * w));
      worst = std::max(worst, std::abs(q.p1 - double(t)) / double(t));
      ++points;
    }
  }
  EXPECT_GE(points, 40);
  EXPECT_LE(points, 1000);
  EXPECT_LE(worst, 1e-12);  // 2e-16 measured
}

// A model of first-order states alone has no maxima of a coordinate to cut
// its orbits at: its default section (MaximaSection) is the bit speed falling
// through its steady-rotation value. The orbit diagram's point at T_m = 10000
// against the reference's crossing of that plane (Odeint, long double), and
// its Lyapunov exponent (the map iterated on that plane) against ln|mu| / T
// of the shooting's orbit on the stick exit (another section, another code).
TEST(ModelFileStates, TheDrillStringsOrbitDiagramCutsAtItsSteadyBitSpeed) {
  const std::unique_ptr<System> s = ReadModel(kModelDir + "drill_string.ini");
  const Drill d(*s);
  LReal period = 0, moved = 1;
  DrillState z = SettledExit(d, &period, &moved);
  ASSERT_LE(moved, 1e-15L);
  const SteadyState rest = SteadySliding(*s);
  ASSERT_TRUE(rest.found);
  const LReal w_rest = rest.z[2];
  const auto slip = [&](const DrillState& y, DrillState& dy) { d.Slip(y, dy); };
  Until(slip, [&](const DrillState& y) { return y[2] - w_rest; }, z);  // rising
  Until(slip, [&](const DrillState& y) { return w_rest - y[2]; }, z);  // falling: the section
  OrbitDiagramOptions o;
  o.from = 10000, o.to = 10100, o.n = 2, o.down = false;
  o.iterate.flow.rtol = o.iterate.flow.atol = 1e-13;
  const OrbitDiagram od = ComputeOrbitDiagram(*s, s->ParameterIndex("T_m"), o);
  ASSERT_FALSE(od.columns.empty());
  const DiagramColumn& c = od.columns.front();
  ASSERT_EQ(c.value, 10000);
  ASSERT_EQ(c.run.status, LyapunovStatus::kDone) << c.run.message;
  ASSERT_FALSE(c.run.points.empty());
  for (const SectionPoint& q : c.run.points) {  // period 1: one point
    EXPECT_NEAR(q.z[0], double(z[0]), 1e-10);
    EXPECT_NEAR(q.z[1], double(z[1]), 1e-10);
    EXPECT_NEAR(q.z[2], double(w_rest), 1e-12);
  }
  ShootingOptions so;
  so.flow.rtol = so.flow.atol = 1e-13;
  const FlowPoint guess{0, Eigen::Vector3d(13.6, 2.35, 0), ModeSet(Mode::kSlipAbove)};
  const PeriodicOrbit orbit = Shooting(*s, so).Find(guess, PoincareSection::StickExit(0));
  ASSERT_TRUE(orbit.ok()) << orbit.message;
  const double lambda = std::log(std::abs(orbit.multipliers.front())) / orbit.period;
  EXPECT_NEAR(c.run.lyapunov, lambda, 1e-9 * std::abs(lambda));
  std::printf("[ measured ] section point (%.15g, %.15g) vs reference %.3e; lyapunov %.15g vs "
              "ln|mu|/T %.15g\n",
              c.run.points.front().z[0], c.run.points.front().z[1],
              std::abs(c.run.points.front().z[0] - double(z[0])), c.run.lyapunov, lambda);
}

}  // namespace
}  // namespace stickslip::model_file
