#include "stickslip/plane.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace stickslip {

namespace {
std::string Num(double x) {
  std::ostringstream os;
  os.precision(12);
  os << x;
  return os.str();
}

std::string AxisError(const Params& base, const std::string& name, const char* which) {
  if (!IsParameterName(name)) {
    std::string all;
    for (const auto& n : AllParameterNames()) all += (all.empty() ? "" : ", ") + n;
    return std::string(which) + " = '" + name + "' is no parameter (expected one of " + all + ")";
  }
  const auto names = ParameterNames(base.law);
  if (std::find(names.begin(), names.end(), name) == names.end())
    return std::string(which) + " = '" + name + "' does not apply to the " + LawName(base.law) +
           " law";
  return "";
}

std::string RangeError(double from, double to, const char* from_name, const char* to_name) {
  if (!std::isfinite(from)) return std::string(from_name) + " = " + Num(from) + " is not finite";
  if (!std::isfinite(to)) return std::string(to_name) + " = " + Num(to) + " is not finite";
  if (!(from < to))
    return std::string(from_name) + " = " + Num(from) + " must be < " + to_name + " = " + Num(to) +
           (from == to ? " (the rectangle is empty)" : " (the rectangle is inverted)");
  return "";
}
}  // namespace

std::string Plane::ValidationError(const Params& base) const {
  for (const std::string& e :
       {AxisError(base, p1, "param"), AxisError(base, p2, "param2"),
        std::string(p1 == p2 ? "param = param2 = '" + p1 + "': the two axes must differ" : ""),
        RangeError(from1, to1, "from", "to"), RangeError(from2, to2, "from2", "to2")})
    if (!e.empty()) return e;
  constexpr int kN = 33;
  for (int i = 0; i < kN; ++i) {
    for (int j = 0; j < kN; ++j) {
      const double x1 = from1 + width1() * i / (kN - 1), x2 = from2 + width2() * j / (kN - 1);
      const std::string e = stickslip::ValidationError(At(base, x1, x2));
      if (!e.empty())
        return "the rectangle leaves the model's domain at " + p1 + " = " + Num(x1) + ", " + p2 +
               " = " + Num(x2) + ": " + e;
    }
  }
  return "";
}

Params Plane::At(const Params& base, double x1, double x2) const {
  Params p = base;
  SetParameter(p, p1, x1);
  SetParameter(p, p2, x2);
  return p;
}

}  // namespace stickslip
