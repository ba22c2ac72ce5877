// A system's chart as files (stickslip/io/system_chart_report.hpp).
#include "stickslip/io/system_chart_report.hpp"

#include <algorithm>
#include <complex>
#include <sstream>

#include "stickslip/io/system_branch_report.hpp"

namespace stickslip {

TsvTable SystemCurvesTable(const System& s, const SystemChart& c) {
  const SystemPlane& pl = c.plane;
  const int nt = s.tangent_dimension();
  std::vector<std::string> cols = {s.ParameterName(pl.p1),
                                   s.ParameterName(pl.p2),
                                   "curve",
                                   "id",
                                   "m",
                                   "period",
                                   "sticks",
                                   "crossings"};
  for (int i = 0; i < s.dimension(); ++i) cols.push_back(StateColumn(s, i) + "_0");
  for (int i = 0; i < nt; ++i) cols.push_back(StateColumn(s, i) + "_min");
  for (int i = 0; i < nt; ++i) cols.push_back(StateColumn(s, i) + "_max");
  // With a clock DP^m on the tangent components, else DP on a surface: one fewer.
  const int nm = s.clocks() > 0 ? nt : nt - 1;
  for (int i = 1; i <= nm; ++i)
    for (const char* part : {"_re", "_im"}) cols.push_back("mult" + std::to_string(i) + part);
  cols.insert(cols.end(), {"mult_max", "test"});
  TsvTable t(cols);
  for (std::size_t k = 0; k < c.curves.size(); ++k) {
    const SystemCurve& cv = c.curves[k];
    const std::string margin = cv.kind != CurveKind::kGrazing ? ""
                               : cv.gap                       ? " (the gap to the surface)"
                                        : " (an arrival's margin to the static limit)";
    const int m = cv.kind == CurveKind::kHopf ? 0 : PeriodMultiple(cv.section);
    t.AddComment("curve " + std::to_string(k + 1) + " " + CurveLabel(cv.kind) + margin +
                 " m = " + std::to_string(m) + ": " + std::to_string(cv.points.size()) +
                 " points, from " + cv.seed + "; ends " + cv.ends.Text());
    for (const SystemCurvePoint& p : cv.points) {
      const OrbitRow& o = p.orbit;
      std::vector<TsvTable::Cell> row = {
          p.p1,     p.p2,     CurveLabel(cv.kind), static_cast<int>(k + 1), m,
          o.period, o.sticks, o.crossings};
      for (int i = 0; i < s.dimension(); ++i)
        row.emplace_back(i < o.start.z.size() ? o.start.z[i] : 0.0);
      const bool hb = cv.kind == CurveKind::kHopf;
      for (const Eigen::VectorXd* v : {&o.lo, &o.hi})
        for (int i = 0; i < nt; ++i) row.emplace_back(hb ? o.start.z[i] : (*v)[i]);
      double mult = 0;
      for (int i = 0; i < nm; ++i) {
        const std::complex<double> mu =
            i < static_cast<int>(o.multipliers.size()) ? o.multipliers[i] : 0.0;
        row.emplace_back(mu.real() + 0.0);  // + 0.0: no -0 written
        row.emplace_back(mu.imag() + 0.0);
        mult = std::max(mult, std::abs(mu));
      }
      row.emplace_back(mult);
      row.emplace_back(p.test);
      t.AddRow(row);
    }
  }
  return t;
}

TsvTable SystemCodim2Table(const System& s, const SystemChart& c) {
  TsvTable t({"label", s.ParameterName(c.plane.p1), s.ParameterName(c.plane.p2), "curve", "on",
              "description", "located"});
  for (const SystemCodim2& p : c.codim2)
    t.AddRow(
        {Name(p.label), p.p1, p.p2, p.curve + 1, CurveLabel(p.on), p.description, Name(p.method)});
  return t;
}

}  // namespace stickslip
