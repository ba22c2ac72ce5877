// The stability chart of a rectangle in two parameters: HB, GR and LP curves
// followed by pseudo-arclength continuation (palc.hpp) of their defining
// equations (hopf_curve.hpp, grazing_curve.hpp, fold_curve.hpp), their
// codimension-two points (GH, GR-LP), and the regions between them.
//
// Start points: sign changes of the HB and GR test functions sampled along the
// rectangle's four edges and three interior lines per axis, refined by Brent's
// method. Each start point not already on a curve is followed both ways until
// the curve leaves the rectangle (its last point is then on the border), closes,
// or ends (the continuation fails: it says why). An LP curve starts at every GH
// point and runs until its orbit reaches the belt speed, at a GR-LP point.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/chart/chart_faces.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/chart/plane.hpp"

namespace stickslip {

enum class CurveKind { kHopf, kGrazing, kFold };
const char* CurveLabel(CurveKind k);  // "HB", "GR", "LP"

struct CurvePoint {
  double p1 = 0, p2 = 0;
  // HB: 2 pi, 0, 1 (eigenvalues +-i). GR: the grazing orbit's period, (x_max -
  // x_min) / 2 and pure-slip multiplier lambda. LP: the fold orbit's.
  double period = 0, amplitude = 0, multiplier = 0;
  double l1 = 0;  // HB only: first Lyapunov coefficient -mu'''(v) / 16
  // HB: supercritical / subcritical; GR: persistence / nonsmooth-fold; LP: fold.
  std::string type;
  // The orbit visits slip speeds where mu <= 0 (not physical there).
  bool unphysical = false;
};

struct Curve {
  CurveKind kind = CurveKind::kHopf;
  std::vector<CurvePoint> points;
  std::string ends;  // how each end ended, e.g. "border / border"
  double seconds = 0;
  int evaluations = 0;  // of its defining function
};

struct Codim2Point {
  std::string label;  // "GH", "GR-LP"
  double p1 = 0, p2 = 0;
  std::string description;
};

enum class Region {
  kSteadyOnly = 0,  // stable steady sliding, no oscillation
  kStickSlip = 1,   // stick-slip, steady sliding unstable
  kPureSlip = 2,    // pure-slip oscillation, steady sliding unstable
  kBistable = 3,    // an oscillation beside stable steady sliding
};
const char* RegionName(Region r);

// Classification of a grid of points: steady sliding stable where
// 2 beta + mu'(v) > 0; a stick-slip orbit where the slip phase from the exit
// point returns to the belt speed (chart_regions.hpp); with
// stable steady sliding and no stick-slip, the section map iterated from the
// exit point's first return tells a surviving (stable pure-slip) oscillation.
struct RegionGrid {
  int n1 = 0, n2 = 0;
  std::vector<double> x1, x2;  // n1, n2 cell centres
  std::vector<Region> cells;   // n1 * n2, index i * n2 + j
  int failed = 0;              // cells whose stick-slip test failed numerically
  std::string failure;         // the first such cell and why
  Region at(int i, int j) const { return cells[static_cast<size_t>(i) * n2 + j]; }
};

// A region as a polygon between the curves (chart_region_faces.hpp).
struct RegionFace {
  Face face;  // face.label is the region's number
  Region region = Region::kSteadyOnly;
};

// Points per way of a curve (PALC max_points): a way longer than this is cut
// short, so max_step must be >= 1 / kMaxCurvePoints.
constexpr int kMaxCurvePoints = 20000;

struct ChartOptions {
  ChartOptions() {
    orbit.max_return_time = kMaxReturnTime;
    orbit.flow.max_steps = kMaxSteps;
  }
  // The chart's own orbit defaults (ss_chart --help states them): a first
  // return takes about one revolution, 2 pi / sqrt(1 - beta^2), a few hundred
  // steps; a longer run is an orbit running away (where mu < 0 at large slip
  // speeds, k5 > 0), given up after this time or this many steps.
  static constexpr double kMaxReturnTime = 50;
  static constexpr long kMaxSteps = 20000;
  Plane plane;
  OrbitOptions orbit;
  double max_step =
      0.01;          // largest continuation step, fraction of the rectangle, >= 1/kMaxCurvePoints
  int samples = 16;  // test-function samples per start line
  bool hopf_curves = true;           // HB curves and GH points
  bool grazing_curves = true;        // GR curves and GR-LP points
  bool fold_curves = true;           // LP curves from GH points
  bool region_faces = false;         // the regions as polygons between the curves
  int region_n1 = 0, region_n2 = 0;  // region grid, a check of the polygons; 0: none
  // Points given by the caller (a restart's HB or GR point), on or near a
  // curve of their kind: each is followed (p2 held while it is corrected)
  // before the start points the scan finds. LP seeds are not supported.
  struct Seed {
    CurveKind kind = CurveKind::kHopf;
    double p1 = 0, p2 = 0;
  };
  std::vector<Seed> seeds;
  std::function<bool()> cancelled;  // polled between points and between region cells
  // Empty if valid for base, else one line naming the violated constraint.
  std::string ValidationError(const Params& base) const;
};

enum class ChartStatus {
  kOk,
  kFailed,     // a numerical failure: message says where; curves so far kept
  kPartial,    // done, but a curve was cut short inside the rectangle (max-points,
               // step-too-small, start-failed) or a region cell failed: message says which
  kCancelled,  // cancelled() returned true
};
const char* ChartStatusName(ChartStatus s);

struct ChartResult {
  ChartStatus status = ChartStatus::kOk;
  std::string message;
  std::vector<Curve> curves;
  std::vector<Codim2Point> codim2;
  std::vector<RegionFace> faces;  // region_faces: largest first (drawing order)
  RegionGrid regions;
  int unphysical_points = 0;  // curve points whose orbit visits mu <= 0
  double seconds = 0, region_seconds = 0;
  double face_seconds = 0;  // region_faces: their arrangement and classification
  int points() const;
};

// Throws InvalidArgument if the options or the model are invalid.
ChartResult Chart(const Params& base, const ChartOptions& options);

}  // namespace stickslip
