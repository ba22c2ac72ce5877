// Seeds of the forced chart (chart/forced_chart_seeds.hpp).
#include "chart/forced_chart_seeds.hpp"

#include <algorithm>

#include "chart/chart_trace.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/forced/branch.hpp"
#include "stickslip/forced/orbit_scan.hpp"

namespace stickslip {

namespace {

bool Sliding(SpecialKind l) {
  return l == SpecialKind::kGrazing || l == SpecialKind::kAdding || l == SpecialKind::kCrossing ||
         l == SpecialKind::kSliding;
}

// One line: its constant, its range and where the seeds' text says they are.
struct Line {
  ForcedParams params;
  ParameterAxis axis = Parameter::kOmega;
  bool along1;
  double c, lo, hi;
  std::string at;  // "at force = 0.3"
};

// The seeds among b's special points; each PD with 2m <= max_m also starts
// the doubled branch (ContinueDoubled), whose special points are seeds too.
void Harvest(const OrbitBranch& b, const Line& line, const ForcedChartOptions& o,
             OrbitBranchOptions bo, const std::string& run, int* runs,
             std::vector<ForcedSeed>* seeds) {
  const int m = PeriodMultiple(b);
  for (const OrbitRow& r : b.special) {
    ForcedSeed s;
    if (r.label == SpecialKind::kFold)
      s.kind = CurveKind::kFold;
    else if (r.label == SpecialKind::kPeriodDoubling)
      s.kind = CurveKind::kPeriodDoubling;
    else if (r.label == SpecialKind::kTorus)
      s.kind = CurveKind::kTorus;
    else if (Sliding(r.label))
      s.kind = CurveKind::kGrazing;
    else
      continue;
    s.m = m, s.x0 = r.start.z[0], s.xdot0 = r.start.z[1];
    s.p1 = line.along1 ? r.p : line.c, s.p2 = line.along1 ? line.c : r.p;
    s.fixed = line.along1 ? 3 : 2;
    s.where = std::string(Name(r.label)) + " of the " + run + line.at;
    seeds->push_back(s);
    const bool inside = r.p > line.lo && r.p < line.hi;
    if (r.label != SpecialKind::kPeriodDoubling || 2 * m > o.max_m || !inside) continue;
    if (o.cancelled && o.cancelled()) return;
    ForcedParams at_pd = line.params;
    line.axis.Set(at_pd, r.p);
    const OrbitBranch doubled =
        ContinueDoubled(at_pd, line.axis, s.x0, s.xdot0, line.lo, line.hi, m, bo);
    ++*runs;
    const std::string name = "m = " + std::to_string(2 * m) + " " + line.axis.name() +
                             " run (doubled at " + Num(r.p, 6) + ") ";
    Harvest(doubled, line, o, bo, name, runs, seeds);
  }
}

}  // namespace

std::vector<ForcedSeed> SeedsOnLine(const ForcedParams& base, const ForcedChartOptions& o,
                                    bool along1, double c, int* runs) {
  const Plane& pl = o.plane;
  Line line;
  line.axis = along1 ? pl.p1 : pl.p2, line.along1 = along1, line.c = c;
  line.lo = along1 ? pl.from1 : pl.from2, line.hi = along1 ? pl.to1 : pl.to2;
  line.params = along1 ? pl.At(base, line.lo, c) : pl.At(base, c, line.lo);
  line.at = "at " + (along1 ? pl.p2 : pl.p1).name() + " = " + Num(c, 6);
  std::vector<ForcedSeed> seeds;
  for (const double from : {line.lo, line.hi}) {
    if (o.cancelled && o.cancelled()) break;
    ForcedParams start = line.params;
    line.axis.Set(start, from);
    ForcedScanOptions so;
    so.orbit = ShootingOptions(o.flow);
    so.max_m = o.max_m, so.max_sticks = 2, so.grid = 3, so.exit_samples = 24;
    so.cancelled = o.cancelled;
    const ForcedOrbits found = FindForcedOrbits(ForcedModel(start), so);
    for (const ForcedScanOrbit& f : found.orbits) {
      if (!f.orbit.stable) continue;
      OrbitBranchOptions bo(o.flow);  // every map on the chart's flow, its step cap too
      bo.max_amplitude = o.max_amplitude;
      bo.palc.ds_max = 0.02 * (line.hi - line.lo);
      bo.palc.ds = std::min(bo.palc.ds, bo.palc.ds_max);
      bo.palc.cancelled = o.cancelled;
      const OrbitBranch b =
          ContinueForced(start, line.axis, from, from == line.lo ? line.hi : line.lo,
                         f.points[0].x(), f.points[0].y(), f.m, bo);
      ++*runs;
      Harvest(b, line, o, bo, std::string(line.axis.name()) + " run ", runs, &seeds);
    }
  }
  return seeds;
}

bool NearForcedCurve(const std::vector<ForcedCurve>& curves, const ForcedSeed& s, const Plane& pl) {
  const Eigen::Vector2d scale(pl.width1(), pl.width2());
  for (const ForcedCurve& c : curves)
    if (c.kind == s.kind && c.m == s.m &&
        NearPolyline(c.points, Eigen::Vector2d(s.p1, s.p2), scale, Tolerances().forced_same_curve))
      return true;
  return false;
}

}  // namespace stickslip
