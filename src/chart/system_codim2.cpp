// Codimension-two points on a system chart's curves (chart/system_codim2.hpp).
#include "chart/system_codim2.hpp"

#include <cmath>
#include <string>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr int kLp = 0, kPd = 1, kNs = 2;  // orbit_detail::RowTest's tests

// One test watched along a curve and what its zero is.
struct Watch {
  int test;
  Codim2Label label;
  double resonance;  // R1 on LP, R2 on PD: two multipliers at this (+1, -1); 0: none needed
  const char* what;
};

std::vector<Watch> WatchesOn(CurveKind kind) {
  switch (kind) {
    case CurveKind::kFold:
      return {
          {kPd, Codim2Label::kFoldFlip, 0, "LP curve: a multiplier at -1 (a PD curve meets it)"},
          {kNs, Codim2Label::kR1, 1, "LP curve: two multipliers at +1 (1:1)"}};
    case CurveKind::kPeriodDoubling:
      return {
          {kLp, Codim2Label::kFoldFlip, 0, "PD curve: a multiplier at +1 (an LP curve meets it)"},
          {kNs, Codim2Label::kR2, -1, "PD curve: two multipliers at -1 (1:2)"}};
    case CurveKind::kTorus:
      return {{kLp, Codim2Label::kR1, 0, "NS curve: the pair meets at +1 (1:1)"},
              {kPd, Codim2Label::kR2, 0, "NS curve: the pair meets at -1 (1:2)"}};
    default:
      return {};
  }
}

// Whether two multipliers of r lie within Tolerances::kResonantPair of `at`.
bool Resonant(const OrbitRow& r, double at) {
  int n = 0;
  for (const std::complex<double>& m : r.multipliers)
    n += std::abs(m - at) < Tolerances::kResonantPair;
  return n >= 2;
}

// The unknowns' scales: the plane's widths, max(1, |u_i|) for the others.
VectorXd ScaleOf(const VectorXd& u, int i1, const SystemPlane& pl) {
  VectorXd s = VectorXd::Constant(u.size(), std::max(1.0, u.head(i1).cwiseAbs().maxCoeff()));
  s[i1] = pl.to1 - pl.from1, s[i1 + 1] = pl.to2 - pl.from2;
  return s;
}

// The curve point on the hyperplane through c = ua + s d normal to d
// (scaled), by Newton on the curve's system bordered by that plane.
bool OnCurve(OrbitCurveProblem& pr, const VectorXd& ua, const VectorXd& d, const VectorXd& scale,
             double s, double tol, VectorXd* u) {
  constexpr int kNewton = 12;
  const int n = static_cast<int>(ua.size());
  const VectorXd w = d.cwiseQuotient(scale.cwiseProduct(scale)), c = ua + s * d;
  *u = c;
  for (int it = 0; it < kNewton; ++it) {
    VectorXd f;
    MatrixXd J;
    std::string why;
    if (!pr.Evaluate(*u, &f, &J, &why)) return false;
    MatrixXd a(n, n);
    a.topRows(n - 1) = J;
    a.row(n - 1) = w.transpose();
    VectorXd r(n);
    r << f, w.dot(*u - c);
    const VectorXd du = a.fullPivLu().solve(-r);
    if (!du.allFinite()) return false;
    *u += du;
    if (!pr.DomainError(*u).empty()) return false;
    if (du.cwiseQuotient(scale).norm() <= tol) return true;
  }
  return false;
}

// The root of test k between curve points ua and ub (ga, gb of opposite
// signs) by Illinois on s in [0, 1]; false if a correction fails.
bool Refine(OrbitCurveProblem& pr, const VectorXd& ua, const VectorXd& ub, int k, double ga,
            double gb, const SystemPlane& pl, double tol, SystemCodim2* x) {
  constexpr int kIllinois = 60;
  const int i1 = pr.plane_index();
  const VectorXd scale = ScaleOf(ua, i1, pl), d = ub - ua;
  const double len = d.cwiseQuotient(scale).norm();
  double lo = 0, hi = 1, glo = ga, ghi = gb, last = -1;
  int side = 0;
  VectorXd u;
  for (int it = 0; it < kIllinois; ++it) {
    const double s = (lo * ghi - hi * glo) / (ghi - glo);
    double test = 0;
    std::string why;
    if (!OnCurve(pr, ua, d, scale, s, tol, &u) || !pr.Sample(u, &x->orbit, &test, &why))
      return false;
    const double g = orbit_detail::RowTest(x->orbit, k);
    if (g == 0 || std::abs(s - last) * len <= tol || (hi - lo) * len <= tol) {
      x->p1 = u[i1], x->p2 = u[i1 + 1], x->test = g;
      x->method = Codim2Method::kRefined;
      return true;
    }
    last = s;
    if ((g > 0) == (ghi > 0)) {
      hi = s, ghi = g;
      if (side == 1) glo /= 2;
      side = 1;
    } else {
      lo = s, glo = g;
      if (side == -1) ghi /= 2;
      side = -1;
    }
  }
  return false;
}

class Locator {
 public:
  Locator(const std::vector<CurveStretch>& all, const SystemChartOptions& o, SystemCurve* c)
      : all_(all), o_(o), c_(c) {
    const FlowOptions& flow = o.branch.shooting.flow;
    tol_ = Tolerances::From(flow.rtol, flow.atol).SystemCurveCorrector();
  }

  // The zero of w.test between a (test ga) and b (gb) on stretch k, if any.
  void Between(int k, const VectorXd& ua, const VectorXd& ub, double ga, double gb,
               const Watch& w) {
    if ((ga > 0) == (gb > 0) || !std::isfinite(ga) || !std::isfinite(gb)) return;
    SystemCodim2 x;
    x.label = w.label, x.on = c_->kind, x.description = w.what;
    OrbitCurveProblem& pr = *all_[k].problem;
    const int i1 = pr.plane_index();
    if (!Refine(pr, ua, ub, w.test, ga, gb, o_.plane, tol_, &x)) {
      if (w.resonance != 0) return;  // R1, R2 on LP, PD: told apart at a located point only
      const double s = ga / (ga - gb);
      x = SystemCodim2::At(w.label, c_->kind, ua[i1] + s * (ub[i1] - ua[i1]),
                           ua[i1 + 1] + s * (ub[i1 + 1] - ua[i1 + 1]), Codim2Method::kChord);
      x.description = std::string(w.what) + " (chord)";
    } else if (w.resonance != 0 && !Resonant(x.orbit, w.resonance)) {
      return;  // another pair's product at 1: no resonance
    }
    Add(x);
  }

  // A point once: a curve that touches the root twice in a row gives it twice.
  void Add(const SystemCodim2& x) {
    const SystemPlane& pl = o_.plane;
    const double same = Tolerances().same_point;
    for (const SystemCodim2& y : c_->codim2)
      if (y.label == x.label && std::abs(y.p1 - x.p1) <= same * (pl.to1 - pl.from1) &&
          std::abs(y.p2 - x.p2) <= same * (pl.to2 - pl.from2))
        return;
    c_->codim2.push_back(x);
  }

 private:
  const std::vector<CurveStretch>& all_;
  const SystemChartOptions& o_;
  SystemCurve* c_;
  double tol_ = 0;
};

void EndsAndCusps(const SystemChartOptions& o, SystemCurve* c) {
  const CurveEnd* ends[2] = {&c->ends.first, &c->ends.last};
  for (int k = 0; k < 2; ++k)
    if (ends[k]->kind == CurveEndKind::kSliding && !c->points.empty()) {
      const SystemCurvePoint& p = k == 0 ? c->points.front() : c->points.back();
      SystemCodim2 x =
          SystemCodim2::At(Codim2Label::kSliding, c->kind, p.p1, p.p2, Codim2Method::kCurveEnd);
      x.description = std::string(CurveLabel(c->kind)) + " curve ends: " + ends[k]->why;
      c->codim2.push_back(x);
    }
  // CP: an LP curve's direction in the (scaled) plane reverses at a point
  // (once for two neighbours that both turn).
  const double w1 = o.plane.to1 - o.plane.from1, w2 = o.plane.to2 - o.plane.from2;
  std::size_t last = 0;
  for (std::size_t i = 1; c->kind == CurveKind::kFold && i + 1 < c->points.size(); ++i) {
    const SystemCurvePoint &a = c->points[i - 1], &b = c->points[i], &d = c->points[i + 1];
    const double dot =
        (b.p1 - a.p1) * (d.p1 - b.p1) / (w1 * w1) + (b.p2 - a.p2) * (d.p2 - b.p2) / (w2 * w2);
    if (dot >= 0 || (last > 0 && i == last + 1)) continue;
    last = i;
    SystemCodim2 x =
        SystemCodim2::At(Codim2Label::kCusp, c->kind, b.p1, b.p2, Codim2Method::kPoint);
    x.orbit = b.orbit;
    x.description = "cusp: two folds merge (the LP curve turns back at this point of it)";
    c->codim2.push_back(x);
  }
}

}  // namespace

// The curve's points in order (the back way's stretches reversed, then the
// first, then the forward way's), each sampled on its stretch's problem, and
// its codimension-two points (system_codim2.hpp).
void Assemble(const std::vector<CurveStretch>& back, const CurveStretch& first,
              const std::vector<CurveStretch>& fwd, const VectorXd saddle[2],
              const SystemChartOptions& o, SystemCurve* curve) {
  std::vector<CurveStretch> all;
  for (auto it = back.rbegin(); it != back.rend(); ++it)
    all.push_back({it->problem, std::vector<VectorXd>(it->u.rbegin(), it->u.rend())});
  all.push_back(first);
  all.insert(all.end(), fwd.begin(), fwd.end());
  std::vector<TracedPoint> traced;
  for (std::size_t k = 0; k < all.size(); ++k)
    for (const VectorXd& u : all[k].u) {
      if (o.cancelled && o.cancelled()) {  // the points beyond are not sampled
        curve->ends.last = {CurveEndKind::kCancelled, ""};
        return;
      }
      SystemCurvePoint p;
      std::string why;
      if (!all[k].problem->Sample(u, &p.orbit, &p.test, &why)) {
        if (o.cancelled && o.cancelled()) {  // the sample cut short, not a bad point
          curve->ends.last = {CurveEndKind::kCancelled, ""};
          return;
        }
        continue;
      }
      const int i1 = all[k].problem->plane_index();
      p.p1 = u[i1], p.p2 = u[i1 + 1];
      for (int t = 0; t < 3; ++t) p.tests[t] = orbit_detail::RowTest(p.orbit, t);
      curve->points.push_back(std::move(p));
      traced.push_back({static_cast<int>(k), u});
    }
  std::vector<BeyondEnd> beyond;
  if (saddle[0].size() > 0) beyond.push_back({true, 0, saddle[0]});
  if (saddle[1].size() > 0) beyond.push_back({false, static_cast<int>(all.size()) - 1, saddle[1]});
  LocateCodim2(all, traced, beyond, o, curve);
}

void LocateCodim2(const std::vector<CurveStretch>& all, const std::vector<TracedPoint>& traced,
                  const std::vector<BeyondEnd>& beyond, const SystemChartOptions& o,
                  SystemCurve* c) {
  EndsAndCusps(o, c);
  Locator loc(all, o, c);
  const std::vector<Watch> watches = WatchesOn(c->kind);
  for (std::size_t i = 1; i < c->points.size(); ++i) {
    if (traced[i].stretch != traced[i - 1].stretch) continue;  // another section: no chord
    for (const Watch& w : watches)
      loc.Between(traced[i].stretch, traced[i - 1].u, traced[i].u, c->points[i - 1].tests[w.test],
                  c->points[i].tests[w.test], w);
  }
  // NS: the pair turns real beyond an end (R1 or R2 between).
  for (const BeyondEnd& b : beyond) {
    if (c->kind != CurveKind::kTorus || c->points.empty()) continue;
    const std::size_t i = b.first ? 0 : c->points.size() - 1;
    if (traced[i].stretch != b.stretch) continue;
    OrbitRow row;
    double test = 0;
    std::string why;
    if (!all[b.stretch].problem->Sample(b.u, &row, &test, &why)) continue;
    for (const Watch& w : watches)
      loc.Between(b.stretch, traced[i].u, b.u, c->points[i].tests[w.test],
                  orbit_detail::RowTest(row, w.test), w);
  }
}

}  // namespace stickslip
