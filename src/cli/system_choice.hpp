// The system an app runs (issue 31 item 8; docs/systems.md): the belt (and
// the forced oscillator, with --force), or a built-in system with several
// masses or contacts: a chain of blocks (systems/chain) or the mode-coupling
// brake model (systems/mode_coupling).
//   --system NAME        belt (default), chain, mode_coupling
//   --blocks N           chain: the number of blocks (default 2)
//   --model FILE         a model file (docs/model_files.md): the system it writes
//   --set A=1,B=2        any of the system's parameters by its own name
// A study file's [system] section holds the same `name = value` lines; --set
// overrides them name by name. The law comes from --law and its coefficients
// (ModelOptions); --beta, --v, --mu_s and --mu_k, where given, also set the
// system's parameters of those names.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli/study.hpp"
#include "stickslip/io/system_restart.hpp"
#include "stickslip/names.hpp"
#include "stickslip/system/system.hpp"

namespace stickslip::cli {

// kForced: the forced oscillator (ForcedBelt), chosen by --force A != 0 or
// --param force, or by a forced run's restart; no --system name.
enum class SystemChoice { kBelt, kChain, kModeCoupling, kModel, kForced };

po::options_description SystemOptions();
// The forcing options (--force, --omega, --max_amplitude), in the model group.
po::options_description ForcingOptions();
// True when the forced oscillator is asked for: --force A != 0, or --param
// force. Throws UsageError for --omega or --param omega without a forcing
// (a restart's point may have one).
bool ForcedRequested(const Arguments& args);
// The --system given (kBelt by default; kModel with --model FILE; kForced
// with --force A != 0 or --param force, ForcedRequested); UsageError for an
// unknown name.
SystemChoice SystemChoiceOf(const Arguments& args);
// True for a system other than the belt and the forced oscillator.
inline bool SystemRequested(const Arguments& args) {
  const SystemChoice c = SystemChoiceOf(args);
  return c != SystemChoice::kBelt && c != SystemChoice::kForced;
}
// The app takes only the belt and the forced oscillator: UsageError naming
// --system where another is chosen (or --set, --blocks, `also`, [system] given).
void RefuseSystem(const Arguments& args, const std::string& prog,
                  const std::vector<std::string>& also = {});
// The chosen system with every setting applied and validated; UsageError
// naming the option or study line and the value otherwise. With a restart
// (system_restart.hpp), its system, blocks, law and parameters at the point
// are the defaults the options override.
std::unique_ptr<System> SystemFromArguments(const Arguments& args,
                                            const SystemPoint* restart = nullptr);
// "chain of 2 blocks: v = 0.25, kc = 1, ..." : the system and its parameters.
// Parameter `continued` (-1: none) reads "[continued]"; `other` (-1: none)
// reads `mark` (a chart's second axis: both then "[axis]").
std::string DescribeSystem(const System& s, SystemChoice choice, int continued, int other = -1,
                           const char* mark = "[continued]");
// "--model FILE" or "--system NAME": the system as the command line chose it.
std::string SystemLabel(const Arguments& args);
// The items of a comma-separated list, each trimmed of blanks; every item,
// an empty one (",," or a trailing ",") included.
std::vector<std::string> CommaItems(const std::string& text);
// The system's parameter names, ", "-separated.
std::string ParameterList(const System& s);
/// The words for an autonomous system's default section (MaximaSection):
/// "x1' = 0 falling (maxima of x1)", or for a first-order state first
/// "w_b = its value at steady sliding (0 where there is none), falling".
std::string DefaultSectionText(const System& s);

}  // namespace stickslip::cli

namespace stickslip {
template <>
struct EnumNames<cli::SystemChoice> {
  static constexpr NamedValue<cli::SystemChoice> kTable[] = {
      {cli::SystemChoice::kBelt, "belt"},
      {cli::SystemChoice::kChain, "chain"},
      {cli::SystemChoice::kModeCoupling, "mode_coupling"},
      {cli::SystemChoice::kModel, "model"},
      {cli::SystemChoice::kForced, "forced"},
  };
};
}  // namespace stickslip
