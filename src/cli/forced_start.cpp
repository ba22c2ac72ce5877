// The orbits a forced branch starts on (forced_start.hpp).
#include "cli/forced_start.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "cli/app.hpp"
#include "stickslip/basin/attractors.hpp"
#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/forced/flow.hpp"
#include "stickslip/forced/orbit.hpp"
#include "stickslip/orbits/orbit_search.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip::cli {

void AddStartOptions(po::options_description& d) {
  d.add_options()("all", po::bool_switch(),
                  "forced: continue a branch from each orbit of the start list (the orbits at "
                  "--from that the scan finds, m <= 12, and the attractor reached from rest, any "
                  "m <= 32; printed, numbered by m then x_max)")(
      "m", Value()->value_name("M"),
      "forced: start on an orbit of least period M forcing periods, in [1, 64] (the attractor "
      "if one has period M, else the first); with --all each orbit of period M; --point N (no "
      "--restart) starts on orbit N of the start list (default: the attractor reached from "
      "rest)");
}

StartChoice StartChoiceFromArguments(const Arguments& args, bool restart) {
  StartChoice c;
  c.all = args.Flag("all");
  if (args.Given("m")) {
    const long m = args.Integer("m", 0);
    if (m < 1 || m > OrbitSearchOptions::kMaxMultiple)
      throw UsageError("invalid value '" + args.Text("m") + "' for " + args.Source("m") +
                       ": must be an integer in [1, " +
                       std::to_string(OrbitSearchOptions::kMaxMultiple) + "]");
    c.m = static_cast<int>(m);
  }
  if (restart) {  // --point is the restart's label
    for (const char* o : {"all", "m"})
      if (args.Given(o) && (std::string(o) != "all" || c.all))
        throw UsageError(args.Source(o) +
                         " chooses the start orbit of a new run; with --restart the branch "
                         "starts at the restart point");
    return StartChoice();
  }
  if (args.Given("point")) {
    const long n = args.Integer("point", 0);
    if (n < 1)
      throw UsageError("invalid value '" + args.Text("point") + "' for " + args.Source("point") +
                       ": without --restart, the number (>= 1) of an orbit of the start list");
    c.point = static_cast<int>(std::min<long>(n, 1L << 30));
    if (c.all)
      throw UsageError(args.Source("point") + " " + args.Text("point") +
                       " picks one start orbit; --all continues each: give one of them");
  }
  return c;
}

Vec2 SettledState(const ForcedModel& model, const OrbitBranchOptions& o) {
  FlowRequest rq;
  rq.t_max = kTransientPeriods * model.period();
  rq.max_steps = o.shooting.flow.max_steps;
  rq.extrema = {0, 1};
  const FlowRun tr = Flow(model, o.shooting.flow).Run(ForcedStart(model, 0, 0, model.v()), rq);
  if (Reached(tr) && std::abs(tr.end.z[0]) <= o.max_amplitude)
    return Vec2(tr.end.z[0], tr.end.z[1]);
  return Vec2(0, model.v());
}

OrbitBranch ContinueFrom(const ForcedParams& base, ParameterAxis axis, double from, double to,
                         const StartOrbit& o, const OrbitBranchOptions& opts, RunControl& run) {
  OrbitBranchOptions c = opts;
  c.palc.cancelled = [&run] { return run.Cancelled(); };  // SIGINT, --max_time
  OrbitBranch b = ContinueForced(base, axis, from, to, o.x, o.xdot, o.m, c);
  if (b.status == BranchStatus::kCancelled) b.message = run.Reason();
  return b;
}

std::optional<StartOrbit> SettledStart(const ForcedModel& model, double x, double xdot,
                                       const OrbitBranchOptions& o, RunControl& run) {
  AttractorOptions bo;
  bo.max_period = kSettleMaxPeriod;
  bo.iterate.flow = o.shooting.flow;
  bo.iterate.transient = bo.iterate.align;
  bo.iterate.keep = 2 * kSettleMaxPeriod;
  bo.max_amplitude = o.max_amplitude;
  const SectionRun r = IterateStroboscopic(
      model, ForcedStart(model, 0, x, xdot), bo.iterate, [&run] { return run.Cancelled(); },
      o.max_amplitude);
  if (r.status != LyapunovStatus::kDone) return std::nullopt;
  const Attractor a = ClassifyAttractor(model, r, bo);
  if (a.kind != AttractorKind::kPeriodic) return std::nullopt;
  StartOrbit s;
  s.m = a.m, s.sticks = a.sticks, s.stable = true, s.settled = true;
  s.x = a.z[0], s.xdot = a.z[1];
  // Its extrema and multipliers: the orbit solved from the settled point.
  const PeriodicOrbit orbit = ShootStroboscopic(model, a.z[0], a.z[1], a.m, o.shooting);
  if (orbit.ok()) {
    s.x_max = OrbitExtrema(orbit).x_max;
    s.mult_max = std::abs(orbit.multipliers[0]);
  }
  return s;
}

namespace {

// The settled point lies on a scanned orbit: same m, near one of its points
// (the settled iterate is within the attractor's contraction of it).
bool SameOrbit(const FoundOrbit& o, const StartOrbit& s) {
  if (o.m != s.m) return false;
  for (const Eigen::VectorXd& p : o.points)
    if (std::abs(p[0] - s.x) + std::abs(p[1] - s.xdot) <=
        1e-5 * (1 + std::abs(s.x) + std::abs(s.xdot)))
      return true;
  return false;
}

}  // namespace

std::vector<StartOrbit> StartOrbits(const ForcedModel& model,
                                    const std::optional<StartOrbit>& settled,
                                    const OrbitBranchOptions& o, int m, RunControl& run) {
  OrbitSearchOptions so;
  so.half_width = model.SearchBox();
  so.orbit = o.shooting;
  so.min_m = m > 0 ? m : 1;
  so.max_m = m > 0 ? m : kStartScanMaxM;
  so.cancelled = [&run] { return run.Cancelled(); };
  const FoundOrbits r = FindOrbits(model, so);
  std::vector<StartOrbit> list;
  bool found = false;
  for (const FoundOrbit& f : r.orbits) {
    if (std::abs(OrbitExtrema(f.orbit).x_max) > o.max_amplitude) continue;
    StartOrbit s;
    s.m = f.m, s.sticks = f.orbit.sticks, s.stable = f.orbit.stable;
    s.settled = settled && SameOrbit(f, *settled);
    found = found || s.settled;
    s.x = f.points[0][0], s.xdot = f.points[0][1];
    s.x_max = OrbitExtrema(f.orbit).x_max, s.mult_max = std::abs(f.orbit.multipliers[0]);
    list.push_back(s);
  }
  if (settled && !found && (m == 0 || settled->m == m)) list.push_back(*settled);
  std::stable_sort(list.begin(), list.end(), [](const StartOrbit& a, const StartOrbit& b) {
    return a.m != b.m ? a.m < b.m : a.x_max < b.x_max;
  });
  return list;
}

std::vector<StartOrbit> ChooseStart(const std::vector<StartOrbit>& list, const StartChoice& c,
                                    const std::string& where) {
  if (c.point > 0) {
    if (c.point > static_cast<int>(list.size()))
      throw UsageError("invalid value '" + std::to_string(c.point) +
                       "' for --point: the start list at " + where + " has " +
                       std::to_string(list.size()) + " orbit" + (list.size() == 1 ? "" : "s") +
                       (c.m > 0 ? " of period m = " + std::to_string(c.m) : ""));
    return {list[c.point - 1]};
  }
  if (c.all) return list;
  for (bool settled : {true, false})  // the attractor reached from rest, else any stable one
    for (const StartOrbit& s : list)
      if (s.stable && (s.settled || !settled)) return {s};
  if (c.m > 0 && !list.empty()) return {list.front()};
  return {};
}

void PrintStartOrbits(std::ostream& os, const std::vector<StartOrbit>& list,
                      const std::string& where) {
  os << "start orbits at " << where << " (--point N continues orbit N):\n";
  for (size_t k = 0; k < list.size(); ++k) {
    const StartOrbit& s = list[k];
    os << "  " << k + 1 << ": m = " << s.m << ", " << s.sticks << " sticks, x_max "
       << FormatNumber(s.x_max) << ", |multiplier| " << FormatNumber(s.mult_max) << ", "
       << (s.stable ? "stable" : "unstable")
       << (s.settled ? " (the attractor reached from rest)" : "") << "\n";
  }
}

}  // namespace stickslip::cli
