// The rows of a system's run in one form, steady sliding and orbits alike
// (system_branch_report.cpp writes them; system_branch_script.cpp draws them).
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "stickslip/io/system_branch_report.hpp"

namespace stickslip::io_detail {

struct SystemLine {
  int branch = 0;  ///< 0 steady sliding, 1, 2, ... the orbit pieces
  double p = 0;
  std::string kind;  ///< equilibrium, stick-slip, pure-slip
  int sticks = 0, exits = 0, crossings = 0;
  int turns = 0;  ///< a clock's turns per period (its piece's section), else 0
  double period = 0;
  Eigen::VectorXd lo, hi, z0;
  ModeSet mode;  ///< z0's mode (steady sliding: every contact slips below)
  std::vector<std::complex<double>> multipliers;
  double mult_max = 0, max_real = 0;
  bool stable = false;
  SpecialKind label = SpecialKind::kNone;
  std::string description;
};

/// Steady sliding's rows, then each piece's, in order (their pt is the index + 1).
std::vector<SystemLine> SystemLines(const System& s, const SystemRun& run);
/// The most multipliers of a row.
int Multipliers(const std::vector<SystemLine>& lines);

}  // namespace stickslip::io_detail
