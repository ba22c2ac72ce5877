// ss_chart --system (chart_system.hpp).
#include "cli/chart_system.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <tuple>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/system_choice.hpp"
#include "cli/system_restart.hpp"
#include "stickslip/chart/response_grid.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/io/response_report.hpp"
#include "stickslip/io/system_chart_report.hpp"

namespace stickslip::cli {

namespace {

// A parameter of s by the option `key`, one s depends on (UsageError naming
// the option otherwise).
int Axis(const Arguments& args, const System& s, const char* key) {
  if (!args.Given(key))
    throw UsageError("--" + std::string(key) + " is required with --system (one of " +
                     ParameterList(s) + ")");
  const int j = s.ParameterIndex(args.Text(key));
  if (j < 0)
    throw UsageError(args.Source(key) + " = '" + args.Text(key) + "' is no parameter of " +
                     Name(SystemChoiceOf(args)) + " (its parameters: " + ParameterList(s) + ")");
  if (const std::string e = s.ParameterError(j); !e.empty())  // as ss_continue's --param
    throw UsageError(args.Source(key) + ": " + e);
  return j;
}

double Required(const Arguments& args, const char* key) {
  if (!args.Given(key)) throw UsageError("--" + std::string(key) + " is required with --system");
  return args.Number(key, 0);
}

// Each range ordered, and each end a valid system with the other parameters
// as given: a bad end is blamed on its own option or study line.
void CheckRangeEnds(const Arguments& args, const System& s, const SystemPlane& pl) {
  for (const auto& [from, to, a, b] :
       {std::tuple{pl.from1, pl.to1, "from", "to"}, std::tuple{pl.from2, pl.to2, "from2", "to2"}})
    if (!(from < to))
      throw UsageError(args.Source(b) + " = " + FormatNumber(to) + " must exceed " +
                       args.Source(a) + " = " + FormatNumber(from));
  if (!s.ValidationError().empty()) return;  // the rectangle's check names it
  const std::unique_ptr<System> at = s.Clone();
  for (const auto& [j, x, key] :
       {std::tuple{pl.p1, pl.from1, "from"}, std::tuple{pl.p1, pl.to1, "to"},
        std::tuple{pl.p2, pl.from2, "from2"}, std::tuple{pl.p2, pl.to2, "to2"}}) {
    at->Assign(s);
    at->SetParameterValue(j, x);
    if (const std::string e = at->ValidationError(); !e.empty())
      throw UsageError(args.Source(key) + " = " + FormatNumber(x) + ": " + e);
  }
}

SystemChartOptions Configure(const Arguments& args, const System& s) {
  for (const char* k : {"restart", "point"})
    if (args.Given(k)) throw UsageError(args.Source(k) + ": not with --system");
  SystemChartOptions o;
  SystemPlane& pl = o.plane;
  pl.p1 = Axis(args, s, "param");
  pl.p2 = Axis(args, s, "param2");
  if (pl.p1 == pl.p2) throw UsageError(args.Source("param2") + ": the two axes must differ");
  pl.from1 = Required(args, "from"), pl.to1 = Required(args, "to");
  pl.from2 = Required(args, "from2"), pl.to2 = Required(args, "to2");
  CheckRangeEnds(args, s, pl);
  if (const std::string e = pl.ValidationError(s); !e.empty())
    throw UsageError(args.Source("from") + ", " + args.Source("to") + ", " + args.Source("from2") +
                     ", " + args.Source("to2") + ": " + e);
  o.branch = OrbitBranchOptions(FlowOptionsFromArguments(args));
  o.branch.max_amplitude = MaxAmplitudeFromArguments(args, o.branch.max_amplitude);
  o.max_step = MaxStepFromArguments(args, o.max_step);
  o.seed_lines = static_cast<int>(
      args.IntegerIn("seed_lines", o.seed_lines, 0, SystemChartOptions::kMaxSeedLines));
  o.max_m = static_cast<int>(args.IntegerIn("max_m", o.max_m, 1, SystemChartOptions::kMaxMultiple));
  if (const std::string e = o.ValidationError(s); !e.empty()) throw UsageError(e);
  return o;
}

// --grid N: the response grid of N x N cells (0, the default: none),
// validated for s with the chart's flow and amplitude bound.
ResponseOptions Grid(const Arguments& args, const System& s, const SystemChartOptions& o) {
  const long n = args.Integer("grid", 0);
  if (n != 0 && (n < 2 || n > kMaxChartGrid))
    throw UsageError("invalid value '" + args.Text("grid") + "' for " + args.Source("grid") +
                     ": must be 0 (no response grid) or in [2, " + std::to_string(kMaxChartGrid) +
                     "]");
  ResponseOptions ro;
  ro.n1 = ro.n2 = static_cast<int>(n);
  ro.attractor.iterate.flow = o.branch.shooting.flow;
  ro.attractor.max_amplitude = o.branch.max_amplitude;
  if (const std::string e = ro.ValidationError(s); n > 0 && !e.empty())
    throw UsageError(args.Source("grid") + ": " + e);
  return ro;
}

// "complete", "partial: 2 curves cut short, ..." or "cut short (interrupted ...)".
std::string Status(const SystemChart& c, const ResponseGrid& g, RunControl& run) {
  if (c.status == ChartStatus::kCancelled || g.cancelled) return "cut short (" + run.Reason() + ")";
  if (c.status == ChartStatus::kOk && g.failed == 0) return "complete";
  std::string why = c.status == ChartStatus::kOk ? "" : c.message;
  if (g.failed > 0) why += (why.empty() ? "" : "; ") + g.failure;
  return "partial: " + why;
}

void PrintSummary(const std::string& prog, const System& s, const SystemChart& c,
                  const ResponseGrid& g, const std::string& model, const std::string& dir,
                  bool script, const std::string& figure) {
  const std::string p1 = s.ParameterName(c.plane.p1), p2 = s.ParameterName(c.plane.p2);
  std::printf("%s: %s; %s x %s\n%d curves, %d points, from %d one-parameter runs in %.2f s\n",
              prog.c_str(), model.c_str(), p1.c_str(), p2.c_str(),
              static_cast<int>(c.curves.size()), c.points(), c.seed_runs, c.seconds);
  if (c.failed_seed_runs + c.seeds_not_traced + c.cut_curves + c.duplicates > 0)
    std::printf(
        "%d seed runs failed, %d seeds gave no curve, %d curves cut short, %d duplicates dropped\n",
        c.failed_seed_runs, c.seeds_not_traced, c.cut_curves, c.duplicates);
  for (size_t i = 0; i < c.curves.size(); ++i) {
    const SystemCurve& cv = c.curves[i];
    // m: forcing periods (a clock's section); an autonomous orbit's returns are in curves.tsv.
    const std::string m = cv.kind != CurveKind::kHopf && cv.section.kind == SectionKind::kTime
                              ? " m=" + std::to_string(cv.section.turns)
                              : "";
    std::printf("  curve %zu %s%s: %zu points, %d evaluations, %.2f s, from %s; ends %s\n", i + 1,
                CurveLabel(cv.kind), m.c_str(), cv.points.size(), cv.evaluations, cv.seconds,
                cv.seed.c_str(), cv.ends.Text().c_str());
  }
  for (const SystemCodim2& p : c.codim2)
    std::printf("  %-5s %s = %.12f  %s = %.12f  %s\n", Name(p.label), p1.c_str(), p.p1, p2.c_str(),
                p.p2, p.description.c_str());
  if (g.n1 > 0)
    std::printf("response grid %d x %d in %.2f s (%d failed%s)\n", g.n1, g.n2, g.seconds, g.failed,
                g.cancelled ? ", cut short" : "");
  std::printf("wrote %s/curves.tsv, codim2.tsv%s%s%s\n", dir.c_str(),
              g.n1 > 0 ? ", response.tsv" : "", script ? ", chart.gp" : "",
              figure.empty() ? "" : (", " + figure).c_str());
}

}  // namespace

double MaxAmplitudeFromArguments(const Arguments& args, double fallback) {
  const double a = args.Number("max_amplitude", fallback);
  if (!(a > 0) || !std::isfinite(a))
    throw UsageError(args.Source("max_amplitude") + " = " + args.Text("max_amplitude") +
                     ": must be a finite number > 0");
  return a;
}

double MaxStepFromArguments(const Arguments& args, double fallback) {
  const double step = args.Number("max_step", fallback);
  if (!(step >= 1.0 / kMaxCurvePoints && step <= SystemChartOptions::kMaxStepLimit))
    throw UsageError("invalid value '" + args.Text("max_step") + "' for " +
                     args.Source("max_step") + ": must be in [1/" +
                     std::to_string(kMaxCurvePoints) + ", " +
                     FormatNumber(SystemChartOptions::kMaxStepLimit) + "]");
  return step;
}

ChartJob SystemChartJob(const Arguments& args, const std::string& prog,
                        const std::string& command) {
  ChartJob job;
  job.system = SystemFromArguments(args);
  const System& s = *job.system;
  job.chart = Configure(args, s);
  job.grid = Grid(args, s, job.chart);
  const FlowOptions& flow = job.chart.branch.shooting.flow;
  job.model =
      DescribeSystem(s, SystemChoiceOf(args), job.chart.plane.p1, job.chart.plane.p2, "[axis]");
  job.title = SystemFigureTitle(job.model);
  job.meta = ToolMetadata(prog, command);
  job.meta.emplace_back("system", job.model);
  AddRestartMetadata(s, SystemChoiceOf(args), UncheckedModelFromArguments(args), flow,
                     job.chart.branch.max_amplitude, nullptr, job.meta);
  job.meta.insert(job.meta.end(),
                  {{"rtol", FormatNumber(flow.rtol)}, {"atol", FormatNumber(flow.atol)}});
  return job;
}

int RunChart(const Arguments& args, const std::string& prog, ChartJob job) {
  if (job.chart.seed_lines == 0 && job.grid.n1 == 0)
    throw UsageError(args.Source("seed_lines") + " = 0 with no grid (--grid 0): the chart " +
                     "would compute nothing; give seed lines or a grid");
  const System& s = *job.system;
  SystemChartOptions& o = job.chart;
  ResponseOptions& ro = job.grid;
  const FigureFormat format = FigureFormatOf(args);
  const std::string figure = FigureFile("chart", format);
  AppRun app(prog, args, "chart", {"curves.tsv", "codim2.tsv", "response.tsv", "chart.gp", figure});
  RunControl& run = app.run();
  run.Phase("following curves");
  o.cancelled = [&run] {
    run.Heartbeat("");
    return run.Cancelled();
  };
  o.branch.palc.cancelled = o.cancelled;
  const SystemChart c = ChartSystem(s, o);
  ResponseGrid grid;
  if (ro.n1 > 0 && !run.Cancelled()) {
    run.Phase("classifying the response grid");
    ro.cancelled = o.cancelled;
    grid = Responses(s, o.plane, ro);
  } else if (ro.n1 > 0) {
    grid.cancelled = true;  // cut short before the grid, after the curves' last poll
  }
  const bool complete = c.status == ChartStatus::kOk && !grid.cancelled && grid.failed == 0;
  const std::string status = Status(c, grid, run);
  Metadata meta = job.meta;
  meta.insert(
      meta.end(),
      {{"range", s.ParameterName(o.plane.p1) + " = [" + FormatNumber(o.plane.from1) + ", " +
                     FormatNumber(o.plane.to1) + "], " + s.ParameterName(o.plane.p2) + " = [" +
                     FormatNumber(o.plane.from2) + ", " + FormatNumber(o.plane.to2) + "]"},
       {"status", status}});
  auto text = [&meta](TsvTable t) {
    t.PrependMeta(meta);
    return t.str();
  };
  run.Phase("writing");
  app.out().Write("curves.tsv", text(SystemCurvesTable(s, c)));
  app.out().Write("codim2.tsv", text(SystemCodim2Table(s, c)));
  if (grid.n1 > 0)  // not where the curves were cut short before the grid
    app.out().Write("response.tsv", text(ResponseGridTable(grid, s.ParameterName(o.plane.p1),
                                                           s.ParameterName(o.plane.p2))));
  const std::string title = job.title + (complete ? "" : " (partial)");
  if (app.plots()) app.out().Write("chart.gp", SystemChartScript(s, c, title, format, &grid));
  std::vector<std::string> stale;
  if (!app.plots()) stale.push_back("chart.gp");
  if (grid.n1 == 0) stale.push_back("response.tsv");
  if (!app.Finish("chart.gp", {figure}, {figure}, stale)) return kExitFailed;
  PrintSummary(prog, s, c, grid, job.model, app.out().dir(), app.plots(),
               app.plots() && app.gnuplot().ok() ? figure : std::string());
  return app.ExitCode(complete ? std::string() : "chart written, " + status);
}

}  // namespace stickslip::cli
