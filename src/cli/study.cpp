#include "cli/study.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/run_control.hpp"
#include "stickslip/report.hpp"

namespace stickslip::cli {

namespace {

// Physical inputs and the dimensionless parameters they replace.
const std::vector<std::string> kPhysical = {"mass",    "damping", "stiffness", "belt_speed",
                                            "gravity", "speed_m", "speed_s",   "delta_phys"};
const std::vector<std::string> kScaled = {"beta", "v", "v_m", "v_s", "delta", "k5"};

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

bool IsKeyChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
}

bool IsKey(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), IsKeyChar);
}

std::string OneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\r', ' ');
  return s;
}

std::string Default(double x) { return " (default " + FormatNumber(x) + ")"; }

}  // namespace

po::typed_value<std::string>* Value() { return po::value<std::string>(); }

po::options_description AppDescription(const po::options_description& app) {
  po::options_description desc;
  desc.add(GeneralOptions()).add(ModelOptions()).add(SolverOptions()).add(app);
  return desc;
}

const std::vector<std::string>& StudySections() {
  static const std::vector<std::string> sections = {"simulate", "continue", "benchmark", "chart",
                                                    "basin"};
  return sections;
}

po::options_description GeneralOptions() {
  po::options_description d("General");
  d.add_options()("help,h", "print this help and exit")(
      "version", po::bool_switch(), "print the version (and git commit) and exit")(
      "study", Value()->value_name("FILE"),
      "read options from a study file (key = value lines; the command line wins)");
  return d;
}

po::options_description ModelOptions() {
  const Params p;
  po::options_description d("Model, dimensionless (seed eq. 3.5; the defaults are the seed set)");
  d.add_options()("law", Value()->value_name("NAME"),
                  "friction law: cubic (default), coulomb, stribeck, leine")(
      "beta", Value()->value_name("X"), ("damping ratio" + Default(p.beta)).c_str())(
      "v", Value()->value_name("X"), ("belt speed" + Default(p.v)).c_str())(
      "mu_s", Value()->value_name("X"), ("static friction coefficient" + Default(p.mu_s)).c_str())(
      "mu_m", Value()->value_name("X"), ("cubic: minimum friction" + Default(p.mu_m)).c_str())(
      "v_m", Value()->value_name("X"),
      ("cubic: slip speed of the minimum" + Default(p.v_m)).c_str())(
      "mu_k", Value()->value_name("X"),
      ("coulomb, stribeck: kinetic coefficient" + Default(p.mu_k)).c_str())(
      "v_s", Value()->value_name("X"), ("stribeck: decay speed" + Default(p.v_s)).c_str())(
      "delta", Value()->value_name("X"), ("leine: decay rate" + Default(p.delta)).c_str())(
      "k5", Value()->value_name("X"),
      ("cubic: quintic term -k5 s^5, >= 0, mu(v) > 0" + Default(p.k5)).c_str());
  po::options_description phys(
      "Model, physical (any of these selects the physical set: mass, damping, stiffness,\n"
      "belt_speed and the law's speed_m / speed_s / delta_phys are then required, and\n"
      "beta, v, v_m, v_s, delta are not allowed; mu_s, mu_m, mu_k are shared)");
  phys.add_options()("mass", Value()->value_name("KG"), "mass M [kg]")(
      "damping", Value()->value_name("NS/M"), "viscous damping C [N s/m]")(
      "stiffness", Value()->value_name("N/M"), "spring constant K [N/m]")(
      "belt_speed", Value()->value_name("M/S"), "belt speed V [m/s]")(
      "gravity", Value()->value_name("M/S2"), "gravity g [m/s^2] (default 9.81)")(
      "speed_m", Value()->value_name("M/S"), "cubic: slip speed of the minimum [m/s]")(
      "speed_s", Value()->value_name("M/S"), "stribeck: decay speed [m/s]")(
      "delta_phys", Value()->value_name("S/M"), "leine: decay rate [s/m]");
  d.add(phys);
  return d;
}

po::options_description SolverOptions() {
  const FlowOptions f;
  po::options_description d("Solver");
  d.add_options()("integrator", Value()->value_name("NAME"),
                  "slip phases by taylor (default: Taylor series) or cvode (CVODE, --method)")(
      "rtol", Value()->value_name("X"),
      ("relative tolerance, in [1e-14, 1e-2]" + Default(f.rtol)).c_str())(
      "atol", Value()->value_name("X"),
      ("absolute tolerance, in [1e-16, 1e-2]" + Default(f.atol)).c_str())(
      "method", Value()->value_name("NAME"), "cvode: adams (default, non-stiff) or bdf (stiff)")(
      "max_steps", Value()->value_name("N"),
      ("steps allowed per output interval, >= 10 (default " + std::to_string(f.max_steps) + ")")
          .c_str());
  return d;
}

// ---------------------------------------------------------------------------
// Arguments

bool Arguments::Given(const std::string& name) const {
  const auto it = vm_.find(name);
  return it != vm_.end() && !it->second.empty() && !it->second.defaulted();
}

std::string Arguments::Source(const std::string& name) const {
  const auto it = origin_.find(name);
  if (it != origin_.end()) return name + " (" + it->second + ")";
  return "--" + name;
}

std::string Arguments::Origin(const std::string& name) const {
  const auto it = origin_.find(name);
  return it != origin_.end() ? it->second : "--" + name;
}

std::string Arguments::Text(const std::string& name, const std::string& fallback) const {
  const auto it = vm_.find(name);
  if (it == vm_.end() || it->second.empty()) return fallback;
  return it->second.as<std::string>();
}

double Arguments::Number(const std::string& name, double fallback) const {
  const auto x = OptionalNumber(name);
  return x ? *x : fallback;
}

std::optional<double> Arguments::OptionalNumber(const std::string& name) const {
  if (!Given(name)) return std::nullopt;
  return ParseNumber(Text(name), Source(name));
}

long Arguments::Integer(const std::string& name, long fallback) const {
  if (!Given(name)) return fallback;
  const std::string text = Text(name);
  long value = 0;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, value);
  if (text.empty() || r.ec != std::errc() || r.ptr != end)
    throw UsageError("invalid value '" + text + "' for " + Source(name) + ": not an integer");
  return value;
}

bool Arguments::Flag(const std::string& name) const {
  const auto it = vm_.find(name);
  return it != vm_.end() && !it->second.empty() && it->second.as<bool>();
}

double ParseNumber(const std::string& text, const std::string& what) {
  auto bad = [&](const std::string& why) {
    return UsageError("invalid value '" + text + "' for " + what + ": " + why);
  };
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-') ++begin;
  double x = 0;
  const auto r = std::from_chars(begin, end, x);
  if (r.ec == std::errc::result_out_of_range) throw bad("out of range");
  if (text.empty() || r.ec != std::errc() || r.ptr != end) throw bad("not a number");
  if (!std::isfinite(x)) throw bad("not a finite number");
  return x;
}

// ---------------------------------------------------------------------------
// Parsing

Arguments ParseArguments(int argc, const char* const argv[], const po::options_description& desc,
                         const std::string& section) {
  Arguments args;
  try {
    const auto style =
        po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
    const po::parsed_options parsed =
        po::command_line_parser(argc, argv).options(desc).style(style).run();
    for (const auto& o : parsed.options) {
      if (o.position_key >= 0 || o.string_key.empty()) {
        const std::string token = o.original_tokens.empty() ? "" : o.original_tokens.front();
        throw UsageError("unexpected argument '" + token + "' (options are --name value)");
      }
    }
    po::store(parsed, args.vm_);
  } catch (const po::error& e) {
    throw UsageError(OneLine(e.what()));
  }
  const bool info = args.vm_.count("help") || args.Flag("version");
  if (!info && args.Given("study")) ReadStudyFile(args.Text("study"), desc, section, args);
  try {
    po::notify(args.vm_);
  } catch (const po::error& e) {
    throw UsageError(OneLine(e.what()));
  }
  return args;
}

void ReadStudyFile(const std::string& path, const po::options_description& desc,
                   const std::string& section, Arguments& args) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
    throw UsageError("cannot read study file '" + path + "': " + std::strerror(errno));
  if (S_ISDIR(st.st_mode))
    throw UsageError("cannot read study file '" + path + "': it is a directory");
  if (!S_ISREG(st.st_mode))
    throw UsageError("cannot read study file '" + path +
                     "': not a regular file (FIFO, device or socket)");
  if (st.st_size > kMaxStudyBytes)
    throw UsageError("cannot read study file '" + path + "': " + std::to_string(st.st_size) +
                     " bytes, more than " + std::to_string(kMaxStudyBytes));
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read study file '" + path + "': " + std::strerror(errno));
  args.study_ = path;

  const auto& sections = StudySections();
  std::map<std::string, int> seen;  // key -> line
  std::string current;              // the current section, "" at top level
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string where = path + ":" + std::to_string(line);
    auto malformed = [&](const std::string& why) {
      return UsageError("study file " + where + ": " + why);
    };
    if (raw.find('\0') != std::string::npos)
      throw malformed("a NUL byte (column " + std::to_string(raw.find('\0') + 1) +
                      "): not a text file");
    if (line > kMaxStudyBytes) throw malformed("the file grew while it was read");
    const std::string text = Trim(raw.substr(0, raw.find('#')));
    if (text.empty()) continue;
    if (text.front() == '[') {
      const std::string name = text.back() == ']' ? Trim(text.substr(1, text.size() - 2)) : "";
      if (!IsKey(name)) throw malformed("malformed section header '" + text + "'");
      if (std::find(sections.begin(), sections.end(), name) == sections.end()) {
        std::string known;
        for (const auto& s : sections) known += (known.empty() ? "" : ", ") + s;
        throw malformed("unknown section [" + name + "] (known: " + known + ")");
      }
      current = name;
      continue;
    }
    const auto eq = text.find('=');
    if (eq == std::string::npos) throw malformed("expected 'key = value', got '" + text + "'");
    const std::string key = Trim(text.substr(0, eq));
    const std::string value = Trim(text.substr(eq + 1));
    if (!IsKey(key)) throw malformed("malformed key in '" + text + "'");
    if (value.empty()) throw malformed("key '" + key + "' has no value");
    if (!current.empty() && current != section) continue;  // another app's section
    if (key == "study" || key == "help" || key == "version")
      throw malformed("key '" + key + "' is not allowed in a study file");
    const po::option_description* d = desc.find_nothrow(key, false);
    if (d == nullptr || d->long_name() != key) throw malformed("unknown key '" + key + "'");
    const auto [it, fresh] = seen.emplace(key, line);
    if (!fresh) throw malformed("key '" + key + "' repeats line " + std::to_string(it->second));
    if (args.Given(key)) continue;  // the command line wins
    po::parsed_options one(&desc);
    po::option o;
    o.string_key = key;
    o.value.push_back(value);
    o.original_tokens = {key, value};
    one.options.push_back(o);
    try {
      po::store(one, args.vm_);
    } catch (const po::error& e) {
      throw malformed(OneLine(e.what()));
    }
    args.origin_[key] = where;
  }
  if (in.bad()) throw UsageError("cannot read study file '" + path + "': read error");
}

// ---------------------------------------------------------------------------
// Model and solver

namespace {

// A validation message "name = value ..." with where the named value came from.
std::string WithOrigin(const Arguments& args, const std::string& err) {
  const std::string name = err.substr(0, err.find(" = "));
  if (name.size() == err.size() || !args.Given(name)) return err;
  return err + " (from " + args.Origin(name) + ")";
}

std::string FirstGiven(const Arguments& args, const std::vector<std::string>& names) {
  for (const auto& n : names)
    if (args.Given(n)) return n;
  return "";
}

// A value given for a parameter the law does not use is validated as its
// own law would (so --v_s -1 is refused with the cubic law too).
void CheckOtherLaws(const Arguments& args, const Params& p) {
  const std::map<std::string, std::string> physical = {
      {"v_m", "speed_m"}, {"v_s", "speed_s"}, {"delta", "delta_phys"}};
  for (LawKind law : {LawKind::kCubic, LawKind::kCoulomb, LawKind::kStribeck, LawKind::kLeine}) {
    if (law == p.law) continue;
    const auto names = ParameterNames(law);
    bool given = false;
    for (std::size_t i = 3; i < names.size(); ++i) {  // past beta, v, mu_s
      const auto it = physical.find(names[i]);
      given = given || args.Given(names[i]) || (it != physical.end() && args.Given(it->second));
    }
    if (!given) continue;
    Params q = p;
    q.law = law;
    const std::string err = ValidationError(q);
    if (!err.empty())
      throw UsageError("invalid model: " + WithOrigin(args, err) + " (a " + LawName(law) +
                       " parameter, unused by the " + LawName(p.law) + " law)");
  }
}

}  // namespace

Params ModelFromArguments(const Arguments& args) { return ModelFromArguments(args, "", 0.0); }

Params ModelFromArguments(const Arguments& args, const std::string& continued, double at) {
  const Params p = UncheckedModelFromArguments(args);
  Params checked = p;
  if (!continued.empty() && IsParameterName(continued)) SetParameter(checked, continued, at);
  const std::string err = ValidationError(checked);
  if (!err.empty()) throw UsageError("invalid model: " + WithOrigin(args, err));
  CheckOtherLaws(args, checked);
  return p;
}

Params UncheckedModelFromArguments(const Arguments& args) {
  LawKind law = LawKind::kCubic;
  if (args.Given("law")) {
    try {
      law = LawFromName(args.Text("law"));
    } catch (const InvalidArgument& e) {
      throw UsageError(args.Source("law") + ": " + e.what());
    }
  }
  const std::string physical = FirstGiven(args, kPhysical);
  Params p;
  if (physical.empty()) {
    p.law = law;
    for (const auto& name : AllParameterNames())
      if (const auto x = args.OptionalNumber(name)) SetParameter(p, name, *x);
  } else {
    const std::string scaled = FirstGiven(args, kScaled);
    if (!scaled.empty())
      throw UsageError(args.Source(scaled) + " is dimensionless and cannot be combined with " +
                       "the physical inputs (" + args.Source(physical) + " given)");
    std::vector<std::string> required = {"mass", "damping", "stiffness", "belt_speed"};
    if (law == LawKind::kCubic) required.push_back("speed_m");
    if (law == LawKind::kStribeck) required.push_back("speed_s");
    if (law == LawKind::kLeine) required.push_back("delta_phys");
    for (const auto& name : required)
      if (!args.Given(name))
        throw UsageError("physical inputs (" + args.Source(physical) + " given) need --" + name +
                         " for the " + LawName(law) + " law");
    PhysicalParams phys;
    phys.law = law;
    phys.mass = args.Number("mass", phys.mass);
    phys.damping = args.Number("damping", phys.damping);
    phys.stiffness = args.Number("stiffness", phys.stiffness);
    phys.belt_speed = args.Number("belt_speed", phys.belt_speed);
    phys.gravity = args.Number("gravity", phys.gravity);
    phys.speed_m = args.Number("speed_m", phys.speed_m);
    phys.speed_s = args.Number("speed_s", phys.speed_s);
    phys.delta = args.Number("delta_phys", phys.delta);
    phys.mu_s = args.Number("mu_s", p.mu_s);
    phys.mu_m = args.Number("mu_m", p.mu_m);
    phys.mu_k = args.Number("mu_k", p.mu_k);
    try {
      p = ToDimensionless(phys);
    } catch (const InvalidArgument& e) {
      throw UsageError("invalid physical inputs: " + WithOrigin(args, e.what()));
    }
  }
  return p;
}

FlowOptions FlowOptionsFromArguments(const Arguments& args) {
  FlowOptions f;
  f.rtol = args.Number("rtol", f.rtol);
  f.atol = args.Number("atol", f.atol);
  f.max_steps = args.Integer("max_steps", f.max_steps);
  if (args.Given("integrator")) {
    const std::string i = args.Text("integrator");
    if (i == "taylor") {
      f.integrator = Integrator::kTaylor;
    } else if (i == "cvode") {
      f.integrator = Integrator::kCvode;
    } else {
      throw UsageError("invalid value '" + i + "' for " + args.Source("integrator") +
                       ": expected taylor or cvode");
    }
  }
  if (args.Given("method")) {
    const std::string m = args.Text("method");
    if (m == "adams") {
      f.method = Method::kAdams;
    } else if (m == "bdf") {
      f.method = Method::kBdf;
    } else {
      throw UsageError("invalid value '" + m + "' for " + args.Source("method") +
                       ": expected adams or bdf");
    }
  }
  const std::string err = f.ValidationError();
  if (!err.empty()) throw UsageError("invalid solver options: " + WithOrigin(args, err));
  return f;
}

std::string DescribeModel(const Params& p) {
  std::string s = std::string("law=") + LawName(p.law);
  for (const auto& name : ParameterNames(p.law))
    s += " " + name + "=" + FormatNumber(GetParameter(p, name));
  return s;
}

// ---------------------------------------------------------------------------
// Printing

void PrintHelp(std::ostream& os, const std::string& usage, const po::options_description& desc,
               const std::string& notes) {
  os << "usage: " << usage << "\n" << desc << "\n";
  if (!notes.empty()) os << notes << (notes.back() == '\n' ? "" : "\n");
}

void PrintError(const std::string& prog, const std::string& message) {
  std::cerr << prog << ": error: " << OneLine(message) << std::endl;
}

int ReportError(const std::string& prog, const std::exception& e) {
  PrintError(prog, e.what());
  const bool bad_input = dynamic_cast<const InvalidArgument*>(&e) != nullptr ||
                         dynamic_cast<const po::error*>(&e) != nullptr;
  return bad_input ? 2 : 1;
}

int RunApp(const std::string& prog, const std::function<int()>& body) {
  std::signal(SIGPIPE, SIG_IGN);  // a closed stdout is reported below, not fatal
  try {
    const int code = body();
    CheckStdout();
    return code;
  } catch (const std::exception& e) {
    return ReportError(prog, e);
  } catch (...) {
    PrintError(prog, "unknown exception");
    return 1;
  }
}

}  // namespace stickslip::cli
