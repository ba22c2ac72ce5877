// ss_simulate: one trajectory of the belt model, written as a TSV
// (metadata lines, then the header t, x, xdot, mode), optionally plotted with gnuplot.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "cli/output.hpp"
#include "cli/physical.hpp"
#include "cli/run_control.hpp"
#include "cli/study.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/integrate/flow.hpp"
#include "stickslip/model/model.hpp"
#include "stickslip/io/report.hpp"

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
    "With --plot, FILE.gp names the TSV and the PNG by their plain names: run it in\n"
    "FILE's directory. The files are written as one set (docs/reliability.md).\n"
    "Exit status: 0 done; 1 numerical or I/O failure, interruption or time limit (the\n"
    "trajectory so far is written, marked '# status: partial (...)', without a figure;\n"
    "if the figure cannot be drawn whole, no file is replaced);\n"
    "2 bad input (nothing written); 3 gnuplot is missing (data and script written).\n"
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
      "also write FILE.gp and run gnuplot on it, giving FILE.png (phase portrait and time\n"
      "series; SI units with physical inputs; FILE.pdf or FILE.svg with --format)")(
      "max_time", cli::Value()->value_name("S"),
      "wall-time limit in seconds (default none); past it, or on SIGINT/SIGTERM, the run\n"
      "stops and writes nothing");
  cli::AddFormatOption(d);
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

// A two-panel figure in the common style (figure_style.hpp): the phase
// portrait with the stick set, and x, x' against t; in SI units (columns
// t_s, x_m, xdot_m_s) when the run has physical inputs.
std::string PlotScript(const std::string& data, const std::string& figure, const ss::Model& model,
                       const std::optional<cli::Scales>& si, ss::FigureFormat format) {
  const double L = si ? si->L : 1, t0 = si ? si->t0 : 1;
  const double v = model.v() * L / t0;
  const double mu_s = model.params().mu_s * L;
  const double shift = 2.0 * model.beta() * model.v() * L;
  const std::string q = GnuplotString(data);
  const int ct = si ? 5 : 1, cx = si ? 6 : 2, cv = si ? 7 : 3;
  const std::string stick = "(strcol(4) eq 'stick' ? $" + std::to_string(cv) + " : NaN)";
  const std::string ux = si ? " [m]" : " (dimensionless)", uv = si ? " [m/s]" : " (dimensionless)",
                    ut = si ? " [s]" : " (dimensionless)";
  const std::string c = ":", n = std::to_string(cx), nv = std::to_string(cv);
  std::string s = ss::FigurePreamble(format, 1400, 650);
  s += "set output " + GnuplotString(figure) + "\n";
  // The stick set: x' = v, |x + 2 beta v| <= mu_s.
  s += "$omega << EOD\n" + ss::FormatNumber(-mu_s - shift) + "\t" + ss::FormatNumber(v) + "\n" +
       ss::FormatNumber(mu_s - shift) + "\t" + ss::FormatNumber(v) + "\nEOD\n";
  s += "set multiplot layout 1,2 title " +
       ss::GnuplotQuoted(ss::FigureTitle(cli::DescribeModel(model.params()), {})) + "\n";
  s += "set xlabel " + ss::GnuplotQuoted("displacement x" + ux) + "\n";
  s += "set ylabel " + ss::GnuplotQuoted("velocity dx/dt" + uv) + "\nset title 'phase portrait'\n";
  s += "plot $omega using 1:2 with lines lw 8 lc rgb '#f4a6a6' title 'stick set: dx/dt = v', \\\n";
  s += "     " + q + " using " + n + c + nv + " with lines ls 1 lw 1.5 title 'trajectory', \\\n";
  s += "     " + q + " using " + n + c + stick + " with lines ls 9 title 'sticking'\n";
  s += "set xlabel " + ss::GnuplotQuoted("time t" + ut) + "\n";
  s += "set ylabel " + ss::GnuplotQuoted("x" + ux + ", dx/dt" + uv) + "\nset title 'time series'\n";
  s += "plot " + q + " using " + std::to_string(ct) + c + n + " with lines ls 1 lw 1.5 title " +
       ss::GnuplotQuoted("displacement x") + ", \\\n";
  s += "     " + q + " using " + std::to_string(ct) + c + nv + " with lines ls 3 lw 1.5 title " +
       ss::GnuplotQuoted("velocity dx/dt") + "\n";
  s += "unset multiplot\n";
  return s;
}

// The output names: the TSV and, with --plot, FILE.gp and FILE.png beside it.
struct OutNames {
  std::string dir, tsv, gp, png;
};
OutNames SplitOut(const std::string& out, ss::FigureFormat format) {
  const auto slash = out.find_last_of('/');
  OutNames n;
  n.dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : out.substr(0, slash));
  n.tsv = slash == std::string::npos ? out : out.substr(slash + 1);
  const bool ext = n.tsv.size() > 4 && n.tsv.compare(n.tsv.size() - 4, 4, ".tsv") == 0;
  const std::string stem = ext ? n.tsv.substr(0, n.tsv.size() - 4) : n.tsv;
  n.gp = stem + ".gp";
  n.png = ss::FigureFile(stem, format);
  return n;
}

// The first row with a non-finite number, or empty.
std::string NonFinite(const ss::Sample& s) {
  if (std::isfinite(s.t) && std::isfinite(s.z[0]) && std::isfinite(s.z[1])) return "";
  return "non-finite state at t = " + ss::FormatNumber(s.t) + ": x = " + ss::FormatNumber(s.z[0]) +
         ", x' = " + ss::FormatNumber(s.z[1]);
}

// The run's settings, all checked before anything runs or is written.
struct Settings {
  ss::Params params;
  ss::FlowOptions options;
  double x0 = 0, xdot0 = 0.25, t_end = 100, dt = 0.01, max_time = 0;
  std::string out;
  bool plot = false;
  ss::FigureFormat format = ss::FigureFormat::kPng;
};

Settings Configure(const cli::Arguments& args) {
  Settings s;
  s.params = cli::ModelFromArguments(args);
  s.options = cli::FlowOptionsFromArguments(args);
  s.x0 = args.Number("x0", s.x0);
  s.xdot0 = args.Number("xdot0", s.xdot0);
  s.t_end = args.Number("t_end", s.t_end);
  s.dt = args.Number("dt", s.dt);
  s.max_time = args.Number("max_time", 0);
  for (const char* name : {"t_end", "dt"})
    if (!(args.Number(name, 1) > 0))
      throw cli::UsageError("invalid value '" + args.Text(name) + "' for " + args.Source(name) +
                            ": must be > 0");
  if (s.max_time < 0)
    throw cli::UsageError("invalid value '" + args.Text("max_time") + "' for " +
                          args.Source("max_time") + ": must be >= 0");
  if (s.t_end / s.dt > kMaxRows)
    throw cli::UsageError("t_end / dt = " + ss::FormatNumber(s.t_end / s.dt) +
                          " rows is more than " + ss::FormatNumber(kMaxRows) +
                          "; use a larger --dt");
  if (!args.Given("out")) throw cli::UsageError("--out FILE is required");
  s.out = args.Text("out");
  CheckOutputPath(s.out, args.Source("out"));
  s.plot = args.Flag("plot");
  s.format = cli::FigureFormatOf(args);
  return s;
}

// Why a run gives no data: a non-finite row, or the flow's status and where.
std::string Failure(const ss::FlowResult& r, const std::string& bad, const cli::RunControl& run) {
  if (!bad.empty()) return bad;
  std::string where;
  if (r.status != ss::FlowStatus::kIntegratorFailed &&  // these messages already say where
      r.status != ss::FlowStatus::kCancelled)
    where = " (at t = " + ss::FormatNumber(r.t) + " in " + ss::ModeName(r.mode) +
            ", x = " + ss::FormatNumber(r.z[0]) + ", x' = " + ss::FormatNumber(r.z[1]) + ")";
  return std::string(ss::FlowStatusName(r.status)) + ": " + r.message + where +
         (r.status == ss::FlowStatus::kCancelled ? " (" + run.Reason() + ")" : "");
}

// Writes the set (the TSV, and with --plot the script and the figure).
int WriteOutputs(cli::OutputSet& files, const OutNames& names, const Settings& s,
                 const ss::Model& model, const ss::TsvTable& table, cli::RunControl& run,
                 const std::optional<cli::Scales>& scales) {
  run.Phase("writing");
  files.Write(names.tsv, table.str());
  cli::GnuplotResult g;
  if (s.plot) {
    files.Write(names.gp, PlotScript(names.tsv, names.png, model, scales, s.format));
    run.Phase("plotting");
    g = files.Draw(names.gp, {names.png}, [&] { return run.Cancelled(); });
    if (g.status == cli::GnuplotStatus::kFailed) {
      cli::PrintError(kProg, g.message + "; nothing replaced");
      return 1;
    }
  }
  files.Commit(g.ok() ? std::vector<std::string>{} : std::vector<std::string>{names.png});
  if (g.status == cli::GnuplotStatus::kCancelled) {
    cli::PrintError(kProg, run.Reason() + " while plotting: " + s.out + " written, no figure");
    return 1;
  }
  if (g.status == cli::GnuplotStatus::kMissing) {
    cli::PrintError(kProg, g.message + "; " + s.out + " and the script written, no figure");
    return 3;
  }
  return 0;
}

int Main(int argc, char** argv) {
  const po::options_description desc = cli::AppDescription(AppOptions());
  const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "simulate");
  if (cli::HelpOrVersion(std::cout, args, kProg,
                         "ss_simulate [--study FILE] [model options] [--x0 X] [--xdot0 Y] "
                         "[--t_end T] [--dt DT] --out FILE.tsv [--plot] [--max_time S]",
                         desc, kNotes))
    return 0;
  const Settings s = Configure(args);
  // With physical inputs, physical copies of t, x and x' follow (seed section 3 scaling).
  const std::optional<cli::Scales> scales = cli::ScalesFromArguments(args);
  const OutNames names = SplitOut(s.out, s.format);
  cli::OutputSet files(names.dir,
                       s.plot ? std::vector<std::string>{names.tsv, names.gp, names.png}
                              : std::vector<std::string>{names.tsv},
                       args.Source("out"), kProg);

  const ss::Model model(s.params);
  ss::Flow flow(model, s.options);
  cli::RunControl run(kProg, s.max_time);
  flow.set_cancel([&] {
    run.Heartbeat("");
    return run.Cancelled();
  });
  run.Phase("integrating");
  const ss::Vec2 z0(s.x0, s.xdot0);
  std::vector<std::string> columns = {"t", "x", "xdot", "mode"};
  if (scales) columns.insert(columns.end(), {"t_s", "x_m", "xdot_m_s"});
  ss::TsvTable table(columns);
  for (const auto& [key, value] :
       cli::RunMetadata(kProg, cli::CommandLine(argc, argv), s.params, s.options))
    table.AddMeta(key, value);
  table.AddMeta("model", cli::DescribeModel(s.params));
  table.AddMeta("x0", ss::FormatNumber(s.x0));
  table.AddMeta("xdot0", ss::FormatNumber(s.xdot0));
  table.AddMeta("t_end", ss::FormatNumber(s.t_end));
  table.AddMeta("dt", ss::FormatNumber(s.dt));
  if (scales) {
    table.AddMeta("L", ss::FormatNumber(scales->L) + " m (M g / K)");
    table.AddMeta("t0", ss::FormatNumber(scales->t0) + " s (sqrt(M / K))");
  }
  ss::Sample last{std::nan(""), ss::Vec2::Zero(), ss::Mode::kStick};
  std::string bad;
  auto observer = [&](const ss::Sample& x) {
    if (x.t == last.t && x.z == last.z && x.mode == last.mode) return;  // a repeated point
    if (bad.empty()) bad = NonFinite(x);
    if (bad.empty() && scales)
      table.AddRow({x.t, x.z[0], x.z[1], ss::ModeName(x.mode), x.t * scales->t0, x.z[0] * scales->L,
                    x.z[1] * scales->L / scales->t0});
    else if (bad.empty())
      table.AddRow({x.t, x.z[0], x.z[1], ss::ModeName(x.mode)});
    last = x;
    run.Progress("t = " + ss::FormatNumber(x.t), x.t / s.t_end, x.t, "time units");
  };
  ss::StopRule stop;
  stop.t_max = s.t_end;
  ss::FlowResult r;
  try {
    r = flow.Run(0.0, z0, model.ModeAt(z0), stop, false, s.dt, observer);
  } catch (const ss::InvalidArgument& e) {  // valid input: a numerical failure
    throw ss::Error(std::string("numerical failure: ") + e.what());
  }
  if (!r.ok() || !bad.empty()) {
    // As every app: the rows so far (all finite), marked partial with where
    // the run stopped; no figure, and an older one is removed (not this run's).
    const std::string why = Failure(r, bad, run);
    table.AddMeta("status", "partial (" + why + ")");
    run.Phase("writing");
    files.Write(names.tsv, table.str());
    files.Commit(s.plot ? std::vector<std::string>{names.gp, names.png}
                        : std::vector<std::string>{});
    cli::PrintError(kProg, why + "; the trajectory so far is written to " + s.out +
                               ", marked partial");
    return 1;
  }
  table.AddMeta("status", "complete");
  return WriteOutputs(files, names, s, model, table, run, scales);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::RunApp(kProg, [&] { return Main(argc, argv); });
}
