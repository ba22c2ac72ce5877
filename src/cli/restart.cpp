#include "cli/restart.hpp"

#include "cli/physical.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip::cli {

void AddRestartOptions(po::options_description& d, bool systems) {
  d.add_options()(
      "restart", Value()->value_name("DIR"),
      systems ? "start from a point of the ss_continue run in DIR, belt, forced or --system (its "
                "system, parameters and solver options are the defaults)"
              : "start from a GR or HB point of the belt's ss_continue run in DIR (its parameters "
                "and solver options are the defaults; the forced chart takes none)")(
      "point", Value()->value_name("LABEL"),
      "with --restart: the point, a label of its special_points.tsv (GR1, HB1, LP1, PD1, CR1, "
      "CL1, ...) or a point number of its branch.tsv");
}

std::optional<LabelledPoint> RestartFromArguments(const Arguments& args) {
  if (!args.Given("restart")) {
    if (args.Given("point"))
      throw UsageError(args.Source("point") + " " + args.Text("point") + " needs --restart DIR");
    return std::nullopt;
  }
  if (!args.Given("point"))
    throw UsageError(args.Source("restart") + " " + args.Text("restart") +
                     " needs --point LABEL (GR1, HB1, ... or a point number)");
  if (ScalesFromArguments(args))
    throw UsageError(args.Source("restart") +
                     " restarts in dimensionless parameters: physical inputs cannot be combined "
                     "with it");
  try {
    return ReadLabelledPoint(args.Text("restart"), args.Text("point"));
  } catch (const RestartError& e) {
    const std::string opt = e.part() == RestartError::Part::kRun ? "restart" : "point";
    throw UsageError(args.Source(opt) + " " + args.Text(opt) + ": " + e.what());
  }
}

ChartOptions::Seed ChartSeed(const Arguments& args, const LabelledPoint& lp, const Plane& pl,
                             const Params& base) {
  if (lp.type != "GR" && lp.type != "HB")
    throw UsageError(args.Source("point") + " " + lp.label + " is a " + lp.type +
                     " point: a chart starts from a GR or HB point");
  ChartOptions::Seed s;
  s.kind = lp.type == "GR" ? CurveKind::kGrazing : CurveKind::kHopf;
  s.p1 = pl.p1.Get(base);
  s.p2 = pl.p2.Get(base);
  if (!pl.Contains(s.p1, s.p2))
    throw UsageError(args.Source("point") + " " + lp.label + ": (" + pl.p1.name() + ", " +
                     pl.p2.name() + ") = (" + FormatNumber(s.p1) + ", " + FormatNumber(s.p2) +
                     ") lies outside the chart's rectangle (--from --to --from2 --to2)");
  return s;
}

std::string DescribeRestart(const Arguments& args, const LabelledPoint& lp) {
  return args.Text("restart") + " point " + lp.label + " (pt " + std::to_string(lp.pt) + ", " +
         lp.type + ", " + lp.ParamName() + " = " + FormatNumber(lp.p) + ")";
}

}  // namespace stickslip::cli
