// Seeds of a system's chart (system_chart.hpp): the special points of
// one-parameter runs on lines across the rectangle. HB from steady sliding
// along the line (ContinueSteadySliding); LP, PD and NS from the branch of
// the stick-slip attractor settled on at each end of the line
// (SettleOnStickSlip, ContinueOrbits to the other end).
#pragma once

#include <string>
#include <vector>

#include "stickslip/chart/system_chart.hpp"

namespace stickslip {

struct SystemSeed {
  CurveKind kind = CurveKind::kHopf;
  FlowPoint start;  ///< LP, PD, NS: the orbit's section point
  PoincareSection section;
  double p1 = 0, p2 = 0;
  int fixed = 1;  ///< the plane coordinate held while it is corrected (the line's constant)
  std::string where;
};

/// The one-parameter runs made for seeds, and those that failed: a branch
/// from an attractor found that could not start, or a run that threw (the
/// first one's why kept).
struct SeedRuns {
  int runs = 0, failed = 0;
  std::string failure;
  void Fail(const std::string& why) {
    if (failed++ == 0) failure = why;
  }
};

/// The seeds of the line along p1 at p2 = c (along1) or along p2 at p1 = c.
std::vector<SystemSeed> SystemSeedsOnLine(const System& base, const SystemChartOptions& o,
                                          bool along1, double c, SeedRuns* runs);

/// The system with the plane's two parameters set to (x1, x2).
std::unique_ptr<System> SystemAt(const System& base, const SystemPlane& plane, double x1,
                                 double x2);

}  // namespace stickslip
