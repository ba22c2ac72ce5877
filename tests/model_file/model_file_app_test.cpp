// Model files in the apps (--model FILE; docs/model_files.md): the belt and
// the brake written as files give the built-in systems' branches row for
// row, and every refusal of a bad file is exit 2 with one line naming the
// file, its line and the problem, and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;

class ModelFileApp : public tu::AppTest {
 protected:
  // Both runs' tables: the same rows, every number within tol relative (the
  // Floquet multipliers within mult_tol), text equal.
  void ExpectSameTables(const std::string& a, const std::string& b, const std::string& file,
                        double tol, double mult_tol) {
    const tu::Tsv x = tu::ReadTsv(tu::ReadFile(a + "/out/" + file));
    const tu::Tsv y = tu::ReadTsv(tu::ReadFile(b + "/out/" + file));
    ASSERT_EQ(x.rows.size(), y.rows.size()) << file;
    ASSERT_GT(x.rows.size(), 1u) << file;
    double worst = 0, worst_mult = 0;
    for (std::size_t i = 0; i < x.rows.size(); ++i)
      for (std::size_t c = 0; c < x.rows[i].size(); ++c) {
        char* end = nullptr;
        const double u = std::strtod(x.rows[i][c].c_str(), &end);
        if (*end != '\0' || x.rows[i][c].empty()) {
          EXPECT_EQ(x.rows[i][c], y.rows[i][c]) << file << " row " << i << " " << x.columns[c];
          continue;
        }
        const double w = std::stod(y.rows[i][c]);
        if (std::isnan(u) && std::isnan(w)) continue;
        // At a fold the largest multiplier is 1 to rounding: stable either way.
        const std::string& m = y.rows[i][y.Column("mult_max")];  // empty on steady sliding
        if (x.columns[c] == "stable" && !m.empty() && std::abs(std::stod(m) - 1) < 1e-8) continue;
        double& to = x.columns[c].rfind("mult", 0) == 0 ? worst_mult : worst;
        const double d = std::abs(u - w) / (1 + std::abs(w));
        EXPECT_LE(d, 1e-6) << file << " row " << i << " " << x.columns[c] << ": " << x.rows[i][c]
                           << " vs " << y.rows[i][c];
        to = std::max(to, d);
      }
    EXPECT_LE(worst, tol) << file;
    EXPECT_LE(worst_mult, mult_tol) << file;
  }
  // A model file of `text` in the test's directory; ss_simulate refuses it.
  void ExpectRefused(const std::string& text, const std::vector<std::string>& parts) {
    const std::string dir = NewDir(), file = dir + "/bad.ini";
    tu::WriteFile(file, text);
    const auto r = RunOut("ss_simulate", dir, {"--model", file});
    EXPECT_EQ(r.outcome.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const std::string& p : parts) EXPECT_TRUE(tu::Contains(r.err, p)) << p << ": " << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << r.err;
  }
};

const std::string kModels = STICKSLIP_SOURCE_DIR "/studies/models/";

TEST_F(ModelFileApp, TheBeltFileGivesTheBuiltInBranch) {
  const std::string a = NewDir(), b = NewDir();
  const auto file =
      RunOut("ss_continue", a,
             {"--model", kModels + "belt.ini", "--param", "v", "--from", "0.05", "--to", "0.5"});
  const auto built = RunOut("ss_continue", b,
                            {"--system", "chain", "--blocks", "1", "--set", "kc=0", "--param", "v",
                             "--from", "0.05", "--to", "0.5"});
  EXPECT_EQ(file.outcome.code, built.outcome.code) << file.err;
  // The log's special points: "  HB1  pt 200  v = 0.44095855184...  x_max ...".
  EXPECT_TRUE(std::regex_search(file.out, std::regex("  HB1  pt [0-9]+  v = 0\\.4409585518")))
      << file.out;
  EXPECT_TRUE(std::regex_search(file.out, std::regex("  GR1  pt [0-9]+  v = 0\\.3957902887")))
      << file.out;
  ExpectSameTables(a, b, "branch.tsv", 1e-12, 1e-12);  // 5.3e-16 measured
  ExpectSameTables(a, b, "special_points.tsv", 1e-12, 1e-12);
}

// studies/mode_coupling.ini's run (flutter at mu_k 0.515, a fold, contact loss)
// with the brake written as a model file, normal force 1 - gamma y.
TEST_F(ModelFileApp, TheBrakeFileGivesTheBuiltInBranch) {
  const std::string a = NewDir(), b = NewDir();
  const auto file = RunOut("ss_continue", a,
                           {"--model", kModels + "mode_coupling.ini", "--mu_s", "0.8", "--rtol",
                            "1e-12", "--atol", "1e-12", "--param", "mu_k", "--from", "0.3", "--to",
                            "0.7", "--start_at", "0.52", "--max_step", "0.05"});
  const auto built =
      RunOut("ss_continue", b, {"--study", STICKSLIP_SOURCE_DIR "/studies/mode_coupling.ini"});
  EXPECT_EQ(file.outcome.code, built.outcome.code) << file.err;
  EXPECT_TRUE(tu::Contains(file.out, "  CL1  pt ")) << file.out;
  // Measured: states 3.3e-13; multipliers 2e-12 where a complex pair meets on
  // the real axis (rows 24-26: a perturbation e of M moves them by sqrt(e)).
  ExpectSameTables(a, b, "branch.tsv", 1e-12, 1e-11);
  ExpectSameTables(a, b, "special_points.tsv", 1e-12, 1e-11);
}

// studies/chain2.ini's run at kc = 0.5, the model file's (two coupled seed
// blocks, two contacts: 9 modes) with the chain written as a model file.
TEST_F(ModelFileApp, TheChainFileGivesTheBuiltInBranch) {
  const std::string a = NewDir(), b = NewDir();
  const auto file = RunOut("ss_continue", a,
                           {"--model", kModels + "chain2.ini", "--param", "v", "--from", "0.05",
                            "--to", "0.5", "--start_at", "0.3"});
  const auto built = RunOut(
      "ss_continue", b, {"--study", STICKSLIP_SOURCE_DIR "/studies/chain2.ini", "--set", "kc=0.5"});
  EXPECT_EQ(file.outcome.code, built.outcome.code) << file.err;
  // Measured: states 7.5e-15 (246 rows); the multipliers 1.3e-7 at the
  // grazing point's row (1e-8 on the rows before it), where the return map's
  // derivative grows without bound (the stick time vanishes like a square
  // root): there a rounding of 1e-16 in the orbit moves them that much, in
  // either code (the file's parameter column is exact, the built-in chain's
  // by differences).
  ExpectSameTables(a, b, "branch.tsv", 1e-12, 1e-6);
  ExpectSameTables(a, b, "special_points.tsv", 1e-12, 1e-6);
}

// The forced belt written as a model file (clock theta = omega) through
// ss_continue's one system path (a stroboscopic settle, the one branch
// driver) against the built-in forced oscillator's --force path
// (studies/seed_forced.ini, ForcedBelt's hand-written field): the same
// special points in the same order. Then the PD's doubled branch from a
// restart of each.
TEST_F(ModelFileApp, TheForcedFileGivesTheForcedOscillatorsSpecialPoints) {
  const std::string a = NewDir(), b = NewDir();
  const auto file =
      RunOut("ss_continue", a,
             {"--model", kModels + "forced.ini", "--param", "omega", "--from", "1", "--to", "0.5"});
  const auto built =
      RunOut("ss_continue", b, {"--study", STICKSLIP_SOURCE_DIR "/studies/seed_forced.ini"});
  ASSERT_EQ(file.outcome.code, 0) << file.err;
  ASSERT_EQ(built.outcome.code, 0) << built.err;
  auto points = [](const std::string& dir) {
    return tu::ReadTsv(tu::ReadFile(dir + "/out/special_points.tsv"));
  };
  auto same = [&](const tu::Tsv& x, const tu::Tsv& y) {
    ASSERT_EQ(x.rows.size(), y.rows.size());
    ASSERT_GE(x.rows.size(), 3u);
    for (std::size_t i = 0; i < x.rows.size(); ++i) {
      const std::string label = x.rows[i][x.Column("label")];
      EXPECT_EQ(label, y.rows[i][y.Column("label")]) << i;
      // Measured: 1.3e-15 (LP, PD, CR); 7e-13 at GR, whose test function
      // is a square root of the distance.
      EXPECT_NEAR(std::stod(x.rows[i][x.Column("omega")]), std::stod(y.rows[i][y.Column("omega")]),
                  label == "GR" ? 1e-11 : 1e-13)
          << label;
    }
  };
  same(points(a), points(b));
  const tu::Tsv row = tu::ReadTsv(tu::ReadFile(a + "/out/branch.tsv"));
  EXPECT_EQ(row.meta.at("section_turns"), "1");
  const std::string c = NewDir(), d = NewDir();
  const auto doubled = RunOut(
      "ss_continue", c,
      {"--model", kModels + "forced.ini", "--restart", a + "/out", "--point", "PD1", "--switch"});
  const auto built_doubled =
      RunOut("ss_continue", d, {"--restart", b + "/out", "--point", "PD1", "--switch"});
  EXPECT_EQ(doubled.outcome.code, built_doubled.outcome.code) << doubled.err;
  same(points(c), points(d));
  EXPECT_EQ(tu::ReadTsv(tu::ReadFile(c + "/out/branch.tsv")).meta.at("switch"),
            "period-doubled branch, turns 1 -> 2");
  // A clock's restart on a system without one (the phase a plain state) is refused by name.
  const std::string e = NewDir(), plain = e + "/plain.ini";
  std::string text = tu::ReadFile(kModels + "forced.ini");
  text.replace(text.find("clock theta = omega"), 19, "states = theta\ntheta' = omega");
  tu::WriteFile(plain, text);
  const auto wrong =
      RunOut("ss_continue", e, {"--model", plain, "--restart", a + "/out", "--point", "PD1"});
  EXPECT_EQ(wrong.outcome.code, 2) << wrong.err;
  EXPECT_TRUE(tu::Contains(wrong.err, "its orbits are on a clock's turns")) << wrong.err;
  // More clock turns than the branch driver takes (kMaxPeriodMultiple = 1000):
  // the restart file is refused by name, not the section the driver was given.
  const std::string f = NewDir() + "/turns";
  ASSERT_EQ(std::system(("cp -r " + a + "/out " + f + " && sed -i 's/^# section_turns: 1$/" +
                         "# section_turns: 1001/' " + f + "/branch.tsv")
                            .c_str()),
            0);
  const auto turns = RunOut("ss_continue", NewDir(),
                            {"--model", kModels + "forced.ini", "--restart", f, "--point", "3"});
  EXPECT_EQ(turns.outcome.code, 2) << turns.err;
  EXPECT_TRUE(tu::Contains(turns.err,
                           "branch.tsv' is corrupt: section_turns = '1001' is not a "
                           "whole number from 1 to 1000"))
      << turns.err;
}

// studies/stribeck_forced.ini's branch on the built-in forced oscillator's
// --force path against studies/models/stribeck_forced.ini on the one system
// path, given the forced run's options (max_step 0.02, tolerances 1e-12,
// max_amplitude 50): every row and every special point, its two PDs among
// them. Measured: 211 rows, every state 9.7e-14 relative; the multipliers
// 7.3e-7 on the GR row (the stick time vanishes like a square root there),
// and the stability flag of the PD row, whose multiplier is -1 to rounding.
TEST_F(ModelFileApp, TheForcedStribeckFileGivesTheBuiltInBranchRowByRow) {
  const std::string a = NewDir(), b = NewDir();
  const auto file = RunOut(
      "ss_continue", a,
      {"--model", kModels + "stribeck_forced.ini", "--param", "omega", "--from", "0.8", "--to",
       "0.5", "--max_step", "0.02", "--rtol", "1e-12", "--atol", "1e-12", "--max_amplitude", "50"});
  const auto built =
      RunOut("ss_continue", b, {"--study", STICKSLIP_SOURCE_DIR "/studies/stribeck_forced.ini"});
  ASSERT_EQ(file.outcome.code, 0) << file.err;
  ASSERT_EQ(built.outcome.code, 0) << built.err;
  const tu::Tsv x = tu::ReadTsv(tu::ReadFile(a + "/out/branch.tsv"));
  const tu::Tsv y = tu::ReadTsv(tu::ReadFile(b + "/out/branch.tsv"));
  ASSERT_EQ(x.rows.size(), y.rows.size());
  double worst = 0, worst_mult = 0;
  int columns = 0;
  for (std::size_t c = 0; c < x.columns.size(); ++c) {
    const std::string& name = x.columns[c];
    const int d = y.Column(name);  // the forced run writes the system's tables
    if (d < 0 || name == "pt") continue;
    ++columns;
    for (std::size_t i = 0; i < x.rows.size(); ++i) {
      const std::string &u = x.rows[i][c], &w = y.rows[i][d];
      const bool fold = std::abs(std::abs(std::stod(y.rows[i][y.Column("mult_max")])) - 1) < 1e-8;
      if (name == "kind" || name == "mode_0" || u.empty() || w.empty()) {  // text, or empty
        EXPECT_EQ(u, w) << name << " row " << i;
        continue;
      }
      if (name == "stable" && !fold) {
        EXPECT_EQ(u, w) << name << " row " << i;
      }
      if (name == "stable") continue;
      const double e = std::abs(std::stod(u) - std::stod(w)) / (1 + std::abs(std::stod(w)));
      (name.rfind("mult", 0) == 0 ? worst_mult : worst) =
          std::max(name.rfind("mult", 0) == 0 ? worst_mult : worst, e);
    }
  }
  EXPECT_GE(columns, 15);
  EXPECT_LE(worst, 1e-12);
  EXPECT_LE(worst_mult, 1e-5);
  const tu::Tsv p = tu::ReadTsv(tu::ReadFile(a + "/out/special_points.tsv"));
  const tu::Tsv q = tu::ReadTsv(tu::ReadFile(b + "/out/special_points.tsv"));
  ASSERT_EQ(p.rows.size(), q.rows.size());
  int pd = 0;
  for (std::size_t i = 0; i < p.rows.size(); ++i) {
    const std::string label = p.rows[i][p.Column("label")];
    EXPECT_EQ(label, q.rows[i][q.Column("label")]) << i;
    pd += label == "PD";
    EXPECT_NEAR(std::stod(p.rows[i][p.Column("omega")]), std::stod(q.rows[i][q.Column("omega")]),
                1e-12)
        << label;
  }
  EXPECT_EQ(pd, 2);
  std::printf("[ measured ] %zu rows, %d columns: states %.1e, multipliers %.1e\n", x.rows.size(),
              columns, worst, worst_mult);
}

// The drill string's chart (docs/model_files.md): its title of twelve
// parameters breaks into two lines, which chart.gp must quote as gnuplot
// reads them (a raw newline inside the quotes was an invalid command).
TEST_F(ModelFileApp, TheDrillStringsChartWritesItsFigure) {
  const std::string dir = NewDir();
  const auto r =
      RunOut("ss_chart", dir,
             {"--model", kModels + "drill_string.ini", "--param", "T_m", "--from", "9240", "--to",
              "10685", "--param2", "W_ob", "--from2", "80000", "--to2", "110000"},
             true);  // with the figure: gnuplot must read the script
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const std::string gp = tu::ReadFile(dir + "/out/chart.gp");
  const auto at = gp.find("set title \"");
  ASSERT_NE(at, std::string::npos);
  const std::string line = gp.substr(at, gp.find('\n', at) - at);
  EXPECT_NE(line.find("\\n"), std::string::npos) << line;  // two lines, as gnuplot's escape
  EXPECT_EQ(line.back(), '"') << line;
  EXPECT_TRUE(tu::Contains(r.out, "curve 1 HB: 88 points")) << r.out;
}

// A study file names its model by a path from its own folder
// (studies/belt_model.ini: model = models/belt.ini), wherever the app runs.
TEST_F(ModelFileApp, AStudyReadsItsModelFromItsOwnFolder) {
  const std::string dir = NewDir();
  const auto r =
      RunOut("ss_continue", dir, {"--study", STICKSLIP_SOURCE_DIR "/studies/belt_model.ini"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv b = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  EXPECT_EQ(b.meta.at("system").rfind("belt:", 0), 0u) << b.meta.at("system");
  EXPECT_GT(b.rows.size(), 200u);
  const std::string study = dir + "/mine.ini";
  tu::WriteFile(study, "model = none.ini\n[continue]\nparam = v\nto = 0.3\n");
  const auto bad = RunOut("ss_continue", NewDir(), {"--study", study});
  EXPECT_EQ(bad.outcome.code, 2);
  EXPECT_TRUE(tu::Contains(bad.err, "mine.ini:1")) << bad.err;
  EXPECT_TRUE(tu::Contains(bad.err, dir + "/none.ini: cannot read the model file")) << bad.err;
}

TEST_F(ModelFileApp, EveryBadFileIsOneLineNamingItsLine) {
  const std::string head = "coordinates = x\nparameter v = 0.25\nparameter mu = 0.4\n";
  const std::string law = "contact F = x' - v\nlaw F = mu\n";
  ExpectRefused(head + "x'' = -x + F + q\n" + law, {"bad.ini:4", "q"});
  ExpectRefused("coordinates = x, y\nparameter v = 0.25\nx'' = -x + F\n" + law,
                {"bad.ini:1", "no equation y''", "2 coordinates, 1 equations"});
  ExpectRefused(head + "x'' = -x + F\nx'' = F\n" + law, {"bad.ini:5", "a second equation"});
  ExpectRefused(head + "x'' = -x + F\ncontact F = v\nlaw F = mu\n",
                {"bad.ini:5", "depends on no state component"});
  ExpectRefused(head + "x'' = -x + F\ncontact F = x'*x' - v\nlaw F = mu\n",
                {"bad.ini:5", "not linear in the state"});
  ExpectRefused(
      head + "parameter vs = 0\nx'' = -x + F\ncontact F = x' - v\nlaw F = mu/(1 + s/vs)\n",
      {"bad.ini:7", "divides by vs"});
  ExpectRefused(head + "x'' = -x + F\ncontact F = x' - v\nlaw F = mu*abs(s)\n",
                {"bad.ini:6", "abs is not smooth"});
  ExpectRefused(head + "x'' = -x + F^2\n" + law, {"bad.ini:4", "nonlinearly"});
  ExpectRefused(
      "coordinates = x, y\nparameter v = 0.25\nparameter mu = 0.4\nx'' = -x\n"
      "y'' = -y + F\n" +
          law,
      {"bad.ini:6", "does not act on its own velocity"});
  ExpectRefused(head + "x'' = -x + F\ncontact F = x' - v\n", {"bad.ini:5", "has no law"});
  ExpectRefused(head + "x'' = -x + F\n" + law + "friction = 3\n",
                {"bad.ini:7", "unknown key 'friction'"});
  ExpectRefused(head + "parameter v = 1\n", {"bad.ini:4", "the name 'v' is used twice"});
  ExpectRefused(head + "x'' = -x + F\n" + law + "static F = -1\n", {"static coefficient"});
  ExpectRefused(head + "x'' = -x + F + 9^(9^9)\n" + law, {"bad.ini:4", "a power in an exponent"});
  ExpectRefused(head + "x'' = -x + F + 2^5000\n" + law, {"bad.ini:4", "is above 1000"});
  ExpectRefused(head + "clock th = v\nx'' = -x + F\ncontact F = x' - th\nlaw F = mu\n",
                {"bad.ini:6", "reads the clock th"});
  ExpectRefused(head + "clock th = v\nclock ph = v\n", {"bad.ini:5", "a second clock"});
  ExpectRefused(head + "x'' = -x + F\ncontact F = x' - v\nlaw F = mu - 0.2*sqrt(s)\n",
                {"bad.ini:6", "not smooth at s = 0"});
  ExpectRefused(head + "x'' = -x - F\n" + law, {"bad.ini:5", "pulls its own velocity"});
  ExpectRefused(head + "x'' = -x + F + 1/F\n" + law, {"bad.ini:4", "nonlinearly"});
  ExpectRefused(head + "parameter Pi = 3\n", {"bad.ini:4", "'Pi' is reserved"});
  ExpectRefused(head + "x'' = -x + F + 0*9^-(9^9)\n" + law,
                {"bad.ini:4", "a power in an exponent"});
  ExpectRefused(head + "x'' = -x + F + 0*9^(9*9*9*9)\n" + law,
                {"bad.ini:4", "must be one number up to 1000"});
  ExpectRefused(head + "x'' = -x + F\ncontact F = x' - v\nlaw F = mu - 0.1*s^3.5\n",
                {"bad.ini:6", "numeric whole exponent"});
  ExpectRefused(head + "x'' = -x + F + 15e500\n" + law, {"bad.ini:4", "'15e500' is beyond"});
  ExpectRefused(head + "x'' = -x + F\n" + law + "normal F = -1\n",
                {"normal force of contact F is -1"});
  ExpectRefused(
      head + "x'' = -x + F + " + std::string(70, '(') + "x" + std::string(70, ')') + "\n" + law,
      {"bad.ini:4", "nested deeper than 64"});
  // The options around the file.
  const std::string dir = NewDir();
  auto r = RunOut("ss_simulate", dir, {"--model", dir + "/none.ini"});
  EXPECT_EQ(r.outcome.code, 2);
  EXPECT_TRUE(tu::Contains(r.err, "none.ini: cannot read the model file")) << r.err;
  r = RunOut("ss_simulate", dir, {"--model", kModels + "belt.ini", "--system", "chain"});
  EXPECT_TRUE(tu::Contains(r.err, "give one of them")) << r.err;
  r = RunOut("ss_simulate", dir, {"--model", kModels + "belt.ini", "--law", "coulomb"});
  EXPECT_TRUE(tu::Contains(r.err, "has its own laws")) << r.err;
  r = RunOut("ss_simulate", dir, {"--model", kModels + "forced.ini", "--state", "0,0.25,1e20"});
  EXPECT_TRUE(tu::Contains(r.err, "component 3 (theta) = 1e20")) << r.err;
  r = RunOut("ss_simulate", dir, {"--model", kModels + "forced.ini", "--set", "omega=0"});
  EXPECT_TRUE(tu::Contains(r.err, "--set omega = 0: the clock's rate omega = 0")) << r.err;
  r = RunOut("ss_simulate", dir, {"--model", kModels + "belt.ini", "--mu_k", "0.3"});
  EXPECT_TRUE(tu::Contains(r.err, "--mu_k: belt has no parameter mu_k")) << r.err;
  r = RunOut("ss_simulate", dir, {"--model", kModels + "belt.ini", "--set", "vv=1"});
  EXPECT_TRUE(tu::Contains(r.err, "'vv' is no parameter of belt")) << r.err;
  // A parameter no expression reads: no axis for a branch (flat before).
  const std::string unread = dir + "/unread.ini";
  tu::WriteFile(unread, "coordinates = x\nparameter v = 0.25\nparameter mu = 0.4\n"
                        "parameter c = 3\nx'' = -x + F\ncontact F = x' - v\nlaw F = mu\n");
  r = RunOut("ss_continue", dir, {"--model", unread, "--param", "c", "--to", "4"});
  EXPECT_EQ(r.outcome.code, 2) << r.err;
  EXPECT_TRUE(tu::Contains(r.err, "--param")) << r.err;
  EXPECT_TRUE(tu::Contains(r.err, "parameter 'c' appears in no expression of")) << r.err;
  // The same axis in a chart and an orbit diagram.
  r = RunOut("ss_chart", dir,
             {"--model", unread, "--param", "v", "--from", "0.1", "--to", "0.3", "--param2", "c",
              "--from2", "1", "--to2", "4"});
  EXPECT_EQ(r.outcome.code, 2) << r.err;
  EXPECT_TRUE(tu::Contains(r.err, "--param2: parameter 'c' appears in no expression")) << r.err;
  r = RunOut("ss_orbit_diagram", dir,
             {"--model", unread, "--param", "c", "--from", "1", "--to", "4"});
  EXPECT_EQ(r.outcome.code, 2) << r.err;
  EXPECT_TRUE(tu::Contains(r.err, "--param: parameter 'c' appears in no expression")) << r.err;
  EXPECT_FALSE(tu::Exists(dir + "/out"));
}

}  // namespace
