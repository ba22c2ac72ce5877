// Codimension-two points on the forced chart's curves (forced_chart.hpp):
// R1 and R2 where det DP = 1 on LP and PD (the other multiplier at +1 or -1),
// LPPD where det DP = -1 on PD, an NS curve's pair turning real (|tr DP| = 2),
// SL at an end where the stick structure changes. A sign change of the test
// function between two curve points is refined on the curve itself: the
// curve's defining system (forced_curve.hpp) bordered by the hyperplane
// normal to the chord at a + s (b - a), solved by Newton, and the root in s
// by Illinois (Dahlquist & Bjorck 1974, section 6.2.3) to the corrector's
// tolerance. The chord's linear interpolation is the fallback, marked.
//
// LPPD cannot occur in this planar system: off stick phases DP is a product
// of exp(int tr J dt) > 0 and crossing saltations det S = x''+ / x''- > 0, and
// a stick phase makes det DP = 0; det DP = -1 never holds. The test stays.
#include <cmath>

#include "chart/forced_curve.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/chart/forced_chart.hpp"
#include "stickslip/forced/orbit.hpp"

namespace stickslip {

namespace {

using Eigen::VectorXd;

// The test function of one codimension-two label on an orbit's DP^m.
struct Codim2Test {
  Codim2Label label;
  double sign = 1;  // NS: tr DP's sign at the real end
  double offset = -1;
  bool trace = false;
  double Of(const Mat2& M) const { return trace ? sign * M.trace() - 2 : M.determinant() + offset; }
};

// The curve point on the hyperplane through c = ua + s d normal to d (scaled),
// by Newton on the curve's system bordered by that plane.
bool OnCurve(ForcedCurveProblem& pr, const VectorXd& ua, const VectorXd& d, const VectorXd& scale,
             double s, double tol, VectorXd* u) {
  constexpr int kNewton = 12;
  const VectorXd w = d.cwiseQuotient(scale.cwiseProduct(scale)), c = ua + s * d;
  *u = c;
  for (int it = 0; it < kNewton; ++it) {
    VectorXd f;
    Eigen::MatrixXd J;
    std::string why;
    if (!pr.Evaluate(*u, &f, &J, &why)) return false;
    Eigen::Matrix4d A;
    A.topRows(3) = J;
    A.row(3) = w.transpose();
    Eigen::Vector4d r;
    r << f, w.dot(*u - c);
    const Eigen::Vector4d du = A.fullPivLu().solve(-r);
    if (!du.allFinite()) return false;
    *u += du;
    if (!pr.DomainError(*u).empty()) return false;
    if (du.cwiseQuotient(scale).norm() <= tol) return true;
  }
  return false;
}

// The root of the test between curve points a and b (ga, gb of opposite
// signs) by Illinois on s in [0, 1]; false if a correction fails.
bool Refine(ForcedCurveProblem& pr, const ForcedCurvePoint& a, const ForcedCurvePoint& b,
            const Codim2Test& test, double ga, double gb, double tol, ForcedCodim2* x) {
  constexpr int kIllinois = 60;
  VectorXd ua(4), ub(4), scale(4);
  ua << a.x0, a.xdot0, a.p1, a.p2;
  ub << b.x0, b.xdot0, b.p1, b.p2;
  scale << 1, 1, pr.plane().width1(), pr.plane().width2();
  const VectorXd d = ub - ua;
  const double len = d.cwiseQuotient(scale).norm();
  double lo = 0, hi = 1, glo = ga, ghi = gb, last = -1;
  int side = 0;
  VectorXd u;
  for (int k = 0; k < kIllinois; ++k) {
    const double s = (lo * ghi - hi * glo) / (ghi - glo);
    if (!OnCurve(pr, ua, d, scale, s, tol, &u)) return false;
    ForcedCurveSample smp;
    std::string why;
    if (!pr.Sample(u, &smp, &why)) return false;
    const double g = test.Of(smp.jacobian);
    if (g == 0 || std::abs(s - last) * len <= tol || (hi - lo) * len <= tol) {
      x->p1 = u[2], x->p2 = u[3], x->x0 = u[0], x->xdot0 = u[1], x->phase = pr.phase();
      x->test = g;
      Multipliers(smp.jacobian, x->multipliers);
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

}  // namespace

void FindCodim2(const ForcedParams& base, const ForcedChartOptions& o, const ForcedCurve& c,
                int index, std::vector<ForcedCodim2>* out) {
  auto add = [&](ForcedCodim2 x, Codim2Label l, const std::string& d) {
    x.label = l, x.on = c.kind, x.curve = index, x.description = d;
    out->push_back(x);
  };
  // An end where the orbit's stick structure changes, located by the tracer.
  for (const bool first : {true, false}) {
    const CurveEnd& e = first ? c.ends.first : c.ends.last;
    if (e.kind != CurveEndKind::kSliding || c.points.empty()) continue;
    const ForcedCurvePoint& p = first ? c.points.front() : c.points.back();
    ForcedCodim2 x;
    x.p1 = p.p1, x.p2 = p.p2, x.phase = p.phase, x.x0 = p.x0, x.xdot0 = p.xdot0;
    add(x, Codim2Label::kSliding,
        std::string(Name(c.kind)) + " curve ends on a sliding point: " + e.why);
  }
  ForcedCurveProblem problem(base, o.plane, c.kind, c.m, o.flow);
  const double tol = Tolerances::From(o.flow.rtol, o.flow.atol).ForcedCurveCorrector();
  auto mat = [](const ForcedCurvePoint& p) {  // DP^m from the stored multipliers' sum, product
    const std::complex<double> tr = p.multipliers[0] + p.multipliers[1],
                               det = p.multipliers[0] * p.multipliers[1];
    return std::pair<double, double>(tr.real(), det.real());
  };
  auto locate = [&](const ForcedCurvePoint& a, const ForcedCurvePoint& b, const Codim2Test& t,
                    const std::string& d) {
    auto g = [&t](const std::pair<double, double>& td) {
      return t.trace ? t.sign * td.first - 2 : td.second + t.offset;
    };
    const double ga = g(mat(a)), gb = g(mat(b));
    if ((ga > 0) == (gb > 0)) return;
    ForcedCodim2 x;
    x.method = ForcedCodim2Method::kRefined;
    problem.set_phase(a.phase);
    if (a.phase != b.phase || !Refine(problem, a, b, t, ga, gb, tol, &x)) {
      const double s = ga / (ga - gb);
      x = ForcedCodim2();
      x.method = ForcedCodim2Method::kChord;
      x.p1 = a.p1 + s * (b.p1 - a.p1), x.p2 = a.p2 + s * (b.p2 - a.p2);
    }
    // A curve that touches the root twice in a row gives one point twice.
    for (const ForcedCodim2& y : *out)
      if (y.curve == index && y.label == t.label &&
          std::abs(y.p1 - x.p1) <= tol * o.plane.width1() &&
          std::abs(y.p2 - x.p2) <= tol * o.plane.width2())
        return;
    add(x, t.label, d);
  };
  for (size_t i = 1; i < c.points.size(); ++i) {
    const ForcedCurvePoint &a = c.points[i - 1], &b = c.points[i];
    if (c.kind == CurveKind::kFold)
      locate(a, b, {Codim2Label::kR1}, "LP curve: both multipliers at +1 (1:1)");
    if (c.kind == CurveKind::kPeriodDoubling) {
      locate(a, b, {Codim2Label::kR2}, "PD curve: both multipliers at -1 (1:2)");
      locate(a, b, {Codim2Label::kFoldFlip, 1, 1},
             "PD curve: the other multiplier at +1 (an LP curve meets it)");
    }
    if (c.kind == CurveKind::kTorus && a.flag != b.flag) {
      const double tr = mat(a.flag ? a : b).first;
      const bool r1 = tr > 0;
      locate(
          a, b, {r1 ? Codim2Label::kR1 : Codim2Label::kR2, r1 ? 1.0 : -1.0, 0, true},
          std::string("NS curve ends: the pair turns real at ") + (r1 ? "+1 (1:1)" : "-1 (1:2)"));
    }
  }
}

// GG: two GR curves of one period whose inner ends (not on the border) meet.
// Each end of a grazing curve traced by Newton stops there (a corner of
// v - max x', the larger of two touches), so the two ends straddle it.
void FindDoubleGrazing(const std::vector<ForcedCurve>& curves, const Plane& pl,
                       std::vector<ForcedCodim2>* out) {
  const double tol = Tolerances().forced_double_grazing;
  auto inner = [](const ForcedCurve& c, bool first) {
    return !c.points.empty() && (first ? c.ends.first : c.ends.last).kind != CurveEndKind::kBorder;
  };
  for (size_t i = 0; i < curves.size(); ++i)
    for (size_t j = i + 1; j < curves.size(); ++j) {
      const ForcedCurve &a = curves[i], &b = curves[j];
      if (a.kind != CurveKind::kGrazing || b.kind != CurveKind::kGrazing || a.m != b.m) continue;
      bool met = false;  // one GG per pair of curves
      for (const bool fa : {true, false})
        for (const bool fb : {true, false}) {
          if (met || !inner(a, fa) || !inner(b, fb)) continue;
          const ForcedCurvePoint &p = fa ? a.points.front() : a.points.back(),
                                 &q = fb ? b.points.front() : b.points.back();
          if (std::hypot((p.p1 - q.p1) / pl.width1(), (p.p2 - q.p2) / pl.width2()) > tol) continue;
          ForcedCodim2 x;
          x.label = Codim2Label::kDoubleGrazing, x.on = CurveKind::kGrazing;
          x.curve = static_cast<int>(i);
          x.p1 = (p.p1 + q.p1) / 2, x.p2 = (p.p2 + q.p2) / 2;
          x.description = "GR curves " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                          " meet: two touches of x' = v at once (double grazing)";
          out->push_back(x);
          met = true;
        }
    }
}

}  // namespace stickslip
