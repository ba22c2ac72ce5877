// Point numbers and labels (labels.hpp) on a hand-made result: each special
// point sits on the nearest row of its kind, and labels count per type in
// row order, whatever the order of r.special.
#include "continuation/labels.hpp"

#include <gtest/gtest.h>

namespace stickslip {
namespace {

BranchPoint Row(double p, PointKind k, double x_max) {
  BranchPoint b;
  b.p = p;
  b.kind = k;
  b.extrema.x_max = x_max;
  return b;
}

SpecialPoint Special(SpecialKind k, double p, double x_max) {
  SpecialPoint s;
  s.kind = k;
  s.p = p;
  s.extrema.x_max = x_max;
  return s;
}

TEST(Labels, SpecialPointsSitOnTheNearestRowOfTheirKindAndCountPerType) {
  ContinuationResult r;
  r.points = {Row(0.1, PointKind::kStickSlip, 1.0),   Row(0.2, PointKind::kStickSlip, 1.1),
              Row(0.3, PointKind::kPureSlip, 0.8),    Row(0.4, PointKind::kPureSlip, 0.5),
              Row(0.1, PointKind::kEquilibrium, 0.3), Row(0.3, PointKind::kEquilibrium, 0.3),
              Row(0.45, PointKind::kEquilibrium, 0.3)};
  // Listed out of row order: the HB at 0.45 first, the fold on the pure-slip
  // rows and the grazing point on the stick-slip rows.
  r.special = {Special(SpecialKind::kHopf, 0.44, 0.3), Special(SpecialKind::kGrazing, 0.21, 1.1),
               Special(SpecialKind::kHopf, 0.29, 0.3), Special(SpecialKind::kFold, 0.39, 0.5)};
  EXPECT_EQ(SpecialPointRows(r), (std::vector<int>{7, 2, 6, 4}));
  EXPECT_EQ(SpecialPointLabels(r), (std::vector<std::string>{"HB2", "GR1", "HB1", "LP1"}));
}

TEST(Labels, AResultWithoutRowsOfAKindGivesRowZero) {
  ContinuationResult r;
  r.points = {Row(0.1, PointKind::kEquilibrium, 0.3)};
  r.special = {Special(SpecialKind::kGrazing, 0.1, 1.0)};
  EXPECT_EQ(SpecialPointRows(r), (std::vector<int>{0}));
  EXPECT_EQ(SpecialPointLabels(r), (std::vector<std::string>{"GR1"}));
}

}  // namespace
}  // namespace stickslip
