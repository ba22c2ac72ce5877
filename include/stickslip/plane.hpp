// The parameter plane of a stability chart: two model parameters (axes) and a
// rectangle in them. Every point of the rectangle must be a valid model.
#pragma once

#include <string>

#include "stickslip/params.hpp"

namespace stickslip {

struct Plane {
  std::string p1 = "v", p2 = "beta";  // axis names (ParameterNames of the law)
  double from1 = 0.05, to1 = 0.6;     // p1 range, from1 < to1
  double from2 = 0.0, to2 = 0.25;     // p2 range, from2 < to2

  // Empty if valid for `base`, else one line naming the violated constraint:
  // unknown or inapplicable axis, equal axes, non-finite, empty or inverted
  // range, or a point of the rectangle (a 33 x 33 grid, edges included) that
  // is not a valid model (ValidationError of params.hpp, e.g. v <= 0).
  std::string ValidationError(const Params& base) const;
  // base with the two axes set to (x1, x2).
  Params At(const Params& base, double x1, double x2) const;
  bool Contains(double x1, double x2) const {
    return x1 >= from1 && x1 <= to1 && x2 >= from2 && x2 <= to2;
  }
  double width1() const { return to1 - from1; }
  double width2() const { return to2 - from2; }
};

}  // namespace stickslip
