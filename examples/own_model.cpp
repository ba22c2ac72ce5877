// Your own friction system as a model file, read from C++ against the
// installed package (<stickslip/model_file.hpp>, docs/model_files.md): a
// block on a belt with an exponential Stribeck law of its own,
//   x'' + 2 beta x' + x = F,  F = mu_k + (mu_s - mu_k) exp(-s / v_s),
// written once as text. The library derives the field, the stick force and
// the Taylor recurrences from it; this program then
//  1. follows steady sliding in v with its Hopf point, where the damping
//     2 beta + mu'(v) vanishes: v_HB = v_s ln((mu_s - mu_k) / (2 beta v_s)),
//  2. settles on the stick-slip attractor at v = 0.2 (its stick phase
//     collapses the state: the one multiplier is 0), and
//  3. continues it in v (stickslip::ContinueOrbits) with its special points.
// It exits 1 if a check fails.
#include <cmath>
#include <cstdio>
#include <memory>

#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/equilibria/steady_branch.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/model_file.hpp"
#include "stickslip/orbits/settle.hpp"

namespace ss = stickslip;

namespace {

const char* kModel =
    "name = stribeck belt\n"
    "coordinates = x\n"
    "parameter beta = 0.05\n"
    "parameter v = 0.2\n"
    "parameter mu_s = 0.4\n"
    "parameter mu_k = 0.25\n"
    "parameter v_s = 0.2\n"
    "x'' = -2*beta*x' - x + F\n"
    "contact F = x' - v\n"
    "law F = mu_k + (mu_s - mu_k)*exp(-s/v_s)\n";

bool Check(bool ok, const char* what, double value, double tol) {
  std::printf("check  %-44s %.3e  (<= %.0e) %s\n", what, value, tol, ok ? "ok" : "FAILED");
  return ok;
}

int Run() {
  const std::unique_ptr<ss::System> s = ss::model_file::ParseModel(kModel, "stribeck_belt.ini");
  const int v = s->ParameterIndex("v");
  std::printf("%s: %d states, %d contact, %d parameters\n", ss::model_file::ModelName(*s).c_str(),
              s->dimension(), s->contacts(), s->parameters());
  // 1. Steady sliding from v = 0.2 to 0.6 and its Hopf point.
  ss::SteadyBranchOptions so;
  const ss::SteadyBranch steady = ss::ContinueSteadySliding(*s, v, 0.6, so);
  const double v_hb = 0.2 * std::log(0.15 / (2 * 0.05 * 0.2));
  double hb = INFINITY;
  for (const ss::SteadyRow& r : steady.special)
    if (r.label == ss::SpecialKind::kHopf) hb = std::abs(r.p - v_hb);
  std::printf("steady sliding: %zu rows; HB at v = %.12f (closed form)\n", steady.rows.size(),
              v_hb);
  bool ok = Check(hb <= 1e-10, "|HB - closed form| in v", hb, 1e-10);
  // 2. The stick-slip attractor at v = 0.2.
  ss::SettleOptions settle;
  const ss::SettledOrbit orbit = ss::SettleOnStickSlip(*s, ss::NearSteadySliding(*s, 0.01), settle);
  if (!orbit.found) {
    std::printf("no stick-slip orbit: %s\n", orbit.message.c_str());
    return 1;
  }
  const double mu =
      orbit.orbit.multipliers.empty() ? INFINITY : std::abs(orbit.orbit.multipliers[0]);
  std::printf("orbit at v = 0.2: period %.12f, %d stick phase(s)\n", orbit.orbit.period,
              orbit.orbit.sticks);
  ok &=
      Check(orbit.orbit.sticks == 1 && mu <= 1e-12, "|multiplier| (a stick collapses)", mu, 1e-12);
  // 3. Its branch in v.
  ss::OrbitBranchOptions bo;
  const ss::OrbitBranch b = ss::ContinueOrbits(*s, v, orbit.orbit.start, orbit.section, 0.6, bo);
  std::printf("branch: %zu rows, %s%s%s\n", b.rows.size(), ss::Name(b.status),
              b.message.empty() ? "" : ": ", b.message.c_str());
  for (const ss::OrbitRow& r : b.special)
    std::printf("  %s at v = %.10f: %s\n", ss::Name(r.label), r.p, r.description.c_str());
  ok &= Check(!b.rows.empty() && std::abs(b.rows[0].period - orbit.orbit.period) <= 1e-9,
              "|first row's period - settled orbit's|",
              b.rows.empty() ? INFINITY : std::abs(b.rows[0].period - orbit.orbit.period), 1e-9);
  std::printf(ok ? "all checks passed\n" : "a check FAILED\n");
  return ok ? 0 : 1;
}

}  // namespace

int main() {
  try {
    return Run();
  } catch (const ss::InvalidArgument& e) {
    std::fprintf(stderr, "own_model: %s\n", e.what());
    return 2;
  }
}
