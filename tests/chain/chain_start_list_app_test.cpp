// ss_continue's start list of a system with no clock (--all, --point N;
// src/cli/autonomous_start.hpp, docs/systems.md): two identical seed blocks
// at v = 0.3 (studies/chain2.ini). --all continues the synchronized orbit
// (x1 = x2 on every row), whose period is the single belt's (FindPeriodicOrbits
// on the 1-DOF Model), and the alternating one (the blocks half a period
// apart: equal ranges, unequal section points); --point picks one; a --point
// beyond the list and --m (clock turns) are refused; a branch on its own
// stick-exit section restarts on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "app_test_util.hpp"
#include "stickslip/orbits/orbit_scan.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace {
namespace start_list {  // unity builds: its own names beside the other chain app tests

namespace tu = stickslip::testing_util;
class ChainStartListApp : public tu::AppTest {};

const std::string kChain = STICKSLIP_SOURCE_DIR "/studies/chain2.ini";

double Cell(const tu::Tsv& t, const std::vector<std::string>& row, const std::string& col) {
  return std::stod(row[t.Column(col)]);
}

// The single seed block of studies/chain2.ini at v: its stick-slip period.
double BeltPeriod(double v) {
  stickslip::Params p;
  p.law = stickslip::LawKind::kCubic;
  p.beta = 0.05, p.mu_s = 0.4, p.mu_m = 0.25, p.v_m = 0.5, p.v = v;
  const stickslip::PeriodicOrbits belt =
      stickslip::FindPeriodicOrbits(stickslip::Model(p), stickslip::OrbitScanOptions());
  EXPECT_TRUE(belt.has_stick_slip);
  return belt.stick_slip.period;
}

std::vector<std::string> At(const std::vector<std::string>& extra) {
  std::vector<std::string> a = {"--study", kChain, "--set", "kc=0.2",     "--from",
                                "0.3",     "--to", "0.302", "--start_at", "0.3"};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

// The rows of each orbit branch (branch > 0), by number.
std::map<int, std::vector<std::vector<std::string>>> Branches(const tu::Tsv& t) {
  std::map<int, std::vector<std::vector<std::string>>> b;
  for (const auto& row : t.rows)
    if (std::stoi(row[t.Column("branch")]) > 0)
      b[std::stoi(row[t.Column("branch")])].push_back(row);
  return b;
}

bool InStep(const tu::Tsv& t, const std::vector<std::string>& row, double tol) {
  for (const char* c : {"_0", "dot_0", "_min", "_max", "dot_min", "dot_max"})
    if (std::abs(Cell(t, row, std::string("x1") + c) - Cell(t, row, std::string("x2") + c)) > tol)
      return false;
  return true;
}

TEST_F(ChainStartListApp, AllContinuesTheSynchronizedAndTheAlternatingOrbit) {
  const AppRun r = RunOut("ss_continue", dir_, At({"--all"}));
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_TRUE(tu::Contains(r.out, "start orbits at v = 0.3 (--point N continues orbit N):"))
      << r.out;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir_ + "/out/branch.tsv"));
  const auto branches = Branches(t);
  ASSERT_EQ(branches.size(), 2u) << r.out;
  const double belt = BeltPeriod(0.3);
  int sync = 0, alternating = 0;
  for (const auto& [number, rows] : branches) {
    SCOPED_TRACE("branch " + std::to_string(number));
    ASSERT_GT(rows.size(), 2u);
    EXPECT_DOUBLE_EQ(Cell(t, rows.front(), "v"), 0.3);
    if (InStep(t, rows.front(), 1e-9)) {
      ++sync;
      for (const auto& row : rows) EXPECT_TRUE(InStep(t, row, 1e-9)) << Cell(t, row, "v");
      EXPECT_NEAR(Cell(t, rows.front(), "period"), belt, 1e-9);
      std::printf("[ measured ] synchronized T(0.3) = %.13f, belt %.13f\n",
                  Cell(t, rows.front(), "period"), belt);
    } else {
      ++alternating;  // x2(t) = x1(t + T/2): the same ranges, the section points apart
      for (const auto& row : rows) {
        for (const char* c : {"_min", "_max", "dot_min", "dot_max"})
          EXPECT_NEAR(Cell(t, row, std::string("x1") + c), Cell(t, row, std::string("x2") + c),
                      1e-8);
        EXPECT_GT(std::abs(Cell(t, row, "x1_0") - Cell(t, row, "x2_0")), 1e-3);
      }
      EXPECT_GT(std::abs(Cell(t, rows.front(), "period") - belt), 0.1);
    }
  }
  EXPECT_EQ(sync, 1);
  EXPECT_EQ(alternating, 1);
}

// --point N: orbit N of the printed list alone, as branch 1.
TEST_F(ChainStartListApp, PointPicksOneOrbitOfTheList) {
  const double belt = BeltPeriod(0.3);
  int found_sync = 0;
  for (const char* n : {"1", "2"}) {
    const std::string dir = NewDir();
    const AppRun r = RunOut("ss_continue", dir, At({"--point", n}));
    ASSERT_EQ(r.outcome.code, 0) << r.err;
    const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
    const auto branches = Branches(t);
    ASSERT_EQ(branches.size(), 1u);
    ASSERT_EQ(branches.begin()->first, 1);
    const auto& first = branches.begin()->second.front();
    const bool sync = InStep(t, first, 1e-9);
    found_sync += sync;
    if (sync) EXPECT_NEAR(Cell(t, first, "period"), belt, 1e-9);
  }
  EXPECT_EQ(found_sync, 1);
}

// Two unequal blocks (chain2_asym, m2 = 1.5) at kc = 0.5, v = 0.3: the list's second
// orbit (both blocks stick twice) closes after 4 stick exits, the first's
// after 1; branch 2's rows name their own section, and a restart from its
// last row continues that orbit (its first row is the row, period and state).
TEST_F(ChainStartListApp, ABranchOnItsOwnSectionRestartsOnIt) {
  const std::string first = NewDir(), again = NewDir();
  const AppRun r =
      RunOut("ss_continue", first,
             {"--study", STICKSLIP_SOURCE_DIR "/studies/chain2_asym.ini", "--set", "kc=0.5",
              "--from", "0.3", "--to", "0.302", "--start_at", "0.3", "--all"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(first + "/out/branch.tsv"));
  EXPECT_EQ(t.meta.at("section_returns"), "1");
  ASSERT_TRUE(t.meta.count("branch_2_section_returns")) << r.out;
  EXPECT_EQ(t.meta.at("branch_2_section_returns"), "4");
  const auto branches = Branches(t);
  ASSERT_EQ(branches.count(2), 1u);
  const auto& last = branches.at(2).back();
  const AppRun b =
      RunOut("ss_continue", again,
             {"--restart", first + "/out", "--point", last[t.Column("pt")], "--to", "0.3"});
  ASSERT_EQ(b.outcome.code, 0) << b.err;
  const tu::Tsv u = tu::ReadTsv(tu::ReadFile(again + "/out/branch.tsv"));
  EXPECT_EQ(u.meta.at("section_returns"), "4");
  const auto restarted = Branches(u);
  ASSERT_FALSE(restarted.empty());
  const auto& row = restarted.begin()->second.front();
  EXPECT_NEAR(Cell(u, row, "v"), Cell(t, last, "v"), 1e-12);
  EXPECT_NEAR(Cell(u, row, "period"), Cell(t, last, "period"), 1e-9);
  for (const char* c : {"x1_0", "x1dot_0", "x2_0", "x2dot_0"})
    EXPECT_NEAR(Cell(u, row, c), Cell(t, last, c), 1e-9) << c;
}

// Identical blocks at kc = 0.5, v = 0.05: the out-of-step orbit comes as two
// mirror images (blocks swapped), orbits 2 and 3 of the list. On one, block 2
// sticks at the section point (x2' = v): as v moves, the map starts with x2'
// at the new v (it stopped, "stick mode requested off the stick set"). Both
// branches reach v = 0.1, each the other's mirror there.
TEST_F(ChainStartListApp, AStuckBlockFollowsTheBeltAsVMoves) {
  std::vector<std::vector<std::string>> last;
  tu::Tsv t;
  for (const char* n : {"2", "3"}) {
    const std::string dir = NewDir();
    const AppRun r = RunOut("ss_continue", dir,
                            {"--study", kChain, "--set", "kc=0.5", "--from", "0.05", "--to", "0.1",
                             "--start_at", "0.05", "--point", n});
    ASSERT_EQ(r.outcome.code, 0) << n << ": " << r.err;
    t = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
    const auto b = Branches(t);
    ASSERT_EQ(b.count(1), 1u);
    const auto end = std::max_element(b.at(1).begin(), b.at(1).end(), [&](auto& a, auto& c) {
      return Cell(t, a, "v") < Cell(t, c, "v");
    });
    EXPECT_EQ(Cell(t, *end, "v"), 0.1);
    last.push_back(*end);
  }
  EXPECT_NEAR(Cell(t, last[0], "period"), Cell(t, last[1], "period"), 1e-9);
  for (const char* c : {"_min", "_max", "dot_min", "dot_max"})
    EXPECT_NEAR(Cell(t, last[0], std::string("x1") + c), Cell(t, last[1], std::string("x2") + c),
                1e-9)
        << c;
}

// A scan cut short by --max_time continues nothing and says so: the time
// limit's exit code (1) and status, never a --point refused for a short list.
// 1 ms may run out in the scan or, on a loaded machine, already in the
// steady-sliding branch before it (the scan is then not run): either way the
// log says which phase was cut and the files' status is partial.
TEST_F(ChainStartListApp, AScanCutShortByTheTimeLimitSaysSo) {
  const std::string dir = NewDir();
  const AppRun r = RunOut("ss_continue", dir, At({"--point", "2", "--max_time", "0.001"}));
  EXPECT_EQ(r.outcome.code, 1) << r.err;
  const bool in_scan = tu::Contains(r.out, "the scan was cut short");
  const bool before_scan = tu::Contains(r.out, "steady sliding: ") &&
                           tu::Contains(r.out, " rows, cancelled") &&
                           !tu::Contains(r.out, "start orbits at");
  EXPECT_TRUE(in_scan || before_scan) << r.out;
  EXPECT_TRUE(tu::Contains(tu::ReadFile(dir + "/out/branch.tsv"), "# status: partial: ")) << dir;
  EXPECT_FALSE(tu::Contains(r.err, "--point")) << r.err;
}

// Refused: exit 2, one line naming the option and value, no --out folder.
TEST_F(ChainStartListApp, APointBeyondTheListAndClockTurnsAreRefused) {
  struct Bad {
    std::vector<std::string> args;
    std::string says;
  };
  const Bad bad[] = {{{"--point", "3"},
                      "invalid value '3' for --point: the start list at v = 0.3 "
                      "has 2 orbits"},
                     {{"--m", "2"}, "--m counts clock turns"},
                     {{"--all", "--transient", "100"}, "--transient"},
                     {{"--point", "0"}, "--point"}};
  for (const Bad& b : bad) {
    const std::string dir = NewDir();
    const AppRun r = RunOut("ss_continue", dir, At(b.args));
    EXPECT_EQ(r.outcome.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(tu::Contains(r.err, b.says)) << r.err;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << r.err;
  }
}

}  // namespace start_list
}  // namespace
