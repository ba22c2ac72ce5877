#include "continuation/labels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace stickslip {

namespace {

bool SitsOn(SpecialKind s, PointKind k) {
  return s == SpecialKind::kHopf ? k == PointKind::kEquilibrium : k != PointKind::kEquilibrium;
}

template <class Field>
double Range(const std::vector<BranchPoint>& pts, Field field) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const BranchPoint& p : pts) {
    lo = std::min(lo, field(p));
    hi = std::max(hi, field(p));
  }
  return hi > lo ? hi - lo : 1.0;
}

}  // namespace

std::vector<int> SpecialPointRows(const ContinuationResult& r) {
  const double sp = Range(r.points, [](const BranchPoint& p) { return p.p; });
  const double sx = Range(r.points, [](const BranchPoint& p) { return p.extrema.x_max; });
  std::vector<int> rows;
  for (const SpecialPoint& s : r.special) {
    int best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const BranchPoint& p = r.points[i];
      if (!SitsOn(s.kind, p.kind)) continue;
      const double d = std::abs(p.p - s.p) / sp + std::abs(p.extrema.x_max - s.extrema.x_max) / sx;
      if (d < best_d) best_d = d, best = static_cast<int>(i) + 1;
    }
    rows.push_back(best);
  }
  return rows;
}

std::vector<std::string> SpecialPointLabels(const ContinuationResult& r) {
  const std::vector<int> rows = SpecialPointRows(r);
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return rows[a] < rows[b]; });
  std::map<SpecialKind, int> count;
  std::vector<std::string> labels(rows.size());
  for (std::size_t i : order) {
    const SpecialKind k = r.special[i].kind;
    labels[i] = SpecialLabel(k) + std::to_string(++count[k]);
  }
  return labels;
}

}  // namespace stickslip
