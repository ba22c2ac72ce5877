#include "stickslip/basin/branch_disturbance.hpp"

#include <limits>

#include "stickslip/basin/basin.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

std::vector<Disturbance> BranchDisturbances(const Params& base, const ContinuationResult& r,
                                            const FlowOptions& flow,
                                            const std::function<bool()>& cancelled) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Disturbance> out;
  out.reserve(r.points.size());
  for (const BranchPoint& pt : r.points) {
    Disturbance d{nan, nan, nan};
    const bool unstable_orbit =
        pt.kind == PointKind::kPureSlip && !pt.stable && !(cancelled && cancelled());
    if (unstable_orbit && pt.amplitude <= 0) {
      d = Disturbance{0, 0, 0};  // the orbit shrinks onto steady sliding (a Hopf point)
    } else if (unstable_orbit && pt.period > 0) {
      const Model m(r.param.At(base, pt.p));
      Orbit o;
      o.kind = OrbitKind::kPureSlip;
      o.start = Vec2(m.SteadySliding().x + pt.amplitude, 0.0);
      o.period = pt.period;
      o.extrema.x_min = pt.extrema.x_min, o.extrema.x_max = pt.extrema.x_max;
      try {
        d = SmallestDisturbance(m, o, flow, 2000);
      } catch (const Error&) {
        d = Disturbance{nan, nan, nan};  // the run failed: no value, not a guess
      }
    }
    out.push_back(d);
  }
  return out;
}

}  // namespace stickslip
