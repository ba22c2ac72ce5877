// What every app says about itself: --help and --version, and the metadata
// lines every output file starts with ("# key: value", report.hpp), so a file
// records the tool, the command and every setting that made it.
//
// In an app, right after parsing:
//   if (cli::HelpOrVersion(std::cout, args, kProg, "ss_x [options]", desc, kNotes)) return 0;
//   ...
//   table.PrependMeta(cli::RunMetadata(kProg, cli::CommandLine(argc, argv), params, flow));
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/study.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"
#include "stickslip/systems/belt/params.hpp"

namespace stickslip::cli {

using Metadata = std::vector<std::pair<std::string, std::string>>;

// "ss_continue 0.1.0 (git 0123456789ab)".
std::string VersionText(const std::string& prog);

// The command line as typed, each argument shell-quoted where it needs it.
std::string CommandLine(int argc, const char* const argv[]);

// With --help (-h) prints the help, with --version the version line, and
// returns true; otherwise false.
bool HelpOrVersion(std::ostream& os, const Arguments& args, const std::string& prog,
                   const std::string& usage, const po::options_description& desc,
                   const std::string& notes = "");

// tool ("ss_continue 0.1.0"), commit (if built from a checkout), command.
Metadata ToolMetadata(const std::string& prog, const std::string& command);
// ToolMetadata, then law, every parameter of the law (the continued one, if
// any, as "continued"), and the integrator: integrator, rtol, atol, max_steps.
Metadata RunMetadata(const std::string& prog, const std::string& command, const Params& p,
                     const FlowOptions& flow, const std::string& continued = "");

}  // namespace stickslip::cli
