// forced_bench: the forced oscillator's costs (issue 20): one stick-slip orbit
// (one exit-map return, and the whole Newton solve), one non-stop orbit, and the
// Den Hartog resonance run; each as the median of repeated runs in one process,
// with the error against the coulomb closed form (tests/forced_reference.hpp).
// Times are thread CPU time.
//   build/bench/forced_bench
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <vector>

#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/orbits/forced_orbit.hpp"
#include "tests/forced_reference.hpp"

namespace {

using namespace stickslip;

// Median thread CPU time in microseconds (robust to other load on a shared machine).
double CpuMicros() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e6 + ts.tv_nsec * 1e-3;
}
double MedianMicros(const std::function<void()>& f, int reps) {
  std::vector<double> t;
  for (int i = 0; i < reps; ++i) {
    const double a = CpuMicros();
    f();
    t.push_back(CpuMicros() - a);
  }
  std::nth_element(t.begin(), t.begin() + reps / 2, t.end());
  return t[reps / 2];
}

ForcedBeltParams Belt() {  // the exit-map test's coulomb belt, one stick per period
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = 0.4, p.base.mu_k = 0.25, p.base.beta = 0.05, p.base.v = 0.2;
  p.force = 0.3, p.omega = 0.8;
  return p;
}

ForcedBeltParams DenHartog(double w) {
  ForcedBeltParams p;
  p.base.law = LawKind::kCoulomb;
  p.base.mu_s = p.base.mu_k = 0.3, p.base.beta = 0, p.base.v = 0;
  p.force = 1, p.omega = w;
  return p;
}

void StickSlipOrbit(double rtol) {
  const ForcedBeltParams p = Belt();
  const ForcedBelt m(p);
  ShootingOptions o(ForcedBelt::FlowDefaults());
  o.flow.rtol = o.flow.atol = rtol;
  const PeriodicOrbit exact = ExitPhaseOrbit(m, 1.9, Mode::kSlipBelow, 1, 1, o);
  const double t_exit = exact.start.t, x_exit = exact.start.z[0];
  FlowRequest rq;
  rq.t_max = t_exit + 3 * m.period();
  rq.variational = true;
  rq.stop_at_exit = 1;
  rq.extrema = {0, 1};
  Flow flow(m, o.flow);
  const FlowPoint start = ForcedStart(m, t_exit, x_exit, p.base.v, Mode::kSlipBelow);
  FlowRun run;
  const double t_return = MedianMicros([&] { flow.Run(start, rq, &run); }, 2001);
  const double t_solve =
      MedianMicros([&] { ExitPhaseOrbit(m, t_exit + 1e-3, Mode::kSlipBelow, 1, 1, o); }, 501);
  // The closed form's return time from the same exit.
  namespace ref = forced_reference;
  ref::PieceSim<ref::CoulombPiece> sim(
      ref::Setup{reference::Law(p.base), p.base.beta, p.base.v, p.force, p.omega});
  ref::Real t = t_exit, x = x_exit, y = p.base.v;
  sim.Run(t, x, y, t_exit + 3 * m.period(), 1);
  ref::Real back = -1;
  for (const auto& e : sim.events)
    if (e.kind == 1) {
      back = e.t;
      break;
    }
  std::printf(
      "stick-slip orbit (coulomb belt, A 0.3, Omega 0.8), rtol %.0e: %ld steps; one "
      "return %.2f us, Newton solve from 1e-3 off %.2f us; period error %.1e; exit t_e %.17g "
      "x_e %.17g\n",
      rtol, run.steps, t_return, t_solve, std::abs(static_cast<double>(back) - run.end.t), t_exit,
      x_exit);
}

void NonStopOrbit(double rtol) {
  const ForcedBelt m(DenHartog(1.3));
  ShootingOptions o(ForcedBelt::FlowDefaults());
  o.flow.rtol = o.flow.atol = rtol;
  const PeriodicOrbit exact = ShootStroboscopic(m, -1.4, 0.01, 1, o);
  const double x0 = exact.start.z[0], xdot0 = exact.start.z[1];
  FlowRequest rq;
  rq.t_max = m.period();
  rq.variational = true;
  rq.extrema = {0, 1};
  Flow flow(m, o.flow);
  FlowRun run;
  const FlowPoint start = ForcedStart(m, 0, x0, xdot0);
  const double t_map = MedianMicros([&] { flow.Run(start, rq, &run); }, 2001);
  const double t_solve = MedianMicros([&] { ShootStroboscopic(m, x0 + 1e-3, xdot0, 1, o); }, 501);
  const double V = 1 / (1 - 1.69), U = std::sin(M_PI / 1.3) / (1.3 * (1 + std::cos(M_PI / 1.3)));
  std::printf(
      "non-stop orbit (Den Hartog, Omega 1.3), rtol %.0e: %ld steps; one period %.2f us, "
      "Newton solve from 1e-3 off %.2f us; x_max error %.1e\n",
      rtol, exact.steps, t_map, t_solve,
      std::abs(OrbitExtrema(exact).x_max - std::sqrt(V * V - 0.09 * U * U)));
}

// The m = 1 branch in Omega from `from` to `to` through the Den Hartog guess
// (x, x') = (1 / (1 - Omega^2), 0.01) at theta = 0: the one driver on the
// stroboscopic section, as ss_continue --force runs it.
OrbitBranch DenHartogBranch(double from, double to, const OrbitBranchOptions& o) {
  const ForcedBelt m(DenHartog(from));
  const FlowPoint guess{0, Eigen::Vector3d(1 / (1 - from * from), 0.01, 0),
                        ModeSet(Mode::kSlipBelow)};
  return ContinueOrbits(m, ParameterAxis(Parameter::kOmega).index(), guess,
                        PoincareSection::Stroboscopic(m, guess.z, 1), to, o);
}

void DenHartogRun() {
  OrbitBranchOptions o(ForcedBelt::FlowDefaults());
  o.shooting.flow.rtol = o.shooting.flow.atol = 1e-12;
  o.max_amplitude = 10;
  o.palc.ds_max = 0.05;
  size_t rows = 0;
  const double t = MedianMicros(
      [&] {
        rows = 0;
        for (const double from : {0.75, 2.5}) {
          const double to = from == 0.75 ? 2.5 : 0.75;
          rows += DenHartogBranch(from, to, o).rows.size();
        }
      },
      11);
  std::printf(
      "Den Hartog run (Omega 0.75 -> 2.5, both ends, rtol 1e-12): %zu rows in %.2f ms "
      "(%.1f us per row)\n",
      rows, t / 1e3, t / rows);
}

// The resonance curve as bench/peers/scipy_forced.py sweeps it: 500 values of
// Omega in [1.2, 2.5], each orbit by stroboscopic Newton from the previous one.
void ResonanceSweep() {
  ShootingOptions o(ForcedBelt::FlowDefaults());
  o.flow.rtol = o.flow.atol = 1e-12;
  double worst = 0;
  const double t = MedianMicros(
      [&] {
        double x = -1.4, xd = 0.01;
        worst = 0;
        for (int i = 0; i < 500; ++i) {
          const double w = 1.2 + 1.3 * i / 499;
          const PeriodicOrbit orbit = ShootStroboscopic(ForcedBelt(DenHartog(w)), x, xd, 1, o);
          x = orbit.start.z[0], xd = orbit.start.z[1];
          const double V = 1 / (1 - w * w), U = std::sin(M_PI / w) / (w * (1 + std::cos(M_PI / w)));
          worst = std::max(worst,
                           std::abs(OrbitExtrema(orbit).x_max - std::sqrt(V * V - 0.09 * U * U)));
        }
      },
      11);
  std::printf(
      "resonance sweep (Den Hartog, 500 Omegas in [1.2, 2.5], strobe Newton, rtol 1e-12): "
      "%.2f ms; max x_max error %.1e\n",
      t / 1e3, worst);
}

}  // namespace

int main() {
  ResonanceSweep();
  for (const double rtol : {1e-10, 1e-12, 1e-14}) StickSlipOrbit(rtol);
  for (const double rtol : {1e-10, 1e-12, 1e-14}) NonStopOrbit(rtol);
  DenHartogRun();
  return 0;
}
