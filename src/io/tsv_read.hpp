// Private to src/io/: a TSV as TsvTable writes it ('# key: value' lines, a
// header, rows), read back for a restart (restart.cpp, system_restart.cpp).
// Every failure is a RestartError of Part::kRun naming the file.
#pragma once

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "stickslip/io/restart.hpp"

namespace stickslip::io_detail {

struct Table {
  std::string path;
  std::map<std::string, std::string> meta;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  /// The column's index; throws if there is none.
  int Column(const std::string& name) const;
  /// The value of a '# key:' line; throws if there is none.
  const std::string& Meta(const std::string& key) const;
  /// A cell or metadata value as a number; throws naming `what` if it is none.
  double Number(const std::string& text, const std::string& what) const;
  /// Number, or NaN for an empty cell (a value that does not apply; older
  /// files wrote `nan` there, which Number reads as NaN too).
  double Optional(const std::string& text, const std::string& what) const {
    return text.empty() ? std::numeric_limits<double>::quiet_NaN() : Number(text, what);
  }
  /// Number, refusing nan and inf ("'path' is corrupt: what = 'text' is not
  /// finite").
  double Finite(const std::string& text, const std::string& what) const;
  /// Number, refusing all but a whole number in [lo, hi] (checked before any
  /// cast: nan, inf and 1e300 are refused, naming `what` and `text`).
  long long Whole(const std::string& text, const std::string& what, long long lo,
                  long long hi) const;
  /// Finite or Whole of the '# key:' line's value, naming the key.
  double MetaFinite(const std::string& key) const { return Finite(Meta(key), key); }
  long long MetaWhole(const std::string& key, long long lo, long long hi) const {
    return Whole(Meta(key), key, lo, hi);
  }
};

/// The file at path, if it is a regular file of at most
/// LabelledPoint::kMaxFileBytes (a FIFO, a device or a socket is refused
/// without blocking).
Table ReadTable(const std::string& path);

/// The integrator, rtol, atol and max_steps of the metadata (cli/about.cpp's
/// RunMetadata); throws if one is missing or unknown.
FlowOptions ReadFlowOptions(const Table& t);

/// The row of a restart's point: row `point` of branch.tsv when `number`,
/// else the row of special_points.tsv whose label is `point` (a RestartError
/// of Part::kPoint listing the labels if none is). Sets *type (the row's kind
/// or label) and *pt.
const std::vector<std::string>& PointRow(const Table& t, const std::string& point, bool number,
                                         std::string* type, int* pt);

}  // namespace stickslip::io_detail
