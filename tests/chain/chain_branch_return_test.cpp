// An orbit branch's map on a stick-exit section gives up kBranchReturnPeriods
// periods of the last orbit after its start, not after the shooting's
// max_return_time (2000): the two-block chain study (studies/chain2.ini at kc = 0.5) past
// its GR (v = 0.395) has no stick phase, and the search beyond the edge once
// ran 2000 time units per Newton (0.7 s of the study's 0.73 s,
// docs/benchmarks.md). The reference for "no return": the flow alone from the
// same point at v = 0.45 (steady sliding stable, beyond HB at 0.441) for the
// full 2000 time units, with its switches recorded, has no stick exit.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "chain/chain.hpp"
#include "numerics/tolerances.hpp"
#include "src/continuation/orbit_problem.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/orbits/settle.hpp"

namespace stickslip::chain {
namespace {

TEST(ChainBranchReturn, NoReturnIsKnownWithinTwentyPeriodsAsWithinTheFullSearch) {
  Params p;  // studies/chain2.ini: the seed's cubic law
  p.law = LawKind::kCubic;
  p.beta = 0.05, p.mu_s = 0.4, p.mu_m = 0.25, p.v_m = 0.5, p.v = 0.3;
  const Chain chain(Uniform(2, p, 0.5));
  const SettledOrbit s = SettleOnStickSlip(chain, NearSteadySliding(chain, 0.01), SettleOptions());
  ASSERT_TRUE(s.found) << s.message;
  ASSERT_EQ(s.section.kind, SectionKind::kStickExit);
  const int v = chain.ParameterIndex("v");
  const OrbitBranchOptions o;
  orbit_detail::OrbitProblem problem(chain, v, s.orbit.start, s.section, o);
  std::string why;
  ASSERT_TRUE(problem.FindAt(0.3, s.orbit.start, &why)) << why;
  const OrbitRow row = problem.Row();
  EXPECT_NEAR(row.period, s.orbit.period, 1e-9 * s.orbit.period);  // the settled orbit

  // At v = 0.3 the map from the orbit's point returns onto it.
  Eigen::VectorXd r;
  PeriodicOrbit at;
  ASSERT_TRUE(problem.MapOf(problem.Unknowns(row.start, 0.3), false, &r, &at, &why)) << why;
  EXPECT_LT(r.lpNorm<Eigen::Infinity>(), 1e-9);

  // At v = 0.45 it does not, and says so after 20 periods.
  EXPECT_FALSE(problem.MapOf(problem.Unknowns(row.start, 0.45), false, &r, &at, &why));
  EXPECT_EQ(at.status, OrbitStatus::kNoReturn) << why;
  const std::size_t k = why.find("within t = ");
  ASSERT_NE(k, std::string::npos) << why;
  const double bound = std::stod(why.substr(k + 11));
  EXPECT_NEAR(bound, Tolerances::kBranchReturnPeriods * row.period, 1e-6 * bound) << why;
  EXPECT_LT(bound, o.shooting.max_return_time / 10);

  // The reference: the flow alone for the full max_return_time sticks nowhere.
  std::unique_ptr<System> beyond = chain.Clone();
  beyond->SetParameterValue(v, 0.45);
  Flow flow(*beyond, FlowOptions());
  FlowRequest rq;
  rq.t_max = o.shooting.max_return_time;
  std::vector<FlowSwitch> switches;
  rq.switches = &switches;
  const FlowRun run = flow.Run(row.start, rq);
  ASSERT_EQ(run.status, FlowStatus::kTimeLimit) << run.message;
  int exits = 0;
  for (const FlowSwitch& e : switches) exits += e.kind == SwitchKind::kStickOut;
  EXPECT_EQ(exits, 0);
}

}  // namespace
}  // namespace stickslip::chain
