// Command-line layer shared by the apps (Boost.Program_options): option
// groups, study files, strict numbers, the model and solver options, and the
// one-line error convention. Only apps and this layer parse and print.
//
// Study files (--study FILE) hold `key = value` lines; `#` starts a comment;
// keys are long option names without "--". Keys outside any section are read
// by every app, so they must be options every app registers (model, solver).
// `[name]` starts a section read only by the app whose section name it is
// (ss_simulate: [simulate]); sections of the other apps listed in
// StudySections() are skipped; any other section is an error. The command
// line overrides the study file. A key may appear once per file.
//
// An app with its own options:
//   po::options_description mine("Continuation (study section [continue])");
//   mine.add_options()("param", cli::Value(), "...")("from", cli::Value(), "...");
//   po::options_description desc;
//   desc.add(cli::GeneralOptions()).add(cli::ModelOptions()).add(cli::SolverOptions()).add(mine);
//   const cli::Arguments args = cli::ParseArguments(argc, argv, desc, "continue");
//   const double from = args.Number("from", 0.05);  // strict; errors name the source
// and main() returns cli::RunApp("ss_continue", [&] { return Main(argc, argv); }).
//
// Physical inputs: if any of --mass --damping --stiffness --belt_speed
// --gravity --speed_m --speed_s --delta_phys is given, the physical set is
// used: --mass --stiffness --damping --belt_speed are required (--gravity
// defaults to 9.81), plus --speed_m (cubic), --speed_s (stribeck) or
// --delta_phys (leine), and they are converted by ToDimensionless. The
// dimensionless --beta --v --v_m --v_s --delta are then an error. The
// friction coefficients --mu_s --mu_m --mu_k are shared by both sets.
// Parameters the chosen law does not use are ignored, but validated if given.
#pragma once

#include <boost/program_options.hpp>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip::cli {

namespace po = boost::program_options;

// Bad input from the command line or a study file. what() is one line that
// names the option (and the study line) and the offending value.
class UsageError : public InvalidArgument {
 public:
  using InvalidArgument::InvalidArgument;
};

// Option groups; an app adds the groups it needs, then its own options.
// Values are taken as text (see Value()) and parsed strictly on use.
po::options_description GeneralOptions();  // --help, --study
po::options_description ModelOptions();    // --law, model and physical parameters
// --rtol --atol --method --max_steps; the help states `defaults` (an app
// whose computation has other solver defaults passes them, e.g. ChartOptions).
po::options_description SolverOptions(const FlowOptions& defaults = FlowOptions());
// General, model and solver options followed by an app's own.
po::options_description AppDescription(const po::options_description& app,
                                       const FlowOptions& solver_defaults = FlowOptions());

// The value semantic for an app's own option: text, parsed on use by
// Arguments::Number / Integer / Text. For flags use po::bool_switch().
po::typed_value<std::string>* Value();

// Section names of the apps; a study file may hold a section for each.
const std::vector<std::string>& StudySections();

// Parsed options with their origin, for messages that say where a value came from.
class Arguments {
 public:
  const po::variables_map& map() const { return vm_; }
  // Given on the command line or in the study file (a default does not count).
  bool Given(const std::string& name) const;
  // Given on the command line itself (not by the study file).
  bool OnCommandLine(const std::string& name) const;
  // Where a given option came from: "--beta" or "beta (studies/seed.ini:7)".
  std::string Source(const std::string& name) const;
  // Just the place: "--beta" or "studies/seed.ini:7".
  std::string Origin(const std::string& name) const;
  // The text of an option; fallback if it was not given.
  std::string Text(const std::string& name, const std::string& fallback = "") const;
  // Strict numbers: the whole text must be a finite decimal number; throws
  // UsageError naming Source(name) and the text otherwise.
  double Number(const std::string& name, double fallback) const;
  std::optional<double> OptionalNumber(const std::string& name) const;
  long Integer(const std::string& name, long fallback) const;
  // Integer(), in [lo, hi]; UsageError naming Source(name) and the bounds otherwise.
  long IntegerIn(const std::string& name, long fallback, long lo, long hi) const;
  // A po::bool_switch() flag.
  bool Flag(const std::string& name) const;
  // The study file read, empty if none.
  const std::string& study() const { return study_; }
  // The study file's [system] section: a built-in system's parameters by
  // their own names (system_choice.hpp), with "file:line" each.
  struct Setting {
    std::string key, value, where;
  };
  const std::vector<Setting>& settings() const { return settings_; }

 private:
  friend Arguments ParseArguments(int, const char* const[], const po::options_description&,
                                  const std::string&);
  friend void ReadStudyFile(const std::string&, const po::options_description&, const std::string&,
                            Arguments&);
  po::variables_map vm_;
  std::map<std::string, std::string> origin_;  // study key -> "file:line"
  std::string study_;
  std::vector<Setting> settings_;
};

// Parses argv against desc (exact long names only, no positional arguments),
// then, unless --help was given, the study file named by --study (if desc has
// that option). `section` is the app's study section (e.g. "simulate").
// Throws UsageError.
Arguments ParseArguments(int argc, const char* const argv[], const po::options_description& desc,
                         const std::string& section);
// Reads a study file into args; keys already given there are kept (the
// command line wins). Throws UsageError naming the file and line. Only a
// regular file of at most kMaxStudyBytes is read (a FIFO or device is refused
// before it is opened); a NUL byte is an error naming its line.
constexpr long kMaxStudyBytes = 1 << 20;
void ReadStudyFile(const std::string& path, const po::options_description& desc,
                   const std::string& section, Arguments& args);

// s without leading and trailing blanks (spaces, tabs, carriage returns).
std::string Trim(const std::string& s);

// Strict number: the whole text is a finite decimal number ("1e-3", "-0.5",
// "+2"); no spaces, no trailing characters, no nan or inf. `what` names the
// source in the message, e.g. "--beta".
double ParseNumber(const std::string& text, const std::string& what);

// The model from ModelOptions(), validated (throws UsageError).
Params ModelFromArguments(const Arguments& args);
// The same for a continuation in `continued`: the model is validated with that
// parameter set to `at`, and as given when a value of `continued` is given
// (--param v --v -1 is refused); the range ends are validated by
// ContinuationOptions.
// Values not given default to `defaults` (a restart's point; --law too).
Params ModelFromArguments(const Arguments& args, const std::string& continued, double at,
                          const Params& defaults = Params());
// The model as given (physical inputs converted), not validated: for
// defaults that depend on it, such as a parameter's range (DefaultRange).
// Throws UsageError on unreadable or inconsistent options.
Params UncheckedModelFromArguments(const Arguments& args, const Params& defaults = Params());
// The parameter named by option `key` (`fallback` if not given): one of
// ParameterAxes(law, forced), the law's (with forced, force and omega too).
// Throws UsageError naming the option and the choices otherwise.
ParameterAxis AxisFromArguments(const Arguments& args, const char* key, const std::string& fallback,
                                LawKind law, bool forced);
// Throws UsageError "invalid forced model<where>: <error> (from <origin>)" if
// p is no valid forced model, naming where the offending value came from
// unless it is `swept` (a swept parameter's value is the range end in <where>).
void CheckForcedBelt(const Arguments& args, const ForcedBeltParams& p,
                     const std::string& where = "", const std::string& swept = "");
// The solver options from SolverOptions(), validated (throws UsageError);
// what is not given keeps its value in `defaults`.
FlowOptions FlowOptionsFromArguments(const Arguments& args,
                                     const FlowOptions& defaults = FlowOptions());
// "law=cubic beta=0.05 v=0.25 ...": the law's parameters, for file headers.
std::string DescribeModel(const Params& p);
// The same with the continued parameter as its range, "... v=[0.05, 0.5] ...":
// its base value is never used, so the line states none.
std::string DescribeModel(const Params& p, const std::string& continued, double from, double to);

// Help text: a usage line, the options, then free-form notes.
void PrintHelp(std::ostream& os, const std::string& usage, const po::options_description& desc,
               const std::string& notes = "");

// Prints "prog: error: message" to stderr as one line (Printable).
void PrintError(const std::string& prog, const std::string& message);
// s with every control character escaped (\n, \t, \x1b, ...) and trailing
// newlines dropped: user input (option values, paths) is never echoed raw.
std::string Printable(const std::string& s);
// Prints e with PrintError and returns the exit code: 2 for bad input
// (InvalidArgument, UsageError, Boost.PO errors), 1 for anything else.
int ReportError(const std::string& prog, const std::exception& e);
// Runs an app's body with SIGPIPE ignored; an escaping exception goes through
// ReportError, and a failed write to stdout (CheckStdout) makes it exit 1.
int RunApp(const std::string& prog, const std::function<int()>& body);

}  // namespace stickslip::cli
