#include "stickslip/chart/plane.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "numerics/numbers.hpp"

namespace stickslip {

namespace {
std::string AxisError(const Params& base, const ParameterAxis& axis, const char* which) {
  const auto axes = ParameterAxes(base.law);
  if (std::find(axes.begin(), axes.end(), axis) == axes.end())
    return std::string(which) + " = '" + axis.name() + "' does not apply to the " + Name(base.law) +
           " law";
  return "";
}

std::string RangeError(double from, double to, const char* from_name, const char* to_name) {
  if (!std::isfinite(from))
    return std::string(from_name) + " = " + Num(from, 12) + " is not finite";
  if (!std::isfinite(to)) return std::string(to_name) + " = " + Num(to, 12) + " is not finite";
  if (!(from < to))
    return std::string(from_name) + " = " + Num(from, 12) + " must be < " + to_name + " = " +
           Num(to, 12) +
           (from == to ? " (the rectangle is empty)" : " (the rectangle is inverted)");
  const double scale = std::max(std::abs(from), std::abs(to));
  if (to - from < kMinRelativeWidth * scale) {
    std::ostringstream os;
    os << to_name << " = " << RoundTrip(to) << " is too close to " << from_name << " = "
       << RoundTrip(from) << ": the width " << Num(to - from, 12)
       << " must be >= " << Num(kMinRelativeWidth, 12) << " max(|" << from_name << "|, |" << to_name
       << "|)";
    return os.str();
  }
  return "";
}

// The model's error at (x1, x2), or "".
std::string PointError(const Plane& pl, const Params& base, double x1, double x2) {
  const std::string e = stickslip::ValidationError(pl.At(base, x1, x2));
  if (e.empty()) return e;
  return "the rectangle leaves the model's domain at " + pl.p1.name() + " = " + Num(x1, 12) + ", " +
         pl.p2.name() + " = " + Num(x2, 12) + ": " + e;
}
}  // namespace

std::string UnknownAxisError(const std::string& name, const char* which) {
  if (IsParameterName(name)) return "";
  std::string all;
  for (const auto& n : AllParameterNames()) all += (all.empty() ? "" : ", ") + n;
  return std::string(which) + " = '" + name + "' is no parameter (expected one of " + all + ")";
}

const char* PlaneInputKey(PlaneInput input) {
  switch (input) {
    case PlaneInput::kParam:
      return "param";
    case PlaneInput::kParam2:
      return "param2";
    case PlaneInput::kFrom:
      return "from";
    case PlaneInput::kTo:
      return "to";
    case PlaneInput::kFrom2:
      return "from2";
    case PlaneInput::kTo2:
      return "to2";
    case PlaneInput::kNone:
    case PlaneInput::kRectangle:
      break;
  }
  return "";
}

PlaneError Plane::Check(const Params& base) const {
  PlaneError out;
  auto fail = [&](PlaneInput input, const std::string& message) {
    out.input = input, out.message = message;
    return out;
  };
  if (auto e = AxisError(base, p1, "param"); !e.empty()) return fail(PlaneInput::kParam, e);
  if (auto e = AxisError(base, p2, "param2"); !e.empty()) return fail(PlaneInput::kParam2, e);
  if (p1 == p2)
    return fail(PlaneInput::kParam2,
                "param = param2 = '" + p1.name() + "': the two axes must differ");
  if (auto e = RangeError(from1, to1, "from", "to"); !e.empty())
    return fail(!std::isfinite(from1) ? PlaneInput::kFrom : PlaneInput::kTo, e);
  if (auto e = RangeError(from2, to2, "from2", "to2"); !e.empty())
    return fail(!std::isfinite(from2) ? PlaneInput::kFrom2 : PlaneInput::kTo2, e);
  // The near corner; each edge from it, its far end (the value given) first,
  // blamed on that end; then a 33 x 33 grid (edges included).
  const std::string near = stickslip::ValidationError(At(base, from1, from2));
  if (!near.empty()) {
    // The end whose move to the far end cures it; else the one the error names.
    const bool second = stickslip::ValidationError(At(base, from1, to2)).empty() ||
                        (!stickslip::ValidationError(At(base, to1, from2)).empty() &&
                         near.rfind(p2.name() + " ", 0) == 0);
    return fail(second ? PlaneInput::kFrom2 : PlaneInput::kFrom,
                PointError(*this, base, from1, from2));
  }
  constexpr int kN = 33;
  auto x1 = [&](int i) { return i == kN - 1 ? to1 : from1 + width1() * i / (kN - 1); };
  auto x2 = [&](int j) { return j == kN - 1 ? to2 : from2 + width2() * j / (kN - 1); };
  for (int i = kN - 1; i >= 1; --i)
    if (auto e = PointError(*this, base, x1(i), from2); !e.empty()) return fail(PlaneInput::kTo, e);
  for (int j = kN - 1; j >= 1; --j)
    if (auto e = PointError(*this, base, from1, x2(j)); !e.empty())
      return fail(PlaneInput::kTo2, e);
  for (int i = kN - 1; i >= 1; --i)
    for (int j = kN - 1; j >= 1; --j)
      if (auto e = PointError(*this, base, x1(i), x2(j)); !e.empty())
        return fail(PlaneInput::kRectangle, e);
  return out;
}

}  // namespace stickslip
