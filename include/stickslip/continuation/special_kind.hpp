// The special points of a branch, one enum for every system (docs/theory.md,
// "Special points"):
//   GR  grazing-sliding: a slip phase touches a contact's surface
//       tangentially within its static limit, a stick phase is born or
//       vanishes (the belt's exit point reaches x' = v);
//   HB  Hopf point of steady sliding;
//   LP  fold: a Floquet multiplier at +1 (the branch turns back);
//   PD  period doubling: a multiplier at -1;
//   NS  Neimark-Sacker: a complex pair on the unit circle;
//   AD  adding-sliding: a stick phase splits around a short slip, or two
//       merge as the slip between them vanishes;
//   CR  crossing-sliding: a crossing of a contact's surface reaches its
//       static limit and becomes a stick phase (or a crossing is born or lost
//       there);
//   CL  contact loss: a contact's normal force reaches 0 on the orbit; the
//       branch ends there (the system changes, no friction system beyond);
//   SL  any other change of the orbit's switching sequence (its stick phases
//       or crossings; di Bernardo, Kowalczyk & Nordmark, Physica D 170, 2002).
#pragma once

#include "stickslip/names.hpp"

namespace stickslip {

enum class SpecialKind {
  kGrazing,
  kHopf,
  kFold,
  kPeriodDoubling,
  kTorus,
  kSliding,
  kAdding,
  kCrossing,
  kContactLoss,
  kNone
};
template <>
struct EnumNames<SpecialKind> {
  static constexpr NamedValue<SpecialKind> kTable[] = {
      {SpecialKind::kGrazing, "GR"},     {SpecialKind::kHopf, "HB"},
      {SpecialKind::kFold, "LP"},        {SpecialKind::kPeriodDoubling, "PD"},
      {SpecialKind::kTorus, "NS"},       {SpecialKind::kSliding, "SL"},
      {SpecialKind::kAdding, "AD"},      {SpecialKind::kCrossing, "CR"},
      {SpecialKind::kContactLoss, "CL"}, {SpecialKind::kNone, ""},
  };
};
const char* SpecialLabel(
    SpecialKind k);  // "GR", "HB", "LP", "PD", "NS", "SL", "AD", "CR", "CL", ""

}  // namespace stickslip
