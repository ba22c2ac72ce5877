#include "stickslip/orbits/orbit_batch.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

#include "batch_rows.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip {

namespace {

// Rows a worker takes at a time: enough to keep the shared counter off the
// profile (a row costs microseconds), few enough to balance two threads.
constexpr std::size_t kBlockRows = 64;
// Rows per worker thread at least: a new thread's start (its allocator arena,
// its finder's first steps) costs about 0.5 ms, some 100 rows.
constexpr std::size_t kThreadRows = 256;

// The column checks of StickSlipOrbits; empty if the columns are usable.
std::string ColumnError(const Params& base, const std::vector<ParameterColumn>& columns) {
  if (columns.empty()) return "no parameter column: give at least one";
  const std::vector<ParameterAxis> law_axes = ParameterAxes(base.law);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const ParameterAxis& a = columns[c].parameter;
    if (std::find(law_axes.begin(), law_axes.end(), a) == law_axes.end())
      return "column '" + a.name() + "': not a parameter of the " + Name(base.law) + " law";
    for (std::size_t d = 0; d < c; ++d)
      if (columns[d].parameter == a) return "column '" + a.name() + "' is given twice";
    if (columns[c].values.size() != columns[0].values.size()) {
      std::ostringstream os;
      os << "columns differ in length: " << columns[0].parameter << " " << columns[0].values.size()
         << ", " << a << " " << columns[c].values.size();
      return os.str();
    }
  }
  return {};
}

// base with every column's value at row i.
Params RowParams(const Params& base, const std::vector<ParameterColumn>& columns, std::size_t i) {
  Params p = base;
  for (const ParameterColumn& c : columns) c.parameter.Set(p, c.values[i]);
  return p;
}

// The first row whose parameter set is invalid, as one line; empty if none.
std::string RowError(const Params& base, const std::vector<ParameterColumn>& columns,
                     std::size_t rows) {
  for (std::size_t i = 0; i < rows; ++i) {
    const std::string err = ValidationError(RowParams(base, columns, i));
    if (!err.empty()) return "row " + std::to_string(i) + ": " + err;
  }
  return {};
}

OrbitBatch Sized(std::size_t rows) {
  OrbitBatch b;
  b.status.assign(rows, OrbitStatus::kCancelled);
  for (auto* col :
       {&b.period, &b.t_stick, &b.x_min, &b.x_max, &b.xdot_min, &b.xdot_max, &b.multiplier})
    col->assign(rows, 0.0);
  b.stable.assign(rows, 0);
  return b;
}

// Row i of the result; a failed row keeps its zeros.
void Store(const OrbitResult& r, std::size_t i, OrbitBatch& out) {
  out.status[i] = r.status;
  if (!r.ok()) return;
  const Orbit& o = r.orbit;
  out.period[i] = o.period;
  out.t_stick[i] = o.t_stick;
  out.x_min[i] = o.extrema.x_min;
  out.x_max[i] = o.extrema.x_max;
  out.xdot_min[i] = o.extrema.xdot_min;
  out.xdot_max[i] = o.extrema.xdot_max;
  out.multiplier[i] = o.multiplier;
  out.stable[i] = o.stable ? 1 : 0;
}

// One worker: one finder, prepared at its first row, then blocks of rows
// until none is left or the run stops (on the calling thread it polls the
// cancel hook before every row and at every step).
void Work(const Params& base, const std::vector<ParameterColumn>& columns,
          const OrbitOptions& options, batch_detail::RowQueue& queue, OrbitBatch& out) {
  auto cancelled = [&] { return queue.Cancelled(); };
  std::optional<OrbitFinder> finder;
  for (std::size_t begin, end; queue.Take(&begin, &end);) {
    for (std::size_t i = begin; i < end && !cancelled(); ++i) {
      const Model model(RowParams(base, columns, i));
      if (finder) {
        finder->set_model(model);
      } else {
        finder.emplace(model, options);
        finder->flow().set_cancel(cancelled);
      }
      Store(finder->StickSlip(true), i, out);
    }
    queue.Done(end - begin);
  }
}

}  // namespace

std::string OrbitBatchOptions::ValidationError() const {
  std::string err = orbit.ValidationError();
  if (err.empty() && threads < 0) err = "threads = " + std::to_string(threads) + " must be >= 0";
  return err;
}

std::size_t OrbitBatch::found() const {
  return static_cast<std::size_t>(std::count(status.begin(), status.end(), OrbitStatus::kOk));
}

OrbitBatch StickSlipOrbits(const Params& base, const std::vector<ParameterColumn>& columns,
                           const OrbitBatchOptions& options) {
  std::string err = options.ValidationError();
  if (err.empty()) err = ColumnError(base, columns);
  const std::size_t rows = columns.empty() ? 0 : columns[0].values.size();
  if (err.empty()) err = RowError(base, columns, rows);
  if (!err.empty()) throw InvalidArgument(err);
  OrbitBatch out = Sized(rows);
  if (rows == 0) return out;
  if (options.cancelled && options.cancelled()) {
    out.cancelled = true;
    return out;
  }
  batch_detail::RowQueue queue(rows, kBlockRows);
  const batch_detail::RowsRun run = batch_detail::RunRows(
      queue, options.threads, kThreadRows, options.cancelled, {},
      [&](batch_detail::RowQueue& q) { Work(base, columns, options.orbit, q, out); });
  out.threads = run.threads;
  out.error = run.error;
  out.cancelled = run.cancelled;
  return out;
}

}  // namespace stickslip
