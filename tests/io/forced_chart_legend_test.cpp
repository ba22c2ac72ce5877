// The forced chart's key: every curve kind and multiple has its own line
// style (LP and PD of m >= 2 orbits were both dotted black), and the filled
// codimension-two dot has a key entry of its own. Its labels keep off the
// curves and each other.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

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
  for (CurveKind kind :
       {CurveKind::kGrazing, CurveKind::kFold, CurveKind::kPeriodDoubling, CurveKind::kTorus})
    for (int m : {1, 2}) {
      SystemCurve c;
      c.kind = kind, c.section.turns = m;
      SystemCurvePoint p;
      p.p1 = 1, p.p2 = 0.5;
      c.points = {p, p};
      r.chart.curves.push_back(c);
    }
  SystemCodim2 gg;
  gg.label = Codim2Label::kDoubleGrazing, gg.p1 = 1, gg.p2 = 0.5;
  r.chart.codim2.push_back(gg);
  Plane pl = ForcedChartOptions().plane;
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

// A label's text box on the page, in pixels of the plot area (870 x 576 on the
// 1000 x 860 page; 8 px per character of the 12-pt font, 16 px high), from a
// "set label 'T' at X,Y [offset a,b left|center]" line.
struct TextBox {
  double x = 0, y = 0, hw = 0, hh = 8;
};
TextBox BoxOf(const std::string& line, const Plane& pl) {
  const auto q0 = line.find_first_of("'\""), q1 = line.find_first_of("'\"", q0 + 1);
  const size_t len = q1 - q0 - 1;
  std::istringstream at(line.substr(line.find(" at ") + 4));
  double x = 0, y = 0, ox = 0, oy = 0;
  char comma = 0;
  at >> x >> comma >> y;
  const auto off = line.find(" offset ");
  if (off != std::string::npos) {
    std::istringstream o(line.substr(off + 8));
    o >> ox >> comma >> oy;
  }
  TextBox b;
  b.hw = 4.0 * len;
  b.x = (x - pl.from1) / pl.width1() * 870 + ox * 8 +
        (line.find(" left ") != std::string::npos ? b.hw : 0);
  b.y = (y - pl.from2) / pl.width2() * 576.2 + oy * 16;
  return b;
}

// Two R1 points 17 px apart with a curve through both, rising to the right:
// each label's box keeps off the curves, the dots and the other label (the
// labels sat up and right of their points, on the curve and on each other).
TEST(ForcedChartLegend, Codim2LabelsKeepOffCurvesAndEachOther) {
  ForcedChartResult r;
  Plane pl = ForcedChartOptions().plane;
  pl.from1 = 0.5, pl.to1 = 1.5, pl.from2 = 0, pl.to2 = 1;
  for (double shift : {0.0, 0.02}) {  // two parallel curves, one through each point
    SystemCurve c;
    c.kind = CurveKind::kTorus;
    for (int i = 0; i <= 20; ++i) {
      SystemCurvePoint p;
      p.p1 = 0.9 + shift + 0.01 * i, p.p2 = 0.4 + 0.01 * i;
      c.points.push_back(p);
    }
    r.chart.curves.push_back(c);
    SystemCodim2 r1;
    r1.label = Codim2Label::kR1, r1.p1 = 1 + shift, r1.p2 = 0.5;
    r.chart.codim2.push_back(r1);
  }
  const std::string script = ForcedChartScript(r, pl, "test", FigureFormat::kPng);
  std::vector<TextBox> boxes;
  std::istringstream in(script);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("set label ", 0) == 0) boxes.push_back(BoxOf(line, pl));
  ASSERT_EQ(boxes.size(), 2u) << script;
  auto inside = [](const TextBox& b, double x, double y) {
    return std::abs(x - b.x) < b.hw && std::abs(y - b.y) < b.hh;
  };
  for (const TextBox& b : boxes) {
    for (const SystemCurve& c : r.chart.curves)
      for (size_t i = 1; i < c.points.size(); ++i)
        for (int k = 0; k <= 50; ++k) {  // the segment, sampled every 0.6 px or closer
          const double t = k / 50.0;
          const double x = ((1 - t) * c.points[i - 1].p1 + t * c.points[i].p1 - pl.from1) * 870;
          const double y = ((1 - t) * c.points[i - 1].p2 + t * c.points[i].p2) * 576.2;
          ASSERT_FALSE(inside(b, x, y))
              << "a curve runs through the label at " << b.x << ", " << b.y << "\n"
              << script;
        }
    for (const SystemCodim2& p : r.chart.codim2)
      EXPECT_FALSE(inside(b, (p.p1 - pl.from1) * 870, p.p2 * 576.2)) << "a label on a dot";
  }
  EXPECT_TRUE(std::abs(boxes[0].x - boxes[1].x) >= boxes[0].hw + boxes[1].hw ||
              std::abs(boxes[0].y - boxes[1].y) >= boxes[0].hh + boxes[1].hh)
      << "the two labels overlap";
}

}  // namespace
}  // namespace stickslip
