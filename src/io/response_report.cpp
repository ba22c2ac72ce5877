// A response grid's table and figure parts (stickslip/io/response_report.hpp).
#include "stickslip/io/response_report.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stickslip/io/figure_style.hpp"

namespace stickslip {

namespace {

// Periodic responses of m >= kManyPeriods share one class (the grid's m and
// sticks columns keep them apart).
constexpr int kManyPeriods = 5;

std::string PeriodicName(int m, int sticks) {
  if (m >= kManyPeriods) return "m >= " + std::to_string(kManyPeriods);
  return "m = " + std::to_string(m) + ", " +
         (sticks == 0 ? std::string("no stick")
                      : std::to_string(sticks) + (sticks == 1 ? " stick" : " sticks"));
}

// An exponent that was not measured (a failed, unbounded or contact-lost
// cell) or is no number: an empty cell (not applicable).
TsvTable::Cell Number(double x, AttractorKind k) {
  return HasExponent(k) && std::isfinite(x) ? TsvTable::Cell(x) : TsvTable::Cell("");
}

std::string KindName(AttractorKind k) {
  return k == AttractorKind::kUndecided ? "quasi-periodic" : Name(k);
}

// Periodic fills: a hue per m (1 blue, 2 green, 3 orange, 4 purple, 5+
// ochre), darker for fewer sticks per period of the orbit (ColorBrewer).
const char* const kPeriodic[5][4] = {{"#08519c", "#3182bd", "#6baed6", "#bdd7e7"},
                                     {"#006d2c", "#31a354", "#74c476", "#bae4b3"},
                                     {"#a63603", "#e6550d", "#fd8d3c", "#fdbe85"},
                                     {"#54278f", "#756bb1", "#9e9ac8", "#cbc9e2"},
                                     {"#8c6d31", "#bd9e39", "#e7ba52", "#e7cb94"}};

}  // namespace

ResponseClasses ClassifyResponses(const ResponseGrid& g) {
  ResponseClasses c;
  std::vector<std::pair<int, int>> periodic;
  std::vector<AttractorKind> others;
  for (size_t k = 0; k < g.cells.size(); ++k) {
    if (!g.done[k]) continue;
    const Attractor& a = g.cells[k];
    if (a.kind == AttractorKind::kPeriodic)
      periodic.emplace_back(std::min(a.m, kManyPeriods), a.m >= kManyPeriods ? 0 : a.sticks);
    else
      others.push_back(a.kind);
  }
  std::sort(periodic.begin(), periodic.end());
  periodic.erase(std::unique(periodic.begin(), periodic.end()), periodic.end());
  for (const auto& [m, s] : periodic) {
    c.names.push_back(PeriodicName(m, s));
    c.kinds.push_back(AttractorKind::kPeriodic);
  }
  for (AttractorKind k : {AttractorKind::kRest, AttractorKind::kSettling, AttractorKind::kUndecided,
                          AttractorKind::kChaotic, AttractorKind::kUnbounded,
                          AttractorKind::kContactLost, AttractorKind::kFailed})
    if (std::find(others.begin(), others.end(), k) != others.end()) {
      c.names.push_back(KindName(k));
      c.kinds.push_back(k);
    }
  c.class_of.assign(g.cells.size(), -1);
  for (size_t k = 0; k < g.cells.size(); ++k) {
    if (!g.done[k]) continue;
    const Attractor& a = g.cells[k];
    const std::string name =
        a.kind == AttractorKind::kPeriodic ? PeriodicName(a.m, a.sticks) : KindName(a.kind);
    c.class_of[k] =
        static_cast<int>(std::find(c.names.begin(), c.names.end(), name) - c.names.begin());
  }
  return c;
}

TsvTable ResponseGridTable(const ResponseGrid& g, const std::string& p1, const std::string& p2) {
  const ResponseClasses c = ClassifyResponses(g);
  TsvTable t({p1, p2, "class", "response", "m", "sticks", "lyapunov", "lyapunov_err"});
  t.AddComment("grid " + std::to_string(g.n1) + " x " + std::to_string(g.n2) +
               " cell centres, each row swept along " + p1 +
               " from the previous cell's end state; " + std::to_string(g.failed) + " failed");
  for (size_t i = 0; i < c.names.size(); ++i)
    t.AddComment("class " + std::to_string(i) + ": " + c.names[i]);
  for (size_t k = 0; k < g.cells.size(); ++k) {
    if (!g.done[k]) continue;
    const Attractor& a = g.cells[k];
    const bool periodic = a.kind == AttractorKind::kPeriodic;
    t.AddRow({g.x1[k % g.n1], g.x2[k / g.n1], c.class_of[k], KindName(a.kind), periodic ? a.m : 0,
              a.sticks, Number(a.lyapunov, a.kind), Number(g.lyapunov_err[k], a.kind)});
  }
  return t;
}

std::string ResponseFill(const ResponseClasses& c, int cls) {
  switch (c.kinds[cls]) {
    case AttractorKind::kPeriodic: {
      // Shades of the m's hue in the classes' order (fewer sticks darker).
      const std::string m = c.names[cls].substr(0, c.names[cls].find(','));
      int m_index = 0, shade = 0;
      for (int k = 0; k < cls; ++k) shade += c.names[k].rfind(m, 0) == 0;
      for (int k = 1; k <= 5; ++k)
        if (m == "m = " + std::to_string(k) || (k == 5 && m.rfind("m >=", 0) == 0)) m_index = k - 1;
      return kPeriodic[m_index][std::min(shade, 3)];
    }
    case AttractorKind::kRest:
      return "#ffffff";
    case AttractorKind::kUndecided:
      return "#d9d9d9";
    case AttractorKind::kChaotic:
      return "#404040";
    case AttractorKind::kUnbounded:
      return "#fbb4ae";
    case AttractorKind::kContactLost:
      return kFillContactLost;
    case AttractorKind::kSettling:
      return kFillSettling;
    case AttractorKind::kFailed:
      return "#ff0000";
  }
  return "#ffffff";
}

void ResponsePalette(std::ostream& os, const ResponseClasses& c) {
  os << "array C[" << std::max<size_t>(1, c.names.size()) << "] = [";
  for (size_t i = 0; i < c.names.size(); ++i)
    os << (i ? ", " : "") << "0x" << ResponseFill(c, static_cast<int>(i)).substr(1);
  if (c.names.empty()) os << "0xffffff";
  os << "]\n";
}

void ResponseRaster(std::ostream& os, const ResponseGrid& g, const ResponseClasses& c,
                    double width1, double width2) {
  // Half a cell and 1 % more: neighbours overlap, so that no hairline of the
  // background shows between them (antialiased edges).
  if (g.n1 > 0)
    os << "'response.tsv' using 1:2:(" << width1 / g.n1 / 2 * 1.01 << "):("
       << width2 / g.n2 / 2 * 1.01
       << "):(C[int($3)+1]) with boxxyerror fs solid 1.0 noborder lc rgb variable notitle";
  else
    os << "NaN notitle";
  for (size_t i = 0; i < c.names.size(); ++i)
    os << ", \\\n     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '"
       << ResponseFill(c, static_cast<int>(i)) << "' title " << GnuplotQuoted(c.names[i]);
}

}  // namespace stickslip
