// The orbits a branch of a system with a clock starts on (clock_start.hpp).
#include "cli/clock_start.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "cli/app.hpp"
#include "stickslip/basin/attractors.hpp"
#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/orbits/orbit_search.hpp"

namespace stickslip::cli {

namespace {

// The state of tangent point z at phase 0 (the clock at 0), in Filippov's mode.
FlowPoint AtPhase0(const System& system, const Eigen::VectorXd& z) {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(system.dimension());
  full.head(z.size()) = z;
  return {0, full, ModeOf(system, full)};
}

double MultMax(const PeriodicOrbit& o) {
  double m = 0;
  for (const auto& mu : o.multipliers) m = std::max(m, std::abs(mu));
  return m;
}

// The settled point lies on a scanned orbit: same m, near one of its points
// (the settled iterate is within the attractor's contraction of it).
bool SameOrbit(const FoundOrbit& o, const StartOrbit& s) {
  if (o.m != s.m) return false;
  const Eigen::Index n = s.z.size();
  for (const Eigen::VectorXd& p : o.points)
    if ((p.head(n) - s.z).lpNorm<1>() <= 1e-5 * (1 + s.z.lpNorm<1>())) return true;
  return false;
}

}  // namespace

void AddStartOptions(po::options_description& d) {
  d.add_options()(
      "all", po::bool_switch(),
      "continue a branch from each orbit of the start list, printed and numbered: with "
      "a clock (the forced oscillator) the orbits at --from that the scan finds, m <= "
      "12, and the attractor reached from rest, any m <= 32, by m then x_max; with "
      "none (chain, mode_coupling) the orbits at --start_at that runs from steady sliding "
      "moved along each mode settle on, by period")(
      "m", Value()->value_name("M"),
      "a system with a clock: start on an orbit of least period M clock turns, in [1, 64] (the "
      "attractor if one has period M, else the first); with --all each orbit of period M; "
      "--point N (no --restart) starts on orbit N of the start list, with a clock or none "
      "(default: the attractor reached from rest, or settled on from steady sliding)");
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

Eigen::VectorXd SettledState(const System& system, const ClockStart& c) {
  const int n = system.tangent_dimension();
  FlowRequest rq;
  rq.t_max = kTransientPeriods * PoincareSection::Stroboscopic(system, c.rest, 1).time;
  rq.max_steps = c.opts.shooting.flow.max_steps;
  for (int i = 0; i < std::min(n, 2); ++i) rq.extrema.push_back(i);
  const FlowRun tr =
      Flow(system, c.opts.shooting.flow).Run({0, c.rest, ModeOf(system, c.rest)}, rq);
  const bool reached = tr.status == FlowStatus::kTimeLimit || tr.status == FlowStatus::kStickExit;
  if (reached && std::abs(tr.end.z[0]) <= c.opts.max_amplitude) return tr.end.z.head(n);
  return c.rest.head(n);
}

std::optional<StartOrbit> SettledStart(const System& system, const Eigen::VectorXd& z,
                                       const ClockStart& c, RunControl& run) {
  AttractorOptions bo;
  bo.max_period = kSettleMaxPeriod;
  bo.iterate.flow = c.opts.shooting.flow;
  bo.iterate.transient = bo.iterate.align;
  bo.iterate.keep = 2 * kSettleMaxPeriod;
  bo.max_amplitude = c.opts.max_amplitude;
  const SectionRun r = IterateStroboscopic(
      system, AtPhase0(system, z), bo.iterate, [&run] { return run.Cancelled(); },
      c.opts.max_amplitude);
  if (r.status != LyapunovStatus::kDone) return std::nullopt;
  const Attractor a = ClassifyAttractor(system, r, bo);
  if (a.kind != AttractorKind::kPeriodic) return std::nullopt;
  StartOrbit s;
  s.m = a.m, s.sticks = a.sticks, s.stable = true, s.settled = true;
  s.z = a.z;
  // Its extrema and multipliers: the orbit solved from the settled point.
  const FlowPoint at = AtPhase0(system, a.z);
  const PeriodicOrbit orbit =
      Shooting(system, c.opts.shooting)
          .Find({0, at.z, ModeSet()}, PoincareSection::Stroboscopic(system, at.z, a.m));
  if (orbit.ok()) {
    s.x_max = orbit.hi.size() ? orbit.hi[0] : 0;
    s.mult_max = MultMax(orbit);
  }
  return s;
}

std::vector<StartOrbit> StartOrbits(const System& system, const std::optional<StartOrbit>& settled,
                                    const ClockStart& c, int m, RunControl& run) {
  OrbitSearchOptions so;
  so.half_width = c.box;
  so.orbit = c.opts.shooting;
  so.min_m = m > 0 ? m : 1;
  so.max_m = m > 0 ? m : kStartScanMaxM;
  so.cancelled = [&run] { return run.Cancelled(); };
  const FoundOrbits r = FindOrbits(system, so);
  std::vector<StartOrbit> list;
  bool found = false;
  for (const FoundOrbit& f : r.orbits) {
    const double x_max = f.orbit.hi.size() ? f.orbit.hi[0] : 0;
    if (std::abs(x_max) > c.opts.max_amplitude) continue;
    StartOrbit s;
    s.m = f.m, s.sticks = f.orbit.sticks, s.stable = f.orbit.stable;
    s.z = f.points[0].head(system.tangent_dimension());
    s.settled = settled && SameOrbit(f, *settled);
    found = found || s.settled;
    s.x_max = x_max, s.mult_max = MultMax(f.orbit);
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

Eigen::VectorXd RestOnContacts(const System& system) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(system.dimension());
  for (int i = 0; i < system.contacts(); ++i) {
    const ContactVelocity g = system.Contact(i);
    if (g.size == 0 || g.terms[0].weight == 0) continue;
    double h = g.speed;  // sum w_t z_t = speed, solved for the first term's component
    for (int t = 1; t < g.size; ++t) h -= g.terms[t].weight * z[g.terms[t].index];
    z[g.terms[0].index] = h / g.terms[0].weight;
  }
  return z;
}

SettledOrbit AsSettled(const System& at, const StartOrbit& o) {
  SettledOrbit s;
  s.found = true;
  s.orbit.start = AtPhase0(at, o.z);
  s.section = PoincareSection::Stroboscopic(at, s.orbit.start.z, o.m);
  s.orbit.period = s.section.time;
  return s;
}

OrbitBranch TraceFromDefaultStart(const System& at, const ClockStart& c, RunControl& run,
                                  const std::function<OrbitBranch(const SettledOrbit&)>& trace,
                                  SettledOrbit* used) {
  const std::string after =
      " after " + std::to_string(kTransientPeriods) + " clock turns from rest on the contacts";
  auto attempt = [&](const StartOrbit& o, const std::string& how, OrbitBranch* b) {
    *used = AsSettled(at, o);
    *b = trace(*used);
    used->found = b->status != BranchStatus::kStartFailed;
    if (used->found) used->message = how + " (m = " + std::to_string(o.m) + ")";
    return used->found || run.Cancelled();
  };
  const Eigen::VectorXd z = SettledState(at, c);
  const std::optional<StartOrbit> settled = SettledStart(at, z, c, run);
  OrbitBranch b;
  if (settled && settled->m > 1 && attempt(*settled, "the attractor reached" + after, &b)) return b;
  StartOrbit newton;  // m = newton_m from the transient's end
  newton.m = c.newton_m;
  newton.z = z;
  if (attempt(newton, "Newton from the state" + after, &b)) return b;
  const SettledOrbit failed = *used;
  for (const StartOrbit& o : ChooseStart(StartOrbits(at, settled, c, 0, run), StartChoice(), "")) {
    OrbitBranch other;
    if (attempt(o, "an orbit of the start list", &other)) return other;
  }
  *used = failed;
  used->found = false;
  used->recurred = true;  // Newton failed: a numerical failure
  used->message = "no periodic orbit: " + std::string(Name(b.status)) +
                  (b.message.empty() ? "" : " (" + b.message + ")");
  return b;
}

std::vector<SettledOrbit> ChosenStarts(const System& at, const ClockStart& c,
                                       const StartChoice& choice, const std::string& where,
                                       std::ostream& os, RunControl& run) {
  const std::optional<StartOrbit> settled = SettledStart(at, SettledState(at, c), c, run);
  const std::vector<StartOrbit> list = StartOrbits(at, settled, c, choice.m, run);
  PrintStartOrbits(os, list, where);
  std::vector<SettledOrbit> out;
  for (const StartOrbit& o : ChooseStart(list, choice, where)) out.push_back(AsSettled(at, o));
  return out;
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
