// Parameter columns derived from a model file (compiled.hpp, model_taylor.cpp):
// dz/dp of a run against the built-in forced oscillator's hand-written columns
// (ForcedBelt: belt_taylor.cpp, a field and saltations of its own) and,
// where the built-in has none, against central differences of runs at a
// tighter tolerance; then the forced Stribeck branch with its PD points,
// through the one branch driver, row by row against the built-in's.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "model_file/model_file.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/flow/flow.hpp"
#include "stickslip/orbits/settle.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::model_file {
namespace {

// studies/stribeck_forced.ini's oscillator as a model file.
constexpr char kStribeckForced[] = R"(name = stribeck_forced
coordinates = x
clock theta = omega
parameter beta = 0.05
parameter v = 0.25
parameter mu_s = 0.4
parameter mu_k = 0.25
parameter v_s = 0.2
parameter force = 0.3
parameter omega = 0.8
x'' = -2*beta*x' - x + F + force*cos(theta)
contact F = x' - v
law F = mu_k + (mu_s - mu_k)*exp(-s/v_s)
)";

ForcedBeltParams StribeckBuiltIn() {
  ForcedBeltParams p;
  p.base.law = LawKind::kStribeck;
  p.base.beta = 0.05, p.base.v = 0.25, p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v_s = 0.2;
  p.force = 0.3, p.omega = 0.8;
  return p;
}

FlowOptions ColumnTol(double tol) {
  FlowOptions o = ForcedBelt::FlowDefaults();
  o.rtol = o.atol = tol;
  return o;
}

// z(t_end) and, with a column for parameter j, dz/dp from (x, x', 0).
FlowRun ColumnRun(const System& s, int j, double t_end, double tol) {
  Flow flow(s, ColumnTol(tol));
  FlowRequest rq;
  rq.t_max = t_end;
  if (j >= 0) {
    flow.set_parameter_column(j);
    rq.variational = rq.parameter_column = true;
  }
  const Eigen::Vector3d z(0.1, -0.05, 0.3);
  FlowRun r;
  flow.Run(FlowPoint{0, z, ModeOf(s, z)}, rq, &r);
  return r;
}

TEST(ModelColumns, ARunsColumnIsTheBuiltInsOrCentralDifferences) {
  const std::unique_ptr<System> file = ParseModel(kStribeckForced, "stribeck_forced.ini");
  const ForcedBelt built(StribeckBuiltIn());
  const double t_end = 25;  // several stick phases and exits
  int against_builtin = 0, against_differences = 0;
  double worst_builtin = 0, worst_differences = 0;
  for (int j = 0; j < file->parameters(); ++j) {
    const std::string name = file->ParameterName(j);
    const FlowRun r = ColumnRun(*file, j, t_end, 1e-13);
    ASSERT_EQ(r.status, FlowStatus::kTimeLimit) << name << ": " << r.message;
    ASSERT_TRUE(r.has_dzdp) << name;
    ASSERT_GT(r.sticks, 1) << name;
    const int b = built.ParameterIndex(name);
    if (b >= 0 && built.SupportsParameterColumn(b)) {
      const FlowRun ref = ColumnRun(built, b, t_end, 1e-13);
      ASSERT_TRUE(ref.has_dzdp);
      for (int i = 0; i < 2; ++i) {
        const double e = std::abs(r.dzdp[i] - ref.dzdp[i]) / (1 + std::abs(ref.dzdp[i]));
        worst_builtin = std::max(worst_builtin, e);
        EXPECT_LE(e, 1e-11) << name << " " << i << ": " << r.dzdp[i] << " vs " << ref.dzdp[i];
      }
      ++against_builtin;
    }
    // Central differences at 1e-14 (truncation h^2 ~ 1e-10, noise 1e-14 / h).
    const double h = 1e-5 * std::max(1.0, std::abs(file->ParameterValue(j)));
    std::unique_ptr<System> up = file->Clone(), down = file->Clone();
    up->SetParameterValue(j, file->ParameterValue(j) + h);
    down->SetParameterValue(j, file->ParameterValue(j) - h);
    const FlowRun a = ColumnRun(*up, -1, t_end, 1e-14), c = ColumnRun(*down, -1, t_end, 1e-14);
    ASSERT_EQ(a.sticks, c.sticks) << name;
    for (int i = 0; i < 2; ++i) {
      const double d = (a.end.z[i] - c.end.z[i]) / (2 * h);
      const double e = std::abs(r.dzdp[i] - d) / (1 + std::abs(d));
      worst_differences = std::max(worst_differences, e);
      EXPECT_LE(e, 1e-7) << name << " " << i << ": " << r.dzdp[i] << " vs " << d;
    }
    ++against_differences;
  }
  std::printf("[ measured ] %d columns vs the built-in's: %.2e; %d vs central differences: %.2e\n",
              against_builtin, worst_builtin, against_differences, worst_differences);
  EXPECT_GE(against_builtin, 3);  // beta, v, force, omega at least
  EXPECT_EQ(against_differences, 7);
}

// studies/stribeck_forced.ini's branch in Omega from 0.8 down to 0.5 (its PD
// cascade begins there) through the one branch driver, on the built-in
// oscillator and on the model file, from the same settled orbit: with both
// parameter columns exact, the same steps, rows and special points.
TEST(ModelColumns, TheForcedStribeckBranchIsTheBuiltInsRowByRow) {
  const std::unique_ptr<System> file = ParseModel(kStribeckForced, "stribeck_forced.ini");
  const ForcedBelt built(StribeckBuiltIn());
  SettleOptions so;
  so.shooting.flow = ColumnTol(1e-12);
  const SettledOrbit start = SettleOnStickSlip(built, Eigen::Vector3d(0, 0, 0), so);
  ASSERT_TRUE(start.found) << start.message;
  OrbitBranchOptions o(ColumnTol(1e-12));
  auto branch = [&](const System& s) {
    return ContinueOrbits(s, s.ParameterIndex("omega"), start.orbit.start, start.section, 0.5, o);
  };
  const OrbitBranch a = branch(*file), b = branch(built);
  EXPECT_EQ(a.status, b.status) << a.message << " | " << b.message;
  ASSERT_EQ(a.rows.size(), b.rows.size());
  ASSERT_EQ(a.special.size(), b.special.size());
  double worst = 0;
  int pd = 0;
  auto same = [&](const OrbitRow& x, const OrbitRow& y, std::size_t i) {
    EXPECT_EQ(x.label, y.label) << i;
    EXPECT_EQ(x.sticks, y.sticks) << i;
    double e = std::abs(x.p - y.p) / (1 + std::abs(y.p));
    e = std::max(e, std::abs(x.period - y.period) / y.period);
    for (int c = 0; c < 2; ++c) e = std::max(e, std::abs(x.start.z[c] - y.start.z[c]));
    worst = std::max(worst, e);
    EXPECT_LE(e, 1e-12) << "row " << i << " at omega " << y.p;
  };
  for (std::size_t i = 0; i < a.rows.size(); ++i) same(a.rows[i], b.rows[i], i);
  for (std::size_t i = 0; i < a.special.size(); ++i) {
    same(a.special[i], b.special[i], i);
    pd += b.special[i].label == SpecialKind::kPeriodDoubling;
  }
  EXPECT_GE(pd, 1);
  std::printf("[ measured ] %zu rows, %zu special points (%d PD), worst %.2e\n", a.rows.size(),
              a.special.size(), pd, worst);
}

}  // namespace
}  // namespace stickslip::model_file
