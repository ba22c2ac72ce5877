#include "cli/about.hpp"

#include "stickslip/io/report.hpp"
#include "stickslip/version.hpp"

namespace stickslip::cli {

std::string VersionText(const std::string& prog) { return prog + " " + VersionString(); }

std::string CommandLine(int argc, const char* const argv[]) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    const bool plain = !a.empty() && a.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789-_=+./,:@%") == std::string::npos;
    std::string quoted = "'";
    for (char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    quoted += "'";
    line += (i > 0 ? " " : "") + (plain ? a : quoted);
  }
  // A line break in an argument would end the metadata line.
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  return line;
}

bool HelpOrVersion(std::ostream& os, const Arguments& args, const std::string& prog,
                   const std::string& usage, const po::options_description& desc,
                   const std::string& notes) {
  if (args.map().count("help")) {
    PrintHelp(os, usage, desc, notes);
    return true;
  }
  if (args.Flag("version")) {
    os << VersionText(prog) << "\n";
    return true;
  }
  return false;
}

Metadata ToolMetadata(const std::string& prog, const std::string& command) {
  Metadata m = {{"tool", prog + " " + Version()}};
  if (*GitCommit()) m.emplace_back("commit", GitCommit());
  m.emplace_back("command", command);
  return m;
}

Metadata RunMetadata(const std::string& prog, const std::string& command, const Params& p,
                     const FlowOptions& flow, const std::string& continued) {
  Metadata m = ToolMetadata(prog, command);
  m.emplace_back("law", Name(p.law));
  for (const auto& name : ParameterNames(p.law))
    m.emplace_back(name, name == continued ? "continued" : FormatNumber(GetParameter(p, name)));
  m.emplace_back("integrator", flow.integrator == Integrator::kCvode
                                   ? std::string("cvode ") + Name(flow.method)
                                   : std::string(Name(flow.integrator)));
  m.emplace_back("rtol", FormatNumber(flow.rtol));
  m.emplace_back("atol", FormatNumber(flow.atol));
  m.emplace_back("max_steps", std::to_string(flow.max_steps));
  return m;
}

}  // namespace stickslip::cli
