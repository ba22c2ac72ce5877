#include "stickslip/basin/basin_stability.hpp"

#include <algorithm>
#include <cmath>

#include "stickslip/errors.hpp"

namespace stickslip {

std::string BasinShare::Name() const {
  if (fate != Fate::kPureSlip || orbit <= 0) return stickslip::Name(fate);
  return std::string(stickslip::Name(fate)) + "-" + std::to_string(orbit + 1);
}

double BasinStability::Of(Fate f) const {
  double s = 0;
  for (const BasinShare& b : shares)
    if (b.fate == f) s += b.fraction;
  return s;
}

namespace {

// The area of the box inside one period of the orbit, sampled from the flow.
double EnclosedArea(const Model& model, const Orbit& o, const Box& box, const FlowOptions& flow,
                    int samples) {
  BeltFlow f(model, flow);
  std::vector<double> t;
  std::vector<Vec2> z, dz;
  auto take = [&](double ts, const Vec2& zs, Mode m) {
    if (!t.empty() && !(ts > t.back())) return;
    t.push_back(ts), z.push_back(zs), dz.push_back(model.Field(m, zs));
  };
  StopRule stop;
  stop.t_max = o.period;
  const FlowResult r = f.Run(0.0, o.start, Mode::kSlipBelow, stop, false, o.period / samples,
                             [&](const Sample& s) { take(s.t, s.z, s.mode); });
  if (!r.ok()) throw Error("ExactBasinStability: the orbit's run failed: " + r.message);
  take(r.t, r.z, r.mode);
  z.back() = z.front();  // closes within the orbit's tolerance: closed exactly
  return ClippedCurveArea(t, z, dz, box);
}

// The attractor of the region between invariant curves k and k + 1.
struct Level {
  Fate fate;
  int orbit;
  bool attracts;
};

}  // namespace

BasinStability ExactBasinStability(const Model& model, const PeriodicOrbits& orbits, const Box& box,
                                   const FlowOptions& flow, int samples) {
  if (!(box.Area() > 0) || !std::isfinite(box.Area()))
    throw InvalidArgument("ExactBasinStability: the box must have a finite area > 0");
  if (!orbits.ok()) throw InvalidArgument("ExactBasinStability: the orbit scan did not succeed");
  if (samples < kMinBasinStabilitySamples)
    throw InvalidArgument("ExactBasinStability: samples must be >= " +
                          std::to_string(kMinBasinStabilitySamples));
  BasinStability b;
  // Levels inward to outward: steady sliding, the pure-slip orbits by
  // increasing amplitude, the stick-slip orbit (or nothing: runs that leave).
  std::vector<Level> levels = {{Fate::kSteadySliding, -1, orbits.steady.stable()}};
  std::vector<double> inside = {0.0};  // fraction of the box inside each level
  for (size_t i = 0; i < orbits.pure_slip.size(); ++i) {
    const Orbit& o = orbits.pure_slip[i];
    const double a = std::clamp(EnclosedArea(model, o, box, flow, samples) / box.Area(), 0.0, 1.0);
    b.enclosed.push_back(a);
    levels.push_back({Fate::kPureSlip, static_cast<int>(i), o.stable});
    inside.push_back(std::max(a, inside.back()));
  }
  levels.push_back(
      {orbits.has_stick_slip ? Fate::kStickSlip : Fate::kUndecided, -1, orbits.has_stick_slip});
  inside.push_back(1.0);
  for (size_t k = 0; k + 1 < levels.size(); ++k) {
    const Level& in = levels[k];
    const Level& out = levels[k + 1];
    const Level& to = in.attracts ? in : out.attracts ? out : Level{Fate::kUndecided, -1, false};
    const double share = inside[k + 1] - inside[k];
    auto it = std::find_if(b.shares.begin(), b.shares.end(), [&](const BasinShare& s) {
      return s.fate == to.fate && s.orbit == to.orbit;
    });
    if (it == b.shares.end()) {
      b.shares.push_back({to.fate, to.orbit, 0.0});
      it = b.shares.end() - 1;
    }
    it->fraction += share;
  }
  // Every attractor is listed, with the share it has (0 if none in the box).
  for (const Level& l : levels)
    if (l.attracts && std::none_of(b.shares.begin(), b.shares.end(), [&](const BasinShare& s) {
          return s.fate == l.fate && s.orbit == l.orbit;
        }))
      b.shares.push_back({l.fate, l.orbit, 0.0});
  return b;
}

BasinStabilityCurve BasinStabilityAlong(const Params& base, const ParameterAxis& axis, double from,
                                        double to, int n, const Box& box,
                                        const OrbitScanOptions& scan) {
  if (n < 1) throw InvalidArgument("BasinStabilityAlong: n must be >= 1");
  BasinStabilityCurve c;
  c.param = axis;
  for (int i = 0; i < n; ++i) {
    const double p = n == 1 ? from : from + (to - from) * i / (n - 1);
    const Model m(axis.At(base, p));
    const PeriodicOrbits po = FindPeriodicOrbits(m, scan);
    if (!po.ok()) {
      c.status =
          po.status == OrbitScanStatus::kCancelled ? BasinStatus::kCancelled : BasinStatus::kFailed;
      c.message = axis.name() + " = " + std::to_string(p) + ": " + po.message;
      return c;
    }
    c.p.push_back(p);
    c.at.push_back(ExactBasinStability(m, po, box, scan.orbit.flow));
  }
  return c;
}

}  // namespace stickslip
