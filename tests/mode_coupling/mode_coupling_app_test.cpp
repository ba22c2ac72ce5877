// ss_continue --study mode_coupling (studies/mode_coupling.ini; docs/systems.md): the
// mode-coupling brake model through the app. Steady sliding's HB against the
// closed form mu_k* (mode_coupling.hpp); every stick-slip row of branch.tsv
// against an independent integrator: Boost.Odeint's Dormand-Prince at 1e-13
// runs the slip phase from the row's stick exit to the stick entry and the
// stick phase (x' = v, y on its own linear field) to the next exit, and must
// come back to the row's state after the row's period; the LP row's largest
// multiplier is +1 and the CL row's normal force 1 - gamma y reaches 0.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "app_test_util.hpp"
#include "mode_coupling/mode_coupling.hpp"

namespace {

namespace tu = stickslip::testing_util;
namespace ode = boost::numeric::odeint;
using State = std::array<double, 4>;
class ModeCouplingApp : public tu::AppTest {};

const std::string kStudy = STICKSLIP_SOURCE_DIR "/studies/mode_coupling.ini";
// The study's set (studies/mode_coupling.ini).
constexpr double kBeta = 0.02, kK11 = 1, kK22 = 1.5, kK12 = -0.3, kGamma = 1, kV = 0.5, kMuS = 0.8;

// Slip below the belt (x' < v) under Coulomb friction mu_k, or stick (x' = v).
struct Field {
  double mu_k;
  bool stick;
  void operator()(const State& z, State& f, double) const {
    f[0] = stick ? kV : z[1];
    f[1] = stick ? 0 : -2 * kBeta * z[1] - kK11 * z[0] - kK12 * z[2] + (1 - kGamma * z[2]) * mu_k;
    f[2] = z[3];
    f[3] = -2 * kBeta * z[3] - kK12 * z[0] - kK22 * z[2];
  }
};

// The phase's end: a root of g on the dense output, bisected to 1e-14 in t.
template <typename G>
double RunUntil(State& z, const Field& f, const G& g, double t_max) {
  auto stepper = ode::make_dense_output(1e-13, 1e-13, ode::runge_kutta_dopri5<State>());
  stepper.initialize(z, 0, 1e-3);
  double before = 0;
  bool armed = false;  // g leaves 0 at the start: a root only after it moved off
  while (stepper.current_time() < t_max) {
    stepper.do_step(f);
    const double now = g(stepper.current_state());
    if (armed && (now >= 0) != (before >= 0)) {
      double lo = stepper.previous_time(), hi = stepper.current_time();
      State mid;
      while (hi - lo > 1e-14) {
        stepper.calc_state(0.5 * (lo + hi), mid);
        ((g(mid) >= 0) == (before >= 0) ? lo : hi) = 0.5 * (lo + hi);
      }
      stepper.calc_state(hi, z);
      return hi;
    }
    armed = armed || std::abs(now) > 1e-9;
    before = now;
  }
  return NAN;
}

TEST_F(ModeCouplingApp, BrakeStudyAgreesWithTheClosedFormAndAnIndependentIntegrator) {
  const auto r = RunOut("ss_continue", dir_, {"--study", kStudy});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv branch = tu::ReadTsv(tu::ReadFile(dir_ + "/out/branch.tsv"));
  const tu::Tsv special = tu::ReadTsv(tu::ReadFile(dir_ + "/out/special_points.tsv"));
  EXPECT_EQ(branch.meta.at("status"), "complete");
  auto at = [](const tu::Tsv& t, const std::vector<std::string>& row, const char* c) {
    return std::stod(row[t.Column(c)]);
  };
  std::vector<std::string> labels;
  for (const auto& row : special.rows) {
    labels.push_back(row[special.Column("lab")]);
    const double mu = at(special, row, "mu_k");
    if (row[0] == "HB") {  // (0.25 + 0.36 + 8 0.02^2 2.5) / 1.2 = 0.515
      stickslip::mode_coupling::CouplingParams p;
      EXPECT_NEAR(mu, stickslip::mode_coupling::FlutterMuK(p), 1e-13);
      EXPECT_NEAR(mu, 0.515, 1e-13);
    }
    if (row[0] == "LP") {
      EXPECT_NEAR(at(special, row, "mult_max"), 1, 1e-8) << mu;
    }
    if (row[0] == "CL") {
      EXPECT_NEAR(1 - kGamma * at(special, row, "y_max"), 0, 1e-9) << mu;
    }
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"HB1", "LP1", "CL1"}));
  int checked = 0;
  for (const auto& row : branch.rows) {
    if (row[branch.Column("kind")] != "stick-slip") continue;
    const double mu = at(branch, row, "mu_k");
    const State z0 = {at(branch, row, "x_0"), at(branch, row, "xdot_0"), at(branch, row, "y_0"),
                      at(branch, row, "ydot_0")};
    State z = z0;
    const double slip = RunUntil(
        z, Field{mu, false}, [](const State& s) { return s[1] - kV; }, 50);
    ASSERT_TRUE(std::isfinite(slip)) << mu;
    z[1] = kV;
    const double stick = RunUntil(
        z, Field{mu, true},
        [](const State& s) {
          return 2 * kBeta * kV + kK11 * s[0] + kK12 * s[2] - kMuS * (1 - kGamma * s[2]);
        },
        50);
    ASSERT_TRUE(std::isfinite(stick)) << mu;
    EXPECT_NEAR(slip + stick, at(branch, row, "period"), 1e-9) << mu;
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(z[i], z0[i], 1e-9) << mu << " component " << i;
    ++checked;
  }
  EXPECT_GT(checked, 40);
}

// ss_simulate --system mode_coupling above the flutter threshold (mu_k 0.6):
// while the contact slips below under Coulomb friction the field is linear,
// z' = A z + b, so every row before the first stick is the closed form
// z* + exp(A t) (z0 - z*), z* = -A^-1 b steady sliding (also the default start,
// moved by 0.01 in x).
TEST_F(ModeCouplingApp, SimulationSlipsAsTheMatrixExponentialUntilItSticks) {
  const double mu_k = 0.6;
  const auto r =
      RunOut("ss_simulate", dir_,
             {"--system", "mode_coupling", "--law", "coulomb", "--mu_s", "0.8", "--mu_k", "0.6",
              "--t_end", "80", "--dt", "0.25", "--rtol", "1e-12", "--atol", "1e-12"});
  ASSERT_EQ(r.outcome.code, 0) << r.err;
  const tu::Tsv t = tu::ReadTsv(tu::ReadFile(dir_ + "/out/trajectory.tsv"));
  Eigen::Matrix4d a;
  a << 0, 1, 0, 0, -kK11, -2 * kBeta, -kK12 - kGamma * mu_k, 0, 0, 0, 0, 1, -kK12, 0, -kK22,
      -2 * kBeta;
  const Eigen::Vector4d b(0, mu_k, 0, 0);
  const Eigen::Vector4d rest = -a.inverse() * b;
  const Eigen::Vector4d z0 = rest + Eigen::Vector4d(0.01, 0, 0, 0);
  int checked = 0;
  for (const auto& row : t.rows) {
    if (row[t.Column("mode")] != "slip-below") break;
    const double time = std::stod(row[0]);
    const Eigen::Vector4d exact = rest + (a * time).exp() * (z0 - rest);
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(std::stod(row[1 + i]), exact[i], 1e-10 * (1 + std::abs(exact[i])))
          << "t = " << time << " component " << i;
    ++checked;
  }
  EXPECT_GT(checked, 250);                              // slip until the first stick at t = 72.32
  EXPECT_LT(checked, static_cast<int>(t.rows.size()));  // then it sticks
}

}  // namespace
