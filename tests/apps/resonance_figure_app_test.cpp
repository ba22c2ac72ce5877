// The data behind the forced figure's styles (bifurcation.gp's first panel,
// x_max and x_min against omega): the script ss_continue
// writes is run by gnuplot into a table (set table), and every drawn segment
// is matched to its two branch.tsv rows. A style change must fall at the
// stability change: a segment next to a located special point (where the
// stability or the stick structure changes) takes the style of its other
// row, and every segment is drawn once.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class ResonanceFigureApp : public tu::AppTest {};

struct Curve {
  std::string title;
  std::vector<std::vector<double>> runs;  // x, y pairs flattened per unbroken run
};

// gnuplot's table: "# Curve N of M", "# Curve title: "..."" (if titled), then "x y type" lines; a
// point of type u (undefined) breaks the line.
std::vector<Curve> ReadTable(const std::string& text) {
  std::vector<Curve> curves;
  std::istringstream is(text);
  bool broken = true;
  for (std::string line; std::getline(is, line);) {
    if (line.rfind("# Curve ", 0) == 0 && line.find(" of ") != std::string::npos) {
      curves.push_back({"", {}});  // an untitled curve keeps ""
      broken = true;
      continue;
    }
    if (line.rfind("# Curve title: ", 0) == 0 && !curves.empty()) {
      curves.back().title = line.substr(16, line.size() - 17);
      continue;
    }
    if (line.empty() || line[0] == '#' || curves.empty()) continue;
    std::istringstream ls(line);
    double x = 0, y = 0;
    std::string type;
    if (!(ls >> x >> y >> type) || type == "u") {
      broken = true;
      continue;
    }
    if (broken) curves.back().runs.emplace_back();
    curves.back().runs.back().insert(curves.back().runs.back().end(), {x, y});
    broken = false;
  }
  return curves;
}

TEST_F(ResonanceFigureApp, StyleChangesFallOnTheLocatedPoints) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::string dir = NewDir();
  const auto r =
      RunOut("ss_continue", dir,
             {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/stribeck_forced.ini"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string out = dir + "/out";
  const tu::Tsv br = tu::ReadTsv(tu::ReadFile(out + "/branch.tsv"));
  const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(out + "/special_points.tsv"));
  std::set<size_t> special;  // 0-based rows
  for (const auto& row : sp.rows) special.insert(std::stoul(row[sp.Column("pt")]) - 1);
  ASSERT_GE(special.size(), 4u);
  std::vector<double> xs, ys;
  std::vector<std::string> style;
  for (const auto& row : br.rows) {
    xs.push_back(std::stod(row[br.Column("omega")]));
    ys.push_back(std::stod(row[br.Column("x_max")]));
    style.push_back(row[br.Column("kind")] +
                    (row[br.Column("stable")] == "1" ? ", stable" : ", unstable"));
  }
  // The script as it is, its output redirected into a table at full precision.
  std::string gp = tu::ReadFile(out + "/bifurcation.gp");
  const auto at = gp.find("set output");
  ASSERT_NE(at, std::string::npos);
  gp.replace(
      at, gp.find('\n', at) - at,
      "set output '/dev/null'\nset table 'table.txt'\nset format x '%.17g'\nset format y '%.17g'");
  tu::WriteFile(out + "/table.gp", gp);
  ASSERT_EQ(std::system(("cd " + tu::ShellQuoted(out) + " && gnuplot table.gp >/dev/null").c_str()),
            0);
  const std::vector<Curve> curves = ReadTable(tu::ReadFile(out + "/table.txt"));
  auto row_of = [&](double x, double y) {
    for (size_t i = 0; i < xs.size(); ++i)
      if (std::abs(xs[i] - x) <= 1e-14 && std::abs(ys[i] - y) <= 1e-14) return static_cast<int>(i);
    return -1;
  };
  std::map<size_t, int> drawn;  // segment (i, i + 1) by i -> times drawn
  int checked = 0;
  for (const Curve& c : curves) {
    if (c.title.find("stable") == std::string::npos) continue;  // overlays, points
    for (const auto& run : c.runs)
      for (size_t j = 2; j + 1 < run.size(); j += 2) {
        const int a = row_of(run[j - 2], run[j - 1]), b = row_of(run[j], run[j + 1]);
        ASSERT_GE(a, 0) << c.title;
        ASSERT_GE(b, 0) << c.title;
        if (a == b) continue;  // a row repeated: no segment
        ASSERT_EQ(b, a + 1) << c.title << ": a segment joins rows " << a + 1 << " and " << b + 1;
        ++drawn[a];
        const bool sa = special.count(a) > 0, sb = special.count(b) > 0;
        if (sa != sb) {  // next to a located point: the other row's style
          EXPECT_EQ(c.title, style[sa ? b : a]) << "segment pt " << a + 1 << " - " << b + 1;
          ++checked;
        } else if (!sa && style[a] == style[b]) {
          EXPECT_EQ(c.title, style[a]) << "segment pt " << a + 1 << " - " << b + 1;
        }
      }
  }
  for (size_t i = 0; i + 1 < xs.size(); ++i) EXPECT_EQ(drawn[i], 1) << "segment pt " << i + 1;
  EXPECT_GE(checked, 8) << "two segments at each of the special points";
}

}  // namespace
