// ss_continue's text on stdout about the estimates: a few rows of the
// comparison and the largest errors.
#pragma once

#include <string>

#include "stickslip/estimates/comparison.hpp"

namespace stickslip {
namespace cli {

// x with `digits` digits after the point (%.*f).
std::string Fixed(double x, int digits);

// A few rows of the estimate comparison, spread over the periodic branch.
void PrintComparison(const EstimateComparison& c, const std::string& param);

}  // namespace cli
}  // namespace stickslip
