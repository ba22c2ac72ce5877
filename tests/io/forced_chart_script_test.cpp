// The forced chart's figure draws an NS curve only where its multipliers are
// complex: the neutral-saddle stretch of det DP = 1 (real mu, 1/mu, flag 1 in
// curves.tsv) is no bifurcation, and was drawn as NS. The script's filter must
// name curves.tsv's flag column (found here by its header, not assumed).
// SL ends crowd where curves bunch (the seed_forced chart has 20 of them):
// they get a marker and one key entry, and only codim-2 points a text label.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "stickslip/io/forced_chart_report.hpp"

namespace stickslip {
namespace {

TEST(ForcedChartScript, NsCurveDrawnOnlyWhereTheMultipliersAreComplex) {
  ForcedChartResult r;
  ForcedCurve ns;
  ns.kind = CurveKind::kTorus;
  for (int i = 0; i < 3; ++i) {
    ForcedCurvePoint p;
    p.p1 = 1 + 0.01 * i, p.p2 = 0.01, p.flag = i == 2;
    ns.points.push_back(p);
  }
  r.curves.push_back(ns);
  Plane pl = ForcedChartOptions().plane;
  pl.from1 = 0.5, pl.to1 = 1.5, pl.from2 = 0, pl.to2 = 0.1;
  const TsvTable t = ForcedCurvesTable(r, pl, "test");
  const auto& c = t.columns();
  const auto it = std::find(c.begin(), c.end(), "flag");
  ASSERT_NE(it, c.end());
  const std::string flag = "$" + std::to_string(it - c.begin() + 1) + " == 0";
  const std::string script = ForcedChartScript(r, pl, "test", FigureFormat::kPng);
  std::istringstream in(script);
  std::string line;
  int ns_lines = 0;
  while (std::getline(in, line)) {
    if (line.find("NS, Neimark-Sacker") == std::string::npos) continue;
    ++ns_lines;
    EXPECT_NE(line.find(flag), std::string::npos) << line;
  }
  EXPECT_EQ(ns_lines, 1);
}

TEST(ForcedChartScript, SlidingEndsAreMarkersAndOnlyCodim2PointsAreNamed) {
  ForcedChartResult r;
  for (int i = 0; i < 3; ++i) {
    ForcedCodim2 p;
    p.label = i < 2 ? Codim2Label::kSliding : Codim2Label::kDoubleGrazing;
    p.p1 = 0.4 + 0.001 * i, p.p2 = 0.5;
    r.codim2.push_back(p);
  }
  Plane pl = ForcedChartOptions().plane;
  pl.from1 = 0.3, pl.to1 = 1.2, pl.from2 = 0.05, pl.to2 = 0.6;
  const std::string script = ForcedChartScript(r, pl, "test", FigureFormat::kPng);
  std::istringstream in(script);
  std::string line;
  int labels = 0, sl_labels = 0, sl_key = 0;
  while (std::getline(in, line)) {
    if (line.rfind("set label", 0) == 0) {
      ++labels;
      sl_labels += line.find("\"SL\"") != std::string::npos;
    }
    sl_key +=
        line.find("eq 'SL'") != std::string::npos && line.find(" title ") != std::string::npos;
  }
  EXPECT_EQ(labels, 1);  // GG only
  EXPECT_EQ(sl_labels, 0);
  EXPECT_EQ(sl_key, 1);
}

}  // namespace
}  // namespace stickslip
