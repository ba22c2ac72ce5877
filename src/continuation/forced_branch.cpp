// The forced oscillator's branches on the one branch driver (orbit_branch.hpp):
// ContinueForced and ContinueDoubled in the forced rows, on the stroboscopic
// section of m forcing periods of the forced model (a System with a clock).
#include "stickslip/continuation/forced_branch.hpp"

#include <cmath>
#include <string>

#include "numerics/numbers.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

// m, then the options: every one checked before a branch starts, so that a
// bad one is InvalidArgument naming it, never a start-failed status.
std::string OptionsError(int m, const OrbitBranchOptions& o) {
  if (m < 1 || m > kMaxPeriodMultiple)
    return "m = " + std::to_string(m) + " must lie in [1, " + std::to_string(kMaxPeriodMultiple) +
           "]";
  return o.ValidationError();
}

// ContinueForced's checks: the model at from, the range (to finite and !=
// from), m and the options, then a start guess that is not finite.
std::string StartError(const ForcedBeltParams& base, ParameterAxis axis, double from, double to,
                       double x_guess, double xdot_guess, int m, const OrbitBranchOptions& o) {
  if (std::string e = AxisError(axis, base.base.law, true); !e.empty()) return e;
  ForcedBeltParams at_from = base;
  axis.Set(at_from, from);
  if (std::string e = ValidationError(at_from); !e.empty()) return e;
  if (!(to != from) || !std::isfinite(to)) return "to must be finite and != from";
  if (std::string e = OptionsError(m, o); !e.empty()) return e;
  if (std::isfinite(x_guess) && std::isfinite(xdot_guess)) return "";
  return "x_guess = " + Num(x_guess) + ", xdot_guess = " + Num(xdot_guess) +
         ": both must be finite";
}

// The stroboscopic point (x, x') at theta = 0.
FlowPoint Strobe(double x, double xdot) {
  return {0, Eigen::Vector3d(x, xdot, 0), ModeSet(Mode::kSlipBelow)};
}

}  // namespace

OrbitBranch ContinueForced(const ForcedBeltParams& base, ParameterAxis axis, double from, double to,
                           double x_guess, double xdot_guess, int m,
                           const OrbitBranchOptions& options) {
  const std::string e = StartError(base, axis, from, to, x_guess, xdot_guess, m, options);
  if (!e.empty()) throw InvalidArgument(e);
  ForcedBeltParams at = base;
  axis.Set(at, from);
  const ForcedBelt model(at);
  const FlowPoint guess = Strobe(x_guess, xdot_guess);
  return ContinueOrbits(model, axis.index(), guess,
                        PoincareSection::Stroboscopic(model, guess.z, m), to, options);
}

OrbitBranch ContinueDoubled(const ForcedBeltParams& at_pd, ParameterAxis axis, double x0,
                            double xdot0, double lo, double hi, int m,
                            const OrbitBranchOptions& options) {
  if (const std::string e = ValidationError(at_pd); !e.empty()) throw InvalidArgument(e);
  if (const std::string e = AxisError(axis, at_pd.base.law, true); !e.empty())
    throw InvalidArgument(e);
  const double p_pd = axis.Get(at_pd);
  if (!(lo < p_pd && p_pd < hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw InvalidArgument("ContinueDoubled: the bounds must be finite with lo < " + Num(p_pd, 12) +
                          " < hi");
  if (const std::string e = options.palc.ValidationError(3); !e.empty()) throw InvalidArgument(e);
  if (const std::string e = OptionsError(m, options); !e.empty()) throw InvalidArgument(e);
  if (!(std::isfinite(x0) && std::isfinite(xdot0)))
    throw InvalidArgument("x0 = " + Num(x0) + ", xdot0 = " + Num(xdot0) + ": both must be finite");
  const ForcedBelt model(at_pd);
  const FlowPoint pd = Strobe(x0, xdot0);
  return ContinueDoubled(model, axis.index(), pd, PoincareSection::Stroboscopic(model, pd.z, m), lo,
                         hi, options);
}

}  // namespace stickslip
