// The one branch driver's inputs (orbit_branch.hpp), checked once before a
// branch starts, for every system: a bad one is InvalidArgument naming its
// value, never a start that failed.
#include <cmath>
#include <memory>
#include <string>

#include "numerics/numbers.hpp"
#include "orbit_problem.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

std::string OrbitBranchOptions::ValidationError() const {
  std::string e = shooting.ValidationError();
  if (!e.empty()) return e;
  if (!(max_amplitude > 0) || !std::isfinite(max_amplitude))
    return "max_amplitude = " + Num(max_amplitude) + " must be a finite number > 0";
  if (!(locate_tol > 0 && locate_tol < 1))
    return "locate_tol = " + Num(locate_tol) + " must be in (0, 1)";
  if (max_jumps < 0) return "max_jumps = " + std::to_string(max_jumps) + " must be >= 0";
  return "";
}

namespace orbit_detail {

namespace {

// "(x, x', theta) = (1, nan, 0)".
std::string StateText(const System& s, const Eigen::VectorXd& z) {
  std::string names, values;
  for (int i = 0; i < z.size(); ++i) {
    names += (i ? ", " : "") + s.StateName(i);
    values += (i ? ", " : "") + Num(z[i]);
  }
  return "(" + names + ") = (" + values + ")";
}

// The guess, then the end `to` (finite, another value, a valid system there).
std::string RangeError(const System& system, int parameter, const FlowPoint& guess, double to) {
  if (guess.z.size() != system.dimension())
    return "the guess has " + std::to_string(guess.z.size()) + " components, the system " +
           std::to_string(system.dimension());
  if (!guess.z.allFinite()) return "the guess " + StateText(system, guess.z) + " is not finite";
  const std::string name = system.ParameterName(parameter);
  const double from = system.ParameterValue(parameter);
  if (!std::isfinite(to) || to == from)
    return "to = " + Num(to) + " must be finite and differ from " + name + " = " + Num(from);
  std::unique_ptr<System> end = system.Clone();
  end->SetParameterValue(parameter, to);
  const std::string e = end->ValidationError();
  return e.empty() ? "" : "at " + name + " = to: " + e;
}

// The section's turns (m, bounded as a restart file's), then PALC's options on
// its unknowns (the map's and p).
std::string SectionError(const System& system, const PoincareSection& section,
                         const OrbitBranchOptions& options) {
  const int lo = system.clocks() == 1 ? 1 : 0;  // an autonomous system's: 0
  if (section.turns < lo || section.turns > kMaxPeriodMultiple)
    return "the section's clock turns m = " + std::to_string(section.turns) + " must lie in [" +
           std::to_string(lo) + ", " + std::to_string(kMaxPeriodMultiple) + "]";
  const bool timed = section.kind == SectionKind::kTime;
  return options.palc.ValidationError((timed ? system.tangent_dimension() : system.dimension()) +
                                      1);
}

}  // namespace

void CheckParameter(const System& system, int parameter) {
  if (parameter < 0 || parameter >= system.parameters())
    throw InvalidArgument("parameter = " + std::to_string(parameter) +
                          " is not one of the system's " + std::to_string(system.parameters()));
  if (const std::string e = system.ParameterError(parameter); !e.empty()) throw InvalidArgument(e);
}

void CheckInputs(const System& system, int parameter, const FlowPoint& guess,
                 const PoincareSection& section, double to, const OrbitBranchOptions& options) {
  std::string e = system.ValidationError();
  if (e.empty()) e = options.ValidationError();
  if (e.empty()) CheckParameter(system, parameter);
  if (e.empty()) e = RangeError(system, parameter, guess, to);
  if (e.empty()) e = SectionError(system, section, options);
  if (!e.empty()) throw InvalidArgument(e);
}

}  // namespace orbit_detail

}  // namespace stickslip
