// The response grid on an autonomous system, the belt (response_grid.hpp),
// against its own stick-slip orbit: the belt start (x = 0 carried by the
// belt) sticks at once, so its trajectory runs into the superstable
// stick-slip orbit wherever that exists. A cell reads periodic with one
// stick per period exactly where FindPeriodicOrbits (the belt's return map
// on the stick band, orbits/orbit_scan.hpp) finds the stick-slip orbit.
#include "stickslip/chart/response_grid.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit_scan.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip {
namespace {

TEST(ResponseGrid, BeltCellsStickSlipWhereTheOrbitExists) {
  const Model belt{Params()};
  SystemPlane pl;
  pl.p1 = belt.ParameterIndex("v"), pl.p2 = belt.ParameterIndex("beta");
  pl.from1 = 0.3, pl.to1 = 0.56, pl.from2 = 0.02, pl.to2 = 0.08;  // v_max ~ 0.441 inside
  ResponseOptions o;
  o.n1 = 8, o.n2 = 3;
  o.attractor.iterate.transient = 100;
  const ResponseGrid g = Responses(belt, pl, o);
  ASSERT_EQ(g.failed, 0) << g.failure;
  int stick_slip = 0, other = 0;
  for (int j = 0; j < g.n2; ++j)
    for (int i = 0; i < g.n1; ++i) {
      Params p;
      p.v = g.x1[i], p.beta = g.x2[j];
      const PeriodicOrbits ref = FindPeriodicOrbits(Model(p), OrbitScanOptions());
      ASSERT_TRUE(ref.ok()) << ref.message;
      const Attractor& a = g.at(i, j);
      const bool cell = a.kind == AttractorKind::kPeriodic && a.m == 1 && a.sticks == 1;
      EXPECT_EQ(cell, ref.has_stick_slip)
          << "v = " << p.v << ", beta = " << p.beta << ": " << Name(a.kind) << " m " << a.m;
      if (!ref.has_stick_slip)  // steady sliding or a pure-slip orbit, never a stick
        EXPECT_EQ(a.sticks, 0) << "v = " << p.v << ", beta = " << p.beta;
      (cell ? stick_slip : other) += 1;
    }
  std::printf("[ measured ] %d stick-slip and %d other cells in %.3f s\n", stick_slip, other,
              g.seconds);
  EXPECT_GE(stick_slip, 3);
  EXPECT_GE(other, 3);
}

TEST(ResponseGrid, RejectsBadOptions) {
  const Model belt{Params()};
  SystemPlane pl;
  pl.p1 = belt.ParameterIndex("v"), pl.p2 = belt.ParameterIndex("beta");
  pl.from1 = 0.3, pl.to1 = 0.5, pl.from2 = 0.02, pl.to2 = 0.08;
  ResponseOptions o;
  o.n1 = 0;
  EXPECT_THROW(Responses(belt, pl, o), InvalidArgument);
  o.n1 = ResponseOptions::kMaxSide + 1;
  EXPECT_THROW(Responses(belt, pl, o), InvalidArgument);
  o = ResponseOptions();
  o.attractor.max_period = o.attractor.iterate.keep;  // > keep / 2
  EXPECT_THROW(Responses(belt, pl, o), InvalidArgument);
  o = ResponseOptions();
  pl.p2 = pl.p1;
  EXPECT_THROW(Responses(belt, pl, o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip
