// The data behind ss_simulate --force's figures (gnuplot's table of
// trajectory.gp): the section draws the transient (t < t_end / 2) apart from
// the rest, under its own key entry, and the time series shows the last 8
// forcing periods, not the whole run (thousands of periods: a block of colour).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class ForcedSimFigureApp : public tu::AppTest {};

struct Point {
  double x = 0, y = 0;
  bool inside = true;  // type 'i' (in range), not 'o' (outside the axis range)
};

using Curves = std::vector<std::pair<std::string, std::vector<Point>>>;

// The titled curves of gnuplot's table in order (untitled ones are left out);
// undefined points ('u') are dropped.
Curves TitledCurves(const std::string& text) {
  Curves curves;
  std::istringstream is(text);
  std::string title;
  for (std::string line; std::getline(is, line);) {
    if (line.rfind("# Curve title: ", 0) == 0) {
      title = line.substr(16, line.size() - 17);
      curves.push_back({title, {}});
    } else if (line.rfind("# Curve ", 0) == 0) {
      title.clear();
    } else if (!title.empty() && !line.empty() && line[0] != '#') {
      std::istringstream ls(line);
      Point p;
      std::string type;
      if (ls >> p.x >> p.y >> type && type != "u")
        curves.back().second.push_back({p.x, p.y, type == "i"});
    }
  }
  return curves;
}

TEST_F(ForcedSimFigureApp, TransientDrawnApartAndTimeSeriesShowsTheLastPeriods) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::string dir = NewDir();
  // The forced seed belt at Omega = 0.6, t_end = 600 (57 forcing periods).
  const auto r =
      RunOut("ss_simulate", dir,
             {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/seed_forced.ini"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string out = dir + "/out";
  std::string gp = tu::ReadFile(out + "/trajectory.gp");
  const auto at = gp.find("set output");
  ASSERT_NE(at, std::string::npos);
  gp.replace(at, gp.find('\n', at) - at,
             "set output '/dev/null'\nset table 'table.txt'\nset format x '%.17g'\n"
             "set format y '%.17g'");
  tu::WriteFile(out + "/table.gp", gp);
  ASSERT_EQ(
      std::system(("cd " + tu::ShellQuoted(out) + " && gnuplot table.gp 2>/dev/null").c_str()), 0);
  const Curves curves = TitledCurves(tu::ReadFile(out + "/table.txt"));
  const tu::Tsv sec = tu::ReadTsv(tu::ReadFile(out + "/section.tsv"));
  const tu::Tsv traj = tu::ReadTsv(tu::ReadFile(out + "/trajectory.tsv"));
  const double t_end = std::stod(traj.rows.back()[traj.Column("t")]);
  const double period = 2 * M_PI / 0.6;
  // The section (the script's last figure): every point once, in the curve
  // its time belongs to.
  const std::vector<Point>* early = nullptr;
  const std::vector<Point>* late = nullptr;
  const std::vector<Point>* xs = nullptr;
  for (const auto& [title, pts] : curves) {
    if (title.rfind("transient (t < ", 0) == 0) early = &pts;
    if (title.rfind("after the transient", 0) == 0) late = &pts;
    if (title == "displacement x") xs = &pts;
  }
  ASSERT_NE(early, nullptr) << "no section curve titled as the transient";
  ASSERT_NE(late, nullptr) << "no section curve titled as after the transient";
  size_t n_early = 0, n_late = 0;
  for (const auto& row : sec.rows)
    ++(std::stod(row[sec.Column("t")]) < t_end / 2 ? n_early : n_late);
  EXPECT_EQ(early->size(), n_early);
  EXPECT_EQ(late->size(), n_late);
  EXPECT_GT(n_early, 0u);
  EXPECT_GT(n_late, 0u);
  // The time series: the points inside the axis range cover the last 8 periods.
  ASSERT_NE(xs, nullptr);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Point& p : *xs)
    if (p.inside) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
  EXPECT_NEAR(hi, t_end, 1e-9);
  EXPECT_NEAR(lo, t_end - 8 * period, 0.05 + 1e-9);  // dt = 0.05
}

}  // namespace
