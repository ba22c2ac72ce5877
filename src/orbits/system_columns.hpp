// The column checks and result set-up shared by the batched orbits of a
// System (system_batch.cpp, settled_batch.cpp).
#pragma once

#include <cstddef>
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

}  // namespace stickslip::batch_detail
