#include "numerics/numbers.hpp"

#include <sstream>

namespace stickslip {

std::string Num(double x, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
}

std::string IntRangeError(const char* name, long value, long lo, long hi) {
  if (value >= lo && value <= hi) return "";
  return std::string(name) + " = " + std::to_string(value) + " must lie in [" + std::to_string(lo) +
         ", " + std::to_string(hi) + "]";
}

}  // namespace stickslip
