// Where the figures' special-point marks sit: the label lines of the gnuplot
// scripts the apps write, read against the run's own tables and against what
// the point is (a grazing-sliding orbit touches the stick set x' = v).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class FigureMarksApp : public tu::AppTest {};

struct Mark {
  std::string text;
  double x = 0, y = 0;
};

// The text of one figure of a multi-figure script: from its "set output
// 'STEM" line to the next "unset output".
std::string FigureSection(const std::string& gp, const std::string& stem) {
  const auto at = gp.find("set output '" + stem);
  if (at == std::string::npos) return "";
  return gp.substr(at, gp.find("unset output", at) - at);
}

// "set label N 'TEXT' at up*X,UNIT*Y ..." lines (the unit factors are 1 here).
std::vector<Mark> Marks(const std::string& section) {
  std::vector<Mark> marks;
  std::istringstream is(section);
  for (std::string line; std::getline(is, line);) {
    if (line.rfind("set label ", 0) != 0) continue;
    const auto q0 = line.find('\''), q1 = line.find('\'', q0 + 1);
    const auto at = line.find(" at ", q1);
    if (q0 == std::string::npos || q1 == std::string::npos || at == std::string::npos) continue;
    const auto star1 = line.find('*', at), comma = line.find(',', at);
    const auto star2 = line.find('*', comma);
    if (star1 == std::string::npos || comma == std::string::npos || star2 == std::string::npos)
      continue;
    marks.push_back({line.substr(q0 + 1, q1 - q0 - 1), std::stod(line.substr(star1 + 1)),
                     std::stod(line.substr(star2 + 1))});
  }
  return marks;
}

// The seed belt and the Stribeck belt: GR is drawn on the curve of x'_max at
// x' = v (where the orbit grazes the stick set), not on x'_min.
TEST_F(FigureMarksApp, GrazingMarkSitsOnTheUpperVelocityCurveAtTheBeltSpeed) {
  for (const char* study : {"seed", "stribeck"}) {
    const std::string dir = NewDir();
    const auto r =
        RunOut("ss_continue", dir,
               {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/" + study + ".ini"});
    ASSERT_EQ(r.outcome.code, 0) << r.err;
    const std::string out = dir + "/out";
    const tu::Tsv br = tu::ReadTsv(tu::ReadFile(out + "/branch.tsv"));
    const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(out + "/special_points.tsv"));
    const std::vector<Mark> marks =
        Marks(FigureSection(tu::ReadFile(out + "/bifurcation.gp"), "bifurcation_xdot"));
    int grazings = 0;
    for (const auto& row : sp.rows) {
      if (row[sp.Column("label")] != "GR") continue;
      const double v = std::stod(row[sp.Column("v")]);
      const auto& at = br.rows.at(std::stoul(row[sp.Column("pt")]) - 1);
      bool found = false;
      for (const Mark& m : marks) {
        if (m.text != "GR" || std::abs(m.x - v) > 1e-12) continue;
        found = true;
        EXPECT_NEAR(m.y, v, 1e-9) << study << ": GR at x' = " << m.y << ", not at v";
        EXPECT_NEAR(m.y, std::stod(at[br.Column("xdot_max")]), 1e-9) << study;
      }
      EXPECT_TRUE(found) << study << ": no GR mark at v = " << v;
      ++grazings;
    }
    EXPECT_EQ(grazings, 1) << study;
  }
}

}  // namespace
