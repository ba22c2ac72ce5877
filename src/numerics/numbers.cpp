#include "numerics/numbers.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

namespace stickslip {

std::string Num(double x, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
}

std::string RoundTrip(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);  // shortest round trip
  return std::string(buf, r.ptr);
}

std::string IntRangeError(const char* name, long value, long lo, long hi) {
  if (value >= lo && value <= hi) return "";
  return std::string(name) + " = " + std::to_string(value) + " must lie in [" + std::to_string(lo) +
         ", " + std::to_string(hi) + "]";
}

}  // namespace stickslip
