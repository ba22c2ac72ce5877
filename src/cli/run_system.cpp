// ss_continue --system (run_system.hpp).
#include "cli/run_system.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/autonomous_start.hpp"
#include "cli/run_log.hpp"
#include "cli/system_choice.hpp"
#include "cli/system_restart.hpp"
#include "cli/system_setup.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/io/system_branch_report.hpp"
#include "stickslip/orbits/settle.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::cli {

namespace {

// The stick-slip attractor at p (no clock), from steady sliding + the disturbance.
SettledOrbit Settle(const SystemSetup& s, double p, RunControl& run) {
  std::unique_ptr<System> at = s.system->Clone();
  at->SetParameterValue(s.param, p);
  SettleOptions o = s.settle;
  o.cancelled = [&run] { return run.Cancelled(); };
  return SettleOnStickSlip(*at, NearSteadySliding(*at, s.disturbance), o);
}

// A restart's orbit, as if settled on: its point and section (a clock's turns at its parameters).
SettledOrbit AtPoint(const SystemSetup& s, const SystemPoint& sp) {
  SettledOrbit o;
  o.found = true;
  o.section = sp.section;
  if (sp.section.kind == SectionKind::kTime) {
    std::unique_ptr<System> at = s.system->Clone();
    at->SetParameterValue(s.param, s.start_at);
    o.section = PoincareSection::Stroboscopic(*at, sp.start.z, sp.section.turns);
  }
  o.orbit.start = sp.start;
  o.orbit.period = sp.period;
  return o;
}

// The branch options of every piece (and a clock's start list).
OrbitBranchOptions BranchOptions(const SystemSetup& s) {
  OrbitBranchOptions o;
  o.shooting.flow = s.flow;
  o.palc.ds_max = s.max_step * std::abs(s.to - s.from);
  o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  o.max_amplitude = s.max_amplitude;
  return o;
}

// The branch from the start (at `from`) to `to`; a restart's leaves along the tangent
// (at an LP, `side` 1 or -1 picks the half; 0 elsewhere); --switch: the doubled branch from the
// PD point to whichever end it opens toward.
OrbitBranch Piece(const SystemSetup& s, const SettledOrbit& settled, double to, int side,
                  RunControl& run, double from) {
  std::unique_ptr<System> at = s.system->Clone();
  at->SetParameterValue(s.param, from);
  OrbitBranchOptions o = BranchOptions(s);
  o.palc.cancelled = [&run] { return run.Cancelled(); };
  if (s.doubled)
    return ContinueDoubled(*at, s.param, settled.orbit.start, settled.section,
                           std::min(s.from, s.to), std::max(s.from, s.to), o);
  if (s.restart)
    return ContinueOrbitsFrom(*at, s.param, settled.orbit.start, settled.section, to, side, o);
  return ContinueOrbits(*at, s.param, settled.orbit.start, settled.section, to, o);
}

// A system with a clock: its start from rest (clock_start.hpp), the scan's
// box FindOrbits' own.
ClockStart ClockStartOf(const SystemSetup& s, const System& at) {
  ClockStart c;
  c.rest = RestOnContacts(at);
  c.opts = BranchOptions(s);
  if (const auto* f = dynamic_cast<const ForcedBelt*>(&at)) c.box = f->SearchBox();
  return c;
}

// The orbits a restart or a start list (--all, --point; a clock's --m) starts on.
std::vector<SettledOrbit> Starts(const SystemSetup& s, const SettledOrbit& settled,
                                 RunControl& run) {
  if (!s.start.scan())
    return settled.found ? std::vector<SettledOrbit>{settled} : std::vector<SettledOrbit>();
  std::unique_ptr<System> at = s.system->Clone();
  at->SetParameterValue(s.param, s.start_at);
  const std::string where = s.system->ParameterName(s.param) + " = " + FormatNumber(s.start_at);
  if (s.system->clocks() == 0)  // no clock: the autonomous scan's list (autonomous_start.hpp)
    return ChosenAutonomousStarts(*at, BranchOptions(s), s.start, where, std::cout, run);
  return ChosenStarts(*at, ClockStartOf(s, *at), s.start, where, std::cout, run);
}

// The piece from the start at p toward `to`: a clock's default start
// (TraceFromDefaultStart), else the attractor settled on. *used: its start.
OrbitBranch FirstPiece(const SystemSetup& s, double p, double to, RunControl& run,
                       SettledOrbit* used) {
  auto trace = [&](const SettledOrbit& o) { return Piece(s, o, to, 0, run, p); };
  if (s.system->clocks() == 1) {
    std::unique_ptr<System> at = s.system->Clone();
    at->SetParameterValue(s.param, p);
    return TraceFromDefaultStart(*at, ClockStartOf(s, *at), run, trace, used);
  }
  *used = Settle(s, p, run);
  return used->found ? trace(*used) : OrbitBranch();
}

// Without a restart or a start list: branch 1 from the start at --start_at
// toward --to, branch 2 from the same orbit back toward --from.
void TraceDefault(const SystemSetup& s, RunControl& run, SystemRun& r, SettledOrbit* settled) {
  const bool up = s.start_at != s.to;
  OrbitBranch first = FirstPiece(s, s.start_at, up ? s.to : s.from, run, settled);
  if (!settled->found) return;
  r.pieces.push_back(std::move(first)), r.numbers.push_back(up ? 1 : 2);
  if (up && s.start_at != s.from)
    r.pieces.push_back(Piece(s, *settled, s.from, 0, run, s.start_at)), r.numbers.push_back(2);
}

// The pieces from each start: toward --to (1) and back toward --from (2; the
// numbers stay where one is not traced); a fold's restart: both halves;
// --switch: the doubled branch. A start list's pieces are numbered in turn.
void TracePieces(const SystemSetup& s, const std::vector<SettledOrbit>& starts, RunControl& run,
                 SystemRun& r) {
  const bool fold = s.restart && s.restart->type == "LP";
  int first = 1;
  for (const SettledOrbit& start : starts) {
    if (s.doubled) {
      r.pieces.push_back(Piece(s, start, s.to, 0, run, s.start_at)), r.numbers.push_back(first);
    } else {
      if (s.start_at != s.to)
        r.pieces.push_back(Piece(s, start, s.to, fold ? 1 : 0, run, s.start_at)),
            r.numbers.push_back(first);
      if (s.start_at != s.from || (fold && s.start_at != s.to))
        r.pieces.push_back(Piece(s, start, fold ? s.to : s.from, fold ? -1 : 0, run, s.start_at)),
            r.numbers.push_back(first + 1);
    }
    first = s.start.scan() ? static_cast<int>(r.pieces.size()) + 1 : first + 2;
  }
}

// A piece that left max_amplitude (kUnbounded: an undamped resonance) is
// traced from its far end too, back toward --start_at, as the next branch;
// the interval between is named (the files' `gap`). Not for a restart, a
// start list or --switch.
std::string TraceOtherEnds(const SystemSetup& s, RunControl& run, SystemRun& r) {
  std::string gap;
  if (s.restart || s.start.scan()) return gap;
  const std::size_t n = r.pieces.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (r.pieces[i].status != BranchStatus::kUnbounded || run.Cancelled()) continue;
    const double end = r.numbers[i] % 2 ? s.to : s.from;
    SettledOrbit settled;
    OrbitBranch b = FirstPiece(s, end, s.start_at, run, &settled);
    if (!settled.found) continue;
    const auto& a = r.pieces[i].rows;
    if (!a.empty() && !b.rows.empty())
      r.gap.insert(r.gap.end(), {a.back().p, b.rows.back().p}),
          gap += (gap.empty() ? "" : "; ") + std::string("not traced between ") +
                 FormatNumber(a.back().p) + " and " + FormatNumber(b.rows.back().p) +
                 ": |x| > max_amplitude " + FormatNumber(s.max_amplitude) +
                 " there (unbounded resonance)";
    r.numbers.push_back(*std::max_element(r.numbers.begin(), r.numbers.end()) + 1);
    r.pieces.push_back(std::move(b));
  }
  return gap;
}

}  // namespace

po::options_description SystemRunOptions() {
  po::options_description d("With --system, --model or --force (docs/systems.md)");
  d.add_options()("start_at", Value()->value_name("P"),
                  "where the stick-slip attractor is sought, between --from and --to (default "
                  "--from); its branch is traced to --to and back to --from")(
      "transient", Value()->value_name("T"),
      "the settling run's length in time units (default 3000; not with a clock, whose run "
      "from rest lasts 200 turns)")(
      "disturbance", Value()->value_name("D"),
      "the settling run starts at steady sliding with the first component moved by D "
      "(default 0.01; not with a clock)");
  return d;
}

namespace {

// Why no orbit was found ("cancelled" where the run was).
std::string NoOrbit(const SettledOrbit& settled) {
  return settled.message.empty() ? std::string("cancelled") : settled.message;
}

// Why the run is cut short ("" if complete): the first piece that did not
// end where it should, or a settling run that failed or was cancelled.
std::string Partial(const SystemRun& r, const SettledOrbit& settled, RunControl& run, bool gap) {
  auto cut = [&](const std::string& what, BranchStatus b, const std::string& message) {
    return what + " " + Name(b) + ": " + (b == BranchStatus::kCancelled ? run.Reason() : message);
  };
  if (!Complete(r.steady.status)) return cut("steady sliding", r.steady.status, r.steady.message);
  for (std::size_t i = 0; i < r.pieces.size(); ++i)
    if (!Complete(r.pieces[i].status) && !(gap && r.pieces[i].status == BranchStatus::kUnbounded))
      return cut("branch " + std::to_string(r.numbers[i]), r.pieces[i].status, r.pieces[i].message);
  if (settled.found) return "";
  if (run.Cancelled()) return "no attractor: " + run.Reason();
  // Newton failed on a cycle that recurred, or the run failed: numerical
  // failures. No stick phase, no recurrence, or a contact that opens: answers.
  if (settled.recurred ||
      (settled.run != FlowStatus::kTimeLimit && settled.run != FlowStatus::kContactOpen))
    return "no attractor: " + settled.message;
  return "";
}

Metadata FileMetadata(const SystemSetup& s, const SystemRun& r, const SettledOrbit& settled,
                      const std::string& model, Metadata meta) {
  meta.insert(
      meta.end(),
      {{"system", model},
       {"continued", s.system->ParameterName(s.param)},
       {"from", FormatNumber(s.from)},
       {"to", FormatNumber(s.to)},
       {"start_at", FormatNumber(s.start_at)},
       {"orbit", s.restart        ? std::string("the restart point's orbit, no settling")
                 : s.start.scan() ? "the start list's orbits at " + FormatNumber(s.start_at) +
                                        (settled.found ? "" : ": none chosen")
                 : settled.found && s.system->clocks() == 1
                     ? settled.message  // which default start (TraceFromDefaultStart)
                 : settled.found ? "the attractor settled on from steady sliding + " +
                                       FormatNumber(s.disturbance) + " after " +
                                       FormatNumber(s.settle.transient) + " time units"
                                 : "none: " + NoOrbit(settled)},
       {"rtol", FormatNumber(s.flow.rtol)},
       {"atol", FormatNumber(s.flow.atol)},
       {"steady_status", s.system->clocks() ? std::string("none: a clock, no rest point")
                                            : std::string(Name(r.steady.status))}});
  PoincareSection section = settled.section;  // ContinueDoubled's: twice the returns or turns
  if (section.kind == SectionKind::kTime)
    section.turns *= s.doubled ? 2 : 1;
  else
    section = PoincareSection::StickExit(section.contact, section.returns * (s.doubled ? 2 : 1));
  AddRestartMetadata(*s.system, s.choice, s.law, s.flow, s.max_amplitude,
                     settled.found ? &section : nullptr, meta);
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const std::string b = "branch_" + std::to_string(r.numbers[i]);
    meta.emplace_back(b + "_status",
                      std::string(Name(r.pieces[i].status)) +
                          (r.pieces[i].message.empty() ? "" : ": " + r.pieces[i].message));
    const PoincareSection& own = r.pieces[i].section;  // a start list's orbit on another section
    if (settled.found && own.kind == SectionKind::kStickExit &&
        (own.contact != section.contact || own.returns != section.returns))
      meta.insert(meta.end(), {{b + "_section_contact", std::to_string(own.contact)},
                               {b + "_section_returns", std::to_string(own.returns)}});
  }
  return meta;
}

void PrintSummary(const std::string& prog, const std::string& model, const SystemSetup& s,
                  const SystemRun& r, const SettledOrbit& settled, const std::string& gap,
                  LogDetail detail) {
  std::cout << prog << ": " << model << ", from " << FormatNumber(s.from) << " to "
            << FormatNumber(s.to) << "\n";
  if (s.system->clocks() == 0)
    std::cout << "steady sliding: " << r.steady.rows.size() << " rows, " << Name(r.steady.status)
              << "\n";
  if (!settled.found)
    std::cerr << prog << ": note: no stick-slip orbit: " << NoOrbit(settled) << "\n";
  for (std::size_t i = 0; i < r.pieces.size(); ++i)
    std::cout << "branch " << r.numbers[i] << ": " << r.pieces[i].rows.size() << " rows, "
              << Name(r.pieces[i].status)
              << (r.pieces[i].message.empty() ? "" : " (" + r.pieces[i].message + ")") << "\n";
  if (!gap.empty()) std::cout << "gap: " << gap << "\n";
  PrintSystemLog(std::cout, *s.system, r, detail);
}

}  // namespace

int RunSystem(const Arguments& args, const std::string& prog, const std::string& command) {
  SystemSetup s = ConfigureSystemRun(args);
  const FigureFormat format = FigureFormatOf(args);
  std::vector<std::string> names = {"branch.tsv", "special_points.tsv", "bifurcation.gp"};
  for (const std::string& f : SystemBranchFigures(format)) names.push_back(f);
  AppRun app(prog, args, "plots", names);
  RunControl& run = app.run();
  SystemRun r;
  r.parameter = s.param;
  run.Phase("steady sliding");
  SteadyBranchOptions so;
  so.points = static_cast<int>(std::ceil(1 / s.max_step)) + 1;
  so.cancelled = [&run] { return run.Cancelled(); };
  r.steady.status = BranchStatus::kReachedEnd;  // a forcing has no rest point
  if (s.system->clocks() == 0) r.steady = ContinueSteadySliding(*s.system, s.param, s.to, so);
  run.Phase("settling");
  SettledOrbit settled;
  if (!run.Cancelled() && (s.restart || s.start.scan())) {
    if (s.restart) settled = AtPoint(s, *s.restart);
    const std::vector<SettledOrbit> starts = Starts(s, settled, run);
    if (s.start.scan()) {  // the first chosen orbit stands for the start (its section)
      settled.message = "no orbit of the start list chosen";
      if (!starts.empty()) settled = starts.front();
    }
    run.Phase("continuing");
    TracePieces(s, starts, run, r);
  } else if (!run.Cancelled()) {
    TraceDefault(s, run, r, &settled);
  }
  const std::string gap = TraceOtherEnds(s, run, r);
  const std::string partial = Partial(r, settled, run, !gap.empty());
  const std::string model = DescribeSystem(*s.system, s.choice, s.param);
  Metadata meta = FileMetadata(s, r, settled, model, ToolMetadata(prog, command));
  if (s.restart) meta.emplace_back("restart", DescribeSystemRestart(args, *s.restart));
  if (s.doubled) {
    const bool turns = s.restart->section.kind == SectionKind::kTime;
    const int m = turns ? s.restart->section.turns : s.restart->section.returns;
    meta.emplace_back("switch", std::string("period-doubled branch, ") +
                                    (turns ? "turns " : "returns ") + std::to_string(m) + " -> " +
                                    std::to_string(2 * m));
  }
  meta.emplace_back("status", partial.empty() ? "complete" : "partial: " + partial);
  if (!gap.empty()) meta.emplace_back("gap", gap);
  TsvTable branch = SystemBranchTable(*s.system, r), special = SystemSpecialTable(*s.system, r);
  branch.PrependMeta(meta);
  special.PrependMeta(meta);
  app.out().Write("branch.tsv", branch.str());
  app.out().Write("special_points.tsv", special.str());
  app.out().Write("bifurcation.gp", SystemBranchScript(*s.system, r, model, format));
  if (!app.Finish("bifurcation.gp", SystemBranchFigures(format), SystemBranchFigures(format)))
    return kExitFailed;
  PrintSummary(prog, model, s, r, settled, gap,
               args.Flag("verbose") ? LogDetail::kEveryPoint : LogDetail::kSpecialPoints);
  std::cout << "wrote " << app.out().dir() << "/branch.tsv, special_points.tsv, bifurcation.gp"
            << (app.gnuplot().ok() ? " and the figure" : "") << "\n";
  return app.ExitCode(partial);
}

}  // namespace stickslip::cli
