// model_file_bench: the seed belt as a model file (studies/models/belt.ini)
// against the built-in one-block chain (the same equations, hand-written
// recurrences): the time to read and prepare the file, one stick-slip orbit
// with its monodromy (the one shooting, stick-exit section), and the branch
// in v from 0.25 to 0.5 (ContinueOrbits). Runs alternate, five pairs; prints
// the medians and their ratio (docs/model_files.md, "Speed").
//   ./build/bench/model_file_bench [ORBITS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
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

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 2000;
  if (n < 1) {
    std::fprintf(stderr, "model_file_bench: usage: model_file_bench [ORBITS >= 1]\n");
    return 2;
  }
  const std::string models = STICKSLIP_SOURCE_DIR "/studies/models/";
  std::vector<double> read_belt, read_brake, orbit_file, orbit_built, branch_file, branch_built;
  std::unique_ptr<ss::System> file;
  const ss::chain::Chain built(ss::chain::Uniform(1, ss::Params(), 0));
  std::size_t rows_file = 0, rows_built = 0;
  for (int pair = 0; pair < 5; ++pair) {
    read_belt.push_back(Seconds([&] { file = ss::model_file::ReadModel(models + "belt.ini"); }));
    read_brake.push_back(Seconds([&] { ss::model_file::ReadModel(models + "mode_coupling.ini"); }));
    orbit_file.push_back(Orbits(*file, n));
    orbit_built.push_back(Orbits(built, n));
    branch_file.push_back(Branch(*file, &rows_file));
    branch_built.push_back(Branch(built, &rows_built));
  }
  std::printf("model_file_bench: medians of 5 interleaved runs\n");
  std::printf("  read and prepare belt.ini           %8.2f ms\n", Median(read_belt) * 1e3);
  std::printf("  read and prepare mode_coupling.ini  %8.2f ms\n", Median(read_brake) * 1e3);
  std::printf("  one orbit: model file %7.2f us, built-in %7.2f us, ratio %.2f\n",
              Median(orbit_file) * 1e6, Median(orbit_built) * 1e6,
              Median(orbit_file) / Median(orbit_built));
  std::printf("  branch (%zu / %zu rows): model file %7.2f ms, built-in %7.2f ms, ratio %.2f\n",
              rows_file, rows_built, Median(branch_file) * 1e3, Median(branch_built) * 1e3,
              Median(branch_file) / Median(branch_built));
  return rows_file == rows_built ? 0 : 1;
}
