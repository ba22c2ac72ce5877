// ss_simulate --force A --omega W --orbits (issue 20, item 2: "every orbit at
// a parameter value is found from a scan"): on the forced Stribeck study at
// Omega = 0.612 (past its first period doubling) orbits.tsv lists the
// unstable m = 1 orbit and the stable m = 2 orbit; each row's stroboscopic
// point is mapped onto the next by the independent long-double map
// (reference/forced_lyapunov.hpp), and the m = 1 orbit's multiplier from that
// map's Jacobian is the one listed. Misuse: exit 2, one line, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include "app_test_util.hpp"
#include "reference/forced_lyapunov.hpp"
#include "test_paths.hpp"

namespace {

namespace tu = stickslip::testing_util;
const std::string kStudy = STICKSLIP_SOURCE_DIR "/studies/stribeck_forced.ini";

class ForcedOrbitsApp : public tu::AppTest {
 protected:
  int Run(const std::string& args) { return RunApp(kBin, "ss_simulate", args + " --no_plots"); }
};

TEST_F(ForcedOrbitsApp, ListsEveryOrbitAndEachClosesOnTheReferenceMap) {
  ASSERT_EQ(Run("--study " + kStudy + " --omega 0.612 --orbits --max_m 2 --out " + dir_ + "/o"), 0)
      << err_;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir_ + "/o/orbits.tsv"));
  ASSERT_EQ(t.rows.size(), 3u);  // m = 1 (one point) and m = 2 (two points)
  EXPECT_EQ(t.meta.at("status"), "complete");
  auto num = [&](size_t r, const std::string& c) { return std::stod(t.rows[r][t.Column(c)]); };
  stickslip::ForcedBeltParams p;
  p.base.law = stickslip::LawKind::kStribeck;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.v_s = 0.2, p.base.beta = 0.05, p.base.v = 0.25;
  p.force = 0.3, p.omega = 0.612;
  const stickslip::reference::ForcedRef m(p);
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const int mm = static_cast<int>(num(r, "m")), point = static_cast<int>(num(r, "point"));
    EXPECT_EQ(num(r, "stable"), mm == 2 ? 1 : 0);
    // The next point of the same orbit (cyclically).
    size_t next = r;
    for (size_t q = 0; q < t.rows.size(); ++q)
      if (num(q, "orbit") == num(r, "orbit") && num(q, "point") == point % mm + 1) next = q;
    const double x = num(r, "x"), y = num(r, "xdot");
    const auto per = stickslip::reference::RefOnePeriod(m, x, y, y == 0.25, 1e-16L);
    ASSERT_TRUE(per.ok);
    EXPECT_NEAR(double(per.x), num(next, "x"), 1e-9) << "row " << r;
    EXPECT_NEAR(double(per.y), num(next, "xdot"), 1e-9) << "row " << r;
    if (mm == 1) {  // the multiplier from the reference Jacobian
      const double tr = double(per.phi[0][0] + per.phi[1][1]);
      const double det = double(per.phi[0][0] * per.phi[1][1] - per.phi[0][1] * per.phi[1][0]);
      const std::complex<double> d = std::sqrt(std::complex<double>(tr * tr / 4 - det));
      const double mu = std::max(std::abs(tr / 2 + d), std::abs(tr / 2 - d));
      EXPECT_NEAR(num(r, "mult_max"), mu, 1e-8);
    }
  }
}

TEST_F(ForcedOrbitsApp, MisuseIsExitTwoWithOneLineNothingWritten) {
  const std::string out = " --out " + dir_ + "/bad";
  const std::string forced = "--law coulomb --mu_s 0.4 --mu_k 0.3 --v 0 --force 0.5 --omega 1.5";
  for (const std::string& args : {std::string("--orbits"), forced + " --orbits --max_m 0",
                                  forced + " --max_m 3", forced + " --orbits --max_m 2.5"}) {
    EXPECT_EQ(Run(args + out), 2) << args;
    EXPECT_TRUE(tu::Contains(err_, args.find("max_m") != std::string::npos ? "max_m" : "orbits"))
        << err_;
    EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
    EXPECT_FALSE(tu::Exists(dir_ + "/bad")) << args;
  }
}

}  // namespace
