#include "chart/chart_regions.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "chart/grazing_curve.hpp"
#include "chart/hopf_curve.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

namespace {
// Iterates the section map from the first maximum of x after the exit point.
// True if it settles on a pure-slip orbit (or sticks), false if it decays.
bool Oscillation(OrbitFinder& finder) {
  const Model& m = finder.model();
  StopRule stop;
  stop.at_section = true;
  stop.at_stick = true;
  stop.t_max = finder.options().max_return_time;
  const FlowResult r = finder.flow().Run(0.0, m.ExitPoint(), Mode::kSlipBelow, stop, false);
  if (r.status == FlowStatus::kStick) return true;
  if (r.status != FlowStatus::kSection) return false;
  const double xbar = m.SteadySliding().x;
  double a = r.z[0] - xbar;
  const double a0 = a;
  for (int n = 0; n < Tolerances::kRegionMapReturns; ++n) {
    const ReturnMap map = finder.Return(xbar + a, false);
    if (map.status == OrbitStatus::kSticks) return true;
    if (map.status != OrbitStatus::kOk) return false;
    const double next = map.x - xbar;
    if (next < Tolerances().map_decay * a0) return false;
    if (std::abs(next - a) < Tolerances().map_settle * a0) return true;
    a = next;
  }
  return a > Tolerances::kRegionLive * a0;
}
}  // namespace

Region ClassifyPoint(OrbitFinder& finder, const Params& p, bool pure_slip_check,
                     std::string* failure) {
  const bool stable = HopfFunction(p) > 0;
  finder.set_model(Model(p));
  finder.set_floquet(false);
  // The first return of the slip phase from the exit point, switching
  // honoured: it reaches the belt speed (stick-slip) or turns below it. Not
  // the grazing gap's run, which ignores switching and so evaluates mu at
  // negative slip speeds, where the Leine law mu_s / (1 + delta s) has a pole.
  const OrbitResult ss = finder.StickSlip(true);
  const bool stick_slip = ss.ok();
  if (failure && ss.status != OrbitStatus::kOk && ss.status != OrbitStatus::kMissed &&
      ss.status != OrbitStatus::kNoReturn)
    *failure = std::string(Name(ss.status)) + (ss.message.empty() ? "" : ": ") + ss.message;
  if (!stable) return stick_slip ? Region::kStickSlip : Region::kPureSlip;
  if (stick_slip) return Region::kBistable;
  if (pure_slip_check && Oscillation(finder)) return Region::kBistable;
  return Region::kSteadyOnly;
}

RegionGrid ClassifyGrid(const Params& base, const ChartOptions& o,
                        const std::vector<Curve>& curves) {
  const Plane& pl = o.plane;
  RegionGrid grid;
  grid.n1 = o.region_n1;
  grid.n2 = o.region_n2;
  for (int i = 0; i < grid.n1; ++i) grid.x1.push_back(pl.from1 + pl.width1() * (i + 0.5) / grid.n1);
  for (int j = 0; j < grid.n2; ++j) grid.x2.push_back(pl.from2 + pl.width2() * (j + 0.5) / grid.n2);
  bool check = false;
  for (const Curve& c : curves)
    for (const CurvePoint& p : c.points)
      check = check || c.kind == CurveKind::kFold ||
              (p.type == CurvePointType::kPersistence && HopfFunction(pl.At(base, p.p1, p.p2)) > 0);
  OrbitFinder finder(Model(base), o.orbit);
  for (double x1 : grid.x1)
    for (double x2 : grid.x2) {
      if (o.cancelled && o.cancelled()) return grid;  // cells so far; Chart says cancelled
      std::string failure;
      grid.cells.push_back(ClassifyPoint(finder, pl.At(base, x1, x2), check, &failure));
      if (failure.empty()) continue;
      if (grid.failed++ == 0) {
        std::ostringstream os;
        os << "region of the cell at " << pl.p1 << " = " << x1 << ", " << pl.p2 << " = " << x2
           << ": stick-slip orbit: " << failure;
        grid.failure = os.str();
      }
    }
  return grid;
}

}  // namespace stickslip
