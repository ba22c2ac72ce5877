// Model files (systems/model_file; docs/model_files.md) against the built-in
// systems they write down again, and the file's checks. The built-in systems'
// fields and recurrences are hand-written (systems/chain, mode_coupling); the
// model file's come from GiNaC's parse and derivatives and the tape: two ways.
#include "model_file/model_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "chain/chain.hpp"
#include "mode_coupling/mode_coupling.hpp"
#include "stickslip/chaos/orbit_diagram.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::model_file {
namespace {

const std::string kModels = STICKSLIP_SOURCE_DIR "/studies/models/";

struct Row {
  double t;
  Eigen::VectorXd z;
  std::string mode;
};

std::vector<Row> Rows(const System& s, const Eigen::VectorXd& z0, double t_end) {
  SimulationOptions o;
  o.t_end = t_end, o.dt = 0.1;
  o.flow.rtol = o.flow.atol = 1e-12;
  std::vector<Row> rows;
  SimulationSink sink;
  sink.row = [&](double t, const double* z, const ModeSet& m) {
    rows.push_back(
        {t, Eigen::Map<const Eigen::VectorXd>(z, s.dimension()), ModeSetName(m, s.contacts())});
  };
  const Simulation r = Simulate(s, FlowPoint{0, z0, ModeOf(s, z0)}, o, sink);
  EXPECT_TRUE(r.ok()) << r.message;
  return rows;
}

// Every row of both runs: the same times and modes, states within tol.
void ExpectSameRows(const System& a, const System& b, const Eigen::VectorXd& z0, double t_end,
                    double tol) {
  const std::vector<Row> ra = Rows(a, z0, t_end), rb = Rows(b, z0, t_end);
  ASSERT_EQ(ra.size(), rb.size());
  double worst = 0;
  for (std::size_t i = 0; i < ra.size(); ++i) {
    ASSERT_EQ(ra[i].mode, rb[i].mode) << "row " << i << " t = " << ra[i].t;
    EXPECT_NEAR(ra[i].t, rb[i].t, tol);
    worst = std::max(worst, (ra[i].z - rb[i].z).lpNorm<Eigen::Infinity>());
  }
  EXPECT_LE(worst, tol) << ra.size() << " rows";
  int stuck = 0;
  for (const Row& r : ra) stuck += r.mode.find("stick") != std::string::npos;
  EXPECT_GT(stuck, 10) << "the run never sticks";
}

TEST(ModelFile, TheBeltFileRunsAsTheOneBlockChain) {
  const std::unique_ptr<System> file = ReadModel(kModels + "belt.ini");
  ASSERT_EQ(file->dimension(), 2);
  EXPECT_EQ(file->StateName(1), "x'");
  EXPECT_EQ(ModelName(*file), "belt");
  Params p;  // the seed set: cubic, beta 0.05, v 0.25, mu_s 0.4, mu_m 0.25, v_m 0.5
  const chain::Chain built(chain::Uniform(1, p, 0));
  ExpectSameRows(*file, built, Eigen::Vector2d(0.1, 0.0), 200, 1e-13);
}

TEST(ModelFile, TheBrakeFileRunsAsTheBuiltInBrake) {
  // Above the flutter threshold (mu_k* = 0.515): the oscillation grows and sticks.
  const std::unique_ptr<System> file = ReadModel(kModels + "mode_coupling.ini");
  file->SetParameterValue(file->ParameterIndex("mu_s"), 0.8);
  file->SetParameterValue(file->ParameterIndex("mu_k"), 0.6);
  mode_coupling::CouplingParams p;
  p.law.law = LawKind::kCoulomb;
  p.law.mu_s = 0.8, p.law.mu_k = 0.6;
  const mode_coupling::ModeCoupling built(p);
  ASSERT_EQ(file->parameters(), 8);
  Eigen::VectorXd z0(4);
  z0 << 0.6, 0.0, 0.05, 0.0;
  ExpectSameRows(*file, built, z0, 100, 1e-13);
}

TEST(ModelFile, ShootingFindsTheSameOrbitWithTheSameMultipliers) {
  const std::unique_ptr<System> file = ReadModel(kModels + "belt.ini");
  const chain::Chain built(chain::Uniform(1, Params(), 0));
  ShootingOptions o;
  o.flow.rtol = o.flow.atol = 1e-12;
  const FlowPoint exit{0, Eigen::Vector2d(0.4 - 2 * 0.05 * 0.25, 0.25), ModeSet(Mode::kSlipBelow)};
  const PeriodicOrbit a = Shooting(*file, o).Find(exit, PoincareSection::StickExit(0));
  const PeriodicOrbit b = Shooting(built, o).Find(exit, PoincareSection::StickExit(0));
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_TRUE(b.ok()) << b.message;
  EXPECT_NEAR(a.period, b.period, 1e-11);
  EXPECT_NEAR(a.hi[0], b.hi[0], 1e-11);
  EXPECT_EQ(a.sticks, b.sticks);
}

// The forced belt (a clock theta' = omega in the file) against ForcedBelt:
// the seed_forced study's trajectory from (0, v, 0), and its stroboscopic
// period-1 orbit at Omega = 0.8 with its multipliers.
TEST(ModelFile, TheForcedFileRunsAsTheBuiltInForcedOscillator) {
  const std::unique_ptr<System> file = ReadModel(kModels + "forced.ini");
  ASSERT_EQ(file->clocks(), 1);
  EXPECT_EQ(file->StateName(2), "theta");
  ForcedBeltParams p;  // the seed set, A = 0.3, Omega = 0.6
  p.force = 0.3, p.omega = 0.6;
  const ForcedBelt built(p);
  ExpectSameRows(*file, built, Eigen::Vector3d(0, 0.25, 0), 300, 1e-11);
  file->SetParameterValue(file->ParameterIndex("omega"), 0.8);
  p.omega = 0.8;
  const ForcedBelt at(p);
  ShootingOptions o;
  o.flow.rtol = o.flow.atol = 1e-12;
  const FlowPoint guess{0, Eigen::Vector3d(0.6, 0.1, 0), ModeSet()};
  const PeriodicOrbit a =
      Shooting(*file, o).Find(guess, PoincareSection::Stroboscopic(*file, guess.z, 1));
  const PeriodicOrbit b =
      Shooting(at, o).Find(guess, PoincareSection::Stroboscopic(at, guess.z, 1));
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_TRUE(b.ok()) << b.message;
  EXPECT_NEAR(a.start.z[0], b.start.z[0], 1e-12);  // equal, measured
  EXPECT_NEAR(a.start.z[1], b.start.z[1], 1e-12);
  ASSERT_EQ(a.multipliers.size(), b.multipliers.size());
  for (std::size_t i = 0; i < a.multipliers.size(); ++i)  // 6.7e-16 measured
    EXPECT_NEAR(std::abs(a.multipliers[i] - b.multipliers[i]), 0, 1e-12) << i;
}

// A contact velocity of two terms (x' + y' - 0.1): after a crossing the
// projection onto h = 0 left h at rounding on the old side, and the arrival
// fired again at every step start (9.5 million rows of one ulp at t = 11.59).
// Taylor and CVODE now cross it alike.
TEST(ModelFile, ATwoTermContactIsCrossedOnce) {
  const std::unique_ptr<System> s = ParseModel(
      "coordinates = x, y\nparameter beta = 0.05\nparameter v = 0.25\n"
      "x'' = -2*beta*x' - x + F + G\ny'' = -y\ncontact F = x' - v\n"
      "law F = 0.3 + 0.1*exp(-s)\ncontact G = x' + y' - 0.1\nlaw G = 0.05\n",
      "two_terms.ini");
  auto run = [&](Integrator integrator, long* rows) {
    SimulationOptions o;
    o.t_end = 50, o.dt = 0.01, o.max_rows = 100000;
    o.flow.integrator = integrator;
    o.flow.rtol = 1e-12, o.flow.atol = 1e-14;
    SimulationSink sink;
    sink.row = [](double, const double*, const ModeSet&) {};
    const Eigen::Vector4d z0(0, 0, 0.5, 0);
    const Simulation r = Simulate(*s, FlowPoint{0, z0, ModeOf(*s, z0)}, o, sink);
    EXPECT_TRUE(r.ok()) << r.message;
    *rows = r.rows;
    EXPECT_EQ(r.crossings, 16);
    return r.end.z;
  };
  long taylor_rows = 0, cvode_rows = 0;
  const Eigen::VectorXd a = run(Integrator::kTaylor, &taylor_rows);
  const Eigen::VectorXd b = run(Integrator::kCvode, &cvode_rows);
  EXPECT_LT(taylor_rows, 5100);
  EXPECT_LT((a - b).lpNorm<Eigen::Infinity>(), 1e-9);  // 1.4e-11 measured
}

}  // namespace
}  // namespace stickslip::model_file

namespace stickslip::model_file {
namespace {

// Malformed files are refused, never a crash or a hang: 3000 mutations of
// the two shipped files (a character deleted, inserted or replaced, a line
// doubled or dropped), each read in full; a refusal is InvalidArgument
// naming the file first.
TEST(ModelFile, MutatedFilesAreReadOrRefusedByName) {
  const std::string alphabet = "xyFsv()*+-/^'=,.#0123456789 \n";
  std::mt19937 rng(20261130);
  int read = 0, refused = 0;
  for (const std::string name : {"belt.ini", "mode_coupling.ini"}) {
    std::ifstream in(kModels + name);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (int round = 0; round < 1500; ++round) {
      std::string t = text;
      const std::size_t at = rng() % t.size();
      const char c = alphabet[rng() % alphabet.size()];
      switch (rng() % 5) {
        case 0:
          t.erase(at, 1);
          break;
        case 1:
          t.insert(at, 1, c);
          break;
        case 2:
          t[at] = c;
          break;
        case 3: {  // the line at `at`, twice
          const std::size_t a = t.rfind('\n', at) + 1, b = t.find('\n', at);
          t.insert(a, t.substr(a, b - a + 1));
          break;
        }
        default: {  // the line at `at`, dropped
          const std::size_t a = t.rfind('\n', at) + 1, b = t.find('\n', at);
          t.erase(a, b == std::string::npos ? std::string::npos : b - a + 1);
        }
      }
      try {
        const std::unique_ptr<System> s = ParseModel(t, "mutant.ini");
        EXPECT_GE(s->dimension(), 2);
        ++read;
      } catch (const InvalidArgument& e) {
        EXPECT_EQ(std::string(e.what()).rfind("mutant.ini", 0), 0u) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 500);
  EXPECT_GT(read, 500);  // a comment or a number changed: still a model
}

// A parameter no expression reads is no axis: ParameterError names it; one
// that a law, a contact, a clock or a static line reads is; one that GiNaC's
// own simplification cancels (k x - k x) is read by none.
TEST(ModelFile, AParameterNoExpressionReadsIsRefusedAsAnAxis) {
  const std::string head =
      "coordinates = x\nparameter v = 0.25\nparameter mu = 0.4\nparameter k = 2\n"
      "parameter w = 1.3\nparameter ms = 0.5\nparameter unused = 7\n";
  const std::unique_ptr<System> s =
      ParseModel(head +
                     "clock th = w\nx'' = -x + k*x - k*x + F + 0.1*cos(th)\ncontact F = x' - v\n"
                     "law F = mu\nstatic F = ms\n",
                 "axes.ini");
  for (const char* used : {"v", "mu", "w", "ms"})
    EXPECT_EQ(s->ParameterError(s->ParameterIndex(used)), "") << used;
  for (const char* unread : {"k", "unused"}) {
    const std::string e = s->ParameterError(s->ParameterIndex(unread));
    EXPECT_NE(
        e.find(std::string("parameter '") + unread + "' appears in no expression of axes.ini"),
        std::string::npos)
        << e;
  }
  // A chart's axis too (SystemPlane; ChartSystem refuses it before any run).
  SystemChartOptions o;
  o.plane = {s->ParameterIndex("v"), s->ParameterIndex("k"), 0.1, 0.3, 1, 3};
  EXPECT_NE(o.ValidationError(*s).find("parameter 'k' appears in no expression of axes.ini"),
            std::string::npos)
      << o.ValidationError(*s);
  EXPECT_THROW(ChartSystem(*s, o), InvalidArgument);
  o.plane.p2 = s->ParameterIndex("mu");
  EXPECT_EQ(o.plane.ValidationError(*s), "");
  // And an orbit diagram's (every column the same).
  OrbitDiagramOptions d;
  d.from = 1, d.to = 3, d.n = 2;
  EXPECT_THROW(ComputeOrbitDiagram(*s, s->ParameterIndex("k"), d), InvalidArgument);
}

}  // namespace
}  // namespace stickslip::model_file
