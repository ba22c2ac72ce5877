// The start list of a system with no clock (autonomous_start.hpp).
#include "cli/autonomous_start.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "cli/app.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/orbits/orbit_search.hpp"

namespace stickslip::cli {

std::vector<AutonomousStart> AutonomousStartOrbits(const System& at, const OrbitBranchOptions& opts,
                                                   RunControl& run) {
  AutonomousSearchOptions so;
  so.orbit = opts.shooting;
  so.cancelled = [&run] { return run.Cancelled(); };
  const AutonomousOrbits r = FindAutonomousOrbits(at, so);
  std::vector<AutonomousStart> list;
  for (const AutonomousOrbit& f : r.orbits) {
    if (f.orbit.hi.size() && std::abs(f.orbit.hi[0]) > opts.max_amplitude) continue;
    AutonomousStart s;
    s.orbit.found = true;
    s.orbit.section = f.section;
    s.orbit.orbit = f.orbit;
    s.orbit.recurred = true;
    s.sticks = f.sticks;
    s.stable = f.orbit.stable;
    for (const auto& mu : f.orbit.multipliers) s.mult_max = std::max(s.mult_max, std::abs(mu));
    list.push_back(std::move(s));
  }
  return list;  // FindAutonomousOrbits': by period
}

std::vector<SettledOrbit> ChosenAutonomousStarts(const System& at, const OrbitBranchOptions& opts,
                                                 const StartChoice& choice,
                                                 const std::string& where, std::ostream& os,
                                                 RunControl& run) {
  const std::vector<AutonomousStart> list = AutonomousStartOrbits(at, opts, run);
  PrintAutonomousStarts(os, list, where);
  if (run.Cancelled()) {  // a list cut short is no list to choose from: nothing continued
    os << "  (the scan was cut short: no orbit of it continued)\n";
    return {};
  }
  if (choice.point > static_cast<int>(list.size()))
    throw UsageError("invalid value '" + std::to_string(choice.point) +
                     "' for --point: the start list at " + where + " has " +
                     std::to_string(list.size()) + " orbit" + (list.size() == 1 ? "" : "s"));
  std::vector<SettledOrbit> out;
  for (std::size_t k = 0; k < list.size(); ++k)
    if (choice.all || static_cast<int>(k) + 1 == choice.point) out.push_back(list[k].orbit);
  return out;
}

void PrintAutonomousStarts(std::ostream& os, const std::vector<AutonomousStart>& list,
                           const std::string& where) {
  os << "start orbits at " << where << " (--point N continues orbit N):\n";
  for (std::size_t k = 0; k < list.size(); ++k) {
    const AutonomousStart& s = list[k];
    os << "  " << k + 1 << ": period " << FormatNumber(s.orbit.orbit.period) << ", sticks";
    for (std::size_t c = 0; c < s.sticks.size(); ++c) os << (c ? ", " : " ") << s.sticks[c];
    os << " (per contact), |multiplier| " << FormatNumber(s.mult_max) << ", "
       << (s.stable ? "stable" : "unstable") << "\n";
  }
}

}  // namespace stickslip::cli
