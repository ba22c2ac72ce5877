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
#include "stickslip/chart/plane.hpp"
#include "stickslip/names.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

/// A chart's curve, for every system: HB of steady sliding, GR grazing
/// (a stick phase born or lost), LP fold, PD period doubling and NS
/// Neimark-Sacker of periodic orbits (special_kind.hpp's points, followed).
enum class CurveKind { kHopf, kGrazing, kFold, kPeriodDoubling, kTorus };
template <>
struct EnumNames<CurveKind> {
  static constexpr NamedValue<CurveKind> kTable[] = {
      {CurveKind::kHopf, "HB"},           {CurveKind::kGrazing, "GR"}, {CurveKind::kFold, "LP"},
      {CurveKind::kPeriodDoubling, "PD"}, {CurveKind::kTorus, "NS"},
  };
};
const char* CurveLabel(CurveKind k);  // "HB", "GR", "LP", "PD", "NS"

/// The type of a curve point: HB supercritical / subcritical (degenerate
/// where l1 = 0); GR persistence / nonsmooth-fold; LP fold.
enum class CurvePointType {
  kSupercritical,
  kSubcritical,
  kDegenerate,
  kPersistence,
  kNonsmoothFold,
  kFold,
};
template <>
struct EnumNames<CurvePointType> {
  static constexpr NamedValue<CurvePointType> kTable[] = {
      {CurvePointType::kSupercritical, "supercritical"},
      {CurvePointType::kSubcritical, "subcritical"},
      {CurvePointType::kDegenerate, "degenerate"},
      {CurvePointType::kPersistence, "persistence"},
      {CurvePointType::kNonsmoothFold, "nonsmooth-fold"},
      {CurvePointType::kFold, "fold"},
  };
};

struct CurvePoint {
  double p1 = 0, p2 = 0;
  // HB: 2 pi, 0, 1 (eigenvalues +-i). GR: the grazing orbit's period, (x_max -
  // x_min) / 2 and pure-slip multiplier lambda. LP: the fold orbit's.
  double period = 0, amplitude = 0, multiplier = 0;
  double l1 = 0;  // HB only: first Lyapunov coefficient -mu'''(v) / 16
  CurvePointType type = CurvePointType::kSupercritical;
  // The orbit visits slip speeds where mu <= 0 (not physical there).
  bool unphysical = false;
};

/// How one end of a curve ended. kNone: not reached (cancelled).
enum class CurveEndKind {
  kNone,
  kStart,            // a way not taken: the curve starts here
  kBorder,           // left the rectangle, last point on its border
  kClosed,           // came back to its first point
  kStopped,          // stopped by the tracer's stop test
  kGeneralizedHopf,  // an LP curve's start, at its GH point
  kGrazingFold,      // an LP curve's end, at its GR-LP point
  kMaxPoints,        // cut short: PALC max_points (why: the message)
  kStepTooSmall,     // cut short: PALC step below ds_min (why says why)
  kStartFailed,      // cut short: a way's PALC start failed
  kBranchJump,       // the next point was no continuation of the last (why says how)
  kSliding,          // the orbit's stick structure changes here (a sliding point)
  kNoStart,          // the start point could not be corrected (why says why)
  kContactLost,      // a contact's normal force reaches 0 on the orbit (why says where)
  kCorner,           // GR: meets another GR curve at a corner (GG; why: the tracer's end)
  kCancelled,        // cut short by a signal or the time limit (the way not ended)
};
template <>
struct EnumNames<CurveEndKind> {
  static constexpr NamedValue<CurveEndKind> kTable[] = {
      {CurveEndKind::kNone, ""},
      {CurveEndKind::kStart, "start"},
      {CurveEndKind::kBorder, "border"},
      {CurveEndKind::kClosed, "closed"},
      {CurveEndKind::kStopped, "stopped"},
      {CurveEndKind::kGeneralizedHopf, "GH"},
      {CurveEndKind::kGrazingFold, "GR-LP"},
      {CurveEndKind::kMaxPoints, "max-points"},
      {CurveEndKind::kStepTooSmall, "step-too-small"},
      {CurveEndKind::kStartFailed, "start-failed"},
      {CurveEndKind::kBranchJump, "branch-jump"},
      {CurveEndKind::kSliding, "sliding"},
      {CurveEndKind::kNoStart, "start failed"},
      {CurveEndKind::kContactLost, "contact-lost"},
      {CurveEndKind::kCorner, "corner"},
      {CurveEndKind::kCancelled, "cancelled"},
  };
};

struct CurveEnd {
  CurveEndKind kind = CurveEndKind::kNone;
  std::string why;  // of a cut: the continuation's message
  /// "name" or "name: why".
  std::string Text() const;
};

/// Both ends of a curve: "first / last", "closed" (last.kind kClosed), or
/// "start failed: why" (first.kind kNoStart).
struct CurveEnds {
  CurveEnd first, last;
  std::string Text() const;
};

struct Curve {
  CurveKind kind = CurveKind::kHopf;
  std::vector<CurvePoint> points;
  CurveEnds ends;  // how each end ended; ends.Text(), e.g. "border / border"
  double seconds = 0;
  int evaluations = 0;  // of its defining function
};

/// The label of a codimension-two point of a chart, for every system.
enum class Codim2Label {
  kGeneralizedHopf,  ///< GH: l1 changes sign on an HB curve
  kGrazingFold,      ///< GR-LP: the grazing type changes on a GR curve
  kR1,               ///< LP with the other multiplier at +1 (1:1 resonance; an NS curve ends)
  kR2,               ///< PD with the other multiplier at -1 (1:2 resonance; an NS curve ends)
  kFoldFlip,         ///< LPPD: PD with the other multiplier at +1 (an LP curve meets it)
  kSliding,  ///< SL: the orbit's stick structure changes on an LP/PD/NS curve (it ends on GR)
  /// GG: two GR curves meet at a corner, the orbit touches the surface twice
  /// at once (the grazing boundary switches from one touch to the other).
  kDoubleGrazing,
  /// CP: a cusp of an LP curve, where two folds of the branch merge (the
  /// curve's direction in the plane reverses).
  kCusp,
};
template <>
struct EnumNames<Codim2Label> {
  static constexpr NamedValue<Codim2Label> kTable[] = {
      {Codim2Label::kGeneralizedHopf, "GH"},
      {Codim2Label::kGrazingFold, "GR-LP"},
      {Codim2Label::kR1, "R1"},
      {Codim2Label::kR2, "R2"},
      {Codim2Label::kFoldFlip, "LPPD"},
      {Codim2Label::kSliding, "SL"},
      {Codim2Label::kDoubleGrazing, "GG"},
      {Codim2Label::kCusp, "CP"},
  };
};

/// How a codimension-two point was placed on its curve.
enum class Codim2Method {
  kCurveEnd,  ///< SL: the curve's end (its last step bisected by the tracer); GG: two ends' middle
  kRefined,   ///< the test function's root by Illinois on the corrected curve
  kChord,     ///< the refinement failed: interpolated linearly between two curve points
  kPoint,     ///< CP: the curve point where its direction reverses
};
template <>
struct EnumNames<Codim2Method> {
  static constexpr NamedValue<Codim2Method> kTable[] = {
      {Codim2Method::kCurveEnd, "end"},
      {Codim2Method::kRefined, "refined"},
      {Codim2Method::kChord, "chord"},
      {Codim2Method::kPoint, "point"},
  };
};

struct Codim2Point {
  Codim2Label label = Codim2Label::kGeneralizedHopf;
  double p1 = 0, p2 = 0;
  std::string description;
};

enum class Region {
  kSteadyOnly = 0,  // stable steady sliding, no oscillation
  kStickSlip = 1,   // stick-slip, steady sliding unstable
  kPureSlip = 2,    // pure-slip oscillation, steady sliding unstable
  kBistable = 3,    // an oscillation beside stable steady sliding
};
template <>
struct EnumNames<Region> {
  static constexpr NamedValue<Region> kTable[] = {
      {Region::kSteadyOnly, "steady sliding only"},
      {Region::kStickSlip, "stick-slip"},
      {Region::kPureSlip, "pure-slip oscillation"},
      {Region::kBistable, "bistable"},
  };
};

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
  // max_step's upper bound (a curve across the rectangle in at least 5 steps).
  static constexpr double kMaxStepLimit = 0.2;
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
template <>
struct EnumNames<ChartStatus> {
  static constexpr NamedValue<ChartStatus> kTable[] = {
      {ChartStatus::kOk, "ok"},
      {ChartStatus::kFailed, "failed"},
      {ChartStatus::kPartial, "partial"},
      {ChartStatus::kCancelled, "cancelled"},
  };
};

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
