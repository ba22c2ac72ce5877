#include "stickslip/io/branch_report.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>
#include <tuple>

#include "continuation/labels.hpp"
#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/figure_style.hpp"

namespace stickslip {

std::vector<std::pair<std::string, std::string>> SummaryFields(const ContinuationResult& r) {
  const ContinuationCounts& c = r.counts;
  const ContinuationTimes& t = r.seconds;
  auto sec = [](double x) { return Num(x, 3); };
  return {{"orbit_solves", std::to_string(c.orbit_solves)},
          {"return_maps", std::to_string(c.return_maps)},
          {"newton_iterations", std::to_string(c.newton_iterations)},
          {"rejected_steps", std::to_string(c.rejected_steps)},
          {"integrator_steps", std::to_string(c.integrator_steps)},
          {"seconds_equilibrium", sec(t.equilibrium)},
          {"seconds_stick_slip", sec(t.stick_slip)},
          {"seconds_pure_slip", sec(t.pure_slip)},
          {"seconds_switching", sec(t.switching)},
          {"seconds_discovery", sec(t.discovery)},
          {"seconds_total", sec(t.total)}};
}

namespace {
// The first field that must be a number but is not: {name, value}; name empty if none.
std::pair<std::string, double> FirstNonFinite(const BranchPoint& p) {
  const bool eq = p.kind == PointKind::kEquilibrium;
  const std::pair<const char*, double> fields[] = {{"parameter", p.p},
                                                   {"x_min", p.extrema.x_min},
                                                   {"x_max", p.extrema.x_max},
                                                   {"xdot_min", p.extrema.xdot_min},
                                                   {"xdot_max", p.extrema.xdot_max},
                                                   {"multiplier", p.multiplier},
                                                   {"amplitude", p.amplitude},
                                                   {"period", eq ? 0.0 : p.period},
                                                   {"t_stick", eq ? 0.0 : p.t_stick}};
  for (const auto& [name, x] : fields)
    if (!std::isfinite(x)) return {name, x};
  return {"", 0.0};
}
}  // namespace

void DropNonFinite(ContinuationResult* r) {
  const std::string param = r->param.name();
  std::string first;
  std::size_t dropped = 0;
  // The finite points are compacted in place: no copy of a long result.
  std::vector<BranchPoint>& points = r->points;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [name, x] = FirstNonFinite(points[i]);
    if (name.empty()) {
      if (kept != i) points[kept] = points[i];
      ++kept;
    } else if (dropped++ == 0) {
      first = name + " = " + FormatNumber(x) + " at " + param + " = " + FormatNumber(points[i].p) +
              " (" + Name(points[i].kind) + ")";
    }
  }
  points.resize(kept);
  std::vector<SpecialPoint> special;
  for (const SpecialPoint& s : r->special) {
    if (std::isfinite(s.p) && std::isfinite(s.period) && std::isfinite(s.extrema.x_min) &&
        std::isfinite(s.extrema.x_max) && std::isfinite(s.extrema.xdot_min)) {
      special.push_back(s);
    } else if (dropped++ == 0) {
      first = std::string("non-finite values at the special point ") + SpecialLabel(s.kind);
    }
  }
  if (dropped == 0) return;
  r->special = std::move(special);
  const std::string what = "numerical failure: " + first + "; " + std::to_string(dropped) +
                           " result(s) with non-finite numbers dropped";
  if (r->status == ContinuationStatus::kOk) r->status = ContinuationStatus::kFailed;
  r->message = r->message.empty() ? what : r->message + "; " + what;
}

TsvTable BranchTable(const ContinuationResult& r, const std::string& model_description,
                     const std::vector<ExtraColumn>& extra) {
  const std::string param = r.param.name();
  std::vector<std::string> cols = {param,     "kind",       "branch",   "period",
                                   "x_min",   "x_max",      "xdot_min", "xdot_max",
                                   "t_stick", "multiplier", "stable",   "amplitude"};
  for (const auto& c : extra) {
    if (c.values.size() != r.points.size())
      throw InvalidArgument("extra column '" + c.name + "' has " + std::to_string(c.values.size()) +
                            " values for " + std::to_string(r.points.size()) + " points");
    cols.push_back(c.name);
  }
  // Point numbers and restart states last (labels.hpp), after the extras.
  cols.insert(cols.end(), {"pt", "x_start", "xdot_start"});
  TsvTable t(cols);
  t.AddMeta("model", model_description);
  if (r.partial())
    t.AddMeta("status", std::string("partial (") + Name(r.status) + "): " + r.message);
  else
    t.AddMeta("status", "complete");
  for (const std::string& w : r.warnings) t.AddMeta("warning", w);
  for (const auto& kv : SummaryFields(r)) t.AddMeta(kv.first, kv.second);
  // One row vector for all rows, its cells built in place (no copies of
  // initializer lists): a dense branch has thousands of rows.
  std::vector<TsvTable::Cell> row;
  row.reserve(cols.size());
  t.Reserve(r.points.size(), 24 * cols.size());  // 17 digits, sign, exponent, tab
  for (size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.points[i];
    row.clear();
    row.emplace_back(p.p);
    row.emplace_back(Name(p.kind));
    row.emplace_back(p.branch);
    // Steady sliding has no period or t_stick: empty cells.
    const bool eq = p.kind == PointKind::kEquilibrium;
    row.push_back(eq ? TsvTable::Cell("") : TsvTable::Cell(p.period));
    for (double x : {p.extrema.x_min, p.extrema.x_max, p.extrema.xdot_min, p.extrema.xdot_max})
      row.emplace_back(x);
    row.push_back(eq ? TsvTable::Cell("") : TsvTable::Cell(p.t_stick));
    row.emplace_back(p.multiplier);
    row.emplace_back(p.stable ? 1 : 0);
    row.emplace_back(p.amplitude);
    for (const auto& c : extra) row.push_back(TsvTable::Cell::OrEmpty(c.values[i]));
    row.emplace_back(static_cast<int>(i) + 1);
    row.emplace_back(p.x_start);
    row.emplace_back(p.xdot_start);
    t.AddRow(row);
  }
  return t;
}

TsvTable SpecialPointTable(const ContinuationResult& r, const std::vector<ExtraColumn>& extra) {
  const std::string param = r.param.name();
  std::vector<std::string> cols = {"label", param,      "period",     "x_min",
                                   "x_max", "xdot_min", "description"};
  for (const auto& c : extra) {
    if (c.values.size() != r.special.size())
      throw InvalidArgument("extra column '" + c.name + "' has " + std::to_string(c.values.size()) +
                            " values for " + std::to_string(r.special.size()) + " special points");
    cols.push_back(c.name);
  }
  cols.insert(cols.end(), {"pt", "lab", "x_start", "xdot_start"});
  const std::vector<int> rows = SpecialPointRows(r);
  const std::vector<std::string> labels = SpecialPointLabels(r);
  TsvTable t(cols);
  if (r.partial())
    t.AddMeta("status", std::string("partial (") + Name(r.status) + "): " + r.message);
  else
    t.AddMeta("status", "complete");
  for (size_t i = 0; i < r.special.size(); ++i) {
    const SpecialPoint& s = r.special[i];
    std::vector<TsvTable::Cell> row = {
        SpecialLabel(s.kind), s.p,          s.period, s.extrema.x_min, s.extrema.x_max,
        s.extrema.xdot_min,   s.description};
    for (const auto& c : extra) row.push_back(TsvTable::Cell::OrEmpty(c.values[i]));
    row.insert(row.end(), {rows[i], labels[i], s.x_start, s.xdot_start});
    t.AddRow(row);
  }
  return t;
}

}  // namespace stickslip
