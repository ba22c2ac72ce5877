// Private to src/: the Taylor recurrences of one slip mode, as the model seam
// (stickslip/model/system.hpp) hands them to the Taylor stepper. The stepper
// calls Coefficients once per step; the recurrences inline inside it.
#pragma once

#include "integrate/series.hpp"
#include "stickslip/model/system.hpp"

namespace stickslip {

constexpr int kTaylorMaxOrder = 36;
// A row of Taylor coefficients: kPad finite entries past the highest order
// (Cauchy() runs in blocks of four).
constexpr int kTaylorRowSize = kTaylorMaxOrder + 1 + kPad;
using TaylorRow = double[kTaylorRowSize];
constexpr Reciprocals<kTaylorMaxOrder> kTaylorInverse;
constexpr Ordinals<kTaylorRowSize + 1> kOrdinals;

class TaylorField {
 public:
  virtual ~TaylorField() = default;
  // At the start of a segment: the slip mode m of system s. False if s is not
  // of the type that made this field (the stepper then asks s for a new one).
  virtual bool Bind(const FrictionSystem& s, Mode m) = 0;
  // Coefficients 1..order of rows 0..n-1 of c from their coefficient 0: z =
  // (x, x') in rows 0, 1; Phi column-major in rows 2..5 when n >= 6; the
  // parameter column dz/dp in rows 6, 7 when n == 8.
  virtual void Coefficients(int order, int n, TaylorRow* c) = 0;
  // Orders above Jorba & Zou's p at which this mode's steps are cheaper per
  // unit time (the stepper keeps their error per step); 0: their rule.
  virtual int ExtraOrder() const { return 0; }
};

}  // namespace stickslip
