// ss_chart's forced run (chart_forced.hpp).
#include "cli/chart_forced.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "cli/app.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::cli {

namespace {

// The chart's (omega, force) defaults: --grid 40, --max_amplitude 50.
constexpr long kDefaultGrid = 40;
constexpr double kDefaultAmplitude = 50;

void Refuse(const Arguments& args) {
  for (const char* phys : {"mass", "damping", "stiffness", "belt_speed"})
    if (args.Given(phys))
      throw UsageError(args.Source(phys) + ": the forced oscillator takes dimensionless inputs");
  for (const char* key : {"restart", "point"})  // a belt run's GR or HB points only
    if (args.Given(key))
      throw UsageError(args.Source(key) +
                       ": the forced chart starts from no point; give the forced run's law, "
                       "parameters, --force and --omega");
}

// The axes (default omega, force) and the rectangle (the chart's own ranges
// of omega and force, the others the forced oscillator's) as ForcedBelt's
// parameter indices (Parameter's order); p takes the rectangle's corner.
SystemPlane PlaneOf(const Arguments& args, ForcedBeltParams& p) {
  const ParameterAxis a1 = AxisFromArguments(args, "param", "omega", p.base.law, true);
  const ParameterAxis a2 = AxisFromArguments(args, "param2", "force", p.base.law, true);
  if (a1 == a2) throw UsageError(args.Source("param2") + " = " + a2.name() + " equals --param");
  auto range = [&](const ParameterAxis& a) {
    if (a == Parameter::kOmega) return ParameterRange{0.5, 2};
    return a == Parameter::kForce ? ParameterRange{0.05, 1} : DefaultRange(p, a);
  };
  SystemPlane pl;
  pl.p1 = a1.index(), pl.p2 = a2.index();
  pl.from1 = args.Number("from", range(a1).from), pl.to1 = args.Number("to", range(a1).to);
  pl.from2 = args.Number("from2", range(a2).from), pl.to2 = args.Number("to2", range(a2).to);
  if (!(pl.from1 < pl.to1))
    throw UsageError(args.Source("to") + " = " + FormatNumber(pl.to1) + " must exceed " +
                     args.Source("from") + " = " + FormatNumber(pl.from1));
  if (!(pl.from2 < pl.to2))
    throw UsageError(args.Source("to2") + " = " + FormatNumber(pl.to2) + " must exceed " +
                     args.Source("from2") + " = " + FormatNumber(pl.from2));
  for (const auto& [from, to, a, b] :
       {std::tuple{pl.from1, pl.to1, "from", "to"}, std::tuple{pl.from2, pl.to2, "from2", "to2"}})
    if (to - from < kMinRelativeWidth * std::max(std::abs(from), std::abs(to)))
      throw UsageError(args.Source(b) + " = " + FormatNumber(to) + " is too close to --" + a +
                       " = " + FormatNumber(from) + ": the width must be >= " +
                       FormatNumber(kMinRelativeWidth) + " max(|--" + a + "|, |--" + b + "|)");
  // Each range end on its own, the other parameters as given (valid): the end is to blame.
  for (const auto& [a, x, key] :
       {std::tuple{a1, pl.from1, "from"}, std::tuple{a1, pl.to1, "to"},
        std::tuple{a2, pl.from2, "from2"}, std::tuple{a2, pl.to2, "to2"}}) {
    ForcedBeltParams at = p;
    a.Set(at, x);
    CheckForcedBelt(args, at, " at " + args.Source(key), a.name());
  }
  a1.Set(p, pl.from1), a2.Set(p, pl.from2);
  return pl;
}

// "law=cubic beta=0.05 ... force=0.3 omega=[0.5, 2] ...": the law's
// parameters and the forcing, the axes as their ranges.
std::string Describe(const ForcedBeltParams& p, const ForcedBelt& m, const SystemPlane& pl) {
  std::string d = "law=" + std::string(Name(p.base.law));
  auto range = [](double a, double b) {
    return "[" + FormatNumber(a) + ", " + FormatNumber(b) + "]";
  };
  const std::string n1 = m.ParameterName(pl.p1), n2 = m.ParameterName(pl.p2);
  for (const auto& name : ParameterNames(p.base.law))
    if (name != n1 && name != n2) d += " " + name + "=" + FormatNumber(GetParameter(p.base, name));
  for (ParameterAxis a : {Parameter::kForce, Parameter::kOmega})
    if (a.name() != n1 && a.name() != n2)
      d += std::string(" ") + a.name() + "=" + FormatNumber(a.Get(p));
  return d + " " + n1 + "=" + range(pl.from1, pl.to1) + " " + n2 + "=" + range(pl.from2, pl.to2);
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

ChartJob ForcedChartJob(const Arguments& args, const std::string& prog,
                        const std::string& command) {
  Refuse(args);
  ForcedBeltParams p;
  p.base = UncheckedModelFromArguments(args);
  p.force = args.Number("force", 0.3);
  p.omega = args.Number("omega", 1);
  CheckForcedBelt(args, p);  // every option as given, an axis's too (it is not used)
  ChartJob job;
  SystemChartOptions& o = job.chart;
  o.plane = PlaneOf(args, p);
  std::unique_ptr<ForcedBelt> model;
  std::string e;
  try {
    model = std::make_unique<ForcedBelt>(p);
    e = o.plane.ValidationError(*model);
  } catch (const InvalidArgument& x) {
    e = x.what();
  }
  if (!e.empty()) throw UsageError("invalid forced chart rectangle (--from .. --to2): " + e);
  // The forced flow's (rtol = atol = 1e-12, its switch cap) with the apps' step cap.
  FlowOptions defaults = ForcedBelt::FlowDefaults();
  defaults.max_steps = FlowOptions().max_steps;
  const FlowOptions run = FlowOptionsFromArguments(args, defaults);
  if (run.integrator != Integrator::kTaylor)  // its GR curves' runs need Taylor's (limits.md)
    throw UsageError(args.Source("integrator") +
                     ": the forced chart is integrated by Taylor series only");
  o.branch = OrbitBranchOptions(run);  // every map on the chart's flow, its step cap too
  o.branch.max_amplitude = MaxAmplitudeFromArguments(args, kDefaultAmplitude);
  o.max_step = MaxStepFromArguments(args, o.max_step);
  o.seed_lines = static_cast<int>(
      args.IntegerIn("seed_lines", o.seed_lines, 0, SystemChartOptions::kMaxSeedLines));
  o.max_m = static_cast<int>(args.IntegerIn("max_m", o.max_m, 1, SystemChartOptions::kMaxMultiple));
  if (const std::string oe = o.ValidationError(*model); !oe.empty())
    throw UsageError("invalid forced chart options: " + oe);
  const long grid = args.Integer("grid", kDefaultGrid);
  if (grid != 0 && (grid < 2 || grid > kMaxChartGrid))
    throw UsageError("invalid value '" + args.Text("grid") + "' for " + args.Source("grid") +
                     ": must be 0 (no response grid) or in [2, " + std::to_string(kMaxChartGrid) +
                     "]");
  ResponseOptions& ro = job.grid;
  ro.n1 = ro.n2 = static_cast<int>(grid);
  ro.attractor.iterate.flow = run, ro.attractor.max_amplitude = o.branch.max_amplitude;
  if (const std::string ge = ro.ValidationError(*model); grid > 0 && !ge.empty())
    throw UsageError(args.Source("grid") + ": " + ge);
  const std::string n1 = model->ParameterName(o.plane.p1), n2 = model->ParameterName(o.plane.p2);
  const std::string described = Describe(p, *model, o.plane);
  job.model = "forced oscillator, " + described;
  job.title = FigureTitle(described, {n1, n2});
  job.meta = RunMetadata(prog, command, p.base, run);
  for (auto& [key, value] : job.meta)  // the axes' base values are never used
    if (key == n1 || key == n2) value = "axis";
  for (ParameterAxis a : {Parameter::kForce, Parameter::kOmega})
    job.meta.push_back(
        {a.name(), a.name() == n1 || a.name() == n2 ? "axis" : FormatNumber(a.Get(p))});
  job.meta.push_back({"model", job.model});
  job.meta.push_back(
      {"grid", ro.n1 == 0 ? std::string("none")
                          : std::to_string(ro.n1) + " x " + std::to_string(ro.n2) + ", " +
                                std::to_string(ro.attractor.iterate.transient) + " transient and " +
                                std::to_string(ro.attractor.iterate.keep) +
                                " kept forcing periods per cell"});
  job.meta.push_back({"max_m", std::to_string(o.max_m)});
  job.meta.push_back({"max_amplitude", FormatNumber(o.branch.max_amplitude)});
  job.system = std::move(model);
  return job;
}

}  // namespace stickslip::cli
