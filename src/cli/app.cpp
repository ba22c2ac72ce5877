#include "cli/app.hpp"

#include <algorithm>

namespace stickslip::cli {

const char* const kExitCodeHelp =
    "Exit status (the same in every app): 0 done; 1 numerical failure, interruption\n"
    "(SIGINT/SIGTERM), time limit or I/O failure (a result cut short is written marked\n"
    "partial; if a figure cannot be drawn whole, no file is replaced); 2 bad input\n"
    "(nothing written); 3 gnuplot is missing (data files and script written, no figures).";

void AddRunOptions(po::options_description& d, const std::string& default_out,
                   const std::string& no_plots_help) {
  d.add_options()("out", Value()->value_name("DIR"),
                  ("output directory (default " + default_out + ")").c_str())(
      "no_plots", po::bool_switch(), no_plots_help.c_str())(
      "max_time", Value()->value_name("S"),
      "wall-time limit in seconds, every phase (gnuplot too); the result so far is kept, "
      "marked partial (default 0: none)");
  AddFormatOption(d);
}

void AddFormatOption(po::options_description& d) {
  d.add_options()("format", Value()->value_name("png|pdf|svg"),
                  "the figures' file format: png (pngcairo), pdf (pdfcairo) or svg (default png)")(
      "size", Value()->value_name("SIZE"),
      "the figures' printed size: single (3.5 in, a journal column), double (7.2 in) or WxH "
      "in inches (e.g. 3.5x2.6), with text, lines and dashes for that size (default: the "
      "screen size, 10 in wide at 12 pt)")(
      "font", Value()->value_name("NAME,PT"),
      "the figures' font with --size (default Sans,7 below 5 in, else Sans,9); below 5 in "
      "the model's title line is left to the caption");
}

FigureFormat FigureFormatOf(const Arguments& args) {
  FigureFormat f = FigureFormat::kPng;
  if (args.Given("format") && !ParseFigureFormat(args.Text("format"), &f))
    throw UsageError("invalid value '" + args.Text("format") + "' for " + args.Source("format") +
                     ": must be png, pdf or svg");
  return f;
}

namespace {

double MaxTime(const Arguments& args) {
  const double t = args.Number("max_time", 0);
  if (t < 0)
    throw UsageError("invalid value '" + args.Text("max_time") + "' for " +
                     args.Source("max_time") + ": must be >= 0");
  return t;
}

}  // namespace

AppRun::AppRun(const std::string& prog, const Arguments& args, const std::string& default_out,
               std::vector<std::string> names)
    : prog_(prog),
      plots_(!args.Flag("no_plots")),
      out_(args.Text("out", default_out), std::move(names),
           args.Given("out") ? args.Source("out") : "--out", prog),
      run_(prog, MaxTime(args)),
      layout_(FigureLayoutOf(args)) {}

bool AppRun::Finish(const std::string& script, const std::vector<std::string>& figures,
                    const std::vector<std::string>& all_figures,
                    const std::vector<std::string>& stale) {
  if (plots_ && !run_.Cancelled() && !figures.empty()) {  // nothing to draw: no gnuplot
    run_.Phase("plotting");
    if (layout_) out_.Write(script, ApplyFigureLayout(out_.Read(script), *layout_));
    gnuplot_ = out_.Draw(script, figures, [this] { return run_.Cancelled(); });
  }
  if (gnuplot_.status == GnuplotStatus::kFailed) {
    PrintError(prog_, gnuplot_.message + "; nothing replaced in '" + out_.dir() + "'");
    return false;
  }
  // Figures this run did not draw are stale beside its data: removed.
  std::vector<std::string> remove = stale;
  for (const auto& f : all_figures)
    if (!gnuplot_.ok() || std::find(figures.begin(), figures.end(), f) == figures.end())
      remove.push_back(f);
  out_.Commit(remove);
  return true;
}

int AppRun::ExitCode(const std::string& partial) const {
  if (!partial.empty()) {
    PrintError(prog_, partial);
    return kExitFailed;
  }
  if (run_.Cancelled()) {
    PrintError(prog_, run_.Reason() + " while " + run_.cancelled_phase() +
                          ": the files are written" +
                          (gnuplot_.ok() || !plots_ ? "" : ", figures not drawn"));
    return kExitFailed;
  }
  if (plots_ && gnuplot_.status == GnuplotStatus::kMissing) {
    PrintError(prog_, gnuplot_.message + "; data files written, no figures");
    return kExitNoGnuplot;
  }
  return kExitDone;
}

}  // namespace stickslip::cli
