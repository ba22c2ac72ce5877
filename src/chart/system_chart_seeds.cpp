// Seeds of a system's chart (chart/system_chart_seeds.hpp).
#include "chart/system_chart_seeds.hpp"

#include <algorithm>

#include "numerics/numbers.hpp"
#include "stickslip/equilibria/steady_branch.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/flow.hpp"
#include "stickslip/orbits/settle.hpp"
#include "stickslip/orbits/system_batch.hpp"

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
    case SpecialKind::kGrazing:  // a change of the switching sequence: GR's margin
    case SpecialKind::kAdding:
    case SpecialKind::kCrossing:
    case SpecialKind::kSliding:
      return CurveKind::kGrazing;
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

void HopfSeeds(const System& base, const SystemChartOptions& o, const Line& line, SeedRuns* runs,
               std::vector<SystemSeed>* out) {
  const SystemPlane& pl = o.plane;
  const auto s =
      line.along1 ? SystemAt(base, pl, line.lo, line.c) : SystemAt(base, pl, line.c, line.lo);
  SteadyBranchOptions so;
  so.cancelled = o.cancelled;
  const SteadyBranch b = ContinueSteadySliding(*s, line.param, line.hi, so);
  ++runs->runs;
  for (const SteadyRow& r : b.special) {
    if (r.label != SpecialKind::kHopf) continue;
    SystemSeed seed = SeedAt(line, CurveKind::kHopf, r.p);
    seed.where = "HB of steady sliding in " + base.ParameterName(line.param) + " " + line.at;
    out->push_back(seed);
  }
}

// The seed runs' continuation settings: steps of at most 2 % of the line.
OrbitBranchOptions SeedBranchOptions(const SystemChartOptions& o, const Line& line) {
  OrbitBranchOptions bo = o.branch;
  bo.palc.ds_max = std::min(bo.palc.ds_max, 0.02 * (line.hi - line.lo));
  bo.palc.ds = std::min(bo.palc.ds, bo.palc.ds_max);
  bo.palc.ds_min = std::min(bo.palc.ds_min, bo.palc.ds_max / 100);  // a narrow rectangle
  bo.palc.cancelled = o.cancelled;
  return bo;
}

// Whether a PD of a branch on `section`, `depth` doublings from the
// attractor's, starts the doubled branch: with a clock while its period
// multiple 2m <= max_m, else while 2^(depth + 1) <= max_m.
bool Doubles(const System& s, const SystemChartOptions& o, const PoincareSection& section,
             int depth) {
  if (s.clocks() > 0 && section.turns > 0) return 2 * section.turns <= o.max_m;
  return (2 << depth) <= o.max_m;
}

// The LP, PD and NS points of branch b as seeds (`run` names it); each PD
// inside the line starts the doubled branch (ContinueDoubled) where Doubles
// says so, whose points are seeds too.
void Harvest(const System& s, const SystemChartOptions& o, const Line& line, const OrbitBranch& b,
             const std::string& run, int depth, SeedRuns* runs, std::vector<SystemSeed>* out) {
  for (const OrbitRow& r : b.special) {
    bool ok = false;
    const CurveKind kind = KindOf(r.label, &ok);
    // GR curves: on a stroboscopic section only (a stick-exit section has
    // no smooth map across a stick phase that vanishes).
    if (!ok || (kind == CurveKind::kGrazing && b.section.kind != SectionKind::kTime)) continue;
    SystemSeed seed = SeedAt(line, kind, r.p);
    seed.start = r.start;
    seed.section = b.section;
    seed.where = std::string(Name(r.label)) + " of the " + run + line.at;
    out->push_back(seed);
    if (kind != CurveKind::kPeriodDoubling || !(r.p > line.lo && r.p < line.hi) ||
        !Doubles(s, o, b.section, depth) || (o.cancelled && o.cancelled()))
      continue;
    const std::unique_ptr<System> at = s.Clone();
    at->SetParameterValue(line.param, r.p);
    const OrbitBranch doubled = ContinueDoubled(*at, line.param, r.start, b.section, line.lo,
                                                line.hi, SeedBranchOptions(o, line));
    ++runs->runs;
    Harvest(s, o, line, doubled,
            s.ParameterName(line.param) + " run doubled at " + Num(r.p, 6) + " ", depth + 1, runs,
            out);
  }
}

// The branch of the attractor settled on at (line, from) to `to`: its LP,
// PD and NS points, and the doubled branches' (Harvest).
void BranchSeeds(const System& s, const SystemChartOptions& o, const Line& line,
                 const FlowPoint& start, const PoincareSection& section, double to, SeedRuns* runs,
                 std::vector<SystemSeed>* out) {
  const OrbitBranch b =
      ContinueOrbits(s, line.param, start, section, to, SeedBranchOptions(o, line));
  ++runs->runs;
  if (b.status == BranchStatus::kStartFailed && !(o.cancelled && o.cancelled()))
    runs->Fail(s.ParameterName(line.param) + " run " + line.at + " from an attractor at " +
               Num(s.ParameterValue(line.param), 6) + ": " + b.message);
  Harvest(s, o, line, b, s.ParameterName(line.param) + " run ", 0, runs, out);
}

// The attractor a run from steady sliding + disturbance settles on at s (an
// autonomous system), or, for a system with a clock, the orbit of period
// multiple <= max_m reached from rest (StroboscopicOrbits: transient,
// recurrence, the one shooting). False where there is none.
bool Attractor(const System& s, const SystemChartOptions& o, FlowPoint* start,
               PoincareSection* section) {
  if (s.clocks() == 0) {
    SettleOptions so;
    so.shooting = o.branch.shooting;
    so.transient = o.transient;
    so.max_returns = std::max(so.max_returns, 2 * s.contacts());
    so.cancelled = o.cancelled;
    const SettledOrbit settled = SettleOnStickSlip(s, NearSteadySliding(s, o.disturbance), so);
    *start = settled.orbit.start, *section = settled.section;
    return settled.found;
  }
  SystemBatchOptions bo;
  bo.shooting = o.branch.shooting;
  bo.max_m = o.max_m;
  bo.threads = 1;
  bo.cancelled = o.cancelled;
  const int j = 0;  // any parameter: its own value, one row
  const SystemBatch b = StroboscopicOrbits(s, {{j, {s.ParameterValue(j)}}}, bo);
  if (b.rows() != 1 || b.status[0] != OrbitStatus::kOk) return false;
  const int nt = b.tangent;
  start->z = Eigen::VectorXd::Zero(s.dimension());
  start->z.head(nt) = Eigen::Map<const Eigen::VectorXd>(b.start.data(), nt);
  start->t = 0;
  start->mode = ModeOf(s, start->z);
  *section = PoincareSection::Stroboscopic(s, start->z, b.m[0]);
  return true;
}

// At settle_points points of the line (ends included) the attractor there,
// continued to both ends of the line.
void OrbitSeeds(const System& base, const SystemChartOptions& o, const Line& line, SeedRuns* runs,
                std::vector<SystemSeed>* out) {
  const SystemPlane& pl = o.plane;
  for (int k = 0; k < o.settle_points; ++k) {
    if (o.cancelled && o.cancelled()) return;
    const double from = line.lo + (line.hi - line.lo) * k / (o.settle_points - 1);
    const auto s =
        line.along1 ? SystemAt(base, pl, from, line.c) : SystemAt(base, pl, line.c, from);
    FlowPoint start;
    PoincareSection section;
    try {  // a run meeting a state the flow refuses (a contact open at a rest point)
      if (!Attractor(*s, o, &start, &section)) continue;
      for (const double to : {line.lo, line.hi})
        if (to != from) BranchSeeds(*s, o, line, start, section, to, runs, out);
    } catch (const InvalidArgument& e) {
      runs->Fail(s->ParameterName(line.param) + " = " + Num(from, 6) + " " + line.at + ": " +
                 e.what());
    }
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
                                          bool along1, double c, SeedRuns* runs) {
  const SystemPlane& pl = o.plane;
  Line line;
  line.along1 = along1, line.c = c;
  line.param = along1 ? pl.p1 : pl.p2;
  line.lo = along1 ? pl.from1 : pl.from2, line.hi = along1 ? pl.to1 : pl.to2;
  line.at = "at " + base.ParameterName(along1 ? pl.p2 : pl.p1) + " = " + Num(c, 6);
  std::vector<SystemSeed> seeds;
  if (o.hopf_curves && base.clocks() == 0) {
    try {
      HopfSeeds(base, o, line, runs, &seeds);
    } catch (const InvalidArgument& e) {
      runs->Fail("steady sliding " + line.at + ": " + e.what());
    }
  }
  if (o.orbit_curves) OrbitSeeds(base, o, line, runs, &seeds);
  return seeds;
}

}  // namespace stickslip
