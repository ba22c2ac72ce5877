// ss_continue --force starts on the orbit that is there: where no m = 1
// orbit lies near the settled state, the branch starts on the attractor the
// transient reached, with its period (a period-11 stick-slip attractor of
// the seed belt at A 0.1, Omega 1.5, as ss_basin finds it).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app_test_util.hpp"
#include "stickslip/forced/flow.hpp"
#include "stickslip/model/forced.hpp"

namespace {

namespace tu = stickslip::testing_util;
class ForcedStartApp : public tu::AppTest {};

TEST_F(ForcedStartApp, StartsOnThePeriodElevenAttractorWhereNoPeriodOneOrbitIs) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_continue", dir,
                          {"--law", "cubic", "--v", "0.25", "--beta", "0.05", "--force", "0.1",
                           "--param", "omega", "--from", "1.5", "--to", "1.505"});
  ASSERT_TRUE(tu::Exists(dir + "/out/branch.tsv")) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  ASSERT_FALSE(t.rows.empty());
  const auto& row = t.rows.front();
  EXPECT_DOUBLE_EQ(std::stod(row[t.Column("omega")]), 1.5);
  EXPECT_EQ(row[t.Column("m")], "11");
  EXPECT_EQ(row[t.Column("sticks")], "5");
  // The row's point, iterated by the flow at a tighter tolerance (no
  // Newton): back after 11 forcing periods with 5 stick phases, not before.
  stickslip::ForcedParams p;
  p.force = 0.1, p.omega = 1.5;
  const stickslip::ForcedModel model(p);
  stickslip::ForcedOptions o;
  o.rtol = o.atol = 1e-13;
  const stickslip::ForcedFlow flow(model, o);
  const double x0 = std::stod(row[t.Column("x0")]), xdot0 = std::stod(row[t.Column("xdot0")]);
  stickslip::ForcedPoint z = stickslip::ForcedStart(model, 0, x0, xdot0);
  int sticks = 0;
  for (int k = 1; k <= 11; ++k) {
    stickslip::ForcedRequest rq;
    rq.t_end = k * model.period();
    const stickslip::ForcedRun run = flow.Run(z, rq);
    ASSERT_EQ(run.status, stickslip::ForcedStatus::kReached) << run.message;
    z = run.end;
    sticks += run.sticks;
    const double gap = std::hypot(z.x - x0, z.xdot - xdot0);
    if (k < 11)
      EXPECT_GT(gap, 1e-3) << "back after " << k << " periods";
    else
      EXPECT_LT(gap, 1e-8);
  }
  EXPECT_EQ(sticks, 5);
}

}  // namespace
