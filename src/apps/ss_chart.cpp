// ss_chart: the stability chart of a study in two parameters: HB, GR and LP
// curves followed by pseudo-arclength continuation, their codimension-two
// points (GH, GR-LP) and the regions between them; TSV files and chart.png.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "cli/about.hpp"
#include "cli/output.hpp"
#include "cli/study.hpp"
#include "stickslip/chart.hpp"
#include "stickslip/chart_report.hpp"
#include "stickslip/report.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_chart";
constexpr const char* kNotes =
    "Outputs in --out (each written whole or not at all): curves.tsv (one row per curve\n"
    "point: HB Hopf with its first Lyapunov coefficient l1, GR grazing with the pure-slip\n"
    "multiplier and its type, LP fold of pure-slip orbits), codim2.tsv (GH generalized\n"
    "Hopf, GR-LP where the grazing type changes), regions.tsv, chart.gp and chart.png.\n"
    "Study files: model and solver keys at top level, this app's keys in [chart].\n"
    "Exit status: 0 done; 1 numerical failure or interruption (the curves so far are\n"
    "written, marked partial); 2 bad input (nothing written).\n"
    "Example: ss_chart --study studies/seed_chart.ini --out chart";

volatile std::sig_atomic_t g_signal = 0;
void OnSignal(int sig) { g_signal = sig; }

po::options_description AppOptions() {
  po::options_description d("Chart (study section [chart])");
  d.add_options()("param", cli::Value()->value_name("NAME"),
                  "first axis, any model parameter (default v)")(
      "from", cli::Value()->value_name("A"), "first axis from (default 0.05)")(
      "to", cli::Value()->value_name("B"), "first axis to, > from (default 0.6)")(
      "param2", cli::Value()->value_name("NAME"), "second axis, != param (default beta)")(
      "from2", cli::Value()->value_name("C"), "second axis from (default 0)")(
      "to2", cli::Value()->value_name("D"), "second axis to, > from2 (default 0.25)")(
      "out", cli::Value()->value_name("DIR"), "output directory (default chart)")(
      "max_step", cli::Value()->value_name("F"),
      "largest continuation step, fraction of the rectangle (default 0.01)")(
      "grid", cli::Value()->value_name("N"),
      "region grid: N x N cells for the shading (default 48)")(
      "no_plots", po::bool_switch(), "only curves.tsv and codim2.tsv: no regions, no gnuplot");
  return d;
}

bool Plot(const std::string& dir, const std::string& script) {
  ss::WriteFileAtomically(dir + "/chart.gp", script);
  const std::string wrapper = dir + "/.chart.part.gp";
  ss::WriteFileAtomically(wrapper, "suffix = '.part'\nload 'chart.gp'\n");
  std::string error;
  bool ok = ss::RunGnuplot(wrapper, dir, &error);
  std::remove(wrapper.c_str());
  const std::string png = dir + "/chart.png", part = png + ".part";
  if (ok && std::rename(part.c_str(), png.c_str()) != 0) ok = false, error = "rename failed";
  std::remove(part.c_str());
  if (!ok) cli::PrintError(kProg, "gnuplot failed: " + error);
  return ok;
}

// What was computed, per curve, and the codim-2 points, on stdout.
void PrintSummary(const ss::ChartResult& r, const ss::Plane& pl, const std::string& model,
                  const std::string& dir, bool plots, bool plots_ok) {
  std::printf("%s: %s x %s; %s\n%d curves, %d points in %.1f ms", kProg, pl.p1.c_str(),
              pl.p2.c_str(), model.c_str(), static_cast<int>(r.curves.size()), r.points(),
              r.seconds * 1e3);
  if (plots)
    std::printf(" (regions %d x %d in %.1f ms)", r.regions.n1, r.regions.n2,
                r.region_seconds * 1e3);
  std::printf("\n");
  for (size_t i = 0; i < r.curves.size(); ++i) {
    const ss::Curve& c = r.curves[i];
    std::printf("  curve %zu %s: %zu points, %d evaluations, %.1f ms, ends %s\n", i + 1,
                ss::CurveLabel(c.kind), c.points.size(), c.evaluations, c.seconds * 1e3,
                c.ends.c_str());
  }
  for (const ss::Codim2Point& p : r.codim2)
    std::printf("  %-5s %s = %.12f  %s = %.12f  %s\n", p.label.c_str(), pl.p1.c_str(), p.p1,
                pl.p2.c_str(), p.p2, p.description.c_str());
  std::printf(
      "wrote %s/curves.tsv, codim2.tsv%s\n", dir.c_str(),
      plots ? (plots_ok ? ", regions.tsv, chart.gp, chart.png" : ", regions.tsv, chart.gp") : "");
}

int Main(int argc, char** argv) {
  const po::options_description desc = cli::AppDescription(AppOptions());
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "chart");
  if (cli::HelpOrVersion(std::cout, args, kProg, "ss_chart [--study FILE] [options]", desc, kNotes))
    return 0;
  ss::ChartOptions opts;
  ss::Plane& pl = opts.plane;
  pl.p1 = args.Text("param", "v");
  pl.p2 = args.Text("param2", "beta");
  pl.from1 = args.Number("from", 0.05);
  pl.to1 = args.Number("to", 0.6);
  pl.from2 = args.Number("from2", 0.0);
  pl.to2 = args.Number("to2", 0.25);
  // The base model is validated at the rectangle's corner; its own values of
  // the two axes are never used.
  const ss::Params base = cli::ModelFromArguments(args);
  opts.orbit.flow = cli::FlowOptionsFromArguments(args);
  // One revolution takes a few hundred steps; where mu < 0 at large slip speeds
  // (k5 > 0) an orbit can run away, and is given up after 20000.
  if (!args.Given("max_steps")) opts.orbit.flow.max_steps = 20000;
  opts.max_step = args.Number("max_step", opts.max_step);
  const bool plots = !args.Flag("no_plots");
  const long grid = args.Integer("grid", 48);
  if (grid < 2 || grid > 1000)
    throw cli::UsageError("invalid value '" + args.Text("grid") + "' for " + args.Source("grid") +
                          ": must be in [2, 1000]");
  if (plots) opts.region_n1 = opts.region_n2 = static_cast<int>(grid);
  const std::string err = opts.ValidationError(base);
  if (!err.empty()) throw cli::UsageError(err);
  const std::string dir = cli::CheckedOutputDir(args.Text("out", "chart"),
                                                args.Given("out") ? args.Source("out") : "--out");

  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  opts.cancelled = [] { return g_signal != 0; };
  const ss::ChartResult r = ss::Chart(base, opts);

  // The law's parameters but the two axes, then the axes' ranges.
  std::string model = std::string("law=") + ss::LawName(base.law);
  for (const auto& name : ss::ParameterNames(base.law))
    if (name != pl.p1 && name != pl.p2)
      model += " " + name + "=" + ss::FormatNumber(ss::GetParameter(base, name));
  model += " " + pl.p1 + "=[" + ss::FormatNumber(pl.from1) + ", " + ss::FormatNumber(pl.to1) +
           "] " + pl.p2 + "=[" + ss::FormatNumber(pl.from2) + ", " + ss::FormatNumber(pl.to2) + "]";
  // Every file starts with the tool, the command, the model and the integrator.
  cli::Metadata meta = cli::RunMetadata(kProg, cli::CommandLine(argc, argv), base, opts.orbit.flow);
  for (auto& [key, value] : meta)  // the axes' base values are never used
    if (key == pl.p1 || key == pl.p2) value = "axis";
  meta.push_back({"range", pl.p1 + " = [" + ss::FormatNumber(pl.from1) + ", " +
                               ss::FormatNumber(pl.to1) + "], " + pl.p2 + " = [" +
                               ss::FormatNumber(pl.from2) + ", " + ss::FormatNumber(pl.to2) + "]"});
  auto text = [&](ss::TsvTable t) {
    t.PrependMeta(meta);
    return t.str();
  };
  ss::WriteFileAtomically(dir + "/curves.tsv", text(ss::CurvesTable(r, pl, model)));
  ss::WriteFileAtomically(dir + "/codim2.tsv", text(ss::Codim2Table(r, pl, model)));
  bool plots_ok = true;
  if (plots) {
    ss::WriteFileAtomically(dir + "/regions.tsv", text(ss::RegionsTable(r, pl, model)));
    plots_ok = Plot(dir, ss::ChartScript(r, pl, model));
  }
  PrintSummary(r, pl, model, dir, plots, plots_ok);
  if (r.unphysical_points > 0)
    cli::PrintError(kProg, std::to_string(r.unphysical_points) +
                               " curve points have orbits visiting slip speeds where mu <= 0 "
                               "(not physical there; flagged in curves.tsv)");
  if (r.status != ss::ChartStatus::kOk) {
    cli::PrintError(kProg, std::string("partial chart written (") + ss::ChartStatusName(r.status) +
                               "): " + r.message);
    return 1;
  }
  return plots_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
