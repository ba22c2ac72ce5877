// ss_simulate: one trajectory of the belt model, written as a TSV
// (# t, x, xdot, mode), optionally plotted with gnuplot.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>

#include "cli/about.hpp"
#include "cli/physical.hpp"
#include "cli/study.hpp"
#include "stickslip/flow.hpp"
#include "stickslip/model.hpp"
#include "stickslip/report.hpp"

namespace ss = stickslip;
namespace cli = stickslip::cli;
namespace po = boost::program_options;

namespace {

constexpr const char* kProg = "ss_simulate";
constexpr double kMaxRows = 1e7;  // rows are held in memory until the atomic write
constexpr const char* kNotes =
    "Output: a TSV that starts with '# key: value' lines (tool, command, model, run and\n"
    "solver settings, status), then the header line 't<TAB>x<TAB>xdot<TAB>mode' (mode:\n"
    "slip-below, stick, slip-above), then one row every --dt and one at every switch.\n"
    "Stick rows have xdot == v exactly.\n"
    "Study files: key = value lines ('#' comments); keys outside sections are model\n"
    "and solver options, [simulate] holds this app's keys; the command line wins.\n"
    "Exit status: 0 done; 1 numerical or I/O failure (no data file written);\n"
    "2 bad input (nothing written).\n"
    "Example: ss_simulate --study studies/seed.ini --xdot0 0.125 --out traj.tsv --plot";

po::options_description AppOptions() {
  po::options_description d("Simulation (study section [simulate])");
  d.add_options()("x0", cli::Value()->value_name("X"), "initial displacement (default 0)")(
      "xdot0", cli::Value()->value_name("X"),
      "initial velocity (default 0.25: on the stick set at the seed's v, fig. 5)")(
      "t_end", cli::Value()->value_name("T"), "end time, > 0 (default 100)")(
      "dt", cli::Value()->value_name("DT"),
      "output interval, > 0 (default 0.01); switches are written too")(
      "out", cli::Value()->value_name("FILE"), "output TSV file (required), written atomically")(
      "plot", po::bool_switch(),
      "also write FILE.gp and run gnuplot on it, giving FILE.png (phase portrait + time series)");
  return d;
}

// The directory of `path` must exist and be writable: checked before the run.
void CheckOutputPath(const std::string& path, const std::string& source) {
  auto bad = [&](const std::string& why) {
    return cli::UsageError("invalid value '" + path + "' for " + source + ": " + why);
  };
  if (path.empty() || path.back() == '/') throw bad("not a file name");
  const auto slash = path.find_last_of('/');
  const std::string dir =
      slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0) throw bad("directory '" + dir + "': " + std::strerror(errno));
  if (!S_ISDIR(st.st_mode)) throw bad("'" + dir + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw bad("directory '" + dir + "' is not writable: " + std::strerror(errno));
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) throw bad("it is a directory");
}

std::string GnuplotString(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// A two-panel figure: phase portrait with the stick set, and x, x' against t.
std::string PlotScript(const std::string& data, const std::string& png, const ss::Model& model) {
  const double v = model.v();
  const double mu_s = model.params().mu_s;
  const double shift = 2.0 * model.beta() * v;
  const std::string q = GnuplotString(data);
  const std::string stick = "(strcol(4) eq 'stick' ? $3 : NaN)";
  std::string s;
  s += "set terminal pngcairo size 1400,600 noenhanced butt font 'Sans,11'\n";
  s += "set output " + GnuplotString(png) + "\n";
  s += "set datafile separator '\\t'\n";  // the header line is skipped as non-numeric
  // The stick set: x' = v, |x + 2 beta v| <= mu_s.
  s += "$omega << EOD\n" + ss::FormatNumber(-mu_s - shift) + "\t" + ss::FormatNumber(v) + "\n" +
       ss::FormatNumber(mu_s - shift) + "\t" + ss::FormatNumber(v) + "\nEOD\n";
  s += "set multiplot layout 1,2 title " + GnuplotString(cli::DescribeModel(model.params())) + "\n";
  s += "set grid\nset key top right\n";
  s += "set xlabel 'x'\nset ylabel \"x'\"\nset title 'phase portrait'\n";
  s += "plot $omega using 1:2 with lines lw 8 lc rgb '#f4a6a6' title \"stick set: x' = v\", \\\n";
  s += "     " + q + " using 2:3 with lines lw 1.5 lc rgb '#1f77b4' title 'trajectory', \\\n";
  s += "     " + q + " using 2:" + stick + " with lines lw 2.5 lc rgb '#d62728' title 'stick'\n";
  s += "set xlabel 't'\nset ylabel \"x, x'\"\nset title 'time series'\n";
  s += "plot " + q + " using 1:2 with lines lw 1.5 title 'x', \\\n";
  s += "     " + q + " using 1:3 with lines lw 1.5 title \"x'\"\n";
  s += "unset multiplot\n";
  return s;
}

int Main(int argc, char** argv) {
  const po::options_description desc = cli::AppDescription(AppOptions());
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "simulate");
  if (cli::HelpOrVersion(std::cout, args, kProg,
                         "ss_simulate [--study FILE] [model options] [--x0 X] [--xdot0 Y] "
                         "[--t_end T] [--dt DT] --out FILE.tsv [--plot]",
                         desc, kNotes))
    return 0;
  // All input is checked before anything runs or is written.
  const ss::Params params = cli::ModelFromArguments(args);
  const ss::FlowOptions options = cli::FlowOptionsFromArguments(args);
  const double x0 = args.Number("x0", 0.0);
  const double xdot0 = args.Number("xdot0", 0.25);
  const double t_end = args.Number("t_end", 100.0);
  const double dt = args.Number("dt", 0.01);
  if (!(t_end > 0))
    throw cli::UsageError("invalid value '" + args.Text("t_end") + "' for " + args.Source("t_end") +
                          ": must be > 0");
  if (!(dt > 0))
    throw cli::UsageError("invalid value '" + args.Text("dt") + "' for " + args.Source("dt") +
                          ": must be > 0");
  if (t_end / dt > kMaxRows)
    throw cli::UsageError("t_end / dt = " + ss::FormatNumber(t_end / dt) + " rows is more than " +
                          ss::FormatNumber(kMaxRows) + "; use a larger --dt");
  if (!args.Given("out")) throw cli::UsageError("--out FILE is required");
  const std::string out = args.Text("out");
  CheckOutputPath(out, args.Source("out"));
  const bool plot = args.Flag("plot");

  const ss::Model model(params);
  ss::Flow flow(model, options);
  const ss::Vec2 z0(x0, xdot0);
  // With physical inputs, physical copies of t, x and x' follow (seed section 3 scaling).
  const std::optional<cli::Scales> scales = cli::ScalesFromArguments(args);
  std::vector<std::string> columns = {"t", "x", "xdot", "mode"};
  if (scales) columns.insert(columns.end(), {"t_s", "x_m", "xdot_m_s"});
  ss::TsvTable table(columns);
  for (const auto& [key, value] :
       cli::RunMetadata(kProg, cli::CommandLine(argc, argv), params, options))
    table.AddMeta(key, value);
  table.AddMeta("model", cli::DescribeModel(params));
  table.AddMeta("x0", ss::FormatNumber(x0));
  table.AddMeta("xdot0", ss::FormatNumber(xdot0));
  table.AddMeta("t_end", ss::FormatNumber(t_end));
  table.AddMeta("dt", ss::FormatNumber(dt));
  if (scales) {
    table.AddMeta("L", ss::FormatNumber(scales->L) + " m (M g / K)");
    table.AddMeta("t0", ss::FormatNumber(scales->t0) + " s (sqrt(M / K))");
  }
  ss::Sample last{std::nan(""), ss::Vec2::Zero(), ss::Mode::kStick};
  auto observer = [&](const ss::Sample& s) {
    if (s.t == last.t && s.z == last.z && s.mode == last.mode) return;  // a repeated point
    if (scales)
      table.AddRow({s.t, s.z[0], s.z[1], ss::ModeName(s.mode), s.t * scales->t0, s.z[0] * scales->L,
                    s.z[1] * scales->L / scales->t0});
    else
      table.AddRow({s.t, s.z[0], s.z[1], ss::ModeName(s.mode)});
    last = s;
  };
  ss::StopRule stop;
  stop.t_max = t_end;
  const ss::FlowResult r = flow.Run(0.0, z0, model.ModeAt(z0), stop, false, dt, observer);
  if (!r.ok()) {
    // No data file: a truncated run must not pass for a complete one.
    std::string where;
    if (r.status != ss::FlowStatus::kIntegratorFailed)  // that message already says where
      where = " (at t = " + ss::FormatNumber(r.t) + " in " + ss::ModeName(r.mode) +
              ", x = " + ss::FormatNumber(r.z[0]) + ", x' = " + ss::FormatNumber(r.z[1]) + ")";
    cli::PrintError(kProg, std::string(ss::FlowStatusName(r.status)) + ": " + r.message + where +
                               "; no output written");
    return 1;
  }
  table.AddMeta("status", "complete");  // a failed run writes no file
  ss::WriteFileAtomically(out, table.str());
  if (plot) {
    const std::string stem = out.size() > 4 && out.compare(out.size() - 4, 4, ".tsv") == 0
                                 ? out.substr(0, out.size() - 4)
                                 : out;
    const std::string gp = stem + ".gp";
    ss::WriteFileAtomically(gp, PlotScript(out, stem + ".png", model));
    std::string error;
    if (!ss::RunGnuplot(gp, "", &error)) {
      cli::PrintError(kProg, error);
      return 1;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
