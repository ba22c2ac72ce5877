// Two-parameter curves of periodic orbits (chart/orbit_curve.hpp).
#include "chart/orbit_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

int TestIndex(CurveKind kind) {
  switch (kind) {
    case CurveKind::kFold:
      return 0;
    case CurveKind::kPeriodDoubling:
      return 1;
    case CurveKind::kTorus:
      return 2;
    case CurveKind::kGrazing:
      return 3;
    default:
      throw InvalidArgument(std::string("a curve of periodic orbits is LP, PD, NS or GR, not ") +
                            Name(kind));
  }
}

// min over the arrivals on a surface of |lambda_i| - mu_s N_i (the header's
// GR), NaN without one.
double ArrivalMargin(const System& s, const std::vector<FlowSwitch>& switches) {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (const FlowSwitch& e : switches) {
    if (e.kind != SwitchKind::kCrossing && e.kind != SwitchKind::kStickIn) continue;
    ModeSet m = e.before;
    m.set(e.contact, Mode::kStick);
    const double g = std::abs(s.StickForce(m, e.contact, e.z)) - s.StaticLimit(e.contact, e.z);
    if (!(g >= best)) best = g;
  }
  return best;
}

// min over the contacts of the gap of h_i to 0 on the side of the orbit's
// start (the header's GR), from the extremes of the tangent components; NaN
// for a contact whose velocity is no single component.
double SurfaceGap(const System& s, const OrbitRow& r) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < s.contacts(); ++i) {
    const ContactVelocity c = s.Contact(i);
    const int k = c.terms[0].index;
    if (c.size != 1 || k >= r.lo.size() || k >= r.hi.size())
      return std::numeric_limits<double>::quiet_NaN();
    const double w = c.terms[0].weight;
    const double a = w * r.lo[k] - c.speed, b = w * r.hi[k] - c.speed;
    const double h_min = std::min(a, b), h_max = std::max(a, b);
    best = std::min(best, c.At(r.start.z.data()) < 0 ? -h_max : h_min);
  }
  return best;
}

OrbitBranchOptions WithMargin(OrbitBranchOptions o, CurveKind kind, GrazingMargin margin) {
  if (kind == CurveKind::kGrazing && margin == GrazingMargin::kGap) o.shooting.switching = false;
  return o;
}

}  // namespace

OrbitCurveProblem::OrbitCurveProblem(const System& system, int p1, int p2, const FlowPoint& start,
                                     const PoincareSection& section, CurveKind kind,
                                     const OrbitBranchOptions& options, GrazingMargin margin)
    : options_(WithMargin(options, kind, margin)),
      orbit_(system, p1, start, section, options_),
      p2_(p2),
      nu_(orbit_.parameter_index()),
      kind_(kind),
      margin_(margin) {
  TestIndex(kind);  // throws for HB
  if (options_.palc.cancelled) orbit_.shooting().flow().set_cancel(options_.palc.cancelled);
}

double OrbitCurveProblem::Test(const OrbitRow& r) {
  if (kind_ != CurveKind::kGrazing) return orbit_detail::RowTest(r, TestIndex(kind_));
  if (margin_ == GrazingMargin::kGap) return SurfaceGap(orbit_.SystemAt(r.p), r);
  const System* s = orbit_.Switches(r, &switches_);
  return s ? ArrivalMargin(*s, switches_) : std::numeric_limits<double>::quiet_NaN();
}

VectorXd OrbitCurveProblem::Unknowns(const OrbitRow& row, double p2) const {
  VectorXd u(nu_ + 2);
  u.head(nu_ + 1) = orbit_.Unknowns(row.start, row.p);
  u[nu_ + 1] = p2;
  return u;
}

bool OrbitCurveProblem::TestOf(const OrbitRow& r, double* test, std::string* why) {
  *test = Test(r);
  if (std::isfinite(*test)) return true;
  *why = margin_ == GrazingMargin::kGap
             ? "GR: a contact's relative velocity is not one component (no gap from extremes)"
             : "GR: the orbit arrives on no contact's surface (no crossing, no stick entry)";
  return false;
}

std::string OrbitCurveProblem::DomainError(const VectorXd& u) const {
  if (!u.allFinite()) return "a point that is not finite";
  orbit_.set_held(p2_, u[nu_ + 1]);
  return orbit_.DomainError(u.head(nu_ + 1));
}

bool OrbitCurveProblem::At(const VectorXd& u, VectorXd* r, double* test, std::string* why) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  PeriodicOrbit o;
  if (!orbit_.MapOf(u.head(nu_ + 1), true, r, &o, why)) return false;
  return TestOf(orbit_detail::RowOf(o, u[nu_]), test, why);
}

bool OrbitCurveProblem::ResidualsAt(const VectorXd& u, Residuals* out, std::string* why) {
  VectorXd r;
  double test = 0;
  if (!At(u, &r, &test, why)) return false;
  out->map = r.lpNorm<Eigen::Infinity>(), out->test = std::abs(test);
  const bool last = u.size() == last_u_.size() && u == last_u_;
  out->distance = last ? out->test / std::max(1.0, test_gradient_) : out->test;
  return std::isfinite(out->map) && std::isfinite(out->test);
}

bool OrbitCurveProblem::Sample(const VectorXd& u, OrbitRow* row, double* test, std::string* why,
                               std::vector<ModeSet>* modes) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  PeriodicOrbit o;
  VectorXd r;
  if (!orbit_.MapOf(u.head(nu_ + 1), true, &r, &o, why)) return false;
  *row = orbit_detail::RowOf(o, u[nu_]);
  if (modes) *modes = o.modes;
  return TestOf(*row, test, why);
}

bool OrbitCurveProblem::Rephase(const VectorXd& u, FlowPoint* start, std::string* why) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  PeriodicOrbit o;
  VectorXd r;
  if (!orbit_.MapOf(u.head(nu_ + 1), true, &r, &o, why)) return false;
  const OrbitRow row = orbit_detail::RowOf(o, u[nu_]);
  std::vector<FlowPoint> steps{row.start};
  std::vector<FlowSwitch> switches;
  const System* s =
      orbit_.Switches(row, &switches, [&steps](double t, const double* z, const ModeSet& m) {
        steps.push_back({t, Eigen::Map<const VectorXd>(z, steps.front().z.size()), m});
      });
  if (!s) return *why = "the system is invalid at the curve's point", false;
  double best = -1;
  for (const FlowPoint& p : steps) {
    if (p.mode.AnySticks()) continue;
    double gap = std::numeric_limits<double>::infinity();
    for (int i = 0; i < s->contacts(); ++i)
      gap = std::min(gap, std::abs(s->Contact(i).At(p.z.data())));
    if (gap > best) best = gap, *start = p;
  }
  if (best < 0) return *why = "the orbit sticks at every step end", false;
  for (int i = s->tangent_dimension(); i < s->dimension(); ++i) {
    start->z[i] = std::fmod(start->z[i], 2 * M_PI);
    if (start->z[i] < 0) start->z[i] += 2 * M_PI;
  }
  return true;
}

int OrbitCurveProblem::ShorterPeriod(const OrbitRow& r) {
  const PoincareSection& sec = orbit_.section();
  if (sec.kind != SectionKind::kTime || sec.turns <= 1) return 0;
  const int m = sec.turns, nt = orbit_.SystemAt(r.p).tangent_dimension();
  for (int d = 1; d < m; ++d) {
    if (m % d != 0) continue;
    OrbitRow part = r;
    part.period = r.period * d / m;
    VectorXd end;
    std::vector<FlowSwitch> switches;
    bool reached = false;
    const FlowObserver last = [&end, nt](double, const double* z, const ModeSet&) {
      end = Eigen::Map<const VectorXd>(z, nt);
    };
    orbit_.Switches(part, &switches, last, &reached);
    if (reached && end.size() == nt &&
        (end - r.start.z.head(nt)).lpNorm<Eigen::Infinity>() < Tolerances().curve_lower_period)
      return m / d;
  }
  return 0;
}

bool OrbitCurveProblem::Evaluate(const VectorXd& u, VectorXd* f, MatrixXd* jac, std::string* why) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  VectorXd f0;
  MatrixXd j0;
  if (!orbit_.Evaluate(u.head(nu_ + 1), &f0, &j0, why)) {
    last_failure_ = *why, last_status_ = orbit_.last_failure();
    return false;
  }
  f->resize(nu_ + 1);
  f->head(nu_) = f0;
  if (!TestOf(orbit_.Row(), &(*f)[nu_], why)) return false;
  jac->setZero(nu_ + 1, nu_ + 2);
  jac->topLeftCorner(nu_, nu_ + 1) = j0;
  // The test's row and dF/dp2: central differences (one-sided where one
  // side fails: the domain's edge).
  VectorXd rp, rm;
  for (int i = 0; i < nu_ + 2; ++i) {
    const double d = Tolerances::kBranchDifference * std::max(1.0, std::abs(u[i]));
    VectorXd up = u, dn = u;
    up[i] += d, dn[i] -= d;
    double tp = 0, tm = 0;
    std::string wp, wm;
    const bool okp = At(up, &rp, &tp, &wp), okm = At(dn, &rm, &tm, &wm);
    if (!okp && !okm) {
      *why = "the test function's derivative: " + wp;
      DomainError(u);  // p2 back to u's
      return false;
    }
    if (!okp) up = u, tp = (*f)[nu_], rp = f0;
    if (!okm) dn = u, tm = (*f)[nu_], rm = f0;
    const double h = up[i] - dn[i];
    (*jac)(nu_, i) = (tp - tm) / h;
    if (i == nu_ + 1) jac->col(i).head(nu_) = (rp - rm) / h;
  }
  DomainError(u);  // the held p2 back to u's
  // The test's gradient at this point, for Residual (the corrector accepts
  // its last evaluated point: where the test is steep, its value there is
  // the update's size times the gradient).
  last_u_ = u;
  test_gradient_ = jac->row(nu_).lpNorm<Eigen::Infinity>();
  return jac->allFinite();
}

}  // namespace stickslip
