#include "cli/estimates_text.hpp"

#include <cstdio>
#include <iostream>

#include "stickslip/continuation/continuation.hpp"

namespace stickslip {
namespace cli {

std::string Fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

void PrintComparison(const EstimateComparison& c, const std::string& param) {
  std::cout << "estimates against the branch (x'_min; error = estimate - computed):\n"
            << "  " << param << "        kind         computed   seed r1    error     "
            << "averaging -a_ps  error\n";
  const size_t n = c.rows.size();
  auto cell = [](const EstimateCell& e) {
    if (!e.applies) return std::string("      n/a             ");
    char buf[64];
    std::snprintf(buf, sizeof buf, "%9.5f  %+9.5f", e.estimate, e.error);
    return std::string(buf);
  };
  for (size_t k = 0; k < 7 && n > 0; ++k) {
    const ComparisonRow& row = c.rows[k * (n - 1) / 6];
    char head[96];
    std::snprintf(head, sizeof head, "  %-9.5f  %-11s  %9.5f  ", row.p, Name(row.kind),
                  row.xdot_min);
    std::cout << head << cell(row.r1) << "  " << cell(row.a_ps) << "\n";
  }
  auto largest = [&](double err, double p, int n, const char* what) {
    if (n == 0) return std::string("n/a (no ") + what + ")";
    return Fixed(err, 5) + " at " + param + " = " + Fixed(p, 5) + " (" + std::to_string(n) + " " +
           what + ")";
  };
  std::cout << "  largest |error|: seed r1 "
            << largest(c.max_err_r1, c.p_max_err_r1, c.r1_applies, "points") << "; averaging "
            << largest(c.max_err_a_ps, c.p_max_err_a_ps, c.a_ps_applies, "pure-slip points")
            << ", n/a on stick-slip orbits\n"
            << "  seed's displacement bound holds at " << c.bound_holds << " points, violated at "
            << c.bound_fails << "\n";
  for (const auto& s : c.special)
    std::cout << "  " << s.label << ": computed " << Fixed(s.computed, 6) << ", " << s.estimate
              << " = " << Fixed(s.estimated, 6) << " (error " << Fixed(s.estimated - s.computed, 6)
              << ")\n";
}

}  // namespace cli
}  // namespace stickslip
