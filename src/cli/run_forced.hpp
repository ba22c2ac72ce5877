// ss_continue for the harmonically forced oscillator:
// --force A --omega W, --param omega|force|v|beta. Validated once at entry,
// started from a transient, continued by ContinueForced (continuation/forced_branch.hpp),
// written as branch.tsv, special_points.tsv and the resonance figure.
#pragma once

#include <boost/program_options.hpp>
#include <optional>

#include "cli/study.hpp"
#include "stickslip/io/restart.hpp"

namespace stickslip::cli {

// The forcing options (--force, --omega), in the model group.
po::options_description ForcingOptions();
// True when the forced oscillator is asked for: --force A != 0, or --param
// omega|force. Throws UsageError for --omega without a forcing.
bool ForcedRequested(const Arguments& args);
// The whole forced run; returns the exit code. With a restart (a forced run's
// point, --restart DIR --point LAB) its parameters, solver options and axis
// are the defaults and the branch starts from its stroboscopic state.
int RunForced(const Arguments& args, const std::string& prog, const std::string& command,
              const std::optional<LabelledPoint>& restart = std::nullopt);

}  // namespace stickslip::cli
