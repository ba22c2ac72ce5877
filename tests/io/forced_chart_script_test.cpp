// The forced chart's figure draws an NS curve only where its multipliers are
// complex: the neutral-saddle stretch of det DP = 1 (real mu, 1/mu, flag 1 in
// curves.tsv) is no bifurcation, and was drawn as NS. The script's filter must
// name curves.tsv's flag column (found here by its header, not assumed).
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
  ns.kind = ForcedCurveKind::kNS;
  for (int i = 0; i < 3; ++i) {
    ForcedCurvePoint p;
    p.p1 = 1 + 0.01 * i, p.p2 = 0.01, p.flag = i == 2;
    ns.points.push_back(p);
  }
  r.curves.push_back(ns);
  ForcedPlane pl;
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

}  // namespace
}  // namespace stickslip
