// Every periodic orbit of a system with a clock (orbit_search.hpp).
#include "stickslip/orbits/orbit_search.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip {

std::string OrbitSearchOptions::ValidationError() const {
  const std::string e = orbit.ValidationError();
  if (!e.empty()) return e;
  for (const std::string& range : {IntRangeError("min_m", min_m, 1, kMaxMultiple),
                                   IntRangeError("max_m", max_m, min_m, kMaxMultiple),
                                   IntRangeError("max_sticks", max_sticks, 0, kMaxMultiple),
                                   IntRangeError("grid", grid, 0, kMaxGrid),
                                   IntRangeError("exit_samples", exit_samples, 2, kMaxExitSamples)})
    if (!range.empty()) return range;
  if (plane[0] < 0 || plane[1] < 0 || plane[0] == plane[1])
    return "plane = (" + std::to_string(plane[0]) + ", " + std::to_string(plane[1]) +
           ") must be two different state components";
  for (int i = 0; i < 2; ++i)
    if (!(half_width[i] >= 0) || !std::isfinite(half_width[i]))
      return "half_width[" + std::to_string(i) + "] = " + Num(half_width[i]) + " must be >= 0";
  for (Eigen::Index i = 0; i < center.size(); ++i)
    if (!std::isfinite(center[i]))
      return "center[" + std::to_string(i) + "] = " + Num(center[i]) + " must be finite";
  return "";
}

namespace {

constexpr double kSame = Tolerances::kSameStrobe;  // one orbit's points

class Search {
 public:
  Search(const System& s, const OrbitSearchOptions& o)
      : s_(s),
        o_(o),
        n_(s.dimension()),
        clock_(s.dimension() - 1),
        flow_(s, o.orbit.flow),
        shooting_(s, o.orbit) {
    rq_.max_steps = o.orbit.flow.max_steps;
    center_ = o.center.size() > 0 ? o.center : Eigen::VectorXd::Zero(n_);
    center_[clock_] = 0;
    T_ = PoincareSection::Stroboscopic(s, center_, 1).time;
  }
  bool Box();
  void Strobe();
  void ExitMap(int contact, Mode side);
  FoundOrbits Result();

 private:
  bool Cancelled() {
    if (o_.cancelled && o_.cancelled()) r_.status = OrbitScanStatus::kCancelled;
    return !r_.ok();
  }
  // Points are compared on the state without its clock.
  bool Same(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
    const auto x = a.head(clock_), y = b.head(clock_);
    return (x - y).cwiseAbs().maxCoeff() <= kSame * (1 + x.cwiseAbs().maxCoeff());
  }
  // One run from p to t_end (to the stop_at_exit-th stick exit if > 0, the
  // switches appended to `switches` if given): whether it reached its end.
  bool Run(const FlowPoint& p, double t_end, int stop_at_exit = 0,
           std::vector<FlowSwitch>* switches = nullptr) {
    rq_.t_max = t_end;
    rq_.stop_at_exit = stop_at_exit;
    rq_.switches = switches;
    flow_.Run(p, rq_, &run_);
    return run_.status == FlowStatus::kTimeLimit || run_.status == FlowStatus::kStickExit;
  }
  // The end of the last run as a stroboscopic point (its clock at 0).
  Eigen::VectorXd EndPoint() const {
    Eigen::VectorXd z = run_.end.z;
    z[clock_] = 0;
    return z;
  }
  std::vector<Eigen::VectorXd> Iterates(const Eigen::VectorXd& z, int n);
  void Add(const Eigen::VectorXd& z, int m, bool from_exit);
  FlowPoint ExitStart(int contact, Mode side, double t) const;
  PeriodicOrbit ExitOrbit(int contact, Mode side, double t_guess, int sticks, int m);

  const System& s_;
  const OrbitSearchOptions& o_;
  const int n_, clock_;
  Flow flow_;
  Shooting shooting_;
  FlowRequest rq_;
  FlowRun run_;
  Eigen::VectorXd center_;
  std::array<double, 2> half_{0, 0};
  double T_ = 0;  // the clock's period
  FoundOrbits r_;
};

// The box's half-widths: given, else a run's extent about the centre.
bool Search::Box() {
  half_ = o_.half_width;
  if (half_[0] > 0 && half_[1] > 0) return true;
  rq_.extrema = {o_.plane[0], o_.plane[1]};
  const bool reached = Run({0, center_, ModeOf(s_, center_)}, Tolerances::kSearchBoxPeriods * T_);
  rq_.extrema.clear();
  if (!reached) {
    r_.status = OrbitScanStatus::kFailed;
    r_.message = "the run that sizes the box of starts: " + run_.message;
    return false;
  }
  for (int i = 0; i < 2; ++i) {
    const double c = center_[o_.plane[i]];
    const double extent = std::max(run_.hi[i] - c, c - run_.lo[i]);
    if (half_[i] <= 0)
      half_[i] = std::max(Tolerances::kSearchBoxGrowth * extent,
                          Tolerances::kSearchBoxFloor * (1 + std::abs(c)));
  }
  return true;
}

// The stroboscopic iterates z, P(z), ..., P^n(z); fewer if the flow fails.
std::vector<Eigen::VectorXd> Search::Iterates(const Eigen::VectorXd& z, int n) {
  std::vector<Eigen::VectorXd> pts{z};
  for (int j = 0; j < n; ++j) {
    if (!Run({0, pts.back(), ModeOf(s_, pts.back())}, T_)) break;
    pts.push_back(EndPoint());
  }
  return pts;
}

// A converged fixed point of P^m: reduced to its least period, kept if new.
void Search::Add(const Eigen::VectorXd& z, int m, bool from_exit) {
  ++r_.converged;
  const std::vector<Eigen::VectorXd> pts = Iterates(z, m);
  if (static_cast<int>(pts.size()) <= m) return;
  int d = 1;
  while (d < m && !(m % d == 0 && Same(pts[d], z))) ++d;
  for (const FoundOrbit& known : r_.orbits)
    if (known.m == d)
      for (const Eigen::VectorXd& p : known.points)
        if (Same(p, z)) return;
  FoundOrbit o;
  o.orbit = shooting_.Find({0, z, ModeSet()}, PoincareSection::Stroboscopic(s_, z, d));
  if (!o.orbit.ok()) return;
  o.m = d;
  o.points.assign(pts.begin(), pts.begin() + d);
  o.from_exit_map = from_exit;
  r_.orbits.push_back(std::move(o));
}

void Search::Strobe() {
  const int n = o_.grid, a = o_.plane[0], b = o_.plane[1];
  const auto at = [&](int k, int i) {
    return n == 1 ? center_[o_.plane[k]]
                  : center_[o_.plane[k]] - half_[k] + 2 * half_[k] * i / (n - 1);
  };
  for (int m = o_.min_m; m <= o_.max_m; ++m)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (Cancelled()) return;
        Eigen::VectorXd z = center_;
        z[a] = at(0, i), z[b] = at(1, j);
        ++r_.shots;
        const PeriodicOrbit o =
            shooting_.Find({0, z, ModeSet()}, PoincareSection::Stroboscopic(s_, z, m));
        if (o.ok()) Add(o.start.z, m, false);
      }
}

// A stick exit of `contact` at time t into `side`: the centre with the
// clock at t, the contact's velocity 0 (OntoSurface) and its stick
// force on the limit the side leaves over (System::ProjectOnExit).
FlowPoint Search::ExitStart(int contact, Mode side, double t) const {
  FlowPoint p{t, center_, ModeSet()};
  p.z[clock_] = 2 * M_PI * t / T_;
  OntoSurface(s_.Contact(contact), p.z);
  p.mode = ModeOf(s_, p.z);
  p.mode.set(contact, Mode::kStick);
  const double sign = side == Mode::kSlipBelow ? 1 : -1;  // lambda = +mu_s N leaves below
  for (int pass = 0; pass < 2; ++pass)  // again at the moved state: a limit mu_s N(z)
    s_.ProjectOnExit(p.mode, contact, sign * s_.StaticLimit(contact, p.z), p.z);
  p.mode.set(contact, side);
  return p;
}

// Newton on the exit-phase map: from an exit at t_e to the sticks-th next
// and m clock turns on; the exit's time brought into [0, T).
PeriodicOrbit Search::ExitOrbit(int contact, Mode side, double t_guess, int sticks, int m) {
  shooting_.set_max_return_time((m + 2) * T_);  // well past the expected return
  PeriodicOrbit p = shooting_.Find(ExitStart(contact, side, t_guess),
                                   PoincareSection::StickExit(contact, sticks, m));
  if (!p.ok()) return p;
  const double t = p.start.z[clock_] * T_ / (2 * M_PI);
  p.start.t = t - std::floor(t / T_) * T_;
  p.start.z[clock_] = 2 * M_PI * p.start.t / T_;
  return p;
}

// Samples t_e -> the times of the next max_sticks exits, then solves every
// bracket of t'_s - t_e - m T on the lift (adjacent samples, the last one's
// neighbour being the first shifted by T).
void Search::ExitMap(int contact, Mode side) {
  const int N = o_.exit_samples, S = o_.max_sticks;
  std::vector<std::vector<double>> tp(N + 1, std::vector<double>(S, NAN));
  for (int i = 0; i < N; ++i) {
    if (Cancelled()) return;
    const double te = i * T_ / N;
    std::vector<FlowSwitch> ev;
    if (!Run(ExitStart(contact, side, te), te + (o_.max_m + 1) * T_, S, &ev)) continue;
    int s = 0;
    for (const FlowSwitch& e : ev)
      if (e.kind == SwitchKind::kStickOut && s < S)
        tp[i][s++] = e.contact == contact && e.after[contact] == side ? e.t : NAN;
  }
  for (int s = 0; s < S; ++s) tp[N][s] = tp[0][s] + T_;
  for (int i = 0; i < N; ++i)
    for (int s = 0; s < S; ++s) {
      const double a = i * T_ / N, b = (i + 1) * T_ / N;
      if (!std::isfinite(tp[i][s]) || !std::isfinite(tp[i + 1][s])) continue;
      for (int m = o_.min_m; m <= o_.max_m; ++m) {
        const double ga = tp[i][s] - a - m * T_, gb = tp[i + 1][s] - b - m * T_;
        if ((ga > 0) == (gb > 0)) continue;
        if (Cancelled()) return;
        ++r_.shots;
        const PeriodicOrbit e = ExitOrbit(contact, side, a + (b - a) * ga / (ga - gb), s + 1, m);
        if (!e.ok()) continue;
        // Its stroboscopic point: from the exit on to the next multiple of T.
        const double t1 = std::ceil(e.start.t / T_) * T_;
        if (t1 <= e.start.t) {  // the exit at phase 0 is its stroboscopic point
          Eigen::VectorXd z = e.start.z;
          z[clock_] = 0;
          Add(z, m, true);
        } else if (Run(e.start, t1)) {
          Add(EndPoint(), m, true);
        }
      }
    }
}

FoundOrbits Search::Result() {
  const int a = o_.plane[0];
  const auto top = [a](const FoundOrbit& o) {
    return o.orbit.hi.size() > a ? o.orbit.hi[a] : o.points[0][a];
  };
  std::sort(r_.orbits.begin(), r_.orbits.end(), [&](const FoundOrbit& x, const FoundOrbit& y) {
    return x.m != y.m ? x.m < y.m : top(x) < top(y);
  });
  r_.half_width = half_;
  return r_;
}

}  // namespace

FoundOrbits FindOrbits(const System& system, const OrbitSearchOptions& options) {
  std::string e = options.ValidationError();
  const int n = system.dimension();
  if (e.empty() && system.clocks() != 1)
    e = "an orbit search needs a system with one clock, not " + std::to_string(system.clocks()) +
        (system.clocks() == 0 ? " (FindAutonomousOrbits scans one with none)" : "");
  if (e.empty() && (options.plane[0] >= n - 1 || options.plane[1] >= n - 1))
    e = "plane = (" + std::to_string(options.plane[0]) + ", " + std::to_string(options.plane[1]) +
        "): the components are 0.." + std::to_string(n - 2) + " (the clock is " +
        std::to_string(n - 1) + ")";
  if (e.empty() && options.center.size() != 0 && options.center.size() != n)
    e = "center: " + std::to_string(options.center.size()) + " values, the system has " +
        std::to_string(n);
  if (!e.empty()) throw InvalidArgument(e);
  Search search(system, options);
  if (!search.Box()) return search.Result();
  if (options.max_sticks > 0)
    for (int c = 0; c < system.contacts(); ++c)
      for (Mode side : {Mode::kSlipBelow, Mode::kSlipAbove}) search.ExitMap(c, side);
  search.Strobe();
  return search.Result();
}

}  // namespace stickslip
