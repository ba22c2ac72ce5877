// ForcedBranchOptions::ValidationError (stickslip/forced/branch.hpp): every
// option checked before a branch starts, so that a bad one is InvalidArgument
// naming it, never a start-failed status (issue 35).
#include <cmath>
#include <string>

#include "numerics/numbers.hpp"
#include "stickslip/forced/branch.hpp"

namespace stickslip {

std::string ForcedBranchOptions::ValidationError() const {
  if (m < 1 || m > kMaxM)
    return "m = " + std::to_string(m) + " must lie in [1, " + std::to_string(kMaxM) + "]";
  if (!(std::isfinite(max_amplitude) && max_amplitude > 0))
    return "max_amplitude = " + Num(max_amplitude) + " must be a finite number > 0";
  if (!(std::isfinite(locate_tol) && locate_tol > 0))
    return "locate_tol = " + Num(locate_tol) + " must be a finite number > 0";
  if (max_jumps < 0) return "max_jumps = " + std::to_string(max_jumps) + " must be >= 0";
  return flow.ValidationError();
}

std::string ForcedBranchOptions::ValidationError(const ForcedParams& base, ForcedAxis axis,
                                                 double from, double to, double x_guess,
                                                 double xdot_guess) const {
  ForcedParams at_from = base;
  SetAxis(at_from, axis, from);
  if (std::string e = stickslip::ValidationError(at_from); !e.empty()) return e;
  if (!(to != from) || !std::isfinite(to)) return "to must be finite and != from";
  if (std::string e = ValidationError(); !e.empty()) return e;
  if (std::isfinite(x_guess) && std::isfinite(xdot_guess)) return "";
  return "x_guess = " + Num(x_guess) + ", xdot_guess = " + Num(xdot_guess) +
         ": both must be finite";
}

}  // namespace stickslip
