// What the figures' line styles mean: within one figure a style has one key
// entry (one meaning), and every style drawn has one; read from the plot
// clauses of the gnuplot scripts the apps write.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class FigureStylesApp : public tu::AppTest {};

// The figures of a script: the text from each "set output 'NAME" to the next
// "unset output", by NAME.
std::map<std::string, std::string> Figures(const std::string& gp) {
  std::map<std::string, std::string> f;
  for (size_t at = gp.find("set output '"); at != std::string::npos;
       at = gp.find("set output '", at + 1)) {
    const size_t q = gp.find('\'', at + 12);
    f[gp.substr(at + 12, q - at - 12)] = gp.substr(at, gp.find("unset output", at) - at);
  }
  return f;
}

struct Clause {
  std::string style;  // "ls N"
  bool titled = false;
  std::string title;
};

// Every "with lines ls N" clause and its title ('...' or "...") or notitle.
std::vector<Clause> Clauses(const std::string& figure) {
  static const std::regex re(
      R"re(with lines (ls \d+) (notitle|title '([^']*)'|title "([^"]*)"))re");
  std::vector<Clause> c;
  for (std::sregex_iterator it(figure.begin(), figure.end(), re), end; it != end; ++it) {
    const std::smatch& m = *it;
    c.push_back({m[1], m[2] != "notitle", m[3].matched ? m[3].str() : m[4].str()});
  }
  return c;
}

// In every figure: one key text per style, and no style drawn without one.
void ExpectOneMeaningPerStyle(const std::string& gp, const std::string& what) {
  const auto figures = Figures(gp);
  ASSERT_FALSE(figures.empty()) << what;
  for (const auto& [name, text] : figures) {
    std::map<std::string, std::set<std::string>> titles;
    std::set<std::string> drawn;
    for (const Clause& c : Clauses(text)) {
      drawn.insert(c.style);
      // a threshold's value is not its meaning: "threshold 1" and "threshold 0"
      if (c.titled) titles[c.style].insert(std::regex_replace(c.title, std::regex(" [0-9]+$"), ""));
    }
    for (const auto& [style, t] : titles)
      EXPECT_EQ(t.size(), 1u) << what << " " << name << ": " << style << " means " << *t.begin()
                              << " and " << *t.rbegin();
    for (const auto& s : drawn) EXPECT_EQ(titles.count(s), 1u) << what << " " << name << ": " << s;
  }
}

// The seed run's figures with estimates.png: r_1, the averaging amplitude and
// the seed's x bound are three meanings and get three styles.
TEST_F(FigureStylesApp, EveryStyleOfTheBifurcationFiguresHasOneMeaning) {
  const std::string dir = NewDir();
  const auto r = RunOut("ss_continue", dir,
                        {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/seed.ini"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string gp = tu::ReadFile(dir + "/out/bifurcation.gp");
  EXPECT_EQ(Figures(gp).count("estimates.png"), 1u);
  ExpectOneMeaningPerStyle(gp, "seed");
}

// The titles of the curves gnuplot draws from a one-figure script, each with
// its count of defined points (the script run into a table).
std::map<std::string, int> DrawnTitles(const std::string& dir, const std::string& script) {
  std::string gp = tu::ReadFile(dir + "/" + script);
  const auto at = gp.find("set output");
  if (at == std::string::npos) return {};
  gp.replace(at, gp.find('\n', at) - at, "set output '/dev/null'\nset table 'table.txt'");
  tu::WriteFile(dir + "/table.gp", gp);
  if (std::system(("cd " + tu::ShellQuoted(dir) + " && gnuplot table.gp 2>/dev/null").c_str()) != 0)
    return {};
  std::map<std::string, int> n;
  std::istringstream is(tu::ReadFile(dir + "/table.txt"));
  std::string title;  // of the current curve; "" untitled
  for (std::string line; std::getline(is, line);) {
    if (line.rfind("# Curve title: ", 0) == 0) {
      title = line.substr(16, line.size() - 17);
      n[title] += 0;
    } else if (line.rfind("# Curve ", 0) == 0) {
      title.clear();
    } else if (!title.empty() && !line.empty() && line[0] != '#') {
      std::istringstream ls(line);
      double x = 0, y = 0;
      std::string type;
      if (ls >> x >> y >> type && type != "u") ++n[title];
    }
  }
  return n;
}

// The floor and Den Hartog bifurcation figures: every key entry names a curve
// with points (no "unstable" entry over a branch that is stable throughout).
TEST_F(FigureStylesApp, ResonanceKeyNamesOnlyCurvesWithData) {
  if (!tu::HaveGnuplot()) GTEST_SKIP() << "no gnuplot";
  for (const char* study : {"floor_static", "den_hartog"}) {
    const std::string dir = NewDir();
    const auto r =
        RunOut("ss_continue", dir,
               {"--study", std::string(STICKSLIP_SOURCE_DIR) + "/studies/" + study + ".ini"});
    ASSERT_EQ(r.outcome.code, 0) << r.err;
    const auto titles = DrawnTitles(dir + "/out", "bifurcation.gp");
    ASSERT_GE(titles.size(), 1u) << study;
    for (const auto& [title, points] : titles)
      EXPECT_GT(points, 0) << study << ": key entry '" << title << "' has no data";
  }
}

}  // namespace
