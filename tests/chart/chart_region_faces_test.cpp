// The chart's region polygons (chart_region_faces.hpp): each face's interior
// point classified against every periodic orbit found there by an independent
// scan of the return map (FindPeriodicOrbits of orbit_scan.hpp), for the
// shipped seed and quintic chart studies; the faces tile the rectangle.
#include "chart/chart_region_faces.hpp"

#include <gtest/gtest.h>

#include <set>

#include "stickslip/orbits/orbit_scan.hpp"

namespace stickslip {
namespace {

// The region from all the periodic orbits at p.
Region RegionFromOrbits(const Params& p) {
  OrbitScanOptions options;
  options.orbit.floquet = true;  // the pure-slip orbits' stability
  const PeriodicOrbits o = FindPeriodicOrbits(Model(p), options);
  EXPECT_TRUE(o.ok()) << o.message;
  bool stable_pure_slip = false;
  for (const Orbit& orbit : o.pure_slip) stable_pure_slip = stable_pure_slip || orbit.stable;
  if (!o.steady.stable()) return o.has_stick_slip ? Region::kStickSlip : Region::kPureSlip;
  return o.has_stick_slip || stable_pure_slip ? Region::kBistable : Region::kSteadyOnly;
}

void ExpectFacesAgreeWithOrbits(const Params& base, const Plane& plane, size_t regions) {
  ChartOptions o;
  o.plane = plane;
  o.region_faces = true;
  const ChartResult r = Chart(base, o);
  ASSERT_EQ(r.status, ChartStatus::kOk) << r.message;
  ASSERT_EQ(r.faces.size(), regions);  // adjacent faces of one region merged
  double area = 0;
  std::set<Region> seen;
  for (const RegionFace& f : r.faces) {
    area += f.face.area;
    seen.insert(f.region);
    EXPECT_EQ(RegionFromOrbits(plane.At(base, f.face.inside[0], f.face.inside[1])), f.region)
        << Name(f.region) << " at " << plane.p1 << " = " << f.face.inside[0] << ", " << plane.p2
        << " = " << f.face.inside[1];
  }
  EXPECT_EQ(seen.size(), regions);
  EXPECT_NEAR(area, plane.width1() * plane.width2(), 1e-12 * plane.width1() * plane.width2());
}

TEST(ChartRegionFaces, SeedChartFacesAgreeWithOrbitScan) {
  // studies/seed_chart.ini: stick-slip, pure slip between GR and HB, steady only.
  ExpectFacesAgreeWithOrbits(Params{}, Plane{Parameter::kV, Parameter::kBeta, 0.02, 0.6, 0.0, 0.25},
                             3);
}

TEST(ChartRegionFaces, QuinticChartFacesAgreeWithOrbitScan) {
  // studies/quintic_chart.ini: all four regions, bistable below GH.
  Params p;
  p.k5 = 0.24;
  ExpectFacesAgreeWithOrbits(p, Plane{Parameter::kV, Parameter::kBeta, 0.05, 0.58, 0.0, 0.12}, 4);
}

TEST(ChartRegionFaces, StribeckChartFacesAgreeWithOrbitScan) {
  // studies/stribeck_chart.ini: subcritical, bistable between HB and GR.
  Params p;
  p.law = LawKind::kStribeck;
  p.mu_s = 0.4, p.mu_k = 0.25, p.v_s = 0.5;
  ExpectFacesAgreeWithOrbits(p, Plane{Parameter::kV, Parameter::kBeta, 0.05, 1.2, 0.01, 0.14}, 3);
}

TEST(ChartRegionFaces, LeineChartFacesAgreeWithOrbitScan) {
  // studies/leine_chart.ini: stick-slip below HB, bistable up to GR.
  Params p;
  p.law = LawKind::kLeine;
  p.mu_s = 1, p.delta = 3;
  ExpectFacesAgreeWithOrbits(p, Plane{Parameter::kV, Parameter::kBeta, 0.05, 1.5, 0, 0.3}, 3);
}

}  // namespace
}  // namespace stickslip
