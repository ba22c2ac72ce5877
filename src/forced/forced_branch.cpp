// The forced oscillator's branches on the one branch driver (orbit_branch.hpp):
// ContinueForced and ContinueDoubled in the forced rows, on the stroboscopic
// section of m forcing periods of the forced model (a System with a clock).
#include <cmath>
#include <string>

#include "numerics/numbers.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/forced/branch.hpp"

namespace stickslip {

namespace {

OrbitBranchOptions CoreOptions(const ForcedBranchOptions& o) {
  OrbitBranchOptions c;
  c.shooting.flow = o.flow;
  c.shooting.max_steps = o.flow.max_steps;
  c.palc = o.palc;
  c.max_amplitude = o.max_amplitude;
  c.locate_tol = o.locate_tol;
  c.max_jumps = o.max_jumps;
  return c;
}

// The stroboscopic point (x, x') at theta = 0.
FlowPoint Strobe(double x, double xdot) {
  return {0, Eigen::Vector3d(x, xdot, 0), ModeSet(Mode::kSlipBelow)};
}

}  // namespace

OrbitBranch ContinueForced(const ForcedParams& base, ForcedAxis axis, double from, double to,
                           double x_guess, double xdot_guess, const ForcedBranchOptions& options) {
  const std::string e = options.ValidationError(base, axis, from, to, x_guess, xdot_guess);
  if (!e.empty()) throw InvalidArgument(e);
  ForcedParams at = base;
  SetAxis(at, axis, from);
  const ForcedModel model(at);
  const FlowPoint guess = Strobe(x_guess, xdot_guess);
  return ContinueOrbits(model, model.ParameterIndex(Name(axis)), guess,
                        PoincareSection::Stroboscopic(model, guess.z, options.m), to,
                        CoreOptions(options));
}

OrbitBranch ContinueDoubled(const ForcedParams& at_pd, ForcedAxis axis, double x0, double xdot0,
                            double lo, double hi, const ForcedBranchOptions& options) {
  if (const std::string e = ValidationError(at_pd); !e.empty()) throw InvalidArgument(e);
  const double p_pd = GetAxis(at_pd, axis);
  if (!(lo < p_pd && p_pd < hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw InvalidArgument("ContinueDoubled: the bounds must be finite with lo < " + Num(p_pd, 12) +
                          " < hi");
  if (const std::string e = options.palc.ValidationError(3); !e.empty()) throw InvalidArgument(e);
  if (const std::string e = options.ValidationError(); !e.empty()) throw InvalidArgument(e);
  if (!(std::isfinite(x0) && std::isfinite(xdot0)))
    throw InvalidArgument("x0 = " + Num(x0) + ", xdot0 = " + Num(xdot0) + ": both must be finite");
  const ForcedModel model(at_pd);
  const FlowPoint pd = Strobe(x0, xdot0);
  return ContinueDoubled(model, model.ParameterIndex(Name(axis)), pd,
                         PoincareSection::Stroboscopic(model, pd.z, options.m), lo, hi,
                         CoreOptions(options));
}

}  // namespace stickslip
