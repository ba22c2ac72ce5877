// Every periodic orbit of an autonomous system at one parameter point
// (orbit_search.hpp, FindAutonomousOrbits).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit_search.hpp"

namespace stickslip {

std::string AutonomousSearchOptions::ValidationError() const {
  const std::string e = orbit.ValidationError();
  if (!e.empty()) return e;
  const int na = static_cast<int>(amplitudes.size()), ns = static_cast<int>(starts.size());
  for (const std::string& range : {IntRangeError("amplitudes (count)", na, 0, kMaxAmplitudes),
                                   IntRangeError("starts (count)", ns, 0, kMaxStarts),
                                   IntRangeError("max_returns", max_returns, 1, kMaxReturns)})
    if (!range.empty()) return range;
  for (int i = 0; i < na; ++i)
    if (!(amplitudes[i] > 0 && amplitudes[i] <= kMaxAmplitude))
      return "amplitudes[" + std::to_string(i) + "] = " + Num(amplitudes[i]) + " must be in (0, " +
             Num(kMaxAmplitude) + "]";
  if (!(scale >= 0) || !std::isfinite(scale))
    return "scale = " + Num(scale) + " must be a finite number >= 0";
  if (!(transient > 0) || !std::isfinite(transient))
    return "transient = " + Num(transient) + " must be a finite number > 0";
  return "";
}

namespace {

constexpr double kSameExit = Tolerances::kSameStrobe;  // one orbit's points

bool SameExit(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() <= kSameExit * (1 + a.lpNorm<Eigen::Infinity>());
}

// d at max norm 1, its largest entry positive, on a grid of 2^-30: entries
// equal to rounding become equal, so a start on an invariant subspace of
// identical parts (x1 = x2 of identical blocks) lies exactly on it.
Eigen::VectorXd ModeDirection(const Eigen::VectorXd& v) {
  Eigen::Index i = 0;
  const double top = v.cwiseAbs().maxCoeff(&i);
  if (!(top > 0)) return Eigen::VectorXd();
  const double grid = std::ldexp(1.0, 30);
  return ((v / (v[i] > 0 ? top : -top)) * grid).array().round() / grid;
}

// Steady sliding: the rest point (System::Rest) of the first pure-slip mode
// that has one, in SteadySliding's order (equilibria/, below this layer):
// every contact below first, then the others by their bits, up to 6 contacts.
bool RestPoint(const System& s, ModeSet* mode, Eigen::VectorXd* z) {
  const int k = s.contacts();
  const long modes = k <= AutonomousSearchOptions::kRestModeContacts ? 1L << k : 1;
  for (long bits = 0; bits < modes; ++bits) {
    for (int c = 0; c < k; ++c) mode->set(c, (bits >> c) & 1 ? Mode::kSlipAbove : Mode::kSlipBelow);
    z->setZero(s.dimension());
    bool stable = false;
    if (s.Rest(*mode, *z, &stable)) return true;
  }
  return false;
}

// Steady sliding disturbed along each mode at each amplitude.
std::vector<ScanStart> ModalStarts(const System& s, const AutonomousSearchOptions& o) {
  std::vector<ScanStart> out;
  ModeSet mode;
  Eigen::VectorXd rest;
  if (!RestPoint(s, &mode, &rest)) return out;
  const int n = s.dimension();
  Eigen::MatrixXd J(n, n);
  s.Jacobian(mode, rest, J);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, true);
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return es.eigenvalues()[a].real() > es.eigenvalues()[b].real();
  });
  const double scale = o.scale > 0 ? o.scale : std::max(1.0, rest.lpNorm<Eigen::Infinity>());
  for (int k = 0; k < n; ++k) {
    const std::complex<double> lambda = es.eigenvalues()[order[k]];
    if (lambda.imag() < 0) continue;  // its pair's other member gives the same plane
    const Eigen::VectorXcd v = es.eigenvectors().col(order[k]);
    for (bool im : {false, true}) {
      if (im && lambda.imag() == 0) break;
      const Eigen::VectorXd d = ModeDirection(im ? v.imag().eval() : v.real().eval());
      if (d.size() == 0) continue;
      for (double a : o.amplitudes) out.push_back({rest + a * scale * d, k, im, a});
    }
  }
  return out;
}

class AutonomousSearch {
 public:
  AutonomousSearch(const System& s, const AutonomousSearchOptions& o)
      : s_(s), o_(o), flow_(s, o.orbit.flow), shooting_(s, o.orbit) {
    if (o.cancelled) flow_.set_cancel(o.cancelled), shooting_.flow().set_cancel(o.cancelled);
  }
  // Runs from start i and shoots from its last exits; false once cancelled.
  bool From(int i);
  AutonomousOrbits& result() { return r_; }

 private:
  bool Cancelled() {
    if (o_.cancelled && o_.cancelled()) r_.status = OrbitScanStatus::kCancelled;
    return !r_.ok();
  }
  bool Transient(const Eigen::VectorXd& z0, std::vector<FlowSwitch>* exits);
  bool OnePeriod(const PeriodicOrbit& p, int returns, AutonomousOrbit* o,
                 std::vector<ModeSet>* modes);
  void Add(const PeriodicOrbit& p, const PoincareSection& sec, int start);

  const System& s_;
  const AutonomousSearchOptions& o_;
  Flow flow_;
  Shooting shooting_;
  FlowRun run_;
  AutonomousOrbits r_;
};

// The run from z0 for the transient, in pieces, keeping its last
// 2 (max_returns + 1) stick exits (as SettleOnStickSlip).
bool AutonomousSearch::Transient(const Eigen::VectorXd& z0, std::vector<FlowSwitch>* exits) {
  std::vector<FlowSwitch> switches;
  FlowRequest req;
  req.max_steps = std::max(1L, o_.orbit.max_steps * 100 / Tolerances::kSettleChunks);
  req.switches = &switches;
  run_.end = FlowPoint{0, z0, ModeOf(s_, z0)};
  const std::size_t keep = 2 * (static_cast<std::size_t>(o_.max_returns) + 1);
  for (int c = 1; c <= Tolerances::kSettleChunks; ++c) {
    req.t_max = o_.transient * c / Tolerances::kSettleChunks;
    switches.clear();
    const FlowPoint from = run_.end;
    flow_.Run(from, req, &run_);
    for (const FlowSwitch& e : switches)
      if (e.kind == SwitchKind::kStickOut) exits->push_back(e);
    if (exits->size() > keep) exits->erase(exits->begin(), exits->end() - keep);
    if (run_.status != FlowStatus::kTimeLimit) break;
  }
  if (run_.status == FlowStatus::kCancelled) r_.status = OrbitScanStatus::kCancelled;
  return run_.status == FlowStatus::kTimeLimit;
}

// The orbit's exits over one period (the run to its returns-th exit), the
// modes they leave into, and its stick phases per contact; false where that
// run fails.
bool AutonomousSearch::OnePeriod(const PeriodicOrbit& p, int returns, AutonomousOrbit* o,
                                 std::vector<ModeSet>* modes) {
  std::vector<FlowSwitch> switches;
  FlowRequest req;
  req.max_steps = o_.orbit.max_steps;
  req.t_max = 2 * p.period + 1;
  req.stop_at_exit = returns;
  req.switches = &switches;
  flow_.Run(p.start, req, &run_);
  if (run_.status != FlowStatus::kStickExit) return false;
  o->points.assign(1, p.start.z);
  o->point_contacts.assign(1, o->section.contact);
  modes->assign(1, p.start.mode);
  o->sticks.assign(s_.contacts(), 0);
  for (const FlowSwitch& e : switches) {
    if (e.kind == SwitchKind::kStickIn) ++o->sticks[e.contact];
    if (e.kind == SwitchKind::kStickOut)
      o->points.push_back(e.z), o->point_contacts.push_back(e.contact), modes->push_back(e.after);
  }
  // The closing exit: the start again.
  o->points.pop_back(), o->point_contacts.pop_back(), modes->pop_back();
  return true;
}

// A converged orbit: at its least number of returns (an exit k in the
// start's state and mode: k returns close it), kept if new: not of a known
// orbit's period and sticks through one of its exits (any contact's, as
// identical blocks in step leave stick at one instant).
void AutonomousSearch::Add(const PeriodicOrbit& p, const PoincareSection& sec, int start) {
  AutonomousOrbit o;
  o.orbit = p, o.section = sec, o.start = start;
  std::vector<ModeSet> modes;
  if (!OnePeriod(o.orbit, sec.returns, &o, &modes)) return;
  for (int k = 1; k < static_cast<int>(o.points.size()); ++k)
    if (modes[k] == modes[0] && SameExit(o.points[0], o.points[k])) {
      o.section.returns = k;  // a multiple of a shorter orbit
      o.orbit = shooting_.Find(p.start, o.section);
      if (!o.orbit.ok() || !OnePeriod(o.orbit, k, &o, &modes)) return;
      break;
    }
  const double T = o.orbit.period;
  for (const AutonomousOrbit& known : r_.orbits) {
    if (std::abs(known.orbit.period - T) > kSameExit * (1 + T) || known.sticks != o.sticks)
      continue;
    for (std::size_t j = 0; j < known.points.size(); ++j)
      if (SameExit(known.points[j], o.orbit.start.z)) return;
  }
  r_.orbits.push_back(std::move(o));
}

bool AutonomousSearch::From(int i) {
  if (Cancelled()) return false;
  std::vector<FlowSwitch> exits;
  if (!Transient(r_.starts[i].z, &exits)) {
    if (!r_.ok()) return false;
    if (r_.failed++ == 0)
      r_.message = "the run from start " + std::to_string(i) + " ended " +
                   std::string(Name(run_.status)) + " at t = " + Num(run_.end.t) + ": " +
                   run_.message;
    return true;
  }
  const int n = static_cast<int>(exits.size());
  for (int c = 0; c < s_.contacts(); ++c) {
    int last = n - 1;
    while (last >= 0 && exits[last].contact != c) --last;
    if (last < 0) continue;
    const Eigen::VectorXd& z = exits[last].z;
    const double scale = 1 + z.lpNorm<Eigen::Infinity>();
    for (int r = 1; r <= o_.max_returns && r <= last; ++r) {
      const FlowSwitch& e = exits[last - r];
      if (e.contact != c || (e.z - z).lpNorm<Eigen::Infinity>() > Tolerances::kScanRecur * scale)
        continue;
      if (Cancelled()) return false;
      ++r_.shots;
      const PoincareSection sec = PoincareSection::StickExit(c, r);
      const PeriodicOrbit p = shooting_.Find(FlowPoint{0, z, exits[last].after}, sec);
      if (p.status == OrbitStatus::kCancelled) r_.status = OrbitScanStatus::kCancelled;
      if (!r_.ok()) return false;
      if (!p.ok()) continue;  // the next recurrence, if any
      ++r_.converged;
      Add(p, sec, i);
      break;
    }
  }
  return true;
}

}  // namespace

AutonomousOrbits FindAutonomousOrbits(const System& system,
                                      const AutonomousSearchOptions& options) {
  std::string e = options.ValidationError();
  const int n = system.dimension();
  if (e.empty() && system.clocks() != 0)
    e = "an autonomous orbit search needs a system with no clock, not " +
        std::to_string(system.clocks()) + " (FindOrbits scans a system with one)";
  for (std::size_t i = 0; e.empty() && i < options.starts.size(); ++i)
    if (options.starts[i].size() != n || !options.starts[i].allFinite())
      e = "starts[" + std::to_string(i) + "] must have " + std::to_string(n) + " finite components";
  if (!e.empty()) throw InvalidArgument(e);
  AutonomousSearch search(system, options);
  AutonomousOrbits& r = search.result();
  r.starts = ModalStarts(system, options);
  for (const Eigen::VectorXd& z : options.starts) r.starts.push_back({z, -1, false, 0});
  for (int i = 0; i < static_cast<int>(r.starts.size()); ++i)
    if (!search.From(i)) break;
  std::stable_sort(r.orbits.begin(), r.orbits.end(),
                   [](const AutonomousOrbit& a, const AutonomousOrbit& b) {
                     return a.orbit.period < b.orbit.period;
                   });
  return std::move(r);
}

}  // namespace stickslip
