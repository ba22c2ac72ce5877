// Every periodic orbit at one parameter point (forced/orbit_scan.hpp).
#include <algorithm>
#include <cmath>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/orbit_scan.hpp"

namespace stickslip {

std::string ForcedScanOptions::ValidationError() const {
  const std::string e = orbit.ValidationError();
  if (!e.empty()) return e;
  for (const std::string& range : {IntRangeError("min_m", min_m, 1, kMaxMultiple),
                                   IntRangeError("max_m", max_m, min_m, kMaxMultiple),
                                   IntRangeError("max_sticks", max_sticks, 0, kMaxMultiple),
                                   IntRangeError("grid", grid, 0, kMaxGrid),
                                   IntRangeError("exit_samples", exit_samples, 2, kMaxExitSamples)})
    if (!range.empty()) return range;
  if (!(radius >= 0) || !std::isfinite(radius)) return "radius = " + Num(radius) + " must be >= 0";
  return "";
}

namespace {

constexpr double kSame = Tolerances::kSameStrobe;  // one orbit's points

double Edge(const ForcedModel& m, double t, Mode mode) {
  const double s = mode == Mode::kSlipBelow ? 1 : -1;
  return s * m.static_limit() - 2 * m.beta() * m.v() + m.force() * std::cos(m.omega() * t);
}

bool Same(const Vec2& a, const Vec2& b) {
  return (a - b).cwiseAbs().maxCoeff() <= kSame * (1 + a.cwiseAbs().maxCoeff());
}

class Scan {
 public:
  Scan(const ForcedModel& m, const ForcedScanOptions& o) : m_(m), o_(o), flow_(m, o.orbit.flow) {
    rq_.max_steps = o.orbit.flow.max_steps;
  }
  bool Cancelled() {
    if (o_.cancelled && o_.cancelled()) r_.status = OrbitScanStatus::kCancelled;
    return !r_.ok();
  }
  // The stroboscopic iterates z, P(z), ..., P^n(z); fewer if the flow fails.
  std::vector<Vec2> Iterates(const Vec2& z, int n) {
    std::vector<Vec2> pts{z};
    for (int j = 0; j < n; ++j) {
      if (!Run(ForcedStart(m_, 0, pts.back()[0], pts.back()[1]), m_.period())) break;
      pts.emplace_back(run_.end.z[0], run_.end.z[1]);
    }
    return pts;
  }
  // One run from p to t_end (to the stop_at_exit-th stick exit if > 0, the
  // switches appended to `switches` if given): whether it reached its end.
  bool Run(const FlowPoint& p, double t_end, int stop_at_exit = 0,
           std::vector<FlowSwitch>* switches = nullptr) {
    rq_.t_max = t_end;
    rq_.stop_at_exit = stop_at_exit;
    rq_.switches = switches;
    flow_.Run(p, rq_, &run_);
    return Reached(run_);
  }
  // A converged fixed point of P^m: reduced to its least period, kept if new.
  void Add(const Vec2& z, int m, bool from_exit) {
    ++r_.converged;
    const std::vector<Vec2> pts = Iterates(z, m);
    if (static_cast<int>(pts.size()) <= m) return;
    int d = 1;
    while (d < m && !(m % d == 0 && Same(pts[d], z))) ++d;
    for (const ForcedScanOrbit& known : r_.orbits)
      if (known.m == d)
        for (const Vec2& p : known.points)
          if (Same(p, z)) return;
    ForcedScanOrbit o;
    o.orbit = ShootStroboscopic(m_, z[0], z[1], d, o_.orbit);
    if (!o.orbit.ok()) return;
    o.m = d;
    o.points.assign(pts.begin(), pts.begin() + d);
    o.from_exit_map = from_exit;
    r_.orbits.push_back(o);
  }
  void Strobe();
  void ExitMap(Mode mode);
  ForcedOrbits Result() {
    std::sort(r_.orbits.begin(), r_.orbits.end(), [](const auto& a, const auto& b) {
      return a.m != b.m ? a.m < b.m : OrbitExtrema(a.orbit).x_max < OrbitExtrema(b.orbit).x_max;
    });
    return r_;
  }

 private:
  const ForcedModel& m_;
  const ForcedScanOptions& o_;
  Flow flow_;
  FlowRequest rq_;
  FlowRun run_;
  ForcedOrbits r_;
};

void Scan::Strobe() {
  const double w = m_.omega(), b = m_.beta();
  const double r = o_.radius > 0 ? o_.radius
                                 : m_.force() / std::max({std::abs(1 - w * w), 2 * b * w, 0.2}) +
                                       m_.static_limit() + m_.v();
  const double rv = r * std::max(1.0, w);
  const int n = o_.grid;
  for (int m = o_.min_m; m <= o_.max_m; ++m)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (Cancelled()) return;
        const double x = n == 1 ? 0 : -r + 2 * r * i / (n - 1);
        const double xd = n == 1 ? m_.v() : -rv + 2 * rv * j / (n - 1);
        ++r_.shots;
        const PeriodicOrbit o = ShootStroboscopic(m_, x, xd, m, o_.orbit);
        if (o.ok()) Add(Vec2(o.start.z[0], o.start.z[1]), m, false);
      }
}

// Samples t_e -> the times of the next max_sticks exits, then solves every
// bracket of t'_s - t_e - m T on the lift (adjacent samples, the last one's
// neighbour being the first shifted by T).
void Scan::ExitMap(Mode mode) {
  const int N = o_.exit_samples, S = o_.max_sticks;
  const double T = m_.period();
  std::vector<std::vector<double>> tp(N + 1, std::vector<double>(S, NAN));
  for (int i = 0; i < N; ++i) {
    if (Cancelled()) return;
    const double te = i * T / N;
    std::vector<FlowSwitch> ev;
    if (!Run(ForcedStart(m_, te, Edge(m_, te, mode), m_.v(), mode), te + (o_.max_m + 1) * T, S,
             &ev))
      continue;
    int s = 0;
    for (const FlowSwitch& e : ev)
      if (e.kind == SwitchKind::kStickOut && s < S) tp[i][s++] = e.after[0] == mode ? e.t : NAN;
  }
  for (int s = 0; s < S; ++s) tp[N][s] = tp[0][s] + T;
  for (int i = 0; i < N; ++i)
    for (int s = 0; s < S; ++s) {
      const double a = i * T / N, b = (i + 1) * T / N;
      if (!std::isfinite(tp[i][s]) || !std::isfinite(tp[i + 1][s])) continue;
      for (int m = o_.min_m; m <= o_.max_m; ++m) {
        const double ga = tp[i][s] - a - m * T, gb = tp[i + 1][s] - b - m * T;
        if ((ga > 0) == (gb > 0)) continue;
        if (Cancelled()) return;
        ++r_.shots;
        const double guess = a + (b - a) * ga / (ga - gb);
        const PeriodicOrbit e = ExitPhaseOrbit(m_, guess, mode, s + 1, m, o_.orbit);
        if (!e.ok()) continue;
        // Its stroboscopic point: from the exit on to the next multiple of T.
        const double t1 = std::ceil(e.start.t / T) * T;
        if (t1 <= e.start.t)  // the exit at phase 0 is its stroboscopic point
          Add(Vec2(e.start.z[0], m_.v()), m, true);
        else if (Run(ForcedStart(m_, e.start.t, e.start.z[0], m_.v(), mode), t1))
          Add(Vec2(run_.end.z[0], run_.end.z[1]), m, true);
      }
    }
}

}  // namespace

ForcedOrbits FindForcedOrbits(const ForcedModel& model, const ForcedScanOptions& options) {
  const std::string e = options.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  Scan scan(model, options);
  if (options.max_sticks > 0) {
    scan.ExitMap(Mode::kSlipBelow);
    scan.ExitMap(Mode::kSlipAbove);
  }
  scan.Strobe();
  return scan.Result();
}

}  // namespace stickslip
