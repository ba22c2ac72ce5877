#include "stickslip/basin/basin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

std::string BasinOptions::ValidationError() const {
  std::string err = scan.ValidationError();
  if (!err.empty()) return err;
  std::ostringstream os;
  auto finite = [](double x) { return std::isfinite(x); };
  if (nx < 1 || ny < 1 || static_cast<long>(nx) * ny > kMaxStarts)
    os << "nx = " << nx << ", ny = " << ny << " must be >= 1 with nx * ny <= " << kMaxStarts;
  else if (!(t_cap > 0) || !finite(t_cap))
    os << "t_cap = " << t_cap << " must be a finite number > 0";
  else if (!(settle > 0 && settle < 1))
    os << "settle = " << settle << " must be in (0, 1)";
  else if (!auto_range &&
           !(std::abs(x_lo) <= kMaxCorner && std::abs(x_hi) <= kMaxCorner && x_lo <= x_hi))
    os << "x range [" << x_lo << ", " << x_hi << "] must lie within +-" << kMaxCorner
       << " with x_lo <= x_hi";
  else if (!auto_range && !(std::abs(xdot_lo) <= kMaxCorner && std::abs(xdot_hi) <= kMaxCorner &&
                            xdot_lo <= xdot_hi))
    os << "x' range [" << xdot_lo << ", " << xdot_hi << "] must lie within +-" << kMaxCorner
       << " with xdot_lo <= xdot_hi";
  return os.str();
}

namespace {

class Classifier {
 public:
  Classifier(const Model& m, const BasinOptions& o, BasinResult& res)
      : m_(m), o_(o), res_(res), flow_(m, o.scan.orbit.flow), xbar_(m.SteadySliding().x) {
    if (o.cancelled) flow_.set_cancel(o.cancelled);
    const PeriodicOrbits& po = res.orbits;
    // Fixed points of the section's return map, increasing: 0 (steady
    // sliding), the pure-slip orbits, the sticking amplitude.
    fixed_.push_back(0.0);
    for (const Orbit& q : po.pure_slip) fixed_.push_back(q.start[0] - xbar_);
    fixed_.push_back(std::min(po.a_stick, po.a_max));
  }

  // The fate of one start; false on a failure (message set).
  bool Classify(BasinStart& s);

 private:
  bool Settled(double a, double a_prev, BasinStart& s) const;

  const Model& m_;
  const BasinOptions& o_;
  BasinResult& res_;
  BeltFlow flow_;
  double xbar_;
  std::vector<double> fixed_;
};

// Successive section amplitudes of a planar flow are monotone between fixed
// points of the return map: approaching one that attracts, close to it, and
// with no other fixed point in between, the run is settled there.
bool Classifier::Settled(double a, double a_prev, BasinStart& s) const {
  if (res_.orbits.steady.stable() && a < a_prev && a < o_.settle * fixed_[1]) {
    s.fate = Fate::kSteadySliding;
    return true;
  }
  const auto& ps = res_.orbits.pure_slip;
  for (size_t i = 0; i < ps.size(); ++i) {
    const double ai = fixed_[i + 1];
    if (!ps[i].stable || !(a > fixed_[i] && a < fixed_[i + 2])) continue;
    if (std::abs(a - ai) < std::abs(a_prev - ai) && std::abs(a - ai) < o_.settle * ai) {
      s.fate = Fate::kPureSlip;
      s.orbit = static_cast<int>(i);
      return true;
    }
  }
  return false;
}

bool Classifier::Classify(BasinStart& s) {
  Vec2 z(s.x, s.xdot);
  // A start within rounding of x' = v is taken on it, where the Filippov rule
  // picks its mode: a slip run started a hair off the surface towards which
  // its field points would miss the crossing at t = 0.
  if (std::abs(z[1] - m_.v()) <= Tolerances().on_belt * (1 + std::abs(m_.v()))) z[1] = m_.v();
  Mode mode = m_.ModeAt(z);
  const bool cycle = res_.orbits.has_stick_slip;
  s.fate = Fate::kUndecided;
  s.t_settle = o_.t_cap;
  if (mode == Mode::kStick && cycle) {  // already on the stick-slip orbit
    s.fate = Fate::kStickSlip;
    s.t_settle = 0;
    return true;
  }
  double t = 0, a_prev = std::numeric_limits<double>::infinity();
  bool stuck = false;
  while (t < o_.t_cap) {
    StopRule stop;
    stop.at_stick = true;
    stop.at_section = true;
    stop.t_max = o_.t_cap;
    const FlowResult r = flow_.Run(t, z, mode, stop, false);
    if (!r.ok()) {
      std::ostringstream os;
      os << "start (x, x') = (" << s.x << ", " << s.xdot << "): " << r.message;
      res_.message = os.str();
      res_.status =
          r.status == FlowStatus::kCancelled ? BasinStatus::kCancelled : BasinStatus::kFailed;
      return false;
    }
    t = r.t;
    if (r.status == FlowStatus::kStick) {
      // Every stick ends at the exit point: on the stick-slip orbit if it
      // exists, else the exit point's own fate follows.
      if (cycle || stuck) {
        s.fate = Fate::kStickSlip;
        s.t_settle = t;
        return true;
      }
      stuck = true;
      z = m_.ExitPoint();
      mode = Mode::kSlipBelow;
      a_prev = std::numeric_limits<double>::infinity();
      continue;
    }
    if (r.status == FlowStatus::kSection) {
      const double a = r.z[0] - xbar_;
      if (Settled(a, a_prev, s)) {
        s.t_settle = t;
        return true;
      }
      a_prev = a;
      z = r.z;
      mode = r.mode;
      continue;
    }
    // Time cap. Runs that settle on stable steady sliding end there exactly.
    const double snap =
        Tolerances::From(o_.scan.orbit.flow.rtol, o_.scan.orbit.flow.atol).SteadySnap();
    if (res_.orbits.steady.stable() && std::abs(r.z[0] - xbar_) < snap && std::abs(r.z[1]) < snap)
      s.fate = Fate::kSteadySliding;
    return true;
  }
  return true;
}

void AutoRange(const Model& m, BasinResult& r) {
  const PeriodicOrbits& po = r.orbits;
  double x_lo = po.steady.x, x_hi = po.steady.x, y_lo = 0, y_hi = m.v();
  auto take = [&](const Orbit& o) {
    x_lo = std::min(x_lo, o.extrema.x_min), x_hi = std::max(x_hi, o.extrema.x_max);
    y_lo = std::min(y_lo, o.extrema.xdot_min), y_hi = std::max(y_hi, o.extrema.xdot_max);
  };
  if (po.has_stick_slip) take(po.stick_slip);
  for (const Orbit& o : po.pure_slip) take(o);
  const Vec2 exit = m.ExitPoint();
  x_lo = std::min(x_lo, exit[0] - 2 * m.params().mu_s);  // the stick band
  x_hi = std::max(x_hi, exit[0]);
  if (!po.has_stick_slip && po.pure_slip.empty()) {  // nothing periodic: around xbar
    x_lo = std::min(x_lo, po.steady.x - m.v()), x_hi = std::max(x_hi, po.steady.x + m.v());
    y_lo = std::min(y_lo, -m.v());
  }
  const double wx = 0.25 * (x_hi - x_lo), wy = 0.25 * (y_hi - y_lo);
  r.x_lo = x_lo - wx, r.x_hi = x_hi + wx, r.xdot_lo = y_lo - wy, r.xdot_hi = y_hi + wy;
}

}  // namespace

BasinResult ClassifyBasins(const Model& model, const BasinOptions& options) {
  const std::string err = options.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  BasinResult res;
  OrbitScanOptions scan = options.scan;
  scan.cancelled = options.cancelled;
  res.orbits = FindPeriodicOrbits(model, scan);
  if (!res.orbits.ok()) {
    res.status = res.orbits.status == OrbitScanStatus::kCancelled ? BasinStatus::kCancelled
                                                                  : BasinStatus::kFailed;
    res.message = res.orbits.message;
    return res;
  }
  if (options.auto_range) {
    AutoRange(model, res);
  } else {
    res.x_lo = options.x_lo, res.x_hi = options.x_hi;
    res.xdot_lo = options.xdot_lo, res.xdot_hi = options.xdot_hi;
  }
  res.nx = options.nx, res.ny = options.ny;
  auto at = [](double lo, double hi, int i, int n) {
    return n == 1 ? 0.5 * (lo + hi) : lo + (hi - lo) * i / (n - 1);
  };
  Classifier c(model, options, res);
  const int total = res.nx * res.ny;
  for (int j = 0; j < res.ny; ++j) {
    for (int i = 0; i < res.nx; ++i) {
      BasinStart s;
      s.x = at(res.x_lo, res.x_hi, i, res.nx);
      s.xdot = at(res.xdot_lo, res.xdot_hi, j, res.ny);
      if (!c.Classify(s)) return res;
      ++res.count[static_cast<int>(s.fate)];
      res.starts.push_back(s);
      if (options.progress) options.progress(static_cast<int>(res.starts.size()), total);
    }
  }
  return res;
}

std::vector<Vec2> OrbitCurve(const Model& model, const Orbit& orbit, const FlowOptions& flow,
                             int n) {
  if (n < 2 || !(orbit.period > 0))
    throw InvalidArgument("OrbitCurve: need n >= 2 and an orbit with a period > 0");
  BeltFlow f(model, flow);
  std::vector<Vec2> pts;
  StopRule stop;
  stop.t_max = orbit.period;
  const FlowResult r = f.Run(0.0, orbit.start, Mode::kSlipBelow, stop, false, orbit.period / n,
                             [&](const Sample& s) { pts.push_back(s.z); });
  if (!r.ok()) throw Error("OrbitCurve: " + r.message);
  if (pts.empty() || (pts.back() - r.z).norm() > 0) pts.push_back(r.z);
  return pts;
}

namespace {
// Cubic Hermite interpolant on [0, 1] from values p0, p1 and slopes d0, d1
// (already scaled by the interval length).
double Hermite(double p0, double d0, double p1, double d1, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * d0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * d1;
}
}  // namespace

namespace {
// One pair of samples (p, q), and the next one when there is one: the
// crossing of x = xbar between p and q and the energy's minimum around q.
void DisturbanceStep(const Model& model, double xbar, const Sample& p, const Sample& q,
                     const Sample* next, Disturbance* d) {
  auto energy = [&](const Sample& s) {
    const double dx = s.z[0] - xbar;
    return 0.5 * (dx * dx + s.z[1] * s.z[1]);
  };
  const double h = q.t - p.t;
  if (!(h > 0)) return;
  // Crossing of x = xbar: root of the Hermite cubic in x, x' there from the
  // Hermite cubic in x' (slopes x'' from the field).
  const double f0 = p.z[0] - xbar, f1 = q.z[0] - xbar;
  if ((f0 > 0) != (f1 > 0)) {
    double lo = 0, hi = 1;
    for (int it = 0; it < Tolerances::kDisturbanceHalvings; ++it) {
      const double mid = 0.5 * (lo + hi);
      const double fm = Hermite(f0, h * p.z[1], f1, h * q.z[1], mid);
      ((fm > 0) == (f0 > 0) ? lo : hi) = mid;
    }
    const double s = 0.5 * (lo + hi);
    const double a0 = model.Acceleration(p.mode, p.z[0], p.z[1]);
    const double a1 = model.Acceleration(q.mode, q.z[0], q.z[1]);
    d->xdot = std::min(d->xdot, std::abs(Hermite(p.z[1], h * a0, q.z[1], h * a1, s)));
  }
  // Energy minimum: a parabola through three samples around a local minimum.
  const double e1 = energy(q);
  d->energy = std::min(d->energy, e1);
  if (next) {
    const double e0 = energy(p), e2 = energy(*next);
    const double curv = e0 - 2 * e1 + e2;
    if (e1 <= e0 && e1 <= e2 && curv > 0)
      d->energy = std::min(d->energy, e1 - (e2 - e0) * (e2 - e0) / (8 * curv));
  }
}
}  // namespace

Disturbance SmallestDisturbance(const Model& model, const Orbit& orbit, const FlowOptions& flow,
                                int n, std::function<bool()> cancelled) {
  if (orbit.kind != OrbitKind::kPureSlip)
    throw InvalidArgument("SmallestDisturbance: the orbit must be pure-slip");
  if (n < kMinDisturbanceSamples || n > kMaxDisturbanceSamples)
    throw InvalidArgument("SmallestDisturbance: n = " + std::to_string(n) + " outside [" +
                          std::to_string(kMinDisturbanceSamples) + ", " +
                          std::to_string(kMaxDisturbanceSamples) + "]");
  const double xbar = model.SteadySliding().x;
  BeltFlow f(model, flow);
  if (cancelled) f.set_cancel(cancelled);
  Disturbance d;
  // The x extremes are where the orbit crosses x' = 0.
  d.x = std::min(orbit.extrema.x_max - xbar, xbar - orbit.extrema.x_min);
  d.xdot = std::numeric_limits<double>::infinity();
  d.energy = std::numeric_limits<double>::infinity();
  // The samples stream through a window of three: memory does not grow with n.
  Sample w[3];
  int have = 0;
  auto take = [&](const Sample& s) {
    if (have == 3) w[0] = w[1], w[1] = w[2], have = 2;
    w[have++] = s;
    if (have == 3) DisturbanceStep(model, xbar, w[0], w[1], &w[2], &d);
  };
  StopRule stop;
  stop.t_max = orbit.period;
  const FlowResult r =
      f.Run(0.0, orbit.start, Mode::kSlipBelow, stop, false, orbit.period / n, take);
  if (r.status == FlowStatus::kCancelled) {
    Disturbance c;
    c.cancelled = true;
    return c;
  }
  if (!r.ok()) throw Error("SmallestDisturbance: " + r.message);
  if (have >= 2) DisturbanceStep(model, xbar, w[have - 2], w[have - 1], nullptr, &d);
  return d;
}

}  // namespace stickslip
