// Where a branch of a system with a clock starts (ss_continue; the forced
// oscillator, a model file's `clock theta = omega`): the orbits at the start
// that a stroboscopic scan finds (FindOrbits, orbit_search.hpp, m <=
// kStartScanMaxM, or m = --m) together with the attractor a transient from
// rest settles on (any m <= kSettleMaxPeriod), numbered by m, then x_max.
// By default the branch starts on the attractor; --all starts one branch on
// each orbit, --m M on the period-M attractor (else the first period-M
// orbit), --point N on orbit N of the list.
#pragma once

#include <array>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/run_control.hpp"
#include "cli/study.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/orbits/settle.hpp"

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

// What a start needs besides the system (one clock): the state at rest the
// transient starts from (clock 0; its mode Filippov's), the orbits' flow and
// shooting, the amplitude bound and the scan's box (0: FindOrbits' default).
struct ClockStart {
  Eigen::VectorXd rest;
  OrbitBranchOptions opts;
  std::array<double, 2> box{0, 0};
  int newton_m = 1;  // the period multiple Newton tries (a restart's m at its far end)
};

struct StartOrbit {
  int m = 1, sticks = 0;
  bool stable = false;
  bool settled = false;            // the attractor the transient from rest reached
  Eigen::VectorXd z;               // its point at phase 0
  double x_max = 0, mult_max = 0;  // of the first component; the largest |multiplier|
};

// The state at rest on the contacts: 0 but where a contact's relative
// velocity names a component, that component at the contact's speed (the
// forced belt's (x, x', theta) = (0, v, 0)).
Eigen::VectorXd RestOnContacts(const System& system);

// The state after kTransientPeriods clock turns from rest (the rest state
// itself if the transient fails or leaves max_amplitude).
Eigen::VectorXd SettledState(const System& system, const ClockStart& c);

// The attractor the state z at phase 0 settles on, if periodic with
// m <= kSettleMaxPeriod: its m, sticks and section point.
std::optional<StartOrbit> SettledStart(const System& system, const Eigen::VectorXd& z,
                                       const ClockStart& c, RunControl& run);

// The start list: the scan's orbits (m = choice.m, else 1..kStartScanMaxM)
// and the settled orbit if the scan missed it; by m, then x_max.
std::vector<StartOrbit> StartOrbits(const System& system, const std::optional<StartOrbit>& settled,
                                    const ClockStart& c, int m, RunControl& run);

// The orbits the choice selects (throws UsageError naming --point or --m if
// it selects none); the default choice: the settled orbit, else the first
// stable one, else none.
std::vector<StartOrbit> ChooseStart(const std::vector<StartOrbit>& list, const StartChoice& c,
                                    const std::string& where);

// An orbit of the list as one settled on: its point at phase 0 on the
// stroboscopic section of its m turns.
SettledOrbit AsSettled(const System& at, const StartOrbit& o);

// The default start at `at`'s parameters: the attractor the transient from
// rest settles on if its m > 1, else Newton at m = 1 from the transient's
// end, else the start list's default orbits. `trace` is called on each in
// turn until its branch starts (status other than kStartFailed) or the run
// is cancelled; returns that branch (else the Newton's) and sets *used to
// its start (found false where none started; found: its message says which
// start it was, for the files' metadata).
OrbitBranch TraceFromDefaultStart(const System& at, const ClockStart& c, RunControl& run,
                                  const std::function<OrbitBranch(const SettledOrbit&)>& trace,
                                  SettledOrbit* used);

// The start list of `at` (its parameters the start's), printed on os, and the
// orbits the choice selects, each as an orbit settled on: its point at phase 0
// on the stroboscopic section of its m turns (UsageError as ChooseStart).
std::vector<SettledOrbit> ChosenStarts(const System& at, const ClockStart& c,
                                       const StartChoice& choice, const std::string& where,
                                       std::ostream& os, RunControl& run);

// "start orbits at omega = 1.5 (--point N continues orbit N):" and a line each.
void PrintStartOrbits(std::ostream& os, const std::vector<StartOrbit>& list,
                      const std::string& where);

}  // namespace stickslip::cli
