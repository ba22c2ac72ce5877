// The one flow every app runs:
//   parse -> validate -> AppRun (OutputSet checked up front, then RunControl)
//   -> compute (polling run().Cancelled()) -> out().Write(...) -> Finish()
//   (draw, check, commit under the lock) -> print -> ExitCode().
// So every app has the same --out DIR, --no_plots and --max_time, the same
// signals and progress, and the same exit codes:
//   0 done; 1 numerical failure, interruption (SIGINT/SIGTERM), time limit or
//   I/O failure (a cut-short result is written marked partial; a figure not
//   drawn whole replaces nothing); 2 bad input (nothing written); 3 gnuplot is
//   missing (data files and script written, stale figures removed).
//
// Use:
//   desc.add(cli::RunOptions("chart", "..."));  // --out --no_plots --max_time
//   ... validate everything ...
//   cli::AppRun app(kProg, args, "chart", {"a.tsv", "a.gp", "a.png"});
//   const Result r = Compute(..., [&] { return app.run().Cancelled(); });
//   app.out().Write("a.tsv", ...);
//   app.out().Write("a.gp", ...);
//   if (!app.Finish("a.gp", {"a.png"}, {"a.png"})) return 1;  // nothing replaced
//   ... print the summary ...
//   return app.ExitCode(r.partial() ? "partial result written (...)" : "");
#pragma once

#include <boost/program_options.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/figure_layout.hpp"
#include "cli/gnuplot.hpp"
#include "cli/output.hpp"
#include "cli/run_control.hpp"
#include "cli/study.hpp"
#include "stickslip/io/figure_style.hpp"

namespace stickslip::cli {

// The exit codes of every app.
enum ExitCode : int { kExitDone = 0, kExitFailed = 1, kExitBadInput = 2, kExitNoGnuplot = 3 };
// The table above as --help text (the last lines of every app's notes).
extern const char* const kExitCodeHelp;

// --out DIR (default `default_out`), --no_plots, --max_time S, --format, added to an
// app's own options. `no_plots_help`: what --no_plots leaves out.
void AddRunOptions(po::options_description& d, const std::string& default_out,
                   const std::string& no_plots_help);

// --format png|pdf|svg (AddRunOptions adds it too).
void AddFormatOption(po::options_description& d);
// The figures' format: png unless --format says otherwise; UsageError (exit 2)
// naming --format on any other value.
FigureFormat FigureFormatOf(const Arguments& args);

class AppRun {
 public:
  // Reads --out, --no_plots and --max_time (UsageError naming the option),
  // checks the output set `names` (UsageError: exit 2, nothing created), then
  // installs the signal handlers and starts the clock.
  AppRun(const std::string& prog, const Arguments& args, const std::string& default_out,
         std::vector<std::string> names);

  OutputSet& out() { return out_; }
  RunControl& run() { return run_; }
  bool plots() const { return plots_; }
  const GnuplotResult& gnuplot() const { return gnuplot_; }

  // Draws `figures` from the staged `script` (unless --no_plots, the run is
  // cancelled or `figures` is empty; gnuplot is killed on a signal or --max_time), checks each,
  // then commits the set; the names of `all_figures` not drawn are removed
  // as stale. False (after one line on stderr) if a figure was not drawn
  // whole: nothing was replaced, exit 1. Throws Error if the commit fails.
  bool Finish(const std::string& script, const std::vector<std::string>& figures,
              const std::vector<std::string>& all_figures,
              const std::vector<std::string>& stale = {});
  // After Finish: 1 with `partial` (the reason the result is cut short, if
  // not empty) or the reason of a cancellation; 3 if gnuplot is missing; 0.
  int ExitCode(const std::string& partial) const;

 private:
  std::string prog_;
  bool plots_;
  OutputSet out_;
  RunControl run_;
  std::optional<FigureLayout> layout_;  // --size, --font
  GnuplotResult gnuplot_{GnuplotStatus::kCancelled, "figures not drawn (--no_plots)"};
};

}  // namespace stickslip::cli
