// The flow's switching rules, one for every system (flow.hpp): Filippov's
// rule at an arrival on a contact's surface, and the one saltation formula
// (Leine & Nijmeijer 2004, section 7.3; di Bernardo et al. 2008, section 2.5).
#pragma once

#include "stickslip/system/system.hpp"

namespace stickslip {

/// The mode after contact c of mode `before` arrives on h_c = 0 at z: stick
/// while |lambda_c| <= StaticLimit_c (Filippov sliding), else slip the way
/// lambda_c points (a crossing, or a touch when that is the side it came from).
ModeSet ModeAfterArrival(const System& s, const ModeSet& before, int c, ConstState z);

/// grad h_c (n entries): the contact's relative velocity's gradient.
void ContactGradient(const System& s, int c, StateOut grad);

/// The saltation matrix of an event g = 0 (gradient grad, n entries) where
/// the field switches from mode `before` to `after` at z, on the tangent
/// block: S = I + (f+ - f-) grad^T / (grad . f-). False (S = I) where the
/// flow meets the surface tangentially (grad . f- = 0): no finite S.
bool Saltation(const System& s, const ModeSet& before, const ModeSet& after, ConstState z,
               ConstState grad, MatrixOut S);

}  // namespace stickslip
