// Results of the Python module's computing functions: the library's results
// with their vectors as read-only NumPy arrays (one per column).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "py_common.hpp"
#include "stickslip/basin/basin.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/continuation/continuation.hpp"

namespace stickslip::python {

// A result class: read-only attributes and result["name"] for result.name.
template <typename T>
py::class_<T> Result(py::module_& m, const char* name, const char* doc) {
  py::class_<T> c(m, name, doc);
  c.def("__getitem__", &GetItem, py::arg("key"), "result['name'] is result.name");
  return c;
}

// simulate(): one row every dt and at every switch.
struct Trajectory {
  py::array t, x, xdot, mode;  // mode: 'slip-below', 'stick', 'slip-above'
  FlowStatus status = FlowStatus::kTimeLimit;
  double t_stick = 0;
  int switches = 0, crossings = 0;
  double x_min = 0, x_max = 0, xdot_min = 0, xdot_max = 0;
};

// The rows of continue_branch(), one array per branch.tsv column.
struct BranchPoints {
  py::array p, kind, branch, period, x_min, x_max, xdot_min, xdot_max, t_stick, multiplier, stable,
      amplitude, newton_stalled;
  py::array pt, x_start, xdot_start;  // pt: the 1-based row number (AUTO's PT)
  explicit BranchPoints(const std::vector<BranchPoint>& points);
  BranchPoints() = default;
};

// A special point with its row (pt) and label (lab: GR1, HB1), as special_points.tsv.
struct BranchSpecial : SpecialPoint {
  int pt = 0;
  std::string lab;
};

struct Branch {
  std::string param;
  ContinuationStatus status = ContinuationStatus::kOk;
  std::string message;
  std::vector<std::string> warnings;
  BranchPoints points;
  std::vector<BranchSpecial> special;
  ContinuationCounts counts;
  ContinuationTimes seconds;
  // What made it, for its tables and restarts (py_branch.cpp).
  std::shared_ptr<const ContinuationResult> result;
  Params base;
  ContinuationOptions options;  // without its callbacks
};
Branch MakeBranch(ContinuationResult r, const Params& base, ContinuationOptions options);
void BindBranch(py::module_& m);  // py_branch.cpp

// One curve of chart(): its points as arrays.
struct ChartCurve {
  CurveKind kind = CurveKind::kHopf;
  std::string param1, param2;  // the names of p1 and p2
  py::array p1, p2, period, amplitude, multiplier, l1, type, unphysical;
  std::string ends;
  double seconds = 0;
  int evaluations = 0;
};

struct ChartPoint {  // a codimension-two point
  std::string label, param1, param2, description;
  double p1 = 0, p2 = 0;
};

struct ChartOut {
  ChartStatus status = ChartStatus::kOk;
  std::string message, param1, param2;
  std::vector<ChartCurve> curves;
  std::vector<ChartPoint> codim2;
  py::array region_p1, region_p2, regions;  // regions: (n1, n2) Region codes; empty if none
  int unphysical_points = 0;
  double seconds = 0, region_seconds = 0;
};
ChartOut MakeChartOut(const ChartResult& r, const Plane& plane);

struct Basins {
  BasinStatus status = BasinStatus::kOk;
  std::string message;
  PeriodicOrbits orbits;
  double x_lo = 0, x_hi = 0, xdot_lo = 0, xdot_hi = 0;
  int nx = 0, ny = 0;
  py::array x, xdot, fate, orbit, t_settle;  // ny * nx starts, row by row (x' outer)
  py::dict counts;                           // Fate -> count
};
Basins MakeBasins(const BasinResult& r);

}  // namespace stickslip::python
