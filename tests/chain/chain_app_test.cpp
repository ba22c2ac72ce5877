// ss_continue --system (docs/systems.md) through the app: the two-block chain
// study (studies/chain2.ini) against closed forms, and every refusal of the
// system options: exit 2, one line naming the option or study line and the
// value, nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "app_test_util.hpp"

namespace {

namespace tu = stickslip::testing_util;
class SystemApp : public tu::AppTest {
 protected:
  // Runs ss_continue with args; expects exit 2, one line on stderr holding
  // each of `parts`, and an untouched --out.
  void ExpectRejected(const std::string& app, std::vector<std::string> args,
                      const std::vector<std::string>& parts) {
    const std::string dir = NewDir();
    const auto r = RunOut(app, dir, args);
    EXPECT_EQ(r.outcome.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const auto& part : parts) EXPECT_TRUE(tu::Contains(r.err, part)) << part;
    EXPECT_FALSE(tu::Exists(dir + "/out")) << r.err;
  }
};

const std::string kChain = STICKSLIP_SOURCE_DIR "/studies/chain2.ini";

// Two identical blocks: steady sliding's eigenvalues are those of one block
// for each mode of the stiffness matrix, with one damping, so its Hopf point
// is the single block's 2 beta + mu'(v) = 0: with mu(s) = mu_s - k1 s + k3 s^3
// (k1 = 0.45, k3 = 0.6 for the seed's mu_m, v_m), v = sqrt((k1 - 2 beta) / (3 k3)).
// The orbit's blocks move half a period apart: each block's extremes are the
// other's. Its stick phases end together at GR (at kc = 0.2, the study's, as
// at kc = 0.5), where the branch ends. The located edge is the branch's own
// orbit: the in-step orbit (x1 = x2, 19 % longer) has the same switching
// counts 1e-7 beyond, and once passed for the edge.
TEST_F(SystemApp, ChainStudyHopfIsTheSingleBlocksAndItsOrbitsAreSymmetric) {
  const auto r = RunOut("ss_continue", dir_, {"--study", kChain});
  ASSERT_EQ(r.outcome.code, 0) << r.err;  // the branch ends at GR: no orbit of its kind beyond
  const tu::Tsv branch = tu::ReadTsv(tu::ReadFile(dir_ + "/out/branch.tsv"));
  const tu::Tsv special = tu::ReadTsv(tu::ReadFile(dir_ + "/out/special_points.tsv"));
  EXPECT_EQ(branch.meta.at("status"), "complete");
  EXPECT_TRUE(tu::Contains(branch.meta.at("branch_1_status"),
                           "sequence-ended: the switching "
                           "sequence ends at GR"))
      << branch.meta.at("branch_1_status");
  ASSERT_EQ(special.rows.size(), 2u);
  const double hb = std::sqrt((0.45 - 0.1) / 1.8);
  EXPECT_EQ(special.rows[0][special.Column("lab")], "HB1");
  EXPECT_NEAR(std::stod(special.rows[0][special.Column("v")]), hb, 1e-12);
  EXPECT_EQ(special.rows[1][special.Column("lab")], "GR1");
  EXPECT_TRUE(tu::Contains(special.rows[1].back(), "sticks 2 -> 0, exits 2 -> 0"));
  // The edge row continues branch 1: its period within 1e-4 of the row before
  // it (by v), its blocks not in step.
  const auto& e = special.rows[1];
  const double v_e = std::stod(e[special.Column("v")]);
  double v_prev = -1, t_prev = 0;
  for (const auto& row : branch.rows) {
    const double v = std::stod(row[branch.Column("v")]);
    if (row[branch.Column("branch")] == "1" && v < v_e && v > v_prev)
      v_prev = v, t_prev = std::stod(row[branch.Column("period")]);
  }
  EXPECT_NEAR(std::stod(e[special.Column("period")]), t_prev, 1e-4 * t_prev);
  EXPECT_GT(std::abs(std::stod(e[special.Column("x1_0")]) - std::stod(e[special.Column("x2_0")])) +
                std::abs(std::stod(e[special.Column("x1dot_0")]) -
                         std::stod(e[special.Column("x2dot_0")])),
            1e-3);
  int rows = 0;
  for (const auto& row : branch.rows) {
    if (row[branch.Column("kind")] != "stick-slip") continue;
    for (const char* c : {"_min", "_max", "dot_min", "dot_max"})
      EXPECT_NEAR(std::stod(row[branch.Column(std::string("x1") + c)]),
                  std::stod(row[branch.Column(std::string("x2") + c)]), 1e-9)
          << row[branch.Column("v")] << " " << c;
    EXPECT_EQ(row[branch.Column("sticks")], "2");
    ++rows;
  }
  EXPECT_GT(rows, 100);
}

// Basins of the chain study at v = 0.45, where steady sliding is stable and
// no stick-slip orbit is left (beyond the study's GR at 0.395): every start
// on the (x1, x1') slice comes to rest at steady sliding, x_i = mu(v) in
// closed form (identical blocks, the coupling spring unstretched).
TEST_F(SystemApp, ChainBasinsRestOnSteadySlidingInClosedForm) {
  const auto r =
      RunOut("ss_basin", dir_, {"--study", kChain, "--v", "0.45", "--nx", "4", "--ny", "3"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv starts = tu::ReadTsv(tu::ReadFile(dir_ + "/out/basins.tsv"));
  const tu::Tsv att = tu::ReadTsv(tu::ReadFile(dir_ + "/out/attractors.tsv"));
  EXPECT_EQ(starts.rows.size(), 12u);
  for (const auto& row : starts.rows) EXPECT_EQ(row[starts.Column("kind")], "rest");
  ASSERT_EQ(att.rows.size(), 1u);
  const double s = 0.45 / 0.5, mu = 0.4 - 1.5 * 0.15 * (s - s * s * s / 3);
  for (const char* c : {"x1", "x2"})
    EXPECT_NEAR(std::stod(att.rows[0][att.Column(c)]), mu, 1e-12) << c;
  for (const char* c : {"x1dot", "x2dot"})
    EXPECT_NEAR(std::stod(att.rows[0][att.Column(c)]), 0, 1e-12) << c;
  EXPECT_TRUE(tu::Contains(starts.meta.at("section"), "x1' = 0 falling"));
  EXPECT_EQ(att.rows[0][att.Column("starts")], "12");
}

// The orbit diagram of the chain study at kc = 0.5 swept up from rest on the
// belt (both blocks stuck at x = 0): the blocks stay in step (at the study's
// kc = 0.2 the in-step orbit is transversally unstable, multiplier 1.153,
// and rounding grows off it; docs/systems.md) (library test
// ChainOrbitDiagram checks that orbit against the single belt's); every
// section point lies on x1' = 0 with both blocks' columns named.
TEST_F(SystemApp, ChainOrbitDiagramKeepsTheBlocksInStep) {
  const auto r = RunOut("ss_orbit_diagram", dir_,
                        {"--study", kChain, "--set", "kc=0.5", "--from", "0.28", "--to", "0.32",
                         "--n", "2", "--direction", "up", "--transient", "100", "--keep", "10"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir_ + "/out/orbit_diagram.tsv"));
  ASSERT_EQ(t.rows.size(), 20u);
  for (const char* c : {"v", "x1", "x1dot", "x2", "x2dot", "stuck1", "stuck2", "sticks"})
    EXPECT_GE(t.Column(c), 0) << c;
  for (const auto& row : t.rows) {
    EXPECT_EQ(std::stod(row[t.Column("x1dot")]), 0);
    EXPECT_NEAR(std::stod(row[t.Column("x1")]), std::stod(row[t.Column("x2")]), 1e-9);
    EXPECT_EQ(row[t.Column("sticks")], "2");
  }
  EXPECT_TRUE(tu::Contains(t.meta.at("section"), "x1' = 0 falling"));
  EXPECT_TRUE(tu::Contains(t.meta.at("system"), "v=[swept]"));
}

// ss_chart --system --grid N: the response grid's N x N cells in
// response.tsv, drawn under the curves; a run with --grid 0 (none) removes
// an older response.tsv; sides outside [2, 400] are refused by name.
TEST_F(SystemApp, ChartGridWritesTheResponseCells) {
  const std::string study = STICKSLIP_SOURCE_DIR "/studies/chain2_chart.ini";
  const std::string dir = NewDir();
  auto r = RunOut("ss_chart", dir, {"--study", study, "--seed_lines", "0", "--grid", "3"},
                  tu::HaveGnuplot());
  ASSERT_EQ(r.outcome.code, tu::HaveGnuplot() ? 0 : 3) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir + "/out/response.tsv"));
  EXPECT_EQ(t.meta.at("status"), "complete");
  EXPECT_TRUE(tu::Contains(tu::ReadFile(dir + "/out/response.tsv"),
                           "# grid 3 x 3 cell centres, each row swept along v"));
  ASSERT_EQ(t.rows.size(), 9u);
  for (const char* c : {"v", "kc", "class", "response", "m", "sticks", "lyapunov"})
    EXPECT_GE(t.Column(c), 0) << c;
  EXPECT_NEAR(std::stod(t.rows[0][0]), 0.1 + 0.4 / 6, 1e-15);  // cell centres, v fastest
  EXPECT_NEAR(std::stod(t.rows[3][1]), 0.1 + 0.9 / 2, 1e-15);
  EXPECT_TRUE(tu::Contains(tu::ReadFile(dir + "/out/chart.gp"), "'response.tsv' using 1:2"));
  EXPECT_TRUE(tu::Contains(r.out, "response grid 3 x 3"));
  // No grid: the curves only (cut short, status and exit 1, or done within the second).
  r = RunOut("ss_chart", dir,
             {"--study", study, "--seed_lines", "1", "--grid", "0", "--max_time", "1"});
  EXPECT_TRUE(r.outcome.code == 0 || r.outcome.code == 1) << r.err;
  EXPECT_TRUE(tu::Exists(dir + "/out/curves.tsv"));
  EXPECT_FALSE(tu::Exists(dir + "/out/response.tsv"));
  // Neither seed lines nor a grid: nothing to compute, refused by name.
  ExpectRejected("ss_chart", {"--study", study, "--seed_lines", "0", "--grid", "0"},
                 {"--seed_lines"});
  for (const char* side : {"1", "401", "-2"})
    ExpectRejected("ss_chart", {"--study", study, "--grid", side}, {"--grid", side});
}

TEST_F(SystemApp, BadSystemInputIsRefusedByName) {
  const std::vector<std::string> run = {"--param", "v", "--to", "0.4"};
  auto with = [&](std::vector<std::string> a) {
    a.insert(a.end(), run.begin(), run.end());
    return a;
  };
  ExpectRejected("ss_continue", with({"--system", "tower"}), {"--system", "tower"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--set", "kd=1"}),
                 {"--set", "'kd' is no parameter of chain", "kc"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--set", "kc"}),
                 {"--set", "NAME=VALUE"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--set", "kc=x"}), {"kc", "x"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--set", "kc=-1"}),
                 {"--set kc = -1", "must be >= 0"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--set", "kc=1,kc=2"}),
                 {"--set", "'kc' is set twice"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--set", "kc=1,"}), {"--set", "''"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--max_step", "1e-8"}),
                 {"--max_step", "1e-08"});
  ExpectRejected("ss_continue",
                 {"--system", "chain", "--param", "v", "--from", "0.3", "--to", "0.3000000001"},
                 {"--max_step", "smallest step"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--max_amplitude", "0"}),
                 {"--max_amplitude", "0"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--blocks", "0"}), {"--blocks", "0"});
  ExpectRejected("ss_continue", with({"--system", "mode_coupling", "--blocks", "3"}),
                 {"--blocks", "--system chain"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--mass", "1"}), {"--mass"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--force", "0.1"}), {"--force"});
  ExpectRejected("ss_continue", {"--system", "chain", "--param", "gamma", "--to", "1"},
                 {"--param", "'gamma' is no parameter of chain"});
  // A parameter the system does not depend on: one block has no coupling
  // (a flat branch in kc before).
  ExpectRejected("ss_continue",
                 {"--system", "chain", "--blocks", "1", "--param", "kc", "--to", "0.5"},
                 {"--param", "'kc' does not apply to a chain of one block"});
  // The same for either axis of a chart, before any run (a partial chart before).
  const std::vector<std::string> plane = {"--from",  "0.1", "--to",  "1",
                                          "--from2", "0.1", "--to2", "0.3"};
  for (const auto& [p1, p2, key] :
       {std::tuple{"kc", "v", "--param"}, std::tuple{"v", "kc", "--param2"}}) {
    std::vector<std::string> a = {"--system", "chain", "--blocks", "1",
                                  "--param",  p1,      "--param2", p2};
    a.insert(a.end(), plane.begin(), plane.end());
    ExpectRejected("ss_chart", a, {key, "'kc' does not apply to a chain of one block"});
  }
  ExpectRejected("ss_orbit_diagram",
                 {"--system", "chain", "--blocks", "1", "--param", "kc", "--from", "0.1", "--to",
                  "1", "--n", "2"},
                 {"--param", "'kc' does not apply to a chain of one block"});
  ExpectRejected("ss_continue", {"--system", "chain", "--param", "v"}, {"--to"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--start_at", "0.9"}),
                 {"--start_at", "0.9"});
  ExpectRejected("ss_continue", with({"--system", "chain", "--restart", "x"}), {"--restart"});
  ExpectRejected("ss_continue", {"--set", "kc=1"}, {"--set", "--system chain"});
  ExpectRejected("ss_continue", {"--start_at", "0.2"}, {"--start_at", "--system"});
  ExpectRejected("ss_chart", {"--system", "chain"}, {"--system", "ss_chart"});
  ExpectRejected("ss_orbit_diagram", {"--system", "mode_coupling"}, {"--from"});
  ExpectRejected("ss_orbit_diagram", {"--system", "chain", "--param", "q", "--from", "0.1"},
                 {"--param", "q", "kc"});
  ExpectRejected("ss_orbit_diagram", {"--system", "chain", "--from", "-0.1", "--to", "0.3"},
                 {"--from", "-0.1"});
  ExpectRejected("ss_basin", {"--system", "chain", "--slice", "x1,x9"}, {"--slice", "'x9'"});
  ExpectRejected("ss_basin", {"--system", "chain", "--slice", "x1',x1dot"}, {"--slice", "differ"});
  ExpectRejected("ss_basin", {"--system", "chain", "--slice", "x1"}, {"--slice", "two"});
  ExpectRejected("ss_basin", {"--system", "chain", "--t_cap", "5"}, {"--t_cap", "--system"});
  ExpectRejected("ss_basin", {"--system", "chain", "--force", "0.3"}, {"--force"});
  ExpectRejected("ss_basin", {"--transient", "5"}, {"--transient", "--force or --system"});
  ExpectRejected("ss_basin", {"--force", "0.3", "--set", "kc=1"}, {"--set", "--system chain"});
  ExpectRejected("ss_basin", {"--force", "0.3", "--blocks", "5"}, {"--blocks", "--system"});
  ExpectRejected("ss_orbit_diagram", {"--force", "0.3", "--set", "kc=1"},
                 {"--set", "--system chain"});
  ExpectRejected("ss_basin", {"--slice", "x,xdot", "--force", "0.3"}, {"--slice", "--system"});
  ExpectRejected("ss_simulate", {"--system", "chain", "--state", "1,2,3"}, {"--state", "4"});
  ExpectRejected("ss_simulate", {"--system", "chain", "--state", "1,2,x,4"}, {"--state", "x"});
  ExpectRejected("ss_simulate", {"--system", "chain", "--x0", "1"}, {"--x0", "--state"});
  ExpectRejected("ss_simulate", {"--state", "1,2"}, {"--state", "--system"});
  ExpectRejected("ss_simulate", {"--system", "chain", "--state", "1,2,3,4,5"}, {"--state", "4"});
  ExpectRejected("ss_simulate", {"--system", "chain", "--state", "1,2,3,4,"}, {"--state", "4"});
  ExpectRejected("ss_simulate", {"--system", "mode_coupling", "--state", "0.5,0,2,0"},
                 {"--state", "contact 0 is open"});
  ExpectRejected("ss_simulate", {"--system", "chain", "--section", "strobe"},
                 {"--section strobe", "autonomous"});
  ExpectRejected("ss_simulate", {"--system", "chain", "--section", "every"},
                 {"'every' for --section"});
  ExpectRejected("ss_simulate", {"--system", "chain", "--orbits"},
                 {"--orbits", "forced oscillator only", "--system chain"});
  // A [system] section without a system, and an unknown key in it.
  const std::string study = dir_ + "/bad.ini";
  tu::WriteFile(study, "law = cubic\n[system]\nkc = 1\n");
  ExpectRejected("ss_continue", {"--study", study}, {"bad.ini:3", "[system]"});
  tu::WriteFile(study, "system = chain\n[system]\nkq = 1\n[continue]\nparam = v\nto = 0.4\n");
  ExpectRejected("ss_continue", {"--study", study}, {"bad.ini:3", "'kq' is no parameter"});
}

// Runs that end early end cleanly: a midpoint of the steady-sliding bisection
// without a rest point ends it (step-too-small, exit 1; it was a segfault); a
// run with no stick-slip attractor writes steady sliding and a one-panel
// figure (exit 0; its script had an empty plot); exactly --max_rows rows fit.
TEST_F(SystemApp, RunsThatEndEarlyEndCleanly) {
  std::string dir = NewDir();
  auto r = RunOut("ss_continue", dir,
                  {"--system", "mode_coupling", "--law", "coulomb", "--mu_s", "0.8", "--mu_k",
                   "0.3", "--set", "gamma=0,k12=-0.5,k22=1", "--param", "k11", "--from", "0",
                   "--to", "1", "--max_step", "0.34"});
  EXPECT_EQ(r.outcome.code, 1) << r.err;
  EXPECT_TRUE(tu::Contains(r.err, "steady sliding step-too-small: no steady sliding at k11"));
  dir = NewDir();
  r = RunOut("ss_continue", dir,
             {"--study", STICKSLIP_SOURCE_DIR "/studies/mode_coupling.ini", "--set", "beta=0.5"},
             tu::HaveGnuplot());
  EXPECT_EQ(r.outcome.code, tu::HaveGnuplot() ? 0 : 3) << r.err;
  EXPECT_TRUE(tu::Contains(r.err, "note: no stick-slip orbit: no stick phase"));
  const tu::Tsv b = tu::ReadTsv(tu::ReadFile(dir + "/out/branch.tsv"));
  EXPECT_EQ(b.meta.at("status"), "complete");
  EXPECT_EQ(b.rows.size(), 21u);  // steady sliding only, stable throughout
  if (tu::HaveGnuplot()) {
    EXPECT_TRUE(tu::Exists(dir + "/out/bifurcation.png"));
  }
  dir = NewDir();
  r = RunOut("ss_simulate", dir,
             {"--system", "chain", "--max_rows", "101", "--t_end", "1", "--dt", "0.01"});
  EXPECT_EQ(r.outcome.code, 0) << r.err;
  EXPECT_EQ(tu::ReadTsv(tu::ReadFile(dir + "/out/trajectory.tsv")).rows.size(), 101u);
}

// ss_simulate --system chain --section exit: every section point is a stick
// exit, so some block moves with the belt (x_i' = v exactly) with its stick
// force on the static limit, |2 beta v + x_i + kc (x_i - x_j)| = mu_s (the
// chain's stick law, docs/systems.md), and that block's contact slips after.
TEST_F(SystemApp, ExitSectionLiesOnABlocksStickEdge) {
  const std::string dir = NewDir();
  const double beta = 0.05, v = 0.3, kc = 0.2, mu_s = 0.4;  // studies/chain2.ini
  const auto r = RunOut("ss_simulate", dir,
                        {"--study", STICKSLIP_SOURCE_DIR "/studies/chain2.ini", "--v", "0.3",
                         "--section", "exit", "--t_end", "200"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv sec = tu::ReadTsv(tu::ReadFile(dir + "/out/section.tsv"));
  EXPECT_EQ(sec.meta.at("section"), "exit");
  EXPECT_EQ(sec.meta.count("x0"), 0u);  // the start is the state, every component
  EXPECT_EQ(std::count(sec.meta.at("state").begin(), sec.meta.at("state").end(), ','), 3);
  ASSERT_GT(sec.rows.size(), 10u);
  for (size_t k = 0; k < sec.rows.size(); ++k) {
    const auto& row = sec.rows[k];
    EXPECT_EQ(std::stol(row[sec.Column("n")]), static_cast<long>(k));
    const double x[2] = {std::stod(row[sec.Column("x1")]), std::stod(row[sec.Column("x2")])};
    const double xd[2] = {std::stod(row[sec.Column("x1dot")]), std::stod(row[sec.Column("x2dot")])};
    const std::string mode = row[sec.Column("mode")];
    int on_edge = 0;
    for (int i = 0; i < 2; ++i) {
      const double f = 2 * beta * v + x[i] + kc * (x[i] - x[1 - i]);
      const std::string own = mode.substr(i ? mode.find(',') + 1 : 0, 5);
      if (xd[i] == v && std::abs(std::abs(f) - mu_s) < 1e-9 && own != "stick") ++on_edge;
    }
    EXPECT_GE(on_edge, 1) << "row " << k << ": " << mode;
  }
}

}  // namespace
