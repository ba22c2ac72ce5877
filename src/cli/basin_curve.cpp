#include "cli/basin_curve.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>

#include "cli/app.hpp"
#include "cli/figure_layout.hpp"
#include "cli/output.hpp"
#include "cli/physical.hpp"
#include "cli/run_control.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/basin_stability_report.hpp"

namespace stickslip::cli {

void AddBasinCurveOptions(po::options_description& d) {
  d.add_options()("param", Value()->value_name("NAME"),
                  "basin stability against this parameter (needs the box --x_min ...); "
                  "writes basin_stability.tsv/.gp/.png (--format) instead of the grid")(
      "from", Value()->value_name("A"), "with --param: first value (default: its range)")(
      "to", Value()->value_name("B"), "with --param: last value (default: its range)")(
      "n", Value()->value_name("N"), "with --param: points, in [2, 10000] (default 41)");
}

namespace {

struct Curve {
  ParameterAxis param = Parameter::kV;
  double from = 0, to = 0;
  int n = 41;
};

Curve CurveFromArguments(const Arguments& args, const Params& base, const BasinOptions& opts) {
  Curve c;
  const std::string name = args.Text("param");
  if (!IsParameterName(name))
    throw UsageError("invalid value '" + name + "' for " + args.Source("param") + ": expected " +
                     ParameterNameList());
  c.param = ParameterAxis(name);
  if (opts.auto_range)
    throw UsageError(args.Source("param") +
                     " needs a fixed box: give --x_min --x_max --xdot_min --xdot_max");
  const ParameterRange range = DefaultRange(base, c.param);
  c.from = args.Number("from", range.from);
  c.to = args.Number("to", range.to);
  const long n = args.Integer("n", c.n);
  if (n < 2 || n > 10000)
    throw UsageError("invalid value '" + args.Text("n") + "' for " + args.Source("n") +
                     ": must be in [2, 10000]");
  c.n = static_cast<int>(n);
  if (c.from == c.to)
    throw UsageError("--from = --to = " + FormatNumber(c.from) + ": the range is empty");
  for (const char* end : {"from", "to"}) {
    const std::string err = ValidationError(c.param.At(base, end[0] == 'f' ? c.from : c.to));
    if (!err.empty())
      throw UsageError((args.Given(end) ? args.Source(end) : std::string("--") + end) + ": " + err);
  }
  return c;
}

// The special points of the branch over the curve's range (ss_continue's
// run): HB, and GR or LP where an orbit ends and the shares jump. None if the
// continuation fails or is cancelled (the figure then has no marks).
std::vector<BasinStabilityMark> BranchMarks(const Params& base, const Curve& c,
                                            const OrbitOptions& orbit,
                                            const std::function<bool()>& cancelled) {
  ContinuationOptions o;
  o.param = c.param;
  o.from = std::min(c.from, c.to), o.to = std::max(c.from, c.to);
  o.orbit = orbit;
  o.cancelled = cancelled;
  std::vector<BasinStabilityMark> marks;
  try {
    const ContinuationResult r = Continue(base, o);
    if (r.partial()) return marks;
    for (const SpecialPoint& s : r.special)
      marks.push_back({s.p, SpecialLabel(s.kind),
                       s.kind == SpecialKind::kGrazing || s.kind == SpecialKind::kFold});
  } catch (const InvalidArgument&) {
  }
  return marks;
}

}  // namespace

int RunBasinStabilityCurve(const std::string& prog, const Arguments& args, const Params& base,
                           const BasinOptions& opts, double max_time, const Metadata& meta) {
  const Curve c = CurveFromArguments(args, base, opts);
  const std::optional<FigureLayout> layout = FigureLayoutOf(args);  // --size, --font
  const FigureFormat format = FigureFormatOf(args);
  const std::string figure = FigureFile("basin_stability", format);
  const bool plots = !args.Flag("no_plots");
  OutputSet out(args.Text("out", "plots/basin"),
                {"basin_stability.tsv", "basin_stability.gp", figure},
                args.Given("out") ? args.Source("out") : "--out", prog);
  RunControl run(prog, max_time);
  const std::function<bool()> cancelled = [&] { return run.Cancelled(); };
  OrbitScanOptions scan = opts.scan;
  scan.cancelled = cancelled;
  const Box box{opts.x_lo, opts.x_hi, opts.xdot_lo, opts.xdot_hi};
  const BasinStabilityCurve r = BasinStabilityAlong(base, c.param, c.from, c.to, c.n, box, scan);
  std::string model = std::string("law=") + Name(base.law);  // the varied one left out
  for (const auto& name : ParameterNames(base.law))
    if (name != c.param.name()) model += " " + name + "=" + FormatNumber(GetParameter(base, name));
  const std::vector<BasinStabilityMark> marks = BranchMarks(base, c, scan.orbit, cancelled);
  TsvTable t = BasinStabilityTable(r, model, box);
  t.PrependMeta(meta);
  out.Write("basin_stability.tsv", t.str());
  std::string script =
      BasinStabilityScript(c.param, model + (r.status == BasinStatus::kOk ? "" : " (partial)"),
                           format, FigureUnitsOf(ScalesFromArguments(args), c.param), marks);
  if (layout) script = ApplyFigureLayout(script, *layout);
  out.Write("basin_stability.gp", script);
  GnuplotResult g{GnuplotStatus::kCancelled, ""};
  if (plots) g = out.Draw("basin_stability.gp", {figure}, cancelled);
  out.Commit(g.ok() ? std::vector<std::string>{} : std::vector<std::string>{figure});
  for (size_t i = 0; i < r.p.size(); ++i) {
    std::cout << c.param << " = " << FormatNumber(r.p[i]) << ":";
    for (const std::string& line : BasinStabilityLines(r.at[i])) std::cout << "  " << line;
    std::cout << "\n";
  }
  std::cout << "wrote " << out.dir() << "/basin_stability.tsv, basin_stability.gp"
            << (g.ok() ? " and " + figure : "") << "\n";
  if (r.status != BasinStatus::kOk) {
    PrintError(prog, std::string("partial curve written (") + Name(r.status) +
                         "): " + (run.Cancelled() ? run.Reason() : r.message));
    return 1;
  }
  if (plots && !g.ok()) {
    PrintError(prog, "gnuplot: " + g.message);
    return 1;
  }
  return 0;
}

}  // namespace stickslip::cli
