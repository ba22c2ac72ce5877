// The column checks shared by the batched orbits (system_columns.hpp).
#include "system_columns.hpp"

#include <cmath>
#include <memory>
#include <sstream>

#include "batch_rows.hpp"
#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::batch_detail {

std::string ColumnError(const System& base, const std::vector<SystemColumn>& columns) {
  if (columns.empty()) return "no parameter column: give at least one";
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const int j = columns[c].parameter;
    if (j < 0 || j >= base.parameters())
      return "column " + std::to_string(c) + ": parameter index " + std::to_string(j) +
             " is not one of the system's " + std::to_string(base.parameters());
    for (std::size_t d = 0; d < c; ++d)
      if (columns[d].parameter == j) return "column '" + base.ParameterName(j) + "' is given twice";
    if (columns[c].values.size() != columns[0].values.size()) {
      std::ostringstream os;
      os << "columns differ in length: " << base.ParameterName(columns[0].parameter) << " "
         << columns[0].values.size() << ", " << base.ParameterName(j) << " "
         << columns[c].values.size();
      return os.str();
    }
  }
  return {};
}

void SetRow(const std::vector<SystemColumn>& columns, std::size_t i, System& s) {
  for (const SystemColumn& c : columns) s.SetParameterValue(c.parameter, c.values[i]);
}

std::string RowError(const System& base, const std::vector<SystemColumn>& columns,
                     std::size_t rows) {
  const std::unique_ptr<System> s = base.Clone();
  for (std::size_t i = 0; i < rows; ++i) {
    SetRow(columns, i, *s);
    for (const SystemColumn& c : columns)
      if (!std::isfinite(c.values[i]))
        return "row " + std::to_string(i) + ": " + base.ParameterName(c.parameter) + " = " +
               Num(c.values[i]) + " is not finite";
    const std::string err = s->ValidationError();
    if (err.empty()) continue;
    std::string values;  // the row's values, as the columns name them
    for (const SystemColumn& c : columns)
      values +=
          (values.empty() ? "" : ", ") + base.ParameterName(c.parameter) + " = " + Num(c.values[i]);
    return "row " + std::to_string(i) + " (" + values + "): " + err;
  }
  return {};
}

SystemBatch Sized(std::size_t rows, int tangent) {
  SystemBatch b;
  b.tangent = tangent;
  b.status.assign(rows, OrbitStatus::kCancelled);
  b.m.assign(rows, 0);
  b.contact.assign(rows, -1);
  b.sticks.assign(rows, 0);
  b.period.assign(rows, 0.0);
  b.multiplier.assign(rows, 0.0);
  for (auto* col : {&b.start, &b.lo, &b.hi}) col->assign(rows * tangent, 0.0);
  b.stable.assign(rows, 0);
  return b;
}

std::string StartError(const System& base, Eigen::VectorXd* start) {
  if (start->size() == 0) *start = Eigen::VectorXd::Zero(base.dimension());
  if (start->size() == base.dimension()) return {};
  return "the start has " + std::to_string(start->size()) + " components, the system " +
         std::to_string(base.dimension());
}

void StoreOrbit(const PeriodicOrbit& o, std::size_t i, SystemBatch& out) {
  const int nt = out.tangent;
  out.sticks[i] = o.sticks;
  for (int c = 0; c < nt; ++c) {
    out.start[i * nt + c] = o.start.z[c];
    out.lo[i * nt + c] = o.lo.size() > c ? o.lo[c] : 0.0;
    out.hi[i * nt + c] = o.hi.size() > c ? o.hi[c] : 0.0;
  }
  out.multiplier[i] = o.multipliers.empty() ? 0.0 : std::abs(o.multipliers.front());
  out.stable[i] = o.stable ? 1 : 0;
}

SystemBatch RunColumns(const System& base, const std::vector<SystemColumn>& columns,
                       std::string err, std::size_t block, std::size_t thread_rows, int threads,
                       const std::function<bool()>& cancelled,
                       const std::function<void(std::size_t)>& progress,
                       const std::function<void(RowQueue&, SystemBatch&)>& work) {
  if (err.empty()) err = ColumnError(base, columns);
  const std::size_t rows = columns.empty() ? 0 : columns[0].values.size();
  if (err.empty()) err = RowError(base, columns, rows);
  if (!err.empty()) throw InvalidArgument(err);
  SystemBatch out = Sized(rows, base.tangent_dimension());
  if (rows == 0) return out;
  if (cancelled && cancelled()) {
    out.cancelled = true;
    return out;
  }
  RowQueue queue(rows, block);
  const RowsRun run =
      RunRows(queue, threads, thread_rows, cancelled, progress, [&](RowQueue& q) { work(q, out); });
  out.threads = run.threads;
  out.error = run.error;
  out.cancelled = run.cancelled;
  return out;
}

}  // namespace stickslip::batch_detail
