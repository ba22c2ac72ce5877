// The forced chart's figure: SL ends crowd where curves bunch (the seed_forced chart has 20 of
// them): they get a marker and one key entry, and only codim-2 points a text label.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "stickslip/io/forced_chart_report.hpp"

namespace stickslip {
namespace {

TEST(ForcedChartScript, SlidingEndsAreMarkersAndOnlyCodim2PointsAreNamed) {
  ForcedChartResult r;
  for (int i = 0; i < 3; ++i) {
    SystemCodim2 p;
    p.label = i < 2 ? Codim2Label::kSliding : Codim2Label::kDoubleGrazing;
    p.p1 = 0.4 + 0.001 * i, p.p2 = 0.5;
    r.chart.codim2.push_back(p);
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
