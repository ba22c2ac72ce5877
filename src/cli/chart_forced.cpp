// ss_chart's forced run (chart_forced.hpp).
#include "cli/chart_forced.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <tuple>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "stickslip/io/forced_chart_report.hpp"

namespace stickslip::cli {

namespace {

struct Setup {
  ForcedParams p;
  ForcedChartOptions o;
  FlowOptions flow;  // for the metadata
};

Setup Configure(const Arguments& args) {
  for (const char* phys : {"mass", "damping", "stiffness", "belt_speed"})
    if (args.Given(phys))
      throw UsageError(args.Source(phys) + ": the forced oscillator takes dimensionless inputs");
  for (const char* key : {"restart", "point"})  // a belt run's GR or HB points only
    if (args.Given(key))
      throw UsageError(args.Source(key) +
                       ": the forced chart starts from no point; give the forced run's law, "
                       "parameters, --force and --omega");
  Setup s;
  s.p.base = UncheckedModelFromArguments(args);
  s.p.force = args.Number("force", 0.3);
  s.p.omega = args.Number("omega", 1);
  Plane& pl = s.o.plane;
  pl.p1 = AxisFromArguments(args, "param", "omega", s.p.base.law, true);
  pl.p2 = AxisFromArguments(args, "param2", "force", s.p.base.law, true);
  if (pl.p1 == pl.p2)
    throw UsageError(args.Source("param2") + " = " + pl.p2.name() + " equals --param");
  // The chart's own ranges of omega and force; the others the forced oscillator's.
  auto range = [&](const ParameterAxis& a) {
    if (a == Parameter::kOmega) return ParameterRange{0.5, 2};
    return a == Parameter::kForce ? ParameterRange{0.05, 1} : DefaultRange(s.p, a);
  };
  pl.from1 = args.Number("from", range(pl.p1).from);
  pl.to1 = args.Number("to", range(pl.p1).to);
  pl.from2 = args.Number("from2", range(pl.p2).from);
  pl.to2 = args.Number("to2", range(pl.p2).to);
  if (!(pl.from1 < pl.to1))
    throw UsageError(args.Source("to") + " = " + FormatNumber(pl.to1) +
                     " must exceed --from = " + FormatNumber(pl.from1));
  if (!(pl.from2 < pl.to2))
    throw UsageError(args.Source("to2") + " = " + FormatNumber(pl.to2) +
                     " must exceed --from2 = " + FormatNumber(pl.from2));
  for (const auto& [from, to, a, b] :
       {std::tuple{pl.from1, pl.to1, "from", "to"}, std::tuple{pl.from2, pl.to2, "from2", "to2"}})
    if (to - from < kMinRelativeWidth * std::max(std::abs(from), std::abs(to)))
      throw UsageError(args.Source(b) + " = " + FormatNumber(to) + " is too close to --" + a +
                       " = " + FormatNumber(from) + ": the width must be >= " +
                       FormatNumber(kMinRelativeWidth) + " max(|--" + a + "|, |--" + b + "|)");
  const std::string e = pl.ValidationError(s.p);
  if (!e.empty()) throw UsageError("invalid forced chart rectangle (--from .. --to2): " + e);
  s.flow = FlowOptionsFromArguments(args);
  if (!args.Given("rtol")) s.flow.rtol = s.o.flow.rtol;  // the forced flow's 1e-12
  if (!args.Given("atol")) s.flow.atol = s.o.flow.atol;
  s.o.flow.rtol = s.flow.rtol, s.o.flow.atol = s.flow.atol, s.o.flow.max_steps = s.flow.max_steps;
  s.o.iterate.flow = s.o.flow;
  s.o.max_step = args.Number("max_step", s.o.max_step);
  const long lines = args.Integer("seed_lines", 3);
  if (lines < 0 || lines > 20)
    throw UsageError("invalid value '" + args.Text("seed_lines") + "' for " +
                     args.Source("seed_lines") + ": must be in [0, 20]");
  s.o.seed_lines = static_cast<int>(lines);
  const long max_m = args.Integer("max_m", s.o.max_m);
  if (max_m < 1 || max_m > 8)
    throw UsageError("invalid value '" + args.Text("max_m") + "' for " + args.Source("max_m") +
                     ": must be in [1, 8]");
  s.o.max_m = static_cast<int>(max_m);
  const long grid = args.Integer("grid", 40);
  if (grid != 0 && (grid < 2 || grid > 400))
    throw UsageError("invalid value '" + args.Text("grid") + "' for " + args.Source("grid") +
                     ": must be 0 (no response grid) or in [2, 400]");
  s.o.n1 = s.o.n2 = static_cast<int>(grid);
  s.o.max_amplitude = args.Number("max_amplitude", 50);
  if (!(s.o.max_amplitude > 0)) throw UsageError(args.Source("max_amplitude") + " must be > 0");
  const std::string err = s.o.ValidationError(s.p);
  if (!err.empty()) throw UsageError("invalid forced chart options: " + err);
  return s;
}

std::string Describe(const Setup& s) {
  std::string d = "law=" + std::string(Name(s.p.base.law));
  const Plane& pl = s.o.plane;
  auto range = [](double a, double b) {
    return "[" + FormatNumber(a) + ", " + FormatNumber(b) + "]";
  };
  for (const auto& name : ParameterNames(s.p.base.law))
    if (name != pl.p1.name() && name != pl.p2.name())
      d += " " + name + "=" + FormatNumber(GetParameter(s.p.base, name));
  for (ParameterAxis a : {Parameter::kForce, Parameter::kOmega})
    if (a != pl.p1 && a != pl.p2) d += std::string(" ") + a.name() + "=" + FormatNumber(a.Get(s.p));
  return d + " " + pl.p1.name() + "=" + range(pl.from1, pl.to1) + " " + pl.p2.name() + "=" +
         range(pl.from2, pl.to2);
}

void PrintSummary(const ForcedChartResult& r, const Plane& pl, const std::string& model,
                  const std::string& dir, bool drawn, const std::string& figure) {
  const SystemChart& c = r.chart;
  std::printf("ss_chart: forced oscillator, %s\n%zu curves from %d one-parameter runs in %.2f s",
              model.c_str(), c.curves.size(), c.seed_runs, r.seconds);
  if (r.grid.n1 > 0)
    std::printf("; response grid %d x %d in %.2f s (%d failed)", r.grid.n1, r.grid.n2,
                r.grid_seconds, r.grid.failed);
  std::printf("\n");
  if (c.failed_seed_runs + c.seeds_not_traced + c.cut_curves + c.duplicates > 0)
    std::printf(
        "  %d seed runs failed, %d seeds gave no curve, %d curves cut short, %d duplicates "
        "dropped\n",
        c.failed_seed_runs, c.seeds_not_traced, c.cut_curves, c.duplicates);
  for (size_t i = 0; i < c.curves.size(); ++i) {
    const SystemCurve& cv = c.curves[i];
    std::printf("  curve %zu %s m=%d: %zu points, %.2f s, from %s; ends %s\n", i + 1, Name(cv.kind),
                cv.section.turns, cv.points.size(), cv.seconds, cv.seed.c_str(),
                cv.ends.Text().c_str());
  }
  for (const SystemCodim2& p : c.codim2)
    std::printf("  %-4s %s = %.8f  %s = %.8f  %s%s\n", Name(p.label), pl.p1.name().c_str(), p.p1,
                pl.p2.name().c_str(), p.p2, p.description.c_str(),
                p.method == Codim2Method::kChord ? " (chord: not refined)" : "");
  std::printf("wrote %s/curves.tsv, codim2.tsv, response.tsv, forced_chart.gp%s\n", dir.c_str(),
              drawn ? (", " + figure).c_str() : "");
}

}  // namespace

bool ForcedChartRequested(const Arguments& args) {
  if (args.Given("force") || args.Given("omega")) return true;
  for (const char* key : {"param", "param2"}) {
    const std::string a = args.Text(key, "");
    if (a == "omega" || a == "force") return true;
  }
  return false;
}

int RunForcedChart(const Arguments& args, const std::string& prog, const std::string& command) {
  Setup s = Configure(args);
  const Plane& pl = s.o.plane;
  const FigureFormat format = FigureFormatOf(args);
  const std::string figure = FigureFile("forced_chart", format);
  AppRun app(prog, args, "chart",
             {"curves.tsv", "codim2.tsv", "response.tsv", "forced_chart.gp", figure});
  RunControl& run = app.run();
  run.Phase("tracing curves, then the response grid");
  s.o.cancelled = [&run] {
    run.Heartbeat("");
    return run.Cancelled();
  };
  const ForcedChartResult r = ForcedChart(s.p, s.o);
  const std::string model = Describe(s);
  Metadata meta = RunMetadata(prog, command, s.p.base, s.flow);
  for (auto& [key, value] : meta)  // the axes' base values are never used
    if (key == pl.p1.name() || key == pl.p2.name()) value = "axis";
  meta.push_back({"model", "forced oscillator, " + model});
  meta.push_back({"grid", std::to_string(s.o.n1) + " x " + std::to_string(s.o.n2) + ", " +
                              std::to_string(s.o.iterate.transient) + " transient and " +
                              std::to_string(s.o.iterate.keep) + " kept forcing periods per cell"});
  meta.push_back({"max_m", std::to_string(s.o.max_m)});
  auto text = [&](TsvTable t) {
    t.PrependMeta(meta);
    return t.str();
  };
  run.Phase("writing");
  app.out().Write("curves.tsv", text(ForcedCurvesTable(r, pl, model)));
  app.out().Write("codim2.tsv", text(ForcedCodim2Table(r, pl, model)));
  app.out().Write("response.tsv", text(ResponseTable(r, pl, model)));
  const std::string title = FigureTitle(model, {pl.p1.name(), pl.p2.name()}) +
                            (r.status == ChartStatus::kCancelled ? " (partial)" : "");
  app.out().Write("forced_chart.gp", ForcedChartScript(r, pl, title, format));
  if (!app.Finish("forced_chart.gp", {figure}, {figure})) return kExitFailed;
  PrintSummary(r, pl, model, app.out().dir(), app.gnuplot().ok(), figure);
  std::string partial;
  if (r.status == ChartStatus::kCancelled)
    partial = "partial forced chart written (cut short: " + run.Reason() + ")";
  else if (r.status != ChartStatus::kOk)
    partial = std::string("partial forced chart written (") + Name(r.status) + "): " + r.message;
  return app.ExitCode(partial);
}

}  // namespace stickslip::cli
