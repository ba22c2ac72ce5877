#include "chart/chart_starts.hpp"

#include <cmath>
#include <utility>

#include "numerics/roots.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

namespace {
// The start lines: the four edges and three interior lines per axis, as
// (fixed coordinate 0 or 1, its value).
std::vector<std::pair<int, double>> StartLines(const Plane& pl) {
  std::vector<std::pair<int, double>> lines = {
      {0, pl.from1}, {0, pl.to1}, {1, pl.from2}, {1, pl.to2}};
  for (int k = 1; k <= 3; ++k) {
    lines.push_back({0, pl.from1 + pl.width1() * k / 4});
    lines.push_back({1, pl.from2 + pl.width2() * k / 4});
  }
  return lines;
}

}  // namespace

std::vector<CurveStart> StartPoints(const Plane& pl, int samples,
                                    const std::function<double(double, double)>& f) {
  std::vector<CurveStart> out;
  for (const auto& [k, c] : StartLines(pl)) {
    const double lo = k == 0 ? pl.from2 : pl.from1, hi = k == 0 ? pl.to2 : pl.to1;
    auto at = [&, k = k, c = c](double t) {
      return k == 0 ? Eigen::Vector2d(c, t) : Eigen::Vector2d(t, c);
    };
    auto g = [&](double t) {
      const Eigen::Vector2d x = at(t);
      return f(x[0], x[1]);
    };
    double t0 = lo, g0 = g(t0);
    for (int i = 1; i < samples; ++i) {
      const double t1 = lo + (hi - lo) * i / (samples - 1), g1 = g(t1);
      if (std::isfinite(g0) && std::isfinite(g1) && g0 * g1 <= 0 && g0 != g1) {
        const RootResult r = FindRoot(g, t0, t1, g0, g1, Tolerances().chart_root * (hi - lo));
        if (r.ok) out.push_back({at(r.x), k});
      }
      t0 = t1;
      g0 = g1;
    }
  }
  return out;
}

std::vector<CurveStart> WithSeeds(const ChartOptions& o, CurveKind kind,
                                  std::vector<CurveStart> scan) {
  std::vector<CurveStart> out;
  for (const ChartOptions::Seed& s : o.seeds)
    if (s.kind == kind) out.push_back({Eigen::Vector2d(s.p1, s.p2), 1});
  out.insert(out.end(), scan.begin(), scan.end());
  return out;
}

}  // namespace stickslip
