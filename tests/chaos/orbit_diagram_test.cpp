// ComputeOrbitDiagram's pieces (OrbitDiagramOptions::chunks): on a window
// with one attractor, a sweep cut into pieces that start from rest gives the
// section points of the sweep that follows each value from the one before,
// to the transient's decay (|lambda| ~ 0.1 over 300 periods: far below 1e-10);
// where two attractors coexist, a piece's first value starts from rest.
#include "stickslip/chaos/orbit_diagram.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "stickslip/errors.hpp"

namespace stickslip {
namespace {

ForcedBeltParams CoulombBelt() {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.beta = 0.05, p.base.v = 0.2;
  p.force = 0.3;
  return p;
}

TEST(OrbitDiagram, PiecesFromRestMatchTheContinuedSweep) {
  OrbitDiagramOptions o;
  o.from = 0.8, o.to = 1.0, o.n = 6, o.down = false;
  o.iterate.transient = 300, o.iterate.keep = 20;
  const OrbitDiagram one = ComputeOrbitDiagram(CoulombBelt(), o);
  o.chunks = 3;
  const OrbitDiagram three = ComputeOrbitDiagram(CoulombBelt(), o);
  ASSERT_EQ(one.columns.size(), three.columns.size());
  for (size_t i = 0; i < one.columns.size(); ++i) {
    const SectionRun &a = one.columns[i].run, &b = three.columns[i].run;
    ASSERT_EQ(a.status, LyapunovStatus::kDone) << a.message;
    ASSERT_EQ(b.status, LyapunovStatus::kDone) << b.message;
    ASSERT_EQ(a.points.size(), b.points.size());
    for (size_t k = 0; k < a.points.size(); ++k) {
      EXPECT_NEAR(a.points[k].z[0], b.points[k].z[0], 1e-10 * (1 + std::abs(a.points[k].z[0])));
      EXPECT_NEAR(a.points[k].z[1], b.points[k].z[1], 1e-10 * (1 + std::abs(a.points[k].z[1])));
    }
  }
}

TEST(OrbitDiagram, APieceStartsFromRest) {
  // Omega = 0.45: pure slip and stick-slip coexist (docs/studies.md). Continued
  // from pure slip at 0.4 the sweep stays on it; a piece of its own from rest
  // reaches stick-slip, one stick per period.
  OrbitDiagramOptions o;
  o.from = 0.4, o.to = 0.45, o.n = 2, o.down = false;
  o.iterate.transient = 300, o.iterate.keep = 20;
  const OrbitDiagram one = ComputeOrbitDiagram(CoulombBelt(), o);
  o.chunks = 2;
  const OrbitDiagram two = ComputeOrbitDiagram(CoulombBelt(), o);
  for (const OrbitDiagram* d : {&one, &two})
    for (const DiagramColumn& c : d->columns) ASSERT_EQ(c.run.status, LyapunovStatus::kDone);
  EXPECT_EQ(one.columns[1].run.points.back().sticks, 0);
  EXPECT_EQ(two.columns[1].run.points.back().sticks, 1);
}

TEST(OrbitDiagram, ChunksOutsideOneToNThrow) {
  OrbitDiagramOptions o;
  o.n = 4, o.chunks = 5;
  EXPECT_THROW(ComputeOrbitDiagram(CoulombBelt(), o), InvalidArgument);
  o.chunks = 0;
  EXPECT_THROW(ComputeOrbitDiagram(CoulombBelt(), o), InvalidArgument);
}

}  // namespace
}  // namespace stickslip
