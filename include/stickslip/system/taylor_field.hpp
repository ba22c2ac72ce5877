// A system's Taylor recurrences, as the Taylor stepper asks for them once per
// step (Jorba & Zou 2005, Exp. Math. 14, section 2): from coefficient 0 of
// each row, coefficients 1..order. The rows of a step (TaylorLayout): the
// state, then Phi = dz/dz0 on the tangent block (column-major), then the
// parameter column dz/dp (all n components: a clock's row is d theta / dp,
// of rate d omega / dp), then the auxiliary rows the events need: for each
// sticking contact in increasing order, lambda_i and StaticLimit_i
// (system.hpp), then any rows of the field's own that bound the step (a
// forcing's series).
#pragma once

#include "stickslip/system/system.hpp"

namespace stickslip {

constexpr int kTaylorMaxOrder = 36;
/// Entries past the highest order kept finite (sums run in blocks of four).
constexpr int kTaylorPad = 4;
constexpr int kTaylorRowSize = kTaylorMaxOrder + 1 + kTaylorPad;
using TaylorRow = double[kTaylorRowSize];

struct TaylorLayout {
  int n = 0;                 ///< state rows [0, n)
  int tangent = 0;           ///< the tangent block's size (n minus the clocks)
  bool variational = false;  ///< Phi rows [n, n + tangent^2), column-major
  bool column = false;       ///< dz/dp rows, n of them, after Phi
  int aux = 0;               ///< auxiliary rows after those
  int phi() const { return n; }
  int param() const { return n + (variational ? tangent * tangent : 0); }
  int aux_first() const { return param() + (column ? n : 0); }
  int rows() const { return aux_first() + aux; }
};

class TaylorField {
 public:
  virtual ~TaylorField() = default;
  /// At the start of a segment: mode m of system s. False if s is not of the
  /// type that made this field (the stepper then asks s for a new one).
  virtual bool Bind(const System& s, const ModeSet& m) = 0;
  /// After Bind, the same system with the same values in another mode m:
  /// true if the field switched to m without reading the system again
  /// (a mode change at every switch); false (the default): Bind is called.
  virtual bool BindMode(const ModeSet& /*m*/) { return false; }
  /// After Bind: the auxiliary rows this mode fills (at least two per
  /// sticking contact: lambda_i, then its static limit).
  virtual int AuxRows() const = 0;
  /// Coefficients 1..order of every row of `layout` from their coefficient 0
  /// (given for the state, Phi and column rows; the field sets the
  /// auxiliary rows' own coefficient 0). Entries past `order` may be read
  /// by the stepper's sums: keep them finite.
  virtual void Coefficients(int order, const TaylorLayout& layout, TaylorRow* c) = 0;
  /// Orders above Jorba & Zou's p(eps) at which this mode's steps are cheaper
  /// per unit time (the stepper keeps their error per step); 0: their rule.
  /// in_steps: the segment watches roots inside steps (extrema), whose
  /// isolation costs O(p^2) a step too.
  virtual int ExtraOrder(double /*eps*/, bool /*in_steps*/) const { return 0; }
  /// The step size measures component i of the state by min(|z_i|, |z_i -
  /// center_i|) (an orbit's error relative to its amplitude about an
  /// equilibrium, not to the equilibrium's offset). Default: 0.
  virtual double ScaleCenter(int /*i*/) const { return 0; }
};

}  // namespace stickslip
