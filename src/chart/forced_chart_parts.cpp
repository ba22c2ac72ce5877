// The forced chart's validation (stickslip/chart/forced_chart.hpp).
#include <algorithm>
#include <cmath>

#include "numerics/numbers.hpp"
#include "stickslip/chart/forced_chart.hpp"

namespace stickslip {

std::string ForcedChartOptions::ValidationError(const ForcedParams& base) const {
  // base's values of the two axes are not used: it is checked at (from1, from2).
  std::string e = stickslip::ValidationError(plane.At(base, plane.from1, plane.from2));
  if (!e.empty()) return e;
  e = plane.ValidationError(base);
  if (!e.empty()) return e;
  e = flow.ValidationError();
  if (!e.empty()) return e;
  e = IntRangeError("max_m", max_m, 1, 8);
  if (e.empty()) e = IntRangeError("seed_lines", seed_lines, 0, kMaxSeedLines);
  if (!e.empty()) return e;
  if (!(max_step >= 1.0 / kMaxCurvePoints && max_step <= kMaxStepLimit))
    return "max_step = " + Num(max_step) + " must lie in [1/" + std::to_string(kMaxCurvePoints) +
           ", " + Num(kMaxStepLimit) + "]";
  if (!(max_amplitude > 0)) return "max_amplitude must be > 0";
  if ((n1 == 0) != (n2 == 0) || n1 < 0 || n2 < 0 || n1 > kMaxGridSide || n2 > kMaxGridSide)
    return "the response grid must be 0 x 0 (none) or within " + std::to_string(kMaxGridSide) +
           " x " + std::to_string(kMaxGridSide);
  if (max_period < 1 || max_period > iterate.keep / 2)
    return "max_period = " + std::to_string(max_period) + " must lie in [1, keep / 2]";
  if (threads < 1) return "threads must be >= 1";
  e = iterate.ValidationError();
  if (!e.empty()) return e;
  const ForcedModel model(plane.At(base, plane.from1, plane.from2));
  return SystemOptions(model, *this).ValidationError(model);
}

}  // namespace stickslip
