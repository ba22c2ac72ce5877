// model_file_bench: the seed belt as a model file (studies/models/belt.ini)
// against the built-in one-block chain (the same equations, hand-written
// recurrences): the time to read and prepare the file (and chain2.ini, the
// drill string and a chain of four blocks: 81 modes), one stick-slip orbit
// with its monodromy (the one shooting, stick-exit section), and the branch
// in v from 0.25 to 0.5 (ContinueOrbits). Runs alternate, five pairs; prints
// the medians and their ratio (docs/model_files.md, "Speed").
//   ./build/bench/model_file_bench [ORBITS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "chain/chain.hpp"
#include "model_file/model_file.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace {
namespace ss = stickslip;

double Seconds(const std::function<void()>& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// One orbit's time (s), over n shots.
double Orbits(const ss::System& s, long n) {
  ss::ShootingOptions so;
  ss::Shooting shooting(s, so);
  const ss::Params p;
  const ss::FlowPoint start{0, Eigen::Vector2d(p.mu_s - 2 * p.beta * p.v, p.v),
                            ss::ModeSet(ss::Mode::kSlipBelow)};
  bool ok = true;
  const double t = Seconds([&] {
    for (long i = 0; i < n; ++i)
      ok = ok && shooting.Find(start, ss::PoincareSection::StickExit(0)).ok();
  });
  if (!ok) std::fprintf(stderr, "model_file_bench: an orbit failed\n");
  return t / n;
}

double Branch(const ss::System& s, std::size_t* rows) {
  const ss::Params p;
  const ss::FlowPoint start{0, Eigen::Vector2d(p.mu_s - 2 * p.beta * p.v, p.v),
                            ss::ModeSet(ss::Mode::kSlipBelow)};
  return Seconds([&] {
    *rows = ss::ContinueOrbits(s, s.ParameterIndex("v"), start, ss::PoincareSection::StickExit(0),
                               0.5, ss::OrbitBranchOptions())
                .rows.size();
  });
}

// Four seed blocks in a row, each with its contact: 3^4 modes.
std::string FourBlocks() {
  std::string t =
      "name = chain4\ncoordinates = x1, x2, x3, x4\nparameter v = 0.25\n"
      "parameter kc = 0.5\nparameter beta = 0.05\nparameter mu_s = 0.4\n"
      "parameter mu_m = 0.25\nparameter v_m = 0.5\n";
  for (int i = 1; i <= 4; ++i) {
    const std::string x = "x" + std::to_string(i);
    t += x + "'' = -2*beta*" + x + "' - " + x;
    for (int j : {i - 1, i + 1})
      if (j >= 1 && j <= 4) t += " - kc*(" + x + " - x" + std::to_string(j) + ")";
    t += " + F" + std::to_string(i) + "\n";
  }
  for (int i = 1; i <= 4; ++i) {
    const std::string f = "F" + std::to_string(i);
    t += "contact " + f + " = x" + std::to_string(i) + "' - v\nlaw " + f +
         " = mu_s - 3*(mu_s - mu_m)/(2*v_m)*s + (mu_s - mu_m)/(2*v_m^3)*s^3\n";
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 2000;
  if (n < 1) {
    std::fprintf(stderr, "model_file_bench: usage: model_file_bench [ORBITS >= 1]\n");
    return 2;
  }
  const std::string models = STICKSLIP_SOURCE_DIR "/studies/models/";
  std::vector<double> read_belt, read_brake, orbit_file, orbit_built, branch_file, branch_built;
  std::vector<double> read_chain2, read_drill, read_chain4;
  const std::string four = FourBlocks();
  std::unique_ptr<ss::System> file;
  const ss::chain::Chain built(ss::chain::Uniform(1, ss::Params(), 0));
  std::size_t rows_file = 0, rows_built = 0;
  for (int pair = 0; pair < 5; ++pair) {
    read_belt.push_back(Seconds([&] { file = ss::model_file::ReadModel(models + "belt.ini"); }));
    read_brake.push_back(Seconds([&] { ss::model_file::ReadModel(models + "mode_coupling.ini"); }));
    read_chain2.push_back(Seconds([&] { ss::model_file::ReadModel(models + "chain2.ini"); }));
    read_drill.push_back(Seconds([&] { ss::model_file::ReadModel(models + "drill_string.ini"); }));
    read_chain4.push_back(Seconds([&] { ss::model_file::ParseModel(four, "chain4.ini"); }));
    orbit_file.push_back(Orbits(*file, n));
    orbit_built.push_back(Orbits(built, n));
    branch_file.push_back(Branch(*file, &rows_file));
    branch_built.push_back(Branch(built, &rows_built));
  }
  std::printf("model_file_bench: medians of 5 interleaved runs\n");
  std::printf("  read and prepare belt.ini           %8.2f ms\n", Median(read_belt) * 1e3);
  std::printf("  read and prepare mode_coupling.ini  %8.2f ms\n", Median(read_brake) * 1e3);
  std::printf("  read and prepare chain2.ini         %8.2f ms\n", Median(read_chain2) * 1e3);
  std::printf("  read and prepare drill_string.ini   %8.2f ms\n", Median(read_drill) * 1e3);
  std::printf("  read and prepare a 4-block chain    %8.2f ms\n", Median(read_chain4) * 1e3);
  std::printf("  one orbit: model file %7.2f us, built-in %7.2f us, ratio %.2f\n",
              Median(orbit_file) * 1e6, Median(orbit_built) * 1e6,
              Median(orbit_file) / Median(orbit_built));
  std::printf("  branch (%zu / %zu rows): model file %7.2f ms, built-in %7.2f ms, ratio %.2f\n",
              rows_file, rows_built, Median(branch_file) * 1e3, Median(branch_built) * 1e3,
              Median(branch_file) / Median(branch_built));
  return rows_file == rows_built ? 0 : 1;
}
