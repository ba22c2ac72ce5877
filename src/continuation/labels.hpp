// Point numbers and labels of a continuation result, as AUTO-07p's PT and LAB
// (Doedel et al., AUTO-07p manual, section 6.2): every branch point gets its
// 1-based row number in branch.tsv; every special point the number of the row
// where it sits and a label GR1, HB1, LP1, ... numbered per type in branch order.
#pragma once

#include <string>
#include <vector>

#include "stickslip/continuation/continuation.hpp"

namespace stickslip {

/// For each special point of r (in r.special's order), the 1-based number of
/// the branch row it sits on: the nearest row of its kind (HB: steady sliding;
/// GR, LP: a periodic orbit) in the parameter and x_max, each scaled by its
/// range over the rows. 0 if r has no row of that kind.
std::vector<int> SpecialPointRows(const ContinuationResult& r);

/// For each special point of r, its label: SpecialLabel and its number among
/// the points of its type, counted in the order of their rows (ties: r.special's
/// order). E.g. {"GR1", "HB1"}.
std::vector<std::string> SpecialPointLabels(const ContinuationResult& r);

}  // namespace stickslip
