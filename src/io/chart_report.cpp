#include "stickslip/io/chart_report.hpp"

#include <sstream>

#include "stickslip/io/figure_style.hpp"

namespace stickslip {

namespace {
void Header(TsvTable& t, const ChartResult& r, const std::string& model) {
  t.AddComment("model: " + model);
  if (r.status == ChartStatus::kPartial)
    t.AddComment("status: partial: " + r.message);
  else if (r.status != ChartStatus::kOk)
    t.AddComment(std::string("status: partial (") + Name(r.status) + "): " + r.message);
  else
    t.AddComment("status: complete");
}
}  // namespace

TsvTable CurvesTable(const ChartResult& r, const Plane& plane, const std::string& model) {
  TsvTable t({plane.p1.name(), plane.p2.name(), "curve", "id", "period", "amplitude", "multiplier",
              "l1", "type", "unphysical"});
  Header(t, r, model);
  for (size_t i = 0; i < r.curves.size(); ++i)
    t.AddComment("curve " + std::to_string(i + 1) + " " + CurveLabel(r.curves[i].kind) + ": " +
                 std::to_string(r.curves[i].points.size()) + " points, ends " +
                 r.curves[i].ends.Text());
  if (r.unphysical_points > 0)
    t.AddComment("unphysical: " + std::to_string(r.unphysical_points) +
                 " points whose orbit visits slip speeds where mu <= 0");
  for (size_t i = 0; i < r.curves.size(); ++i) {
    const Curve& c = r.curves[i];
    for (const CurvePoint& p : c.points) {
      const bool hb = c.kind == CurveKind::kHopf;
      t.AddRow({p.p1, p.p2, CurveLabel(c.kind), static_cast<int>(i + 1), p.period, p.amplitude,
                p.multiplier, hb ? TsvTable::Cell(p.l1) : TsvTable::Cell(""), Name(p.type),
                p.unphysical ? 1 : 0});
    }
  }
  return t;
}

TsvTable Codim2Table(const ChartResult& r, const Plane& plane, const std::string& model) {
  TsvTable t({"label", plane.p1.name(), plane.p2.name(), "description"});
  Header(t, r, model);
  for (const Codim2Point& p : r.codim2) t.AddRow({Name(p.label), p.p1, p.p2, p.description});
  return t;
}

TsvTable RegionsTable(const ChartResult& r, const Plane& plane, const std::string& model) {
  TsvTable t({"face", "region", "name", "ring", plane.p1.name(), plane.p2.name()});
  Header(t, r, model);
  t.AddComment(
      "one row per polygon vertex, each ring closed (its first vertex repeated); ring 0 "
      "is the face's outline, 1, 2, ... its holes; faces largest first");
  for (size_t k = 0; k < r.faces.size(); ++k) {
    const Face& f = r.faces[k].face;
    std::ostringstream os;
    os << "face " << k + 1 << ": " << Name(r.faces[k].region) << ", area " << FormatNumber(f.area)
       << ", classified at " << plane.p1 << " = " << FormatNumber(f.inside[0]) << ", " << plane.p2
       << " = " << FormatNumber(f.inside[1]);
    t.AddComment(os.str());
  }
  for (size_t k = 0; k < r.faces.size(); ++k) {
    const RegionFace& rf = r.faces[k];
    std::vector<const std::vector<Point2>*> rings{&rf.face.outer};
    for (const auto& h : rf.face.holes) rings.push_back(&h);
    for (size_t ring = 0; ring < rings.size(); ++ring)
      for (size_t i = 0; i <= rings[ring]->size(); ++i) {
        const Point2& p = (*rings[ring])[i % rings[ring]->size()];
        t.AddRow({static_cast<int>(k + 1), static_cast<int>(rf.region), Name(rf.region),
                  static_cast<int>(ring), p[0], p[1]});
      }
  }
  return t;
}

}  // namespace stickslip
