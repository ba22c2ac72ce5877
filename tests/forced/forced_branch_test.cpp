// Continuation of the forced oscillator in Omega (issue 20, item 4): the Den
// Hartog run (coulomb mu_s = mu_k = 0.3, v = 0, beta = 0, A = 1) against his
// closed form on every non-stop row.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "forced_reference.hpp"
#include "forced_run.hpp"
#include "forced_trace.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/forced_orbit.hpp"

namespace stickslip {
namespace {

// Den Hartog (1931), checked against the closed-form pieces in forced_orbit_test.cpp.
using forced_reference::DenHartogX;

ForcedBeltParams DenHartog() {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = p.base.mu_k = 0.3;
  p.base.beta = 0, p.base.v = 0;
  p.force = 1;
  return p;
}

// Without damping the amplitude grows without bound at Omega = 1 (mu < pi A / 4):
// one branch from each end, each stopped at |x| = 10.
TEST(OrbitBranch, DenHartogRunMatchesClosedFormOnEveryNonStopRow) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-14;
  o.max_amplitude = 10;
  o.palc.ds_max = 0.05;
  int compared = 0;
  double worst = 0, p_min = 10, p_max = 0;
  for (const double from : {0.75, 2.5}) {
    const double to = from == 0.75 ? 2.5 : 0.75;
    const double V = 1 / (1 - from * from);
    const OrbitBranch b =
        testing_util::StrobeBranch(DenHartog(), Parameter::kOmega, from, to, V, 0.01, 1, o);
    EXPECT_EQ(b.status, BranchStatus::kUnbounded) << b.message;
    EXPECT_GT(b.rows.size(), 20u);
    for (const OrbitRow& r : b.rows) {
      if (r.sticks > 0) continue;
      ++compared;
      const double X = DenHartogX(0.3, 1, r.p);
      EXPECT_NEAR(RowExtrema(r).x_max, X, 1e-9 * std::max(1.0, X)) << "Omega = " << r.p;
      worst = std::max(worst, std::abs(RowExtrema(r).x_max - X) / std::max(1.0, X));
      p_min = std::min(p_min, r.p), p_max = std::max(p_max, r.p);
    }
    std::printf("[ measured ] from %g: %zu rows, status %s, %d evaluations, %.3f s\n", from,
                b.rows.size(), Name(b.status), b.evaluations, b.seconds);
  }
  EXPECT_EQ(p_min, 0.75);
  EXPECT_EQ(p_max, 2.5);
  std::printf("[ measured ] %d non-stop rows: max |x_max - X| / max(1, X) = %.2e\n", compared,
              worst);
}

// A period doubling of stick-slip orbits on an undamped forced belt (coulomb
// mu_s = 0.4, mu_k = 0.25, v = 0.2, beta = 0, A = 0.3): located on the
// stroboscopic branch (det(DP + I) = 0), checked by the exit-phase map, whose
// multiplier comes from the exit time's derivative instead.
TEST(OrbitBranch, PeriodDoublingAgreesWithTheExitPhaseMap) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.beta = 0, p.base.v = 0.2;
  p.force = 0.3, p.omega = 0.8;
  const ForcedBelt m0(p);
  const FlowRun transient =
      testing_util::RunForced(m0, ForcedStart(m0, 0, 0, 0.2), 200 * m0.period());
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-14;
  o.palc.ds_max = 0.05;
  const OrbitBranch b = testing_util::StrobeBranch(p, Parameter::kOmega, 0.8, 2, transient.end.z[0],
                                                   transient.end.z[1], 1, o);
  EXPECT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  std::vector<OrbitRow> pds;  // the sliding points are tested in forced_sliding_test
  for (const OrbitRow& r : b.special)
    if (r.label == SpecialKind::kPeriodDoubling) pds.push_back(r);
  ASSERT_EQ(pds.size(), 1u);
  const OrbitRow& pd = pds[0];
  EXPECT_EQ(pd.label, SpecialKind::kPeriodDoubling);
  EXPECT_EQ(pd.sticks, 1);
  EXPECT_NEAR(pd.multipliers[0].real(), -1, 1e-9);
  // The exit-phase map at the located Omega: its multiplier is -1 there too.
  p.omega = pd.p;
  const ForcedBelt m(p);
  std::vector<FlowSwitch> events;
  FlowRequest rq;
  rq.switches = &events;
  testing_util::RunForced(m, ForcedStart(m, 0, pd.start.z[0], pd.start.z[1]), m.period(), rq,
                          o.shooting.flow);
  double t_exit = -1;
  Mode mode = Mode::kSlipBelow;
  for (const auto& e : events)
    if (e.kind == SwitchKind::kStickOut) t_exit = e.t, mode = e.after[0];
  ASSERT_GE(t_exit, 0);
  ShootingOptions oo(ForcedBelt::FlowDefaults());
  oo.flow = o.shooting.flow;
  const PeriodicOrbit exit = ExitPhaseOrbit(m, t_exit, mode, 1, 1, oo);
  ASSERT_TRUE(exit.ok()) << exit.message;
  EXPECT_NEAR(exit.multipliers[0].real(), -1, 1e-9);
  EXPECT_NEAR(OrbitExtrema(exit).x_max, RowExtrema(pd).x_max, 1e-11);
  std::printf("[ measured ] PD at Omega = %.15g: multiplier %.15g (strobe), %.15g (exit map)\n",
              pd.p, pd.multipliers[0].real(), exit.multipliers[0].real());
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// The one lens (parameter_axis.hpp) takes any parameter of the forced model:
// the Den Hartog branch in the kinetic coefficient mu_k at Omega = 2 (mu_s =
// 0.3 held) against his closed form X(mu_k) on every non-stop row.
TEST(OrbitBranch, ContinuesABeltParameterOfTheForcedModel) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-14;
  o.palc.ds_max = 0.01;
  ForcedBeltParams p = DenHartog();
  p.omega = 2;
  const double V = 1 / (1 - 4.0);
  const OrbitBranch b = testing_util::StrobeBranch(p, Parameter::kMuK, 0.3, 0.05, V, 0.01, 1, o);
  EXPECT_EQ(b.status, BranchStatus::kReachedEnd) << b.message;
  int compared = 0;
  for (const OrbitRow& r : b.rows) {
    if (r.sticks > 0) continue;
    ++compared;
    EXPECT_NEAR(RowExtrema(r).x_max, DenHartogX(r.p, 1, 2), 1e-9) << "mu_k = " << r.p;
  }
  EXPECT_GT(compared, 10);
  EXPECT_EQ(b.rows.back().p, 0.05);
  std::printf("[ measured ] mu_k 0.3 -> 0.05: %zu rows, %d non-stop, %d evaluations\n",
              b.rows.size(), compared, b.evaluations);
}

// The one driver refuses a bad input of a stroboscopic branch by name before
// it starts (InvalidArgument, never a start that failed): the message names
// the value.
void ExpectRefused(const std::function<void()>& run, const std::string& words) {
  try {
    run();
    ADD_FAILURE() << "accepted; expected: " << words;
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(OrbitBranch, AStroboscopicBranchRefusesBadInputsByName) {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  ForcedBeltParams p = DenHartog();
  p.omega = 2;
  const ForcedBelt m(p);
  const int omega = ParameterAxis(Parameter::kOmega).index();
  const FlowPoint z = testing_util::StrobePoint(-1 / 3.0, 0.01);
  const PoincareSection s = PoincareSection::Stroboscopic(m, z.z, 1);
  const auto from = [&](const FlowPoint& guess, const PoincareSection& sec, double to,
                        const OrbitBranchOptions& oo) {
    return [&m, omega, guess, sec, to, oo] { ContinueOrbits(m, omega, guess, sec, to, oo); };
  };
  // A parameter the law has not (mu_m is Stribeck's), here and at a PD.
  ExpectRefused([&] { ContinueOrbits(m, int(Parameter::kMuM), z, s, 0.2, o); },
                "'mu_m' does not apply");
  ExpectRefused([&] { ContinueDoubled(m, int(Parameter::kMuM), z, s, 0.1, 0.3, o); },
                "'mu_m' does not apply");
  // m outside [1, kMaxPeriodMultiple].
  ExpectRefused([&] { PoincareSection::Stroboscopic(m, z.z, 0); }, "m = 0");
  ExpectRefused(from(z, PoincareSection::Stroboscopic(m, z.z, 1001), 2.5, o),
                "m = 1001 must lie in [1, 1000]");
  // The range: to finite and not the start's value.
  ExpectRefused(from(z, s, 2, o), "to = 2 must be finite and differ from omega = 2");
  ExpectRefused(from(z, s, NAN, o), "to = nan");
  // A guess that is not finite, its values named.
  ExpectRefused(from(testing_util::StrobePoint(NAN, 0.01), s, 2.5, o),
                "the guess (x, x', theta) = (nan, 0.01, 0) is not finite");
  // The system at the start and at the end.
  ForcedBelt bad(p);
  bad.SetParameterValue(int(Parameter::kMuK), 0.5);  // > mu_s
  ExpectRefused([&] { ContinueOrbits(bad, omega, z, s, 2.5, o); }, "mu_k = 0.5");
  ExpectRefused(from(z, s, -1, o), "at omega = to");
  // PALC's options, checked on the section's unknowns (x, x', Omega).
  OrbitBranchOptions steps = o;
  steps.palc.ds = 10 * steps.palc.ds_max;
  ExpectRefused(from(z, s, 2.5, steps), "ds_min <= ds <= ds_max");
  steps = o;
  steps.palc.scale = Eigen::VectorXd::Ones(2);
  ExpectRefused(from(z, s, 2.5, steps), "scale has 2 entries, need 3");
}

}  // namespace
}  // namespace stickslip
