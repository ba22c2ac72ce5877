// Seeds of a system's chart (chart/system_chart_seeds.hpp).
#include "chart/system_chart_seeds.hpp"

#include <algorithm>

#include "numerics/numbers.hpp"
#include "stickslip/equilibria/steady_branch.hpp"
#include "stickslip/orbits/settle.hpp"

namespace stickslip {

namespace {

// One line: which parameter runs, its range, the constant, and the text.
struct Line {
  bool along1 = true;
  int param = 0;
  double c = 0, lo = 0, hi = 0;
  std::string at;  // "at mu_k = 0.5"
};

CurveKind KindOf(SpecialKind l, bool* ok) {
  *ok = true;
  switch (l) {
    case SpecialKind::kFold:
      return CurveKind::kFold;
    case SpecialKind::kPeriodDoubling:
      return CurveKind::kPeriodDoubling;
    case SpecialKind::kTorus:
      return CurveKind::kTorus;
    default:
      *ok = false;
      return CurveKind::kFold;
  }
}

SystemSeed SeedAt(const Line& line, CurveKind kind, double p) {
  SystemSeed s;
  s.kind = kind;
  s.p1 = line.along1 ? p : line.c, s.p2 = line.along1 ? line.c : p;
  s.fixed = line.along1 ? 1 : 0;
  return s;
}

void HopfSeeds(const System& base, const SystemChartOptions& o, const Line& line, int* runs,
               std::vector<SystemSeed>* out) {
  const SystemPlane& pl = o.plane;
  const auto s =
      line.along1 ? SystemAt(base, pl, line.lo, line.c) : SystemAt(base, pl, line.c, line.lo);
  SteadyBranchOptions so;
  so.cancelled = o.cancelled;
  const SteadyBranch b = ContinueSteadySliding(*s, line.param, line.hi, so);
  ++*runs;
  for (const SteadyRow& r : b.special) {
    if (r.label != SpecialKind::kHopf) continue;
    SystemSeed seed = SeedAt(line, CurveKind::kHopf, r.p);
    seed.where = "HB of steady sliding in " + base.ParameterName(line.param) + " " + line.at;
    out->push_back(seed);
  }
}

// The branch of the attractor settled on at (line, from) to `to`: its LP,
// PD and NS points.
void BranchSeeds(const System& s, const SystemChartOptions& o, const Line& line,
                 const SettledOrbit& settled, double to, int* runs, std::vector<SystemSeed>* out) {
  OrbitBranchOptions bo = o.branch;
  bo.palc.ds_max = std::min(bo.palc.ds_max, 0.02 * (line.hi - line.lo));
  bo.palc.ds = std::min(bo.palc.ds, bo.palc.ds_max);
  bo.palc.cancelled = o.cancelled;
  const OrbitBranch b = ContinueOrbits(s, line.param, settled.orbit.start, settled.section, to, bo);
  ++*runs;
  for (const OrbitRow& r : b.special) {
    bool ok = false;
    const CurveKind kind = KindOf(r.label, &ok);
    if (!ok) continue;
    SystemSeed seed = SeedAt(line, kind, r.p);
    seed.start = r.start;
    seed.section = b.section;
    seed.where =
        std::string(Name(r.label)) + " of the " + s.ParameterName(line.param) + " run " + line.at;
    out->push_back(seed);
  }
}

// At settle_points points of the line (ends included) the attractor a run
// from steady sliding + disturbance settles on, continued to both ends.
void OrbitSeeds(const System& base, const SystemChartOptions& o, const Line& line, int* runs,
                std::vector<SystemSeed>* out) {
  const SystemPlane& pl = o.plane;
  for (int k = 0; k < o.settle_points; ++k) {
    if (o.cancelled && o.cancelled()) return;
    const double from = line.lo + (line.hi - line.lo) * k / (o.settle_points - 1);
    const auto s =
        line.along1 ? SystemAt(base, pl, from, line.c) : SystemAt(base, pl, line.c, from);
    SettleOptions so;
    so.shooting = o.branch.shooting;
    so.transient = o.transient;
    so.max_returns = std::max(so.max_returns, 2 * s->contacts());
    so.cancelled = o.cancelled;
    const SteadyState rest = SteadySliding(*s);
    Eigen::VectorXd z0 = rest.found ? rest.z : Eigen::VectorXd::Zero(s->dimension());
    z0[0] += o.disturbance;
    const SettledOrbit settled = SettleOnStickSlip(*s, z0, so);
    if (!settled.found) continue;
    for (const double to : {line.lo, line.hi})
      if (to != from) BranchSeeds(*s, o, line, settled, to, runs, out);
  }
}

}  // namespace

std::unique_ptr<System> SystemAt(const System& base, const SystemPlane& plane, double x1,
                                 double x2) {
  std::unique_ptr<System> s = base.Clone();
  s->SetParameterValue(plane.p1, x1);
  s->SetParameterValue(plane.p2, x2);
  return s;
}

std::vector<SystemSeed> SystemSeedsOnLine(const System& base, const SystemChartOptions& o,
                                          bool along1, double c, int* runs) {
  const SystemPlane& pl = o.plane;
  Line line;
  line.along1 = along1, line.c = c;
  line.param = along1 ? pl.p1 : pl.p2;
  line.lo = along1 ? pl.from1 : pl.from2, line.hi = along1 ? pl.to1 : pl.to2;
  line.at = "at " + base.ParameterName(along1 ? pl.p2 : pl.p1) + " = " + Num(c, 6);
  std::vector<SystemSeed> seeds;
  if (o.hopf_curves) HopfSeeds(base, o, line, runs, &seeds);
  if (o.orbit_curves) OrbitSeeds(base, o, line, runs, &seeds);
  return seeds;
}

}  // namespace stickslip
