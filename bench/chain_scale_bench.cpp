// chain_scale_bench: the chain's cost per unit simulated time against its
// number of blocks N (systems/chain: N seed blocks, v = 0.3, kc = 0.5, from
// steady sliding with x1 moved by 0.01, as ss_simulate --system chain starts).
// Each N runs T time units REPEATS times; prints the median CPU time per unit
// time, the switches per unit time, and the exponent p of cost ~ N^p between
// neighbouring N and fitted over all (least squares in log-log).
//   ./build/bench/chain_scale_bench [T [REPEATS]]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "chain/chain.hpp"
#include "stickslip/flow/flow.hpp"

namespace {
namespace ss = stickslip;

struct Sample {
  double cpu = 0;  // seconds of CPU per unit simulated time
  int switches = 0;
  bool ok = false;
};

Sample Run(int n, double t_end) {
  ss::Params p;  // the seed set
  p.v = 0.3;
  const ss::chain::Chain chain(ss::chain::Uniform(n, p, 0.5));
  const ss::ModeSet below;
  Eigen::VectorXd z(2 * n);
  bool stable = false;
  Sample s;
  if (!chain.Rest(below, z, &stable)) return s;
  z[0] += 0.01;
  ss::FlowRequest rq;
  rq.t_max = t_end;
  ss::Flow flow(chain, ss::FlowOptions{});
  const std::clock_t c0 = std::clock();
  const ss::FlowRun r = flow.Run(ss::FlowPoint{0, z, below}, rq);
  s.cpu = double(std::clock() - c0) / CLOCKS_PER_SEC / t_end;
  s.switches = r.switches, s.ok = r.ok();
  return s;
}
}  // namespace

int main(int argc, char** argv) {
  const double t_end = argc > 1 ? std::atof(argv[1]) : 2000;
  const int reps = argc > 2 ? std::atoi(argv[2]) : 3;
  if (!(t_end > 0) || reps < 1) {
    std::fprintf(stderr, "chain_scale_bench: usage: chain_scale_bench [T > 0 [REPEATS >= 1]]\n");
    return 2;
  }
  const std::vector<int> ns = {2, 5, 10, 20, 50, 100};
  std::vector<double> lx, ly;
  bool ok = true;
  for (int n : ns) {
    std::vector<double> cpu;
    Sample s;
    for (int k = 0; k < reps; ++k) cpu.push_back((s = Run(n, t_end)).cpu);
    ok = ok && s.ok;
    std::nth_element(cpu.begin(), cpu.begin() + reps / 2, cpu.end());
    const double med = cpu[reps / 2];
    std::printf("N %3d: %.3g ms CPU per unit time, %.2f switches per unit time%s", n, med * 1e3,
                s.switches / t_end, s.ok ? "" : " (run failed)");
    if (!lx.empty())
      std::printf(", exponent %.2f since N = %d",
                  (std::log(med) - ly.back()) / (std::log(n) - lx.back()), ns[lx.size() - 1]);
    std::printf("\n");
    lx.push_back(std::log(n)), ly.push_back(std::log(med));
  }
  const double mx = [&] {
    double a = 0;
    for (double x : lx) a += x;
    return a / lx.size();
  }();
  const double my = [&] {
    double a = 0;
    for (double y : ly) a += y;
    return a / ly.size();
  }();
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < lx.size(); ++i)
    sxy += (lx[i] - mx) * (ly[i] - my), sxx += (lx[i] - mx) * (lx[i] - mx);
  std::printf("fitted exponent over N = 2..100: %.2f\n", sxy / sxx);
  return ok ? 0 : 1;
}
