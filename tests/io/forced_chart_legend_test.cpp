// The forced chart's key: every curve kind and multiple has its own line
// style (LP and PD of m >= 2 orbits were both dotted black), and the filled
// codimension-two dot has a key entry of its own.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>

#include "stickslip/io/forced_chart_report.hpp"

namespace stickslip {
namespace {

// The style of a plot line: from "lw" to "title" (width, colour, dashes).
std::string StyleOf(const std::string& line) {
  const auto a = line.find(" lw "), b = line.find(" title ");
  return a == std::string::npos || b == std::string::npos ? "" : line.substr(a, b - a);
}

TEST(ForcedChartLegend, EveryCurveKindHasItsOwnStyleAndCodim2DotsAKeyEntry) {
  ForcedChartResult r;
  for (ForcedCurveKind kind :
       {ForcedCurveKind::kGR, ForcedCurveKind::kLP, ForcedCurveKind::kPD, ForcedCurveKind::kNS})
    for (int m : {1, 2}) {
      ForcedCurve c;
      c.kind = kind, c.m = m;
      ForcedCurvePoint p;
      p.p1 = 1, p.p2 = 0.5;
      c.points = {p, p};
      r.curves.push_back(c);
    }
  ForcedCodim2 gg;
  gg.label = ForcedCodim2Label::kDoubleGrazing, gg.p1 = 1, gg.p2 = 0.5;
  r.codim2.push_back(gg);
  ForcedPlane pl;
  pl.from1 = 0.5, pl.to1 = 1.5, pl.from2 = 0, pl.to2 = 1;
  const std::string script = ForcedChartScript(r, pl, "test", FigureFormat::kPng);
  std::istringstream in(script);
  std::map<std::string, std::string> style_of_title;
  bool codim2_key = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("'curves.tsv'") != std::string::npos) {
      const auto t = line.find(" title ");
      ASSERT_NE(t, std::string::npos) << "one curve of each kind and m: each titled\n" << line;
      style_of_title[line.substr(t + 7)] = StyleOf(line);
    }
    if (line.find("'codim2.tsv'") != std::string::npos && line.find("pt 7") != std::string::npos)
      codim2_key = line.find(" title ") != std::string::npos;
  }
  ASSERT_EQ(style_of_title.size(), 8u) << script;
  std::set<std::string> styles;
  for (const auto& [title, style] : style_of_title) styles.insert(style);
  EXPECT_EQ(styles.size(), 8u) << "two curve kinds share a line style:\n" << script;
  EXPECT_TRUE(codim2_key) << script;
}

}  // namespace
}  // namespace stickslip
