// Small numeric helpers shared by the library: the NaN that marks a value
// that does not apply, and numbers as text in messages.
#pragma once

#include <limits>
#include <string>

namespace stickslip {

/// A quiet NaN, for "does not apply".
inline constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// x with `digits` significant digits (as printf's %.<digits>g).
std::string Num(double x, int digits = 10);
/// x in the fewest digits that read back as x (std::to_chars), "nan", "inf", "-inf".
std::string RoundTrip(double x);

/// "name = value must lie in [lo, hi]" if value lies outside, else "" (an
/// option's range check in a ValidationError).
std::string IntRangeError(const char* name, long value, long lo, long hi);

}  // namespace stickslip
