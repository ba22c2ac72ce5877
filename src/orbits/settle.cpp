// The stick-slip attractor a run settles on (settle.hpp).
#include "stickslip/orbits/settle.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

// The least r (1..max) for which exit L - r is of L's contact and within
// kSettleRecur of it; 0 if none. *closest: the smallest such distance seen.
int Recurrence(const std::vector<FlowSwitch>& exits, int max, double* closest) {
  const FlowSwitch& last = exits.back();
  const double scale = 1 + last.z.lpNorm<Eigen::Infinity>();
  *closest = INFINITY;
  const int n = static_cast<int>(exits.size());
  for (int r = 1; r <= max && r < n; ++r) {
    const FlowSwitch& e = exits[n - 1 - r];
    if (e.contact != last.contact) continue;
    const double d = (e.z - last.z).lpNorm<Eigen::Infinity>() / scale;
    *closest = std::min(*closest, d);
    if (d <= Tolerances::kSettleRecur) return r;
  }
  return 0;
}

// Why a settling run that did not reach its transient ended.
std::string Ended(const FlowRun& run) {
  if (run.status == FlowStatus::kCancelled) return "cancelled";
  return "the settling run ended " + std::string(Name(run.status)) + " at t = " + Num(run.end.t) +
         (run.message.empty() ? "" : ": " + run.message);
}

// A system with a clock: its state at every clock turn (the stroboscopic
// map), kept for the last max_returns + 1 turns; the least m for which the
// point m turns back is within kSettleRecur of the last (the tangent block:
// the clock has turned) gives Stroboscopic(m) and Shooting::Find's guess.
SettledOrbit SettleStroboscopic(const System& system, const Eigen::VectorXd& z0,
                                const SettleOptions& options) {
  SettledOrbit out;
  Shooting shooting(system, options.shooting);
  Flow& flow = shooting.flow();
  if (options.cancelled) flow.set_cancel(options.cancelled);
  const int nt = system.tangent_dimension(), clock = system.dimension() - 1;
  const double turn = PoincareSection::Stroboscopic(system, z0, 1).time;
  const double turns = std::ceil(options.transient / turn);
  if (!(turns <= Tolerances::kSettleMaxTurns)) {
    out.message = "the transient " + Num(options.transient) + " is " + Num(turns, 3) +
                  " clock turns of " + Num(turn, 6) + ", more than " +
                  Num(Tolerances::kSettleMaxTurns, 3);
    return out;
  }
  std::deque<Eigen::VectorXd> kept;
  FlowRequest req;
  // The whole run's step budget, as the autonomous settle's.
  long budget = options.shooting.max_steps * 100;
  FlowRun run;
  run.end = FlowPoint{0, z0, ModeOf(system, z0)};
  for (long k = 1; k <= static_cast<long>(turns); ++k) {
    req.t_max = static_cast<double>(k) * turn;
    req.max_steps = std::max(1L, budget);
    const FlowPoint from = run.end;
    flow.Run(from, req, &run);
    budget -= run.steps;
    out.stick_exits += run.exits;
    if (run.status != FlowStatus::kTimeLimit) break;
    kept.push_back(run.end.z);
    if (kept.size() > static_cast<std::size_t>(options.max_returns) + 1) kept.pop_front();
  }
  out.run = run.status;
  if (run.status != FlowStatus::kTimeLimit) {
    out.message = Ended(run);
    return out;
  }
  if (kept.size() < 2) {
    out.message = "the transient " + Num(options.transient) +
                  " holds fewer than 2 clock turns of " + Num(turn, 6);
    return out;
  }
  const Eigen::VectorXd& last = kept.back();
  const double scale = 1 + last.head(nt).lpNorm<Eigen::Infinity>();
  double closest = INFINITY;
  int m = 0;
  const int n = static_cast<int>(kept.size());
  for (int r = 1; r < n && m == 0; ++r) {
    const double d = (kept[n - 1 - r] - last).head(nt).lpNorm<Eigen::Infinity>() / scale;
    closest = std::min(closest, d);
    if (d <= Tolerances::kSettleRecur) m = r;
  }
  if (m == 0) {
    out.message = "no clock-turn point recurs within " + std::to_string(options.max_returns) +
                  " turns (closest " + Num(closest, 3) + "): not settled, or not periodic";
    return out;
  }
  // At the start's own phase (the turns' are it + 2 pi k, to rounding).
  FlowPoint start{0, last, run.end.mode};
  start.z[clock] = std::remainder(z0[clock], 2 * M_PI);
  out.recurred = true;
  out.section = PoincareSection::Stroboscopic(system, start.z, m);
  out.orbit = shooting.Find(start, out.section);
  out.found = out.orbit.ok();
  if (!out.found)
    out.message = "Newton from the settled clock-turn point failed (" +
                  std::string(Name(out.orbit.status)) + "): " + out.orbit.message;
  return out;
}

}  // namespace

std::string SettleOptions::ValidationError() const {
  if (!(transient > 0) || !std::isfinite(transient))
    return "transient = " + Num(transient) + " must be a finite number > 0";
  if (max_returns < 1) return IntRangeError("max_returns", max_returns, 1, 1 << 20);
  return shooting.ValidationError();
}

SettledOrbit SettleOnStickSlip(const System& system, const Eigen::VectorXd& z0,
                               const SettleOptions& options) {
  std::string e = options.ValidationError();
  if (e.empty() && system.clocks() > 1)
    e = "the system has " + std::to_string(system.clocks()) +
        " clocks: no one stroboscopic section";
  if (e.empty() && (z0.size() != system.dimension() || !z0.allFinite()))
    e = "the start must have " + std::to_string(system.dimension()) + " finite components";
  if (!e.empty()) throw InvalidArgument(e);
  if (system.clocks() == 1) return SettleStroboscopic(system, z0, options);
  SettledOrbit out;
  Shooting shooting(system, options.shooting);
  Flow& flow = shooting.flow();
  if (options.cancelled) flow.set_cancel(options.cancelled);
  // In kSettleChunks pieces, each keeping only the last max_returns + 1 stick
  // exits: the switches held stay bounded by one piece's.
  std::vector<FlowSwitch> switches, kept;
  FlowRequest req;
  // The whole run's step budget, shared by the pieces.
  req.max_steps = std::max(1L, options.shooting.max_steps * 100 / Tolerances::kSettleChunks);
  req.switches = &switches;
  FlowRun run;
  run.end = FlowPoint{0, z0, ModeOf(system, z0)};
  for (int c = 1; c <= Tolerances::kSettleChunks; ++c) {
    req.t_max = options.transient * c / Tolerances::kSettleChunks;
    switches.clear();
    const FlowPoint from = run.end;
    flow.Run(from, req, &run);
    for (const FlowSwitch& s : switches)
      if (s.kind == SwitchKind::kStickOut) kept.push_back(s), ++out.stick_exits;
    const std::size_t keep = static_cast<std::size_t>(options.max_returns) + 1;
    if (kept.size() > keep) kept.erase(kept.begin(), kept.end() - keep);
    if (run.status != FlowStatus::kTimeLimit) break;
  }
  out.run = run.status;
  const std::vector<FlowSwitch>& exits = kept;
  if (run.status != FlowStatus::kTimeLimit) {
    out.message = Ended(run);
    return out;
  }
  double closest = INFINITY;
  const int r = exits.size() < 2 ? 0 : Recurrence(exits, options.max_returns, &closest);
  if (r == 0) {
    out.message =
        exits.size() < 2
            ? (exits.empty() ? "no stick phase" : "a single stick exit") + std::string(" by t = ") +
                  Num(options.transient) + " (then steady sliding or a pure-slip motion)"
            : "no stick exit recurs within " + std::to_string(options.max_returns) +
                  " exits (closest " + Num(closest, 3) + "): not settled, or not periodic";
    return out;
  }
  const FlowSwitch& last = exits.back();
  out.recurred = true;
  out.section = PoincareSection::StickExit(last.contact, r);
  out.orbit = shooting.Find(FlowPoint{0, last.z, last.after}, out.section);
  out.found = out.orbit.ok();
  if (!out.found)
    out.message = "Newton from the settled stick exit failed (" +
                  std::string(Name(out.orbit.status)) + "): " + out.orbit.message;
  return out;
}

}  // namespace stickslip
