// The parameter plane of the belt's chart: two
// of its parameters (axes, the one lens) and a rectangle in them. Every point
// of the rectangle must be a valid model.
#pragma once

#include <string>

#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip {

// "<which> = '<name>' is no parameter (expected one of beta, v, ...)" if name
// is none (an option's value, read at the entry), else "".
std::string UnknownAxisError(const std::string& name, const char* which);

// The input a plane's validation error is about: ss_chart names that option.
enum class PlaneInput { kNone, kParam, kParam2, kFrom, kTo, kFrom2, kTo2, kRectangle };
// "param", "param2", "from", "to", "from2", "to2" (the option names); "" else.
const char* PlaneInputKey(PlaneInput input);

struct PlaneError {
  PlaneInput input = PlaneInput::kNone;  // kRectangle: its far corner (to, to2)
  std::string message;                   // empty if valid
};

// A range narrower than this, relative to max(|from|, |to|), is degenerate:
// the continuation's steps would be lost in rounding.
constexpr double kMinRelativeWidth = 1e-6;

struct Plane {
  ParameterAxis p1 = Parameter::kV, p2 = Parameter::kBeta;  // the axes (of the law's parameters)
  double from1 = 0.05, to1 = 0.6;                           // p1 range, from1 < to1
  double from2 = 0.0, to2 = 0.25;                           // p2 range, from2 < to2

  // Empty if valid for `base`, else one line naming the violated constraint:
  // inapplicable axis, equal axes, non-finite, empty or inverted
  // range, or a point of the rectangle (a 33 x 33 grid, edges included) that
  // is not a valid model (ValidationError of params.hpp, e.g. v <= 0).
  // A range narrower than kMinRelativeWidth is refused.
  std::string ValidationError(const Params& base) const { return Check(base).message; }
  // The same, with the input it is about. A point outside the model's domain
  // is blamed on the range end that reaches it (from the corner (from, from2)
  // along each edge), or on the rectangle.
  PlaneError Check(const Params& base) const;
  // base (Params or ForcedBeltParams) with the two axes set to (x1, x2).
  template <class P>
  P At(const P& base, double x1, double x2) const {
    P q = base;
    p1.Set(q, x1);
    p2.Set(q, x2);
    return q;
  }
  bool Contains(double x1, double x2) const {
    return x1 >= from1 && x1 <= to1 && x2 >= from2 && x2 <= to2;
  }
  double width1() const { return to1 - from1; }
  double width2() const { return to2 - from2; }
};

}  // namespace stickslip
