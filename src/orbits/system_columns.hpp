// The column checks and result set-up shared by the batched orbits of a
// System (system_batch.cpp, settled_batch.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/orbits/system_batch.hpp"

namespace stickslip::batch_detail {

/// Empty if the columns are usable, else one line naming the column.
std::string ColumnError(const System& base, const std::vector<SystemColumn>& columns);
/// The first row whose system is invalid, as one line; empty if none.
std::string RowError(const System& base, const std::vector<SystemColumn>& columns,
                     std::size_t rows);
/// Row i's values into s.
void SetRow(const std::vector<SystemColumn>& columns, std::size_t i, System& s);
/// rows kCancelled rows of zeros (contact -1) with `tangent` components each.
SystemBatch Sized(std::size_t rows, int tangent);
/// A start of base's size or the origin; the error line if its size differs.
std::string StartError(const System& base, Eigen::VectorXd* start);
/// Row i's orbit (ok): its sticks, start, extremes, largest |multiplier| and
/// stability; the caller sets status, m, contact and period.
void StoreOrbit(const PeriodicOrbit& o, std::size_t i, SystemBatch& out);

class RowQueue;
/// After the caller's own checks (err: empty if they passed), the column and
/// row checks (InvalidArgument on any), then `work` on every row in blocks
/// of `block` (one worker per `thread_rows` rows at most): the batch's common
/// run of StroboscopicOrbits and SettledOrbits.
SystemBatch RunColumns(const System& base, const std::vector<SystemColumn>& columns,
                       std::string err, std::size_t block, std::size_t thread_rows, int threads,
                       const std::function<bool()>& cancelled,
                       const std::function<void(std::size_t)>& progress,
                       const std::function<void(RowQueue&, SystemBatch&)>& work);

}  // namespace stickslip::batch_detail
