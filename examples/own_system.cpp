// Your own system through the library's generic calls (docs/library.md, "Your
// own system in C++"): the block on a belt of own_system.hpp, with its own
// exponential Stribeck + viscous law, is
//  1. simulated by stickslip::Flow (exact events: stick-in, stick-out),
//  2. shot onto its stick-slip orbit on the stick-exit section
//     (stickslip::Shooting; docs/theory.md, "One shooting") with its Floquet
//     multipliers, and
//  3. continued in the belt speed v (stickslip::ContinueOrbits; docs/theory.md,
//     "One branch driver"), with its special points,
//  4. charted in (v, beta) (stickslip::ChartSystem): the Hopf curve of steady
//     sliding, and
//  5. its basins on the (x, x') plane (stickslip::ClassifyAttractors).
// It checks what it can verify and exits 1 if one fails: the stick phase
// collapses the state, so the orbit's multiplier is 0; a plain Flow run from
// the orbit's start returns to the next stick exit after the period; the
// branch's first row is the shot orbit, and at its grazing end a plain run
// sticks for no time; every point of the Hopf curve lies on the closed form
// 2 beta = (mu_s - mu_k)/v_s exp(-v/v_s) - eta; the basins' rest point is
// steady sliding, x = mu(v), and their cycle's maximum is the shot orbit's.
#include "own_system.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stickslip/basin/attractors.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/flow.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace ss = stickslip;

namespace {

bool Check(bool ok, const char* what, double value, double tol) {
  std::printf("check  %-44s %.3e  (<= %.0e) %s\n", what, value, tol, ok ? "ok" : "FAILED");
  return ok;
}

// 1. From rest at x = 0 (slipping below the belt), 300 time units of the
// flow, then on to the next stick exit: a start on the section for step 2.
ss::FlowPoint Simulate(const own::StribeckBelt& belt) {
  ss::Flow flow(belt, ss::FlowOptions());
  ss::FlowRequest run;
  run.t_max = 300;
  run.extrema = {0, 1};
  const ss::FlowRun r =
      flow.Run({0, Eigen::Vector2d(0, 0), ss::ModeSet(ss::Mode::kSlipBelow)}, run);
  std::printf("flow   t = %g: %s, %d sticks, %d exits, x in [%.6f, %.6f], x' in [%.6f, %.6f]\n",
              r.end.t, ss::Name(r.status), r.sticks, r.exits, r.lo[0], r.hi[0], r.lo[1], r.hi[1]);
  ss::FlowRequest to_exit;
  to_exit.stop_at_exit = 1;  // ends just after the switch: on the section
  to_exit.t_max = r.end.t + 1e3;
  const ss::FlowRun e = flow.Run(r.end, to_exit);
  if (e.exits != 1) throw ss::InvalidArgument("the simulation does not reach a stick exit");
  return e.end;
}

// The time a row's orbit sticks per period: a plain run from its start to
// the next stick exit at its v (the branch ends where this vanishes).
double StickTime(const own::StribeckBelt& belt, const ss::OrbitRow& row) {
  own::StribeckBelt at = belt;
  at.SetParameterValue(at.ParameterIndex("v"), row.p);
  ss::Flow flow(at, ss::FlowOptions());
  ss::FlowRequest once;
  once.stop_at_exit = 1;
  once.t_max = row.start.t + 10 * row.period;
  return flow.Run(row.start, once).t_stick;
}

// 3. The branch in v, every row and the located special points.
ss::OrbitBranch Continue(const own::StribeckBelt& belt, const ss::PeriodicOrbit& orbit, double to) {
  ss::OrbitBranchOptions o;
  o.palc.ds_max = 0.02;
  const ss::OrbitBranch b = ss::ContinueOrbits(belt, belt.ParameterIndex("v"), orbit.start,
                                               ss::PoincareSection::StickExit(0), to, o);
  std::printf("\nbranch in v toward %g: %zu rows, status %s, %d evaluations, %.2f s\n", to,
              b.rows.size(), ss::Name(b.status), b.evaluations, b.seconds);
  if (!b.message.empty()) std::printf("  %s\n", b.message.c_str());
  std::printf("  %-3s %-12s %-10s %-10s %-10s %-10s %-9s %s\n", "", "v", "period", "t_stick",
              "x_min", "x_max", "|mu|max", "stable");
  for (const ss::OrbitRow& r : b.rows) {
    double mu = 0;
    for (const auto& m : r.multipliers) mu = std::max(mu, std::abs(m));
    std::printf("  %-3s %-12.8f %-10.6f %-10.3e %-10.6f %-10.6f %-9.2e %s\n",
                ss::SpecialLabel(r.label), r.p, r.period, StickTime(belt, r), r.lo[0], r.hi[0], mu,
                r.stable ? "yes" : "no");
  }
  std::printf("special points:\n");
  for (const ss::OrbitRow& s : b.special)
    std::printf("  %-3s v = %.10f  period %.6f: %s\n", ss::SpecialLabel(s.label), s.p, s.period,
                s.description.c_str());
  return b;
}

// 4. The Hopf curve of steady sliding in (v, beta) and the largest distance
// of its points from the closed form beta(v) (own_system.hpp, Rest).
double HopfCurve(const own::StribeckBelt& belt, int* points) {
  const own::BeltParams& p = belt.params();
  ss::SystemChartOptions o;
  o.plane = {belt.ParameterIndex("v"), belt.ParameterIndex("beta"), 0.2, 0.8, 0.02, 0.1};
  o.orbit_curves = false;  // HB only: the orbit curves take longer
  const ss::SystemChart c = ss::ChartSystem(belt, o);
  double worst = 0;
  *points = 0;
  for (const ss::SystemCurve& curve : c.curves) {
    if (curve.kind != ss::CurveKind::kHopf) continue;
    for (const ss::SystemCurvePoint& q : curve.points) {
      const double beta = ((p.mu_s - p.mu_k) / p.v_s * std::exp(-q.p1 / p.v_s) - p.eta) / 2;
      worst = std::max(worst, std::abs(q.p2 - beta));
      ++*points;
    }
  }
  std::printf("\nchart in (v, beta): %zu curves, %d HB points, status %s, %.3f s\n",
              c.curves.size(), *points, ss::Name(c.status), c.seconds);
  return worst;
}

// 5. Basins at belt speed v on a 9 x 9 grid of (x, x') around steady sliding.
ss::AttractorBasins Basins(const own::StribeckBelt& belt) {
  ss::AttractorOptions o;
  o.slice.base = Eigen::Vector2d(belt.Mu(belt.params().v), 0);
  o.slice.lo = {o.slice.base[0] - 1, -1};
  o.slice.hi = {o.slice.base[0] + 1, 1};
  o.slice.n = {9, 9};
  const ss::AttractorBasins b = ss::ClassifyAttractors(belt, o);
  std::printf("\nbasins at v = %g: %zu attractors, %d failed, %.2f s\n", belt.params().v,
              b.attractors.size(), b.failed, b.seconds);
  for (const ss::Attractor& a : b.attractors)
    std::printf("  %-9s m = %d, %d sticks, x = %.10f, %d starts\n", ss::Name(a.kind), a.m, a.sticks,
                a.z[0], a.starts);
  return b;
}

// Above v_HB (and below GR) steady sliding and the stick-slip orbit both
// attract: the rest point is mu(v) and the cycle's maximum the orbit's.
bool CheckBasins(const own::BeltParams& p, const ss::ShootingOptions& so) {
  own::BeltParams q = p;
  q.v = 0.5;
  const own::StribeckBelt fast(q);
  // Its stick exit is (mu_s - 2 beta v, v): the orbit's start on the section.
  const ss::FlowPoint exit_q{0, Eigen::Vector2d(q.mu_s - 2 * q.beta * q.v, q.v),
                             ss::ModeSet(ss::Mode::kSlipBelow)};
  const ss::PeriodicOrbit at_q =
      ss::Shooting(fast, so).Find(exit_q, ss::PoincareSection::StickExit(0));
  const ss::AttractorBasins basins = Basins(fast);
  double rest = 1, cycle = 1;
  for (const ss::Attractor& a : basins.attractors) {
    if (a.kind == ss::AttractorKind::kRest) rest = std::abs(a.z[0] - fast.Mu(q.v));
    if (a.kind == ss::AttractorKind::kPeriodic && at_q.ok()) cycle = std::abs(a.z[0] - at_q.hi[0]);
  }
  bool ok = Check(rest <= 1e-8, "|basins' rest point - mu(v)|", rest, 1e-8);
  ok &= Check(cycle <= 1e-8, "|basins' cycle x_max - shot orbit's|", cycle, 1e-8);
  return ok;
}

int Run() {
  own::BeltParams p;  // beta 0.05, v 0.3, mu_s 0.4, mu_k 0.25, v_s 0.5, eta 0.02
  const own::StribeckBelt belt(p);
  if (!belt.ValidationError().empty()) throw ss::InvalidArgument(belt.ValidationError());
  std::printf(
      "own system: x'' + 2 beta x' + x = F(x' - v), mu(s) = mu_k + (mu_s - mu_k) "
      "exp(-s/v_s) + eta s\n");
  for (int j = 0; j < belt.parameters(); ++j)
    std::printf("%s%s = %g", j ? ", " : "  ", belt.ParameterName(j).c_str(),
                belt.ParameterValue(j));
  std::printf("\n");
  const ss::FlowPoint start = Simulate(belt);

  // 2. The stick-slip orbit: Newton on the stick-exit map (its start's mode
  // is the slip it leaves into: below).
  ss::ShootingOptions so;
  ss::Shooting shooting(belt, so);
  const ss::PeriodicOrbit orbit = shooting.Find(start, ss::PoincareSection::StickExit(0));
  if (!orbit.ok()) throw ss::InvalidArgument("shooting: " + orbit.message);
  std::printf("orbit  start (x, x') = (%.12f, %.12f), period %.12f, %d stick(s), %d Newton\n",
              orbit.start.z[0], orbit.start.z[1], orbit.period, orbit.sticks, orbit.iterations);
  std::printf("       x in [%.6f, %.6f], multipliers:", orbit.lo[0], orbit.hi[0]);
  for (const auto& m : orbit.multipliers) std::printf(" %.3e%+.3ei", m.real(), m.imag());
  std::printf(" (%s)\n", orbit.stable ? "stable" : "unstable");

  bool ok = true;
  // The stick phase maps every start onto one exit point: DP is singular
  // and the one nontrivial multiplier is 0 (the seed's case 1).
  const double mu = orbit.multipliers.empty() ? 1.0 : std::abs(orbit.multipliers[0]);
  ok &= Check(orbit.multipliers.size() == 1 && mu <= 1e-12, "|multiplier| (a stick collapses)", mu,
              1e-12);
  // A plain run from the orbit's start to its next stick exit: one period.
  ss::Flow flow(belt, so.flow);
  ss::FlowRequest once;
  once.stop_at_exit = 1;
  once.t_max = orbit.start.t + 10 * orbit.period;  // t_max is a time, not a duration
  const ss::FlowRun r = flow.Run(orbit.start, once);
  const double dt = std::abs(r.end.t - orbit.start.t - orbit.period);
  ok &= Check(r.exits == 1 && dt <= 1e-9, "|flow return time - period|", dt, 1e-9);
  const double dz = (r.end.z - orbit.start.z).lpNorm<Eigen::Infinity>();
  ok &= Check(r.exits == 1 && dz <= 1e-9, "|flow return point - start|", dz, 1e-9);

  // Steady sliding (Rest) loses stability where dF/dx' = 2 beta (a Hopf):
  // v_HB = v_s ln((mu_s - mu_k) / (v_s (2 beta + eta))); above it both
  // attract until the stick-slip orbit's stick phase vanishes.
  const double v_hb = p.v_s * std::log((p.mu_s - p.mu_k) / (p.v_s * (2 * p.beta + p.eta)));
  std::printf("steady sliding x = mu(v) is stable for v > v_HB = %.10f\n", v_hb);
  const ss::OrbitBranch b = Continue(belt, orbit, 0.8);
  bool first = !b.rows.empty();
  double d = 1;
  if (first) {
    const ss::OrbitRow& r0 = b.rows.front();
    d = std::max({std::abs(r0.p - p.v), std::abs(r0.period - orbit.period),
                  (r0.start.z - orbit.start.z).lpNorm<Eigen::Infinity>()});
  }
  ok &= Check(first && d <= 1e-9, "|first row - shot orbit|", d, 1e-9);
  // Its end, where the stick phase shrinks to nothing (the orbit turns into
  // a pure-slip one there): a plain run from the last row barely sticks.
  const bool ends = !b.rows.empty() && b.rows.back().label != ss::SpecialKind::kNone;
  const double t_stick = ends ? StickTime(belt, b.rows.back()) : 1.0;
  ok &= Check(ends && t_stick <= 1e-4, "stick time at the branch's end", t_stick, 1e-4);

  int hb_points = 0;
  const double hb = HopfCurve(belt, &hb_points);
  ok &= Check(hb_points >= 10 && hb <= 1e-8, "|HB curve - closed form| in beta", hb, 1e-8);

  ok &= CheckBasins(p, so);
  std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
  return ok ? 0 : 1;
}

}  // namespace

int main() {
  try {
    return Run();
  } catch (const ss::Error& e) {
    std::fprintf(stderr, "own_system: %s\n", e.what());
    return 2;
  }
}
