// The shading of every chart study (studies/*_chart.ini) against an
// independent classification at each cell centre: every periodic orbit found
// by FindPeriodicOrbits (orbit_scan.hpp) and the equilibrium's stability.
// Cells that a curve crosses are excluded (there the region is a matter of
// which side of the curve the centre lies on, to the curve's accuracy).
#include "chart/chart_regions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "cli/study.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/orbits/orbit_scan.hpp"

namespace stickslip {
namespace {

namespace po = boost::program_options;

struct Study {
  Params base;
  ChartOptions options;
};

// The model, solver options and rectangle of a study file, read the way
// ss_chart reads them (cli/study.hpp), with ss_chart's max_steps.
Study ReadChartStudy(const std::string& name) {
  po::options_description app("Chart");
  for (const char* key : {"param", "from", "to", "param2", "from2", "to2", "out"})
    app.add_options()(key, cli::Value());
  const std::string path = std::string(STICKSLIP_SOURCE_DIR) + "/studies/" + name;
  const char* argv[] = {"test", "--study", path.c_str()};
  const cli::Arguments args = cli::ParseArguments(3, argv, cli::AppDescription(app), "chart");
  Study s;
  Plane& pl = s.options.plane;
  pl.p1 = ParameterAxis(args.Text("param", "v"));
  pl.p2 = ParameterAxis(args.Text("param2", "beta"));
  pl.from1 = args.Number("from", 0.05);
  pl.to1 = args.Number("to", 0.6);
  pl.from2 = args.Number("from2", 0.0);
  pl.to2 = args.Number("to2", 0.25);
  s.base = cli::ModelFromArguments(args);
  s.options.orbit.flow = cli::FlowOptionsFromArguments(args);
  s.options.orbit.flow.max_steps = 20000;
  return s;
}

// The cells (i * n2 + j) that a curve's polyline passes through.
std::set<int> CrossedCells(const ChartResult& r, const Plane& pl) {
  std::set<int> out;
  const RegionGrid& g = r.regions;
  auto mark = [&](double p1, double p2) {
    const int i = static_cast<int>(std::floor((p1 - pl.from1) / pl.width1() * g.n1));
    const int j = static_cast<int>(std::floor((p2 - pl.from2) / pl.width2() * g.n2));
    if (i >= 0 && i < g.n1 && j >= 0 && j < g.n2) out.insert(i * g.n2 + j);
  };
  for (const Curve& c : r.curves)
    for (size_t k = 0; k < c.points.size(); ++k) {
      const CurvePoint& b = c.points[k];
      const CurvePoint& a = c.points[k == 0 ? 0 : k - 1];
      for (int s = 0; s <= 64; ++s)  // 64 substeps: far finer than a cell
        mark(a.p1 + (b.p1 - a.p1) * s / 64, a.p2 + (b.p2 - a.p2) * s / 64);
    }
  return out;
}

// The region from every periodic orbit at p and steady sliding's stability;
// false if the orbits fit no region (no attractor at all).
bool ReferenceRegion(const Params& p, const OrbitOptions& orbit, Region* region, std::string* why) {
  OrbitScanOptions so;
  so.orbit = orbit;
  const PeriodicOrbits po = FindPeriodicOrbits(Model(p), so);
  if (!po.ok()) return *why = po.message, false;
  bool stable_pure_slip = false;
  for (const Orbit& o : po.pure_slip) stable_pure_slip = stable_pure_slip || o.stable;
  const bool stable = po.steady.stable();
  std::ostringstream os;
  os << "steady " << (stable ? "stable" : "unstable") << ", stick-slip " << po.has_stick_slip
     << ", " << po.pure_slip.size() << " pure-slip (stable among them: " << stable_pure_slip << ")";
  *why = os.str();
  if (stable)
    *region = po.has_stick_slip || stable_pure_slip ? Region::kBistable : Region::kSteadyOnly;
  else if (po.has_stick_slip)
    *region = Region::kStickSlip;
  else if (stable_pure_slip)
    *region = Region::kPureSlip;
  else
    return false;
  return true;
}

void ExpectShadingAgrees(const std::string& name) {
  Study s = ReadChartStudy(name);
  constexpr int kN = 16;  // 256 cells
  s.options.region_n1 = s.options.region_n2 = kN;
  const ChartResult r = Chart(s.base, s.options);
  ASSERT_EQ(r.status, ChartStatus::kOk) << r.message;
  const Plane& pl = s.options.plane;
  const std::set<int> crossed = CrossedCells(r, pl);
  int checked = 0, wrong = 0;
  std::set<Region> seen;
  s.options.orbit.floquet = true;  // the pure-slip orbits' stability
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      if (crossed.count(i * kN + j)) continue;
      const double x1 = r.regions.x1[i], x2 = r.regions.x2[j];
      Region want;
      std::string why;
      const bool fits = ReferenceRegion(pl.At(s.base, x1, x2), s.options.orbit, &want, &why);
      ++checked;
      const Region got = r.regions.at(i, j);
      seen.insert(got);
      if (fits && want == got) continue;
      if (++wrong <= 8)
        ADD_FAILURE() << name << ": " << pl.p1 << " = " << x1 << ", " << pl.p2 << " = " << x2
                      << " shaded " << Name(got) << ", reference " << (fits ? Name(want) : "none")
                      << " (" << why << ")";
    }
  EXPECT_GE(checked, 200) << name;
  EXPECT_EQ(wrong, 0) << name << ": " << wrong << " of " << checked << " cells disagree";
  EXPECT_GE(seen.size(), 2u) << name;
}

TEST(ChartRegions, SeedChart) { ExpectShadingAgrees("seed_chart.ini"); }
TEST(ChartRegions, StribeckChart) { ExpectShadingAgrees("stribeck_chart.ini"); }
TEST(ChartRegions, QuinticChart) { ExpectShadingAgrees("quintic_chart.ini"); }
TEST(ChartRegions, LeineChart) { ExpectShadingAgrees("leine_chart.ini"); }
TEST(ChartRegions, SeedMuChart) { ExpectShadingAgrees("seed_mu_chart.ini"); }

}  // namespace
}  // namespace stickslip
