// A chart's figure (SystemChartScript) on the forced oscillator's (Omega, A)
// plane. Its key: every curve kind and multiple has its own line style (LP and
// PD of m >= 2 orbits were both dotted black), and the filled codimension-two
// dot has a key entry of its own. Its labels keep off the curves and each
// other. SL ends crowd where curves bunch (the seed_forced chart has 20 of
// them): they get a marker and one key entry, and only codim-2 points a label.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "stickslip/io/system_chart_report.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {
namespace {

// The chart's rectangle on (omega, force).
SystemChart Chart(double from1, double to1, double from2, double to2) {
  SystemChart c;
  c.plane.p1 = ParameterAxis(Parameter::kOmega).index();
  c.plane.p2 = ParameterAxis(Parameter::kForce).index();
  c.plane.from1 = from1, c.plane.to1 = to1, c.plane.from2 = from2, c.plane.to2 = to2;
  return c;
}

std::string Script(const SystemChart& c) {
  return SystemChartScript(ForcedBelt(ForcedBeltParams()), c, "test", FigureFormat::kPng);
}

// The style of a plot line: from "lw" to "title" (width, colour, dashes).
std::string StyleOf(const std::string& line) {
  const auto a = line.find(" lw "), b = line.find(" title ");
  return a == std::string::npos || b == std::string::npos ? "" : line.substr(a, b - a);
}

TEST(ChartScript, EveryCurveKindHasItsOwnStyleAndCodim2DotsAKeyEntry) {
  SystemChart r = Chart(0.5, 1.5, 0, 1);
  for (CurveKind kind :
       {CurveKind::kGrazing, CurveKind::kFold, CurveKind::kPeriodDoubling, CurveKind::kTorus})
    for (int m : {1, 2}) {
      SystemCurve c;
      c.kind = kind, c.section.kind = SectionKind::kTime, c.section.turns = m;
      SystemCurvePoint p;
      p.p1 = 1, p.p2 = 0.5;
      c.points = {p, p};
      r.curves.push_back(c);
    }
  SystemCurve hb;  // an autonomous system's
  hb.kind = CurveKind::kHopf, hb.points.resize(2);
  r.curves.push_back(hb);
  SystemCodim2 gg;
  gg.label = Codim2Label::kDoubleGrazing, gg.p1 = 1, gg.p2 = 0.5;
  r.codim2.push_back(gg);
  const std::string script = Script(r);
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
  ASSERT_EQ(style_of_title.size(), 9u) << script;
  std::set<std::string> styles;
  for (const auto& [title, style] : style_of_title) styles.insert(style);
  EXPECT_EQ(styles.size(), 9u) << "two curve kinds share a line style:\n" << script;
  EXPECT_TRUE(codim2_key) << script;
}

// A label's text box on the page, in pixels of the plot area (870 x 576 on the
// 1000 x 860 page; 8 px per character of the 12-pt font, 16 px high), from a
// "set label 'T' at X,Y [offset a,b left|center]" line.
struct TextBox {
  double x = 0, y = 0, hw = 0, hh = 8;
};
TextBox BoxOf(const std::string& line, const SystemPlane& pl) {
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
  b.x = (x - pl.from1) / (pl.to1 - pl.from1) * 870 + ox * 8 +
        (line.find(" left ") != std::string::npos ? b.hw : 0);
  b.y = (y - pl.from2) / (pl.to2 - pl.from2) * 576.2 + oy * 16;
  return b;
}

// Two R1 points 17 px apart with a curve through both, rising to the right:
// each label's box keeps off the curves, the dots and the other label (the
// labels sat up and right of their points, on the curve and on each other).
TEST(ChartScript, Codim2LabelsKeepOffCurvesAndEachOther) {
  SystemChart r = Chart(0.5, 1.5, 0, 1);
  const SystemPlane& pl = r.plane;
  for (double shift : {0.0, 0.02}) {  // two parallel curves, one through each point
    SystemCurve c;
    c.kind = CurveKind::kTorus;
    for (int i = 0; i <= 20; ++i) {
      SystemCurvePoint p;
      p.p1 = 0.9 + shift + 0.01 * i, p.p2 = 0.4 + 0.01 * i;
      c.points.push_back(p);
    }
    r.curves.push_back(c);
    SystemCodim2 r1;
    r1.label = Codim2Label::kR1, r1.p1 = 1 + shift, r1.p2 = 0.5;
    r.codim2.push_back(r1);
  }
  const std::string script = Script(r);
  std::vector<TextBox> boxes;
  std::istringstream in(script);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("set label ", 0) == 0) boxes.push_back(BoxOf(line, pl));
  ASSERT_EQ(boxes.size(), 2u) << script;
  auto inside = [](const TextBox& b, double x, double y) {
    return std::abs(x - b.x) < b.hw && std::abs(y - b.y) < b.hh;
  };
  for (const TextBox& b : boxes) {
    for (const SystemCurve& c : r.curves)
      for (size_t i = 1; i < c.points.size(); ++i)
        for (int k = 0; k <= 50; ++k) {  // the segment, sampled every 0.6 px or closer
          const double t = k / 50.0;
          const double x = ((1 - t) * c.points[i - 1].p1 + t * c.points[i].p1 - pl.from1) * 870;
          const double y = ((1 - t) * c.points[i - 1].p2 + t * c.points[i].p2) * 576.2;
          ASSERT_FALSE(inside(b, x, y))
              << "a curve runs through the label at " << b.x << ", " << b.y << "\n"
              << script;
        }
    for (const SystemCodim2& p : r.codim2)
      EXPECT_FALSE(inside(b, (p.p1 - pl.from1) * 870, p.p2 * 576.2)) << "a label on a dot";
  }
  EXPECT_TRUE(std::abs(boxes[0].x - boxes[1].x) >= boxes[0].hw + boxes[1].hw ||
              std::abs(boxes[0].y - boxes[1].y) >= boxes[0].hh + boxes[1].hh)
      << "the two labels overlap";
}

TEST(ChartScript, SlidingEndsAreMarkersAndOnlyCodim2PointsAreNamed) {
  SystemChart r = Chart(0.3, 1.2, 0.05, 0.6);
  for (int i = 0; i < 3; ++i) {
    SystemCodim2 p;
    p.label = i < 2 ? Codim2Label::kSliding : Codim2Label::kDoubleGrazing;
    p.p1 = 0.4 + 0.001 * i, p.p2 = 0.5;
    r.codim2.push_back(p);
  }
  std::istringstream in(Script(r));
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
