// The built-in systems as a choice of the apps (system_choice.hpp).
#include "cli/system_choice.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "chain/chain.hpp"
#include "mode_coupling/mode_coupling.hpp"
#include "model_file/model_file.hpp"
#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::cli {

namespace {

constexpr long kMaxBlocks = 64;  // the chain's blocks: a bound on the state (2 per block)

// The settings in order: the study's [system] lines, then --set's entries
// (a later one of the same name wins).
std::vector<Arguments::Setting> Settings(const Arguments& args) {
  std::vector<Arguments::Setting> out = args.settings();
  if (!args.Given("set")) return out;
  std::vector<std::string> seen;
  for (const std::string& item : CommaItems(args.Text("set"))) {
    const auto eq = item.find('=');
    const std::string key = eq == std::string::npos ? "" : Trim(item.substr(0, eq));
    const std::string value = eq == std::string::npos ? "" : Trim(item.substr(eq + 1));
    if (key.empty() || value.empty())
      throw UsageError(args.Source("set") + ": expected NAME=VALUE, got '" + item + "'");
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
      throw UsageError(args.Source("set") + ": '" + key + "' is set twice");
    seen.push_back(key);
    out.push_back({key, value, args.Source("set")});
  }
  return out;
}

// --model's path; a study file's relative one is read from the study's folder.
std::string ModelPath(const Arguments& args) {
  const std::string path = args.Text("model");
  if (args.OnCommandLine("model") || path.empty() || path[0] == '/') return path;
  const std::size_t slash = args.study().find_last_of('/');
  return slash == std::string::npos ? path : args.study().substr(0, slash + 1) + path;
}

std::unique_ptr<System> Build(SystemChoice choice, const Arguments& args, const Params& law,
                              long blocks) {
  if (choice == SystemChoice::kModel) {
    for (const char* o : {"law", "mu_m", "v_m", "k5", "v_s", "delta"})
      if (args.Given(o))
        throw UsageError(args.Source(o) + ": the model file " + args.Text("model") +
                         " has its own laws (set its parameters with --set)");
    try {
      return model_file::ReadModel(ModelPath(args));
    } catch (const InvalidArgument& e) {
      throw UsageError(args.Source("model") + " " + e.what());
    }
  }
  if (choice == SystemChoice::kChain) {
    const long n = args.Integer("blocks", blocks);
    if (n < 1 || n > kMaxBlocks)
      throw UsageError(args.Source("blocks") + " = " + std::to_string(n) + ": must lie in [1, " +
                       std::to_string(kMaxBlocks) + "]");
    return std::make_unique<chain::Chain>(chain::Uniform(static_cast<int>(n), law, 0));
  }
  if (choice == SystemChoice::kForced) {  // its parameters: the law's, then A and Omega
    ForcedBeltParams p;
    p.base = law;
    p.force = args.Number("force", 0);
    p.omega = args.Number("omega", 1);
    CheckForcedBelt(args, p);
    return std::make_unique<ForcedBelt>(p);
  }
  mode_coupling::CouplingParams c;
  c.law = law;
  return std::make_unique<mode_coupling::ModeCoupling>(c);
}

// The parameters the restart's run recorded, at the point.
void SetRestartParameters(const Arguments& args, const SystemPoint& sp, System* s) {
  for (const auto& [name, value] : sp.parameters) {
    const int j = s->ParameterIndex(name);
    if (j < 0)
      throw UsageError(args.Source("restart") + " " + args.Text("restart") + ": '" + name +
                       "' is no parameter of " + sp.system);
    s->SetParameterValue(j, value);
  }
}

}  // namespace

po::options_description SystemOptions() {
  po::options_description d(
      "System (docs/systems.md; default the belt, or the forced oscillator "
      "with --force)");
  d.add_options()("system", Value()->value_name("NAME"),
                  "belt (default), chain (blocks on a belt, coupled by springs) or "
                  "mode_coupling (a brake model of two modes): every app takes it")(
      "model", Value()->value_name("FILE"),
      "a model file: the system it writes down (docs/model_files.md); every app that takes "
      "--system takes it")("blocks", Value()->value_name("N"),
                           "chain: the number of blocks, in [1, 64] (default 2)")(
      "set", Value()->value_name("A=X,B=Y"),
      "the system's parameters by their own names, applied in order (a study file's [system] "
      "section, then these; docs/systems.md lists them, and so does an unknown name's error)");
  return d;
}

po::options_description ForcingOptions() {
  po::options_description d("Model, forcing (x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t))");
  d.add_options()("force", Value()->value_name("A"),
                  "force amplitude A >= 0; != 0 selects the forced oscillator (default 0: the "
                  "belt model)")("omega", Value()->value_name("W"),
                                 "forcing frequency over the natural one, > 0 (default 1)")(
      "max_amplitude", Value()->value_name("X"),
      "forced: a branch ends where |x| passes X (default 50); ss_chart: seed branches and "
      "grid cells end there (forced 50, --system 1000); the forced oscillator's rtol and "
      "atol default to 1e-12");
  return d;
}

bool ForcedRequested(const Arguments& args) {
  const std::string param = args.Text("param", "");
  const bool forced = args.Number("force", 0) != 0 || param == "force";
  if (!forced && !args.Given("restart") && (args.Given("omega") || param == "omega"))
    throw UsageError((args.Given("omega") ? args.Source("omega") : args.Source("param")) +
                     " needs the forced oscillator: give --force A > 0");
  return forced;
}

SystemChoice SystemChoiceOf(const Arguments& args) {
  SystemChoice c = SystemChoice::kBelt;
  if (!args.Given("system") && !args.Given("model"))  // ForcedRequested's test, without its error
    return args.Number("force", 0) != 0 || args.Text("param", "") == "force" ? SystemChoice::kForced
                                                                             : c;
  const std::string name = args.Text("system", args.Given("model") ? "model" : "belt");
  if (name == Name(SystemChoice::kForced))
    throw UsageError(args.Source("system") +
                     " forced: the forced oscillator is chosen with "
                     "--force A (A != 0)");
  if (args.Given("model") && name != "model")
    throw UsageError(args.Source("model") + " and " + args.Source("system") + " " + name +
                     ": give one of them");
  if (name == "model" && !args.Given("model"))
    throw UsageError(args.Source("system") + " model needs --model FILE");
  if (!FromName(name, &c))
    throw UsageError(args.Source("system") + ": unknown system '" + name +
                     "' (expected belt, chain or mode_coupling, or --model FILE)");
  return c;
}

void RefuseSystem(const Arguments& args, const std::string& prog,
                  const std::vector<std::string>& also) {
  if (SystemRequested(args))
    throw UsageError(args.Source("system") + " = " + args.Text("system") + ": " + prog +
                     " takes the belt and the forced oscillator only (the other apps take every "
                     "system)");
  std::vector<std::string> options = {"set", "blocks"};
  options.insert(options.end(), also.begin(), also.end());
  for (const std::string& o : options)
    if (args.Given(o))
      throw UsageError(args.Source(o) + " needs --system chain or mode_coupling, or --model FILE");
  if (!args.settings().empty())
    throw UsageError(args.settings().front().where +
                     ": a [system] section needs system = chain or mode_coupling");
}

std::unique_ptr<System> SystemFromArguments(const Arguments& args, const SystemPoint* restart) {
  SystemChoice choice = SystemChoiceOf(args);
  if (restart && !FromName(restart->system, &choice))
    throw UsageError(args.Source("restart") + " " + args.Text("restart") + ": unknown system '" +
                     restart->system + "'");
  if (choice == SystemChoice::kModel && !args.Given("model"))
    throw UsageError(args.Source("restart") + " " + args.Text("restart") +
                     ": the run was of a model file; give it again with --model FILE");
  if (args.Given("blocks") && choice != SystemChoice::kChain)
    throw UsageError(args.Source("blocks") + " needs --system chain");
  const bool forced = choice == SystemChoice::kForced;
  for (const char* o : {"mass", "damping", "stiffness", "belt_speed", "force", "omega"})
    if (args.Given(o) && !(forced && (o == std::string("force") || o == std::string("omega"))))
      throw UsageError(args.Source(o) + (forced ? ": the forced oscillator takes dimensionless "
                                                  "inputs"
                                                : ": --system " + std::string(Name(choice)) +
                                                      " takes dimensionless inputs without "
                                                      "forcing"));
  const Params law = UncheckedModelFromArguments(args, restart ? restart->law : Params());
  std::unique_ptr<System> s;
  try {
    s = Build(choice, args, law, restart ? restart->blocks : 2);
  } catch (const UsageError&) {
    throw;
  } catch (const InvalidArgument& e) {
    throw UsageError(std::string("--system ") + Name(choice) + ": " + e.what());
  }
  if (restart) SetRestartParameters(args, *restart, s.get());
  for (int j = 0; forced && j < s->parameters(); ++j)  // each an option: given ones override
    if (args.Given(s->ParameterName(j)))
      s->SetParameterValue(j, args.Number(s->ParameterName(j), 0));
  for (const char* o : {"beta", "v", "mu_s", "mu_k"}) {  // the model options the system names
    if (args.Given(o) && s->ParameterIndex(o) >= 0)
      s->SetParameterValue(s->ParameterIndex(o), args.Number(o, 0));
    else if (args.Given(o) && choice == SystemChoice::kModel)  // a model names its own
      throw UsageError(args.Source(o) + ": " + model_file::ModelName(*s) + " has no parameter " +
                       o + " (its parameters: " + ParameterList(*s) + ")");
  }
  for (const Arguments::Setting& set : Settings(args)) {
    const int j = s->ParameterIndex(set.key);
    if (j < 0)
      throw UsageError(set.where + ": '" + set.key + "' is no parameter of " +
                       (choice == SystemChoice::kModel ? model_file::ModelName(*s) : Name(choice)) +
                       " (its parameters: " + ParameterList(*s) + ")");
    s->SetParameterValue(j, ParseNumber(set.value, set.where + " " + set.key));
  }
  if (const std::string e = s->ValidationError(); !e.empty()) {
    // Blamed on the last setting the message names, else on --system.
    const std::vector<Arguments::Setting> all = Settings(args);
    for (auto it = all.rbegin(); it != all.rend(); ++it)
      if (e.find(it->key + " =") != std::string::npos ||
          e.find(it->key + " must") != std::string::npos)
        throw UsageError(it->where + " " + it->key + " = " + it->value + ": " + e);
    throw UsageError(std::string("--system ") + Name(choice) + ": " + e);
  }
  return s;
}

std::string SystemLabel(const Arguments& args) {
  return args.Given("model") ? "--model " + args.Text("model")
                             : "--system " + args.Text("system", "belt");
}

std::vector<std::string> CommaItems(const std::string& text) {
  std::vector<std::string> out;
  std::size_t from = 0;
  for (;;) {
    const std::size_t comma = text.find(',', from);
    out.push_back(Trim(text.substr(from, comma - from)));
    if (comma == std::string::npos) return out;
    from = comma + 1;
  }
}

std::string ParameterList(const System& s) {
  std::string out;
  for (int j = 0; j < s.parameters(); ++j) out += (j ? ", " : "") + s.ParameterName(j);
  return out;
}

std::string DescribeSystem(const System& s, SystemChoice choice, int continued, int other,
                           const char* mark) {
  std::string out = choice == SystemChoice::kModel ? model_file::ModelName(s) : Name(choice);
  for (int j = 0; j < s.parameters(); ++j)
    out += (j ? " " : ": ") + s.ParameterName(j) + "=" +
           (j == continued || j == other ? std::string(mark) : FormatNumber(s.ParameterValue(j)));
  return out;
}

std::string DefaultSectionText(const System& s) {
  const Section x = MaximaSection(s);
  if (s.DerivativeOf(0) >= 0)
    return s.StateName(x.g.terms[0].index) + " = 0 falling (maxima of " + s.StateName(0) + ")";
  std::string h;  // contact 0's relative velocity, as its terms
  for (int t = 0; t < x.g.size; ++t)
    h += (t ? " + " : "") +
         (x.g.terms[t].weight == 1 ? "" : FormatNumber(x.g.terms[t].weight) + " ") +
         s.StateName(x.g.terms[t].index);
  return h + " = its value at steady sliding (0 where there is none), falling";
}

}  // namespace stickslip::cli
