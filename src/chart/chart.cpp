#include "stickslip/chart/chart.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "chart/chart_region_faces.hpp"
#include "chart/chart_regions.hpp"
#include "chart/chart_starts.hpp"
#include "chart/chart_trace.hpp"
#include "chart/fold_curve.hpp"
#include "chart/grazing_curve.hpp"
#include "chart/hopf_curve.hpp"
#include "numerics/roots.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

using Eigen::VectorXd;

const char* CurveLabel(CurveKind k) { return Name(k); }

int ChartResult::points() const {
  int n = 0;
  for (const Curve& c : curves) n += static_cast<int>(c.points.size());
  return n;
}

std::string ChartOptions::ValidationError(const Params& base) const {
  std::string err = plane.ValidationError(base);
  if (err.empty()) err = orbit.ValidationError();
  std::ostringstream os;
  if (!err.empty())
    os << err;
  else if (!(max_step >= 1.0 / kMaxCurvePoints && max_step <= kMaxStepLimit))
    os << "max_step = " << max_step << " must be in [" << 1.0 / kMaxCurvePoints << ", "
       << kMaxStepLimit
       << "]: a curve across the rectangle takes about 1 / max_step points, at most "
       << kMaxCurvePoints;
  else if (samples < 4)
    os << "samples = " << samples << " must be >= 4";
  else if (region_n1 < 0 || region_n2 < 0 || (region_n1 == 0) != (region_n2 == 0))
    os << "region grid " << region_n1 << " x " << region_n2 << " must be empty or positive";
  for (const Seed& s : seeds)
    if (const bool kind = s.kind == CurveKind::kHopf || s.kind == CurveKind::kGrazing;
        os.str().empty() && (!kind || !plane.Contains(s.p1, s.p2)))
      os << "seed " << CurveLabel(s.kind) << " at (" << s.p1 << ", " << s.p2 << ")"
         << (!kind ? ": only HB and GR seeds are supported" : " is outside the plane");
  return os.str();
}

namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

bool NonPositiveFriction(const Params& p, double max_slip) {
  return Friction(p).NonPositiveUpTo(max_slip);
}

class Charter {
 public:
  Charter(const Params& base, const ChartOptions& o) : base_(base), o_(o), pl_(o.plane) {}
  ChartResult Run();

 private:
  TraceOptions TraceOpts() const;
  void HopfCurves();
  void GrazingCurves();
  void FoldCurves();
  bool Stop(ChartResult& r, const TraceResult& t, CurveKind kind);
  void CutShort(CurveKind kind, const Eigen::Vector2d& start, const std::string& why);
  bool Halted() const {
    return r_.status == ChartStatus::kFailed || r_.status == ChartStatus::kCancelled;
  }

  Params base_;
  ChartOptions o_;
  Plane pl_;
  ChartResult r_;
};

TraceOptions Charter::TraceOpts() const {
  TraceOptions t;
  t.plane = pl_;
  t.max_step = o_.max_step;
  t.cancelled = o_.cancelled;
  return t;
}

bool Charter::Stop(ChartResult& r, const TraceResult& t, CurveKind kind) {
  if (t.cancelled) {
    r.status = ChartStatus::kCancelled;
    r.message = std::string("cancelled while following a ") + CurveLabel(kind) + " curve";
    return true;
  }
  return false;
}

// The first curve cut short makes the chart partial; later ones are counted.
void Charter::CutShort(CurveKind kind, const Eigen::Vector2d& start, const std::string& why) {
  if (r_.status != ChartStatus::kOk) return;
  r_.status = ChartStatus::kPartial;
  std::ostringstream os;
  os << CurveLabel(kind) << " curve from " << pl_.p1 << " = " << start[0] << ", " << pl_.p2 << " = "
     << start[1] << " cut short: " << why;
  r_.message = os.str();
}

void Charter::HopfCurves() {
  HopfCurveProblem problem(base_, pl_);
  TraceOptions to = TraceOpts();
  to.tol = Tolerances().hopf_corrector;
  const auto starts =
      WithSeeds(o_, CurveKind::kHopf, StartPoints(pl_, 8 * o_.samples, [&](double x1, double x2) {
                  return HopfFunction(pl_.At(base_, x1, x2));
                }));
  for (const CurveStart& s : starts) {
    if (NearCurve(r_.curves, CurveKind::kHopf, pl_, s.x)) continue;
    const auto t0 = Clock::now();
    const TraceResult t = TraceBothWays(problem, to, VectorXd(s.x), s.fixed);
    if (Stop(r_, t, CurveKind::kHopf)) return;
    if (!t.cut.empty()) CutShort(CurveKind::kHopf, s.x, t.cut);
    Curve c;
    c.kind = CurveKind::kHopf;
    c.ends = t.ends;
    c.evaluations = t.evaluations;
    for (const VectorXd& u : t.u) {
      if (o_.cancelled && o_.cancelled()) {  // up to 2 x 20000 points: poll here too
        r_.status = ChartStatus::kCancelled;
        r_.message = "cancelled while sampling an HB curve";
        return;
      }
      CurvePoint p;
      p.p1 = u[0], p.p2 = u[1];
      p.period = 2 * M_PI, p.amplitude = 0, p.multiplier = 1;
      p.l1 = HopfCriticality(pl_.At(base_, u[0], u[1]));
      p.type = p.l1 < 0   ? CurvePointType::kSupercritical
               : p.l1 > 0 ? CurvePointType::kSubcritical
                          : CurvePointType::kDegenerate;
      c.points.push_back(p);
    }
    // GH: the criticality changes sign between two points.
    for (size_t i = 1; i < c.points.size(); ++i) {
      const CurvePoint &a = c.points[i - 1], &b = c.points[i];
      if (a.l1 * b.l1 > 0) continue;
      const Newton2Result gh =
          LocateGeneralizedHopf(base_, pl_, 0.5 * (a.p1 + b.p1), 0.5 * (a.p2 + b.p2));
      if (gh.ok && pl_.Contains(gh.x[0], gh.x[1]))
        r_.codim2.push_back({Codim2Label::kGeneralizedHopf, gh.x[0], gh.x[1],
                             "generalized Hopf: l1 changes sign on HB (mu''' = 0)"});
    }
    c.seconds = Since(t0);
    r_.curves.push_back(std::move(c));
  }
}

void Charter::GrazingCurves() {
  GrazingCurveProblem problem(base_, pl_, o_.orbit);
  OrbitFinder finder(Model(base_), o_.orbit);
  if (o_.cancelled) {  // a slow first return stops too; Run() then says cancelled
    problem.set_cancel(o_.cancelled);
    finder.flow().set_cancel(o_.cancelled);
  }
  const auto starts =
      WithSeeds(o_, CurveKind::kGrazing, StartPoints(pl_, o_.samples, [&](double x1, double x2) {
                  const GrazingSample g = SampleGrazing(finder, pl_.At(base_, x1, x2), false);
                  return g.ok() ? g.gap : NAN;
                }));
  for (const CurveStart& s : starts) {
    if (NearCurve(r_.curves, CurveKind::kGrazing, pl_, s.x)) continue;
    const auto t0 = Clock::now();
    const TraceResult t = TraceBothWays(problem, TraceOpts(), VectorXd(s.x), s.fixed);
    if (Stop(r_, t, CurveKind::kGrazing)) return;
    if (!t.cut.empty()) CutShort(CurveKind::kGrazing, s.x, t.cut);
    Curve c;
    c.kind = CurveKind::kGrazing;
    c.ends = t.ends;
    c.evaluations = t.evaluations;
    for (const VectorXd& u : t.u) {
      if (o_.cancelled && o_.cancelled()) {  // one integration per point: poll here too
        r_.status = ChartStatus::kCancelled;
        r_.message = "cancelled while sampling a GR curve";
        return;
      }
      const GrazingSample g = problem.Sample(u[0], u[1]);
      if (!g.ok()) continue;
      CurvePoint p;
      p.p1 = u[0], p.p2 = u[1];
      p.period = g.period, p.amplitude = g.amplitude, p.multiplier = g.multiplier;
      p.type = g.multiplier < 1 ? CurvePointType::kPersistence : CurvePointType::kNonsmoothFold;
      p.unphysical = NonPositiveFriction(pl_.At(base_, u[0], u[1]), g.max_slip);
      c.points.push_back(p);
    }
    // GR-LP: the pure-slip side's multiplier crosses 1.
    for (size_t i = 1; i < c.points.size(); ++i) {
      const CurvePoint &a = c.points[i - 1], &b = c.points[i];
      if ((a.multiplier - 1) * (b.multiplier - 1) > 0) continue;
      const double w = (1 - a.multiplier) / (b.multiplier - a.multiplier);
      const Newton2Result lp = LocateGrazingFold(base_, pl_, o_.orbit, a.p1 + w * (b.p1 - a.p1),
                                                 a.p2 + w * (b.p2 - a.p2));
      if (lp.ok && pl_.Contains(lp.x[0], lp.x[1]))
        r_.codim2.push_back({Codim2Label::kGrazingFold, lp.x[0], lp.x[1],
                             "grazing type changes (lambda = 1): a fold curve of pure-slip "
                             "orbits ends here"});
    }
    c.seconds = Since(t0);
    r_.curves.push_back(std::move(c));
  }
}

void Charter::FoldCurves() {
  FoldCurveProblem problem(base_, pl_, o_.orbit);
  TraceOptions to = TraceOpts();
  to.i1 = 1;
  to.other_scale = 0.5;
  // dG/da is noisy at small a (the integration error over a^2), the fold is
  // ill-conditioned in a: Newton stalls at ~1e-7 in a, not in the parameters
  // (stalls are accepted, palc.hpp). The stopping test follows the integration
  // tolerance: a fixed 1e-10 left the rows 3e-12 off at any rtol.
  to.tol = Tolerances::From(o_.orbit.flow.rtol, o_.orbit.flow.atol).Corrector();
  // An orbit that reaches the belt speed is on the GR curve: the fold ends there.
  to.stop = [&](const VectorXd& u) {
    const FoldSample s = problem.Sample(u);
    return !s.ok() || s.xdot_max >= pl_.At(base_, u[1], u[2]).v;
  };
  const std::vector<Codim2Point> gh_points = r_.codim2;
  for (const Codim2Point& gh : gh_points) {
    if (gh.label != Codim2Label::kGeneralizedHopf) continue;
    const auto t0 = Clock::now();
    // Start at a small amplitude, parameters held near GH (a^2 ~ distance).
    const VectorXd u0 = (VectorXd(3) << Tolerances().fold_start_amplitude, gh.p1, gh.p2).finished();
    const TraceResult t = TraceOneWay(problem, to, u0, 0, VectorXd::Unit(3, 0));
    if (Stop(r_, t, CurveKind::kFold)) return;
    Curve c;
    c.kind = CurveKind::kFold;
    c.ends = t.ends;
    c.evaluations = t.evaluations;
    CurvePoint first;
    first.p1 = gh.p1, first.p2 = gh.p2, first.period = 2 * M_PI, first.multiplier = 1;
    first.type = CurvePointType::kFold;
    c.points.push_back(first);  // the GH point itself: a = 0
    for (const VectorXd& u : t.u) {
      const FoldSample s = problem.Sample(u);
      if (!s.ok()) continue;
      CurvePoint p;
      p.p1 = u[1], p.p2 = u[2];
      p.period = s.period, p.amplitude = s.amplitude, p.multiplier = s.multiplier;
      p.type = CurvePointType::kFold;
      p.unphysical = NonPositiveFriction(pl_.At(base_, u[1], u[2]), s.max_slip);
      c.points.push_back(p);
    }
    // Where its orbit reaches the belt (the way stops, or fails as trial orbits
    // stick): the GR-LP point closes it.
    if (c.points.size() > 1) {
      const CurvePoint& last = c.points.back();
      const Newton2Result lp = LocateGrazingFold(base_, pl_, o_.orbit, last.p1, last.p2);
      const double d =
          std::hypot((lp.x[0] - last.p1) / pl_.width1(), (lp.x[1] - last.p2) / pl_.width2());
      if (lp.ok && d < 5 * o_.max_step) {
        OrbitFinder finder(Model(base_), o_.orbit);
        const GrazingSample g = SampleGrazing(finder, pl_.At(base_, lp.x[0], lp.x[1]), true);
        CurvePoint p;
        p.p1 = lp.x[0], p.p2 = lp.x[1];
        p.period = g.period, p.amplitude = g.amplitude, p.multiplier = g.multiplier;
        p.type = CurvePointType::kFold;
        c.points.push_back(p);
        c.ends = {{CurveEndKind::kGeneralizedHopf, ""}, {CurveEndKind::kGrazingFold, ""}};
      }
    }
    if (!t.cut.empty() && c.ends.last.kind != CurveEndKind::kGrazingFold)
      CutShort(CurveKind::kFold, Eigen::Vector2d(gh.p1, gh.p2), t.cut);
    c.seconds = Since(t0);
    r_.curves.push_back(std::move(c));
  }
}

ChartResult Charter::Run() {
  const auto t0 = Clock::now();
  if (o_.hopf_curves) HopfCurves();
  if (!Halted() && o_.grazing_curves) GrazingCurves();
  if (!Halted() && o_.fold_curves) FoldCurves();
  if (!Halted() && o_.cancelled && o_.cancelled()) {
    r_.status = ChartStatus::kCancelled;  // evaluations may have failed for it: curves cut
    r_.message = "cancelled";
  }
  // Codim-2 points found twice (from two curves or start points) are one.
  std::vector<Codim2Point> unique;
  for (const Codim2Point& p : r_.codim2) {
    bool seen = false;
    for (const Codim2Point& q : unique)
      seen = seen || (q.label == p.label &&
                      std::abs(q.p1 - p.p1) < Tolerances().same_point * pl_.width1() &&
                      std::abs(q.p2 - p.p2) < Tolerances().same_point * pl_.width2());
    if (!seen) unique.push_back(p);
  }
  r_.codim2 = unique;
  for (const Curve& c : r_.curves)
    for (const CurvePoint& p : c.points) r_.unphysical_points += p.unphysical;
  r_.seconds = Since(t0);
  if (!Halted() && o_.region_n1 > 0) {
    const auto t1 = Clock::now();
    r_.regions = ClassifyGrid(base_, o_, r_.curves);
    r_.region_seconds = Since(t1);
    if (r_.regions.cells.size() < static_cast<size_t>(r_.regions.n1) * r_.regions.n2) {
      r_.status = ChartStatus::kCancelled;  // ClassifyGrid stopped early
      r_.message = "cancelled while classifying the regions";
    } else if (r_.regions.failed > 0 && r_.status == ChartStatus::kOk) {
      r_.status = ChartStatus::kPartial;
      r_.message = std::to_string(r_.regions.failed) +
                   " region cells unclassified; first: " + r_.regions.failure;
    }
  }
  if (!Halted() && o_.region_faces) {
    const auto t1 = Clock::now();
    std::string failure;
    r_.faces = ClassifyFaces(base_, o_, r_.curves, &failure);
    r_.face_seconds = Since(t1);
    if (!failure.empty() && r_.status == ChartStatus::kOk) {
      r_.status = ChartStatus::kPartial;
      r_.message = failure;
    }
  }
  return r_;
}

}  // namespace

ChartResult Chart(const Params& base, const ChartOptions& options) {
  const std::string err = options.ValidationError(base);
  if (!err.empty()) throw InvalidArgument(err);
  return Charter(base, options).Run();
}

}  // namespace stickslip
