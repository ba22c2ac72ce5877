// Where a forced branch starts (ss_continue --force without --restart): the
// orbits at --from that a stroboscopic scan finds (FindOrbits, orbit_search.hpp, m <=
// kStartScanMaxM, or m = --m) together with the attractor the transient from
// rest settles on (any m <= kSettleMaxPeriod), numbered by m, then x_max.
// By default the branch starts on the attractor; --all starts one branch on
// each orbit, --m M on the period-M attractor (else the first period-M
// orbit), --point N on orbit N of the list.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/run_control.hpp"
#include "cli/study.hpp"
#include "stickslip/forced/branch.hpp"
#include "stickslip/model/forced.hpp"

namespace stickslip::cli {

constexpr int kTransientPeriods = 200;  // docs/library.md: start from a settled state
constexpr int kStartScanMaxM = 12;      // the scan's work grows like max_m^2
constexpr int kSettleMaxPeriod = 32;    // the settled attractor's period bound

// The options that choose the start, validated at entry (UsageError naming
// the option): --all, --m M in [1, OrbitSearchOptions::kMaxMultiple], --point N
// >= 1 (without --restart). Not with --restart or --switch.
struct StartChoice {
  bool all = false;
  int m = 0;      // 0: any period
  int point = 0;  // 0: none
  bool scan() const { return all || m > 0 || point > 0; }
};
StartChoice StartChoiceFromArguments(const Arguments& args, bool restart);
// The options of the choice, for the help text.
void AddStartOptions(po::options_description& d);

struct StartOrbit {
  int m = 1, sticks = 0;
  bool stable = false;
  bool settled = false;                             // the attractor the transient from rest reached
  double x = 0, xdot = 0, x_max = 0, mult_max = 0;  // its point at phase 0
};

// The state after kTransientPeriods forcing periods from rest, at t = N T
// (from rest itself if the transient fails or leaves max_amplitude).
Vec2 SettledState(const ForcedModel& model, const OrbitBranchOptions& o);

// ContinueForced from the orbit o (its m and point), cancelled by run.
OrbitBranch ContinueFrom(const ForcedParams& base, ParameterAxis axis, double from, double to,
                         const StartOrbit& o, const OrbitBranchOptions& opts, RunControl& run);

// The attractor the state (x, xdot) at phase 0 settles on, if periodic with
// m <= kSettleMaxPeriod: its m, sticks and section point.
std::optional<StartOrbit> SettledStart(const ForcedModel& model, double x, double xdot,
                                       const OrbitBranchOptions& o, RunControl& run);

// The start list: the scan's orbits (m = choice.m, else 1..kStartScanMaxM)
// and the settled orbit if the scan missed it; by m, then x_max.
std::vector<StartOrbit> StartOrbits(const ForcedModel& model,
                                    const std::optional<StartOrbit>& settled,
                                    const OrbitBranchOptions& o, int m, RunControl& run);

// The orbits the choice selects (throws UsageError naming --point or --m if
// it selects none); the default choice: the settled orbit, else the first
// stable one, else none.
std::vector<StartOrbit> ChooseStart(const std::vector<StartOrbit>& list, const StartChoice& c,
                                    const std::string& where);

// "start orbits at omega = 1.5 (--point N continues orbit N):" and a line each.
void PrintStartOrbits(std::ostream& os, const std::vector<StartOrbit>& list,
                      const std::string& where);

}  // namespace stickslip::cli
