#include "numerics/numbers.hpp"

#include <sstream>

namespace stickslip {

std::string Num(double x, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
}

}  // namespace stickslip
