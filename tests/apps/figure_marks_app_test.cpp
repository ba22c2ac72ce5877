// Where the figures' special-point marks sit: the label lines of the gnuplot
// scripts the apps write, read against the run's own tables and against what
// the point is (a grazing-sliding orbit touches the stick set x' = v).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>
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

// "set label N 'TEXT' at up*X,UNIT*Y ..." lines (the unit factors are 1 here;
// y is NaN where the label sits at a graph coordinate).
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
    if (star1 == std::string::npos || comma == std::string::npos) continue;
    marks.push_back({line.substr(q0 + 1, q1 - q0 - 1), std::stod(line.substr(star1 + 1)),
                     star2 == std::string::npos ? NAN : std::stod(line.substr(star2 + 1))});
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

// The points gnuplot draws for the curve titled `title` (the script run into
// a table: "x y type" lines after "# Curve title: "TITLE""; undefined points left out).
std::vector<std::array<double, 2>> DrawnPoints(const std::string& dir, const std::string& script,
                                               const std::string& title) {
  std::string gp = tu::ReadFile(dir + "/" + script);
  const auto at = gp.find("set output");
  if (at == std::string::npos) return {};
  gp.replace(at, gp.find('\n', at) - at,
             "set output '/dev/null'\nset table 'table.txt'\nset format x '%.17g'\n"
             "set format y '%.17g'");
  tu::WriteFile(dir + "/table.gp", gp);
  if (std::system(("cd " + tu::ShellQuoted(dir) + " && gnuplot table.gp 2>/dev/null").c_str()) != 0)
    return {};
  std::vector<std::array<double, 2>> pts;
  std::istringstream is(tu::ReadFile(dir + "/table.txt"));
  bool in = false;
  for (std::string line; std::getline(is, line);) {
    if (line.rfind("# Curve title: ", 0) == 0)
      in = line.find(title) != std::string::npos;
    else if (line.rfind("# Curve ", 0) == 0)
      in = false;  // "# Curve N of M": a new curve, untitled until its title line
    if (!in || line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    double x = 0, y = 0;
    std::string type;
    if (ls >> x >> y >> type && type != "u") pts.push_back({x, y});
  }
  return pts;
}

// The forced seed basin (Omega = 0.559): the period-2 attractor's two section
// points are both in the figure's plotted data, the second the image of the
// first under one forcing period (ss_simulate at rtol 1e-13, the reference).
TEST_F(FigureMarksApp, ForcedBasinFigureDrawsEverySectionPointOfAPeriodicAttractor) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::string src = STICKSLIP_SOURCE_DIR;
  const std::string dir = NewDir();
  const auto r = RunOut(
      "ss_basin", dir,
      {"--study", src + "/studies/seed_forced_basin.ini", "--nx", "2", "--ny", "2", "--x_min",
       "0.5", "--x_max", "0.6", "--xdot_min", "0.1", "--xdot_max", "0.2", "--threads", "1"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string out = dir + "/out";
  const tu::Tsv att = tu::ReadTsv(tu::ReadFile(out + "/attractors.tsv"));
  const auto pts = DrawnPoints(out, "basins_forced.gp", "periodic attractor");
  int periodic = 0;
  size_t want = 0;
  for (const auto& row : att.rows) {
    if (row[att.Column("kind")] != "periodic") continue;
    ++periodic;
    const int m = std::stoi(row[att.Column("m")]);
    want += m;
    ASSERT_EQ(m, 2);
    const double x = std::stod(row[att.Column("x")]), xd = std::stod(row[att.Column("xdot")]);
    // The reference: one forcing period (2 pi / 0.559 = 11.24) from (x, x').
    const std::string sim = NewDir();
    const auto s = RunOut("ss_simulate", sim,
                          {"--study", src + "/studies/seed_forced.ini", "--omega", "0.559", "--x0",
                           row[att.Column("x")], "--xdot0", row[att.Column("xdot")], "--t_end",
                           "12", "--rtol", "1e-13", "--atol", "1e-15"});
    ASSERT_EQ(s.outcome.code, 0) << s.err;
    const tu::Tsv sec = tu::ReadTsv(tu::ReadFile(sim + "/out/section.tsv"));
    ASSERT_GE(sec.rows.size(), 2u);
    const std::array<double, 2> image = {std::stod(sec.rows[1][sec.Column("x")]),
                                         std::stod(sec.rows[1][sec.Column("xdot")])};
    auto drawn = [&](const std::array<double, 2>& q) {
      for (const auto& p : pts)
        if (std::abs(p[0] - q[0]) < 1e-8 && std::abs(p[1] - q[1]) < 1e-8) return true;
      return false;
    };
    EXPECT_TRUE(drawn({x, xd})) << "the attractor's point (" << x << ", " << xd << ")";
    EXPECT_TRUE(drawn(image)) << "its image (" << image[0] << ", " << image[1] << ")";
    EXPECT_GT(std::abs(image[0] - x), 0.1);  // two distinct points
  }
  EXPECT_EQ(periodic, 1);
  EXPECT_EQ(pts.size(), want);
}

// The forced Stribeck belt's figure (its first panel): a label drawn above its point
// (even rows of special_points.tsv, offset 1.2 characters up) has 6 % of the
// y range above it, one below has 6 % under it; LP2 at x_max 0.887 was cut by
// the top border at 0.9.
TEST_F(FigureMarksApp, ResonanceLabelsHaveRoomInsideThePlot) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  for (const char* study : {"stribeck_forced", "seed_forced", "floor_static"}) {
    const std::string dir = NewDir();
    const auto r =
        RunOut("ss_continue", dir,
               {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/" + study + ".ini"});
    ASSERT_EQ(r.outcome.code, 0) << r.err;
    const std::string out = dir + "/out";
    std::string gp = tu::ReadFile(out + "/bifurcation.gp");
    const auto at = gp.find("set output");
    ASSERT_NE(at, std::string::npos);
    gp.replace(at, gp.find('\n', at) - at, "set output '/dev/null'");
    gp = gp.substr(0, gp.find("\nunset label\n") + 1);  // the first panel: x's extremes
    tu::WriteFile(out + "/range.gp",
                  gp + "set print 'range.txt'\nprint sprintf('%.17g %.17g', GPVAL_Y_MIN, "
                       "GPVAL_Y_MAX)\n");
    ASSERT_EQ(
        std::system(("cd " + tu::ShellQuoted(out) + " && gnuplot range.gp 2>/dev/null").c_str()),
        0);
    std::istringstream range(tu::ReadFile(out + "/range.txt"));
    double lo = 0, hi = 0;
    ASSERT_TRUE(range >> lo >> hi) << study;
    const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(out + "/special_points.tsv"));
    for (size_t i = 0; i < sp.rows.size(); ++i) {
      const double y = std::stod(sp.rows[i][sp.Column("x_max")]);
      const double room = i % 2 == 0 ? hi - y : y - lo;
      EXPECT_GE(room, 0.06 * (hi - lo)) << study << ": " << sp.rows[i][sp.Column("lab")]
                                        << " at x_max " << y << " in [" << lo << ", " << hi << "]";
    }
  }
}

// Runs of consecutive defined points per curve of gnuplot's table of a
// one-figure script (a break: an undefined point or a new curve).
std::vector<std::vector<std::array<double, 2>>> DrawnRuns(const std::string& dir,
                                                          const std::string& script) {
  std::string gp = tu::ReadFile(dir + "/" + script);
  const auto at = gp.find("set output");
  if (at == std::string::npos) return {};
  gp.replace(at, gp.find('\n', at) - at,
             "set output '/dev/null'\nset table 'table.txt'\nset format x '%.17g'");
  tu::WriteFile(dir + "/table.gp", gp);
  if (std::system(("cd " + tu::ShellQuoted(dir) + " && gnuplot table.gp 2>/dev/null").c_str()) != 0)
    return {};
  std::vector<std::vector<std::array<double, 2>>> runs;
  bool broken = true;
  std::istringstream is(tu::ReadFile(dir + "/table.txt"));
  for (std::string line; std::getline(is, line);) {
    if (line.empty() || line[0] == '#') {
      broken = broken || line.rfind("# Curve ", 0) == 0;
      continue;
    }
    std::istringstream ls(line);
    double x = 0, y = 0;
    std::string type;
    if (!(ls >> x >> y >> type) || type == "u") {
      broken = true;
      continue;
    }
    if (broken) runs.emplace_back();
    runs.back().push_back({x, y});
    broken = false;
  }
  return runs;
}

// Basin stability along v (the Stribeck belt): HB and GR marked at the values
// ss_continue locates over the same range, and no line joins the rows on the
// two sides of GR (the fold where the stick-slip orbit ends: a jump, not a slope).
TEST_F(FigureMarksApp, BasinStabilityMarksHopfAndGrazingAndBreaksAtTheJump) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const std::string study =
      std::string(STICKSLIP_SOURCE_DIR) + "/studies/stribeck_basin_stability.ini";
  const std::string dir = NewDir(), ref = NewDir();
  const auto r = RunOut("ss_basin", dir, {"--study", study, "--n", "11"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const auto c = RunOut("ss_continue", ref,
                        {"--study", study, "--param", "v", "--from", "0.5", "--to", "0.7"});
  ASSERT_EQ(c.outcome.code, 0) << c.err;
  const tu::Tsv sp = tu::ReadTsv(tu::ReadFile(ref + "/out/special_points.tsv"));
  double hb = NAN, gr = NAN;
  for (const auto& row : sp.rows) {
    const std::string label = row[sp.Column("label")];
    if (label == "HB") hb = std::stod(row[sp.Column("v")]);
    if (label == "GR") gr = std::stod(row[sp.Column("v")]);
  }
  ASSERT_TRUE(std::isfinite(hb) && std::isfinite(gr));
  const std::string gp = tu::ReadFile(dir + "/out/basin_stability.gp");
  bool hb_marked = false, gr_marked = false;
  for (const Mark& m : Marks(gp)) {
    hb_marked = hb_marked || (m.text.find("HB") != std::string::npos && std::abs(m.x - hb) < 1e-9);
    gr_marked = gr_marked || (m.text.find("GR") != std::string::npos && std::abs(m.x - gr) < 1e-9);
  }
  EXPECT_TRUE(hb_marked) << "no HB label at v = " << hb;
  EXPECT_TRUE(gr_marked) << "no GR label at v = " << gr;
  int runs = 0;
  for (const auto& run : DrawnRuns(dir + "/out", "basin_stability.gp")) {
    ++runs;
    for (size_t j = 1; j < run.size(); ++j)
      EXPECT_FALSE(run[j - 1][0] < gr && run[j][0] > gr)
          << "a line from v = " << run[j - 1][0] << " to " << run[j][0] << " across GR";
  }
  EXPECT_GE(runs, 4);
}

// The numbers after "set KEY [" (a range) or "set KEY at screen " in a
// script's text, in order.
std::vector<double> Settings(const std::string& text, const std::string& key) {
  std::vector<double> v;
  for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
    std::istringstream is(text.substr(at + key.size()));
    double x = 0;
    char colon = 0;
    if (key.back() == '[') {
      double y = 0;
      if (is >> x >> colon >> y) v.push_back(x), v.push_back(y);
    } else if (is >> x) {
      v.push_back(x);
    }
  }
  return v;
}

// The quintic chart: its two codimension-two points (GH, GR-LP) lie within
// 0.04 in v and 0.02 in beta of each other; the chart draws them again in an
// inset, zoomed (each range under 30 % of the chart's), that contains both,
// and sits on the page where it hides neither them nor the zoomed box.
TEST_F(FigureMarksApp, QuinticChartZoomsTheCrowdedCornerInAnInset) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";  // chart.gp comes with the figure
  const std::string dir = NewDir();
  const auto r =
      RunOut("ss_chart", dir,
             {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/quintic_chart.ini"}, true);
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string gp = tu::ReadFile(dir + "/out/chart.gp");
  const tu::Tsv c2 = tu::ReadTsv(tu::ReadFile(dir + "/out/codim2.tsv"));
  ASSERT_EQ(c2.rows.size(), 2u);
  const auto inset_at = gp.find("# the inset");
  ASSERT_NE(inset_at, std::string::npos) << "no inset";
  const std::string main = gp.substr(0, inset_at), inset = gp.substr(inset_at);
  const auto mx = Settings(main, "set xrange ["), my = Settings(main, "set yrange [");
  const auto ix = Settings(inset, "set xrange ["), iy = Settings(inset, "set yrange [");
  ASSERT_TRUE(mx.size() == 2 && my.size() == 2 && ix.size() == 2 && iy.size() == 2);
  EXPECT_LT(ix[1] - ix[0], 0.3 * (mx[1] - mx[0]));
  EXPECT_LT(iy[1] - iy[0], 0.3 * (my[1] - my[0]));
  // The page: main frame and inset frame, screen fractions l, r, t, b.
  auto frame = [](const std::string& t) {
    return std::vector<double>{
        Settings(t, "set lmargin at screen ").at(0), Settings(t, "set rmargin at screen ").at(0),
        Settings(t, "set tmargin at screen ").at(0), Settings(t, "set bmargin at screen ").at(0)};
  };
  const auto mf = frame(main), f = frame(inset);
  auto on_page = [&](double v, double b) {
    return std::array<double, 2>{mf[0] + (v - mx[0]) / (mx[1] - mx[0]) * (mf[1] - mf[0]),
                                 mf[3] + (b - my[0]) / (my[1] - my[0]) * (mf[2] - mf[3])};
  };
  auto covered = [&](const std::array<double, 2>& q) {
    return q[0] > f[0] && q[0] < f[1] && q[1] > f[3] && q[1] < f[2];
  };
  for (const auto& row : c2.rows) {
    const double v = std::stod(row[c2.Column("v")]), b = std::stod(row[c2.Column("beta")]);
    EXPECT_TRUE(v > ix[0] && v < ix[1] && b > iy[0] && b < iy[1]) << row[0] << " not in the inset";
    EXPECT_FALSE(covered(on_page(v, b))) << row[0] << " hidden by the inset";
  }
  for (double v : {ix[0], ix[1]})
    for (double b : {iy[0], iy[1]}) EXPECT_FALSE(covered(on_page(v, b))) << "the zoomed box hidden";
}

}  // namespace
