// The special points of a branch, one enum for every system (docs/theory.md,
// "Special points"):
//   GR  grazing-sliding: a stick phase shrinks to zero (the belt's exit point
//       reaches x' = v);
//   HB  Hopf point of steady sliding;
//   LP  fold: a Floquet multiplier at +1 (the branch turns back);
//   PD  period doubling: a multiplier at -1;
//   NS  Neimark-Sacker: a complex pair on the unit circle;
//   SL  the orbit's switching sequence changes (its stick phases or crossings
//       of a contact's surface; di Bernardo, Kowalczyk & Nordmark 2002).
#pragma once

#include "stickslip/names.hpp"

namespace stickslip {

enum class SpecialKind { kGrazing, kHopf, kFold, kPeriodDoubling, kTorus, kSliding, kNone };
template <>
struct EnumNames<SpecialKind> {
  static constexpr NamedValue<SpecialKind> kTable[] = {
      {SpecialKind::kGrazing, "GR"}, {SpecialKind::kHopf, "HB"},
      {SpecialKind::kFold, "LP"},    {SpecialKind::kPeriodDoubling, "PD"},
      {SpecialKind::kTorus, "NS"},   {SpecialKind::kSliding, "SL"},
      {SpecialKind::kNone, ""},
  };
};
const char* SpecialLabel(SpecialKind k);  // "GR", "HB", "LP", "PD", "NS", "SL", ""

}  // namespace stickslip
