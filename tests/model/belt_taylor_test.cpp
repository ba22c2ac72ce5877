// The seed law's own recurrence loop (BeltTaylorField::Cubic3, k5 = 0) against
// the general cubic loop, reached with a quintic term far below rounding
// (k5 = 1e-300), and against seed eq. (3.5) in closed form at order 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "stickslip/system/taylor_field.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {
namespace {

struct Rows {
  TaylorRow c[8] = {};
};

Rows Coefficients(const Params& p, Mode mode, int n, const std::optional<ParameterAxis>& axis,
                  const double* z0, int order) {
  const Model m(p);
  TaylorRequest rq;
  rq.variational = n >= 6;
  if (axis) rq.parameter = static_cast<int>(axis->id());
  auto field = m.MakeTaylorField(rq);
  EXPECT_TRUE(field->Bind(m, ModeSet(mode)));
  Rows r;
  for (int i = 0; i < n; ++i) r.c[i][0] = z0[i];
  const TaylorLayout layout{2, 2, n >= 6, n == 8, field->AuxRows()};
  field->Coefficients(order, layout, r.c);
  return r;
}

TEST(BeltTaylor, SeedLawLoopMatchesTheGeneralCubicLoop) {
  Params seed;  // the seed set: cubic law, k5 = 0
  seed.v = 0.3;
  Params general = seed;
  general.k5 = 1e-300;
  const int order = 24;
  // x, x', Phi = I, dz/dp = 0 at a point below and one above the belt speed.
  const double below[8] = {0.4, 0.1, 1, 0, 0, 1, 0, 0};
  const double above[8] = {-0.2, 0.45, 1, 0, 0, 1, 0, 0};
  const std::optional<ParameterAxis> none;
  struct Case {
    Mode mode;
    const double* z0;
    int n;
    std::optional<ParameterAxis> axis;
  } cases[] = {{Mode::kSlipBelow, below, 2, none},
               {Mode::kSlipBelow, below, 6, none},
               {Mode::kSlipBelow, below, 8, ParameterAxis(Parameter::kV)},
               {Mode::kSlipBelow, below, 8, ParameterAxis(Parameter::kBeta)},
               {Mode::kSlipAbove, above, 6, none},
               {Mode::kSlipAbove, above, 8, ParameterAxis(Parameter::kV)}};
  for (const Case& c : cases) {
    const Rows a = Coefficients(seed, c.mode, c.n, c.axis, c.z0, order);
    const Rows b = Coefficients(general, c.mode, c.n, c.axis, c.z0, order);
    for (int k = 1; k <= order; ++k) {
      double scale = 0;
      for (int i = 0; i < c.n; ++i) scale = std::max(scale, std::abs(b.c[i][k]));
      for (int i = 0; i < c.n; ++i)
        EXPECT_NEAR(a.c[i][k], b.c[i][k], 1e-13 * scale)
            << "n " << c.n << " row " << i << " k " << k;
    }
    // Order 1 of x' by seed eq. (3.5): x'' = -x - 2 beta x' + sigma mu(sigma (v - x')).
    const double sigma = c.mode == Mode::kSlipBelow ? 1 : -1;
    const double s = sigma * (seed.v - c.z0[1]);
    const double mu = seed.mu_s - seed.k1() * s + seed.k3() * s * s * s;
    EXPECT_NEAR(a.c[1][1], -c.z0[0] - 2 * seed.beta * c.z0[1] + sigma * mu, 1e-15);
  }
}

}  // namespace
}  // namespace stickslip
