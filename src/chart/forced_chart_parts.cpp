// The forced chart's plane, names, validation and codimension-two points
// (stickslip/chart/forced_chart.hpp).
#include <algorithm>
#include <cmath>

#include "numerics/numbers.hpp"
#include "stickslip/chart/forced_chart.hpp"

namespace stickslip {

ForcedParams ForcedPlane::At(const ForcedParams& base, double x1, double x2) const {
  ForcedParams q = base;
  p1.Set(q, x1);
  p2.Set(q, x2);
  return q;
}

Plane ForcedPlane::AsPlane() const {
  Plane pl;
  // The trace reads the rectangle only: the axes keep the belt defaults.
  pl.from1 = from1, pl.to1 = to1, pl.from2 = from2, pl.to2 = to2;
  return pl;
}

std::string ForcedPlane::ValidationError(const ForcedParams& base) const {
  if (p1 == p2) return "the two axes are both " + p1.name();
  for (const ParameterAxis& a : {p1, p2})
    if (std::string e = AxisError(a, base.base.law, true); !e.empty()) return e;
  for (double x : {from1, to1, from2, to2})
    if (!std::isfinite(x)) return "a range end is not finite";
  if (!(from1 < to1)) return "the first range is empty or inverted: from >= to";
  if (!(from2 < to2)) return "the second range is empty or inverted: from2 >= to2";
  // As the belt chart's (plane.hpp): a narrower range cannot hold a curve's steps.
  if (width1() < kMinRelativeWidth * std::max(std::abs(from1), std::abs(to1)) ||
      width2() < kMinRelativeWidth * std::max(std::abs(from2), std::abs(to2)))
    return "a range is narrower than " + Num(kMinRelativeWidth) + " max(|from|, |to|)";
  constexpr int kEdge = 17;
  for (int k = 0; k < kEdge; ++k) {
    const double f = static_cast<double>(k) / (kEdge - 1);
    const double pts[4][2] = {{from1 + f * width1(), from2},
                              {from1 + f * width1(), to2},
                              {from1, from2 + f * width2()},
                              {to1, from2 + f * width2()}};
    for (const auto& pt : pts) {
      const std::string e = stickslip::ValidationError(At(base, pt[0], pt[1]));
      if (!e.empty())
        return "at " + p1.name() + " = " + Num(pt[0], 6) + ", " + p2.name() + " = " +
               Num(pt[1], 6) + ": " + e;
    }
  }
  return {};
}

std::string ForcedChartOptions::ValidationError(const ForcedParams& base) const {
  std::string e = stickslip::ValidationError(base);
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
  return iterate.ValidationError();
}

}  // namespace stickslip
