// How the analytic estimates compare with a continued branch (cubic law):
// the seed's Liapunov estimate r1 of the smallest slip velocity (3.17), its
// displacement bound (after 3.30) and velocity bound (3.28), and the averaging
// amplitude a_ps of Thomsen & Fidlin (2003), point by point; GR and HB against
// the averaging grazing estimate and the seed's v_max (3.16).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip {

/// One estimate at one point of the branch; `applies` false with a note says
/// why no number is given (past v_max, averaging on a stick-slip orbit, ...).
struct EstimateCell {
  bool applies = false;
  double estimate = 0;
  double computed = 0;
  double error = 0;  // estimate - computed
  std::string note;
};

/// One periodic point of the branch against the estimates of its x'_min and x range.
struct ComparisonRow {
  double p = 0;
  PointKind kind = PointKind::kStickSlip;
  double xdot_min = 0;       // computed
  EstimateCell r1;           // seed: x'_min ~ r1
  EstimateCell a_ps;         // averaging: x'_min ~ -a_ps
  EstimateCell x_max_bound;  // seed: x_max <= xbar + sqrt(y0^2 + (v - a1 y0)^2)
};

/// A computed special point (GR, HB) against its closed-form estimate.
struct SpecialComparison {
  std::string label;     // "GR", "HB"
  std::string estimate;  // what it is compared with
  double computed = 0, estimated = 0;
};

/// The whole comparison: per-point rows, largest errors and branch.tsv columns.
struct EstimateComparison {
  bool applies = false;    // cubic law without k5 (and k5 not the continued parameter)
  bool cancelled = false;  // cut short: the rows so far, nan in the columns after them
  std::string reason;
  std::vector<ExtraColumn> columns;  // for branch.tsv, one value per point
  std::vector<ComparisonRow> rows;   // every periodic point
  std::vector<SpecialComparison> special;
  /// Largest |error| over the branch where the estimate applies, and where.
  double max_err_r1 = 0, p_max_err_r1 = 0;
  double max_err_a_ps = 0, p_max_err_a_ps = 0;
  int r1_applies = 0, a_ps_applies = 0, bound_holds = 0, bound_fails = 0;
};

/// base: the model; r.param: the continued parameter. check_points: the grid on
/// which each NLopt fit is verified (coarser than the default keeps it cheap).
/// `cancelled` (if set) is polled before every row's fits.
EstimateComparison CompareEstimates(const Params& base, const ContinuationResult& r,
                                    int check_points = 2001,
                                    const std::function<bool()>& cancelled = {});

}  // namespace stickslip
