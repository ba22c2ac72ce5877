// The chart of any system (system.hpp) in two of its parameters
// (docs/systems.md, "Charts"): codimension-one curves followed by
// pseudo-arclength continuation through a rectangle,
//   HB  of steady sliding (the Jacobian's complex pair nearest the imaginary
//       axis reaches it: Re lambda = 0; Kuznetsov 2004, ch. 3);
//   LP, PD, NS  of periodic orbits: the one branch driver's problem with the
//       second parameter free, bordered by its test function on the
//       monodromy (orbit_branch.hpp);
//   GR  with a clock: an orbit's arrivals on a contact's surface turn from
//       crossings into sticks, or an orbit first touches a surface
//       (docs/theory.md, "Charts of any system");
// seeded by the special points of one-parameter runs (ContinueSteadySliding,
// and ContinueOrbits from the attractor at points of the line: the stick-slip
// orbit settled on, or with a clock the stroboscopic orbit reached from rest,
// and the doubled branches from their PD points) on lines across the
// rectangle. A system with a clock has no steady sliding: its curves are of
// orbits only, on stroboscopic sections kept off the orbits' stick phases.
// A curve of orbits ends where the orbit's switching sequence changes (an SL
// point: a sliding bifurcation meets it) or the normal force of a contact
// reaches 0 on it. Codimension-two points, located on the curves: those SL
// ends, LPPD, R1 and R2, CP (a cusp of an LP curve) and GG (two GR curves
// meet).
#pragma once

#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/chart/chart.hpp"
#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip {

/// Two parameters of a system by index (System::ParameterIndex: the lens)
/// and a rectangle in them.
struct SystemPlane {
  int p1 = 0, p2 = 1;
  double from1 = 0, to1 = 1, from2 = 0, to2 = 1;
  /// Empty if valid for `system`, else one line naming the offending value:
  /// an index out of range, equal axes, an axis the system does not depend
  /// on (System::ParameterError), a range not finite, empty, inverted
  /// or narrower than kMinRelativeWidth, or a point of the rectangle's
  /// border (17 per edge) where the system is invalid.
  std::string ValidationError(const System& system) const;
  bool Contains(double x1, double x2) const {
    return x1 >= from1 && x1 <= to1 && x2 >= from2 && x2 <= to2;
  }
};

struct SystemChartOptions {
  /// Upper bound of seed_lines; max_step's bounds (a curve across the
  /// rectangle in at least 2 steps, at most kMaxCurvePoints per way).
  static constexpr int kMaxSeedLines = 20, kMaxSettlePoints = 50, kMaxMultiple = 8;
  static constexpr double kMaxStepLimit = 0.5;
  SystemPlane plane;
  /// Every run's flow and Newton, and the seed runs' PALC and max_amplitude.
  OrbitBranchOptions branch;
  /// An autonomous system's settling run at a line's point, from steady
  /// sliding moved by `disturbance` in the first component.
  double transient = 3000, disturbance = 0.5;
  /// A system with a clock: the orbit reached from rest of period multiple
  /// 1..max_m (StroboscopicOrbits' transient and recurrence), and the
  /// doubled branch of each PD of period multiple 2m <= max_m. Without a
  /// clock: doubled branches while 2^doublings <= max_m.
  int max_m = 2;
  int seed_lines = 3;  ///< lines per axis across the rectangle, each seeding curves
  /// Points per line (ends included) where a run settles on an attractor,
  /// whose branch is continued to both ends of the line.
  int settle_points = 5;
  double max_step = 0.01;    ///< largest curve step, fraction of the rectangle
  bool hopf_curves = true;   ///< HB of steady sliding
  bool orbit_curves = true;  ///< LP, PD and NS of periodic orbits
  /// Polled between points, inside every run of a curve's maps and by the
  /// seed runs.
  std::function<bool()> cancelled;
  /// Empty if valid for `system`, else one line naming the offending value.
  std::string ValidationError(const System& system) const;
};

struct SystemCurvePoint {
  double p1 = 0, p2 = 0;
  /// LP, PD, NS: the orbit there (its p is p1). HB: orbit.start.z is the rest
  /// point and orbit.period 2 pi / omega of the pair on the imaginary axis.
  OrbitRow orbit;
  double test = 0;  ///< the curve's own test function there (about 0)
  /// The other tests there: LP, PD, NS (prod (mu - 1), prod (mu + 1),
  /// prod (mu_i mu_j - 1)); HB: unused.
  double tests[3] = {0, 0, 0};
};

struct SystemCodim2 {
  Codim2Label label = Codim2Label::kSliding;
  CurveKind on = CurveKind::kFold;
  int curve = 0;  ///< index into SystemChart::curves
  double p1 = 0, p2 = 0;
  Codim2Method method = Codim2Method::kCurveEnd;
  /// kRefined: the orbit there (its p is p1) and the located test's value.
  OrbitRow orbit;
  double test = 0;
  std::string description;
  static SystemCodim2 At(Codim2Label label, CurveKind on, double p1, double p2,
                         Codim2Method method) {
    SystemCodim2 x;
    x.label = label, x.on = on, x.p1 = p1, x.p2 = p2, x.method = method;
    return x;
  }
};

struct SystemCurve {
  CurveKind kind = CurveKind::kFold;
  std::vector<SystemCurvePoint> points;
  CurveEnds ends;
  PoincareSection section;  ///< the orbits' section (LP, PD, NS, GR)
  /// GR: the margin traced, an arrival's (|lambda| - mu_s N at a crossing)
  /// or, if true, the gap of an orbit that reaches no surface.
  bool gap = false;
  std::string seed;  ///< where it started: "LP of the v run at mu_k = 0.5"
  /// Its codimension-two points, located on it (curve: 0 until ChartSystem
  /// numbers it).
  std::vector<SystemCodim2> codim2;
  int evaluations = 0;
  double seconds = 0;
};

struct SystemChart {
  SystemPlane plane;  ///< the chart's axes and rectangle
  /// kOk; kPartial where a curve was cut short or a seed run failed;
  /// kCancelled.
  ChartStatus status = ChartStatus::kOk;
  std::string message;
  std::vector<SystemCurve> curves;
  std::vector<SystemCodim2> codim2;
  int seed_runs = 0;         ///< one-parameter runs made for seeds
  int failed_seed_runs = 0;  ///< of them, those that failed (message: the first)
  int seeds_not_traced = 0;  ///< seeds that gave no curve of two points or more
  /// Curves traced from seeds off their curve, most of whose points lie on
  /// one already drawn (dropped).
  int duplicates = 0;
  /// Curves cut short inside the rectangle: an end at max-points,
  /// step-too-small or start-failed (message: the first). The ends where the
  /// map stops being smooth (stopped), SL, contact-lost, a branch jump (the
  /// next point, also at half the step, lies off the curve: a corner or
  /// another curve) and a GR curve's corner at GG are ends of the curve, not
  /// cuts.
  int cut_curves = 0;
  double seconds = 0;
  int points() const;
};

/// A curve's orbits' period in units of its section: forcing periods (a
/// stroboscopic section's clock turns), else returns to the section.
inline int PeriodMultiple(const PoincareSection& s) {
  return s.kind == SectionKind::kTime ? s.turns : s.returns;
}

/// The chart of `system` (its values of the two axes are not used). Throws
/// InvalidArgument on an invalid system or options.
SystemChart ChartSystem(const System& system, const SystemChartOptions& options);

/// One curve of periodic orbits from `start`, a point of an orbit of
/// `section` at (p1, p2) near the curve (`fixed` 0 holds p1 while it is
/// corrected, 1 holds p2), both ways to the rectangle's border: what
/// ChartSystem does per seed. kind LP, PD, NS or GR (else InvalidArgument);
/// GR takes the margin nearer 0 at the start (orbit_curve.hpp).
SystemCurve TraceOrbitCurve(const System& system, const SystemChartOptions& options, CurveKind kind,
                            const FlowPoint& start, double p1, double p2,
                            const PoincareSection& section, int fixed);

/// One HB curve of steady sliding from (p1, p2) near it, both ways.
SystemCurve TraceHopfCurve(const System& system, const SystemChartOptions& options, double p1,
                           double p2, int fixed);

}  // namespace stickslip
