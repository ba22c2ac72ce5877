// The fixed points of a Poincare map as a PalcProblem (orbit_problem.hpp).
#include "orbit_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip::orbit_detail {

using Eigen::MatrixXd;
using Eigen::VectorXd;

OrbitProblem::OrbitProblem(const System& system, int parameter, const FlowPoint& start,
                           const PoincareSection& section, const OrbitBranchOptions& o)
    : system_(system.Clone()),
      j_(parameter),
      nu_(section.kind == SectionKind::kTime ? system.tangent_dimension() : system.dimension()),
      start_(start),
      section_(section),
      o_(o),
      shooting_(system, o.shooting),
      last_u_(VectorXd::Zero(nu_ + 1)) {
  // dF/dp by the flow's parameter column where the system has one (Taylor).
  if (system.SupportsParameterColumn(parameter)) shooting_.set_parameter_column(parameter);
}

FlowPoint OrbitProblem::PointAt(const VectorXd& u) const {
  FlowPoint z = start_;
  z.z.head(nu_) = u.head(nu_);
  return z;
}

VectorXd OrbitProblem::Unknowns(const FlowPoint& z, double p) const {
  VectorXd u(nu_ + 1);
  u.head(nu_) = z.z.head(nu_);
  u[nu_] = p;
  return u;
}

PoincareSection SectionFor(const System& s, const PoincareSection& section, const VectorXd& z) {
  if (section.kind == SectionKind::kTime && section.turns >= 1 && s.clocks() == 1)
    return PoincareSection::Stroboscopic(s, z, section.turns);
  return section;
}

std::vector<bool> Displacements(const System& s) {
  const int nt = s.tangent_dimension();
  std::vector<bool> out(nt, true);
  for (int i = 0; i < nt; ++i)
    if (const int j = s.DerivativeOf(i); j >= 0 && j < nt) out[j] = false;
  return out;
}

PoincareSection OrbitProblem::SectionAt(const FlowPoint& z) const {
  return SectionFor(*system_, section_, z.z);
}

std::string OrbitProblem::DomainError(const VectorXd& u) const {
  if (!u.allFinite()) return "a point that is not finite";
  const double old = system_->ParameterValue(j_);
  system_->SetParameterValue(j_, u[nu_]);
  std::string e = system_->ValidationError();
  system_->SetParameterValue(j_, old);
  const int nt = std::min(nu_, system_->tangent_dimension());
  const double bound = 2 * o_.max_amplitude;  // rows stop at max_amplitude first
  const double size = u.head(nt).cwiseAbs().maxCoeff();
  if (e.empty() && !(size <= bound)) {  // "|x| or |x'| = 2001 beyond max_amplitude"
    for (int i = 0; i < nt; ++i) e += (i ? " or |" : "|") + system_->StateName(i) + "|";
    e += " = " + Num(size) + " beyond max_amplitude";
  }
  return e;
}

void OrbitProblem::BoundReturn() {
  const double full = o_.shooting.max_return_time;
  shooting_.set_max_return_time(
      period_ > 0 ? std::min(full, Tolerances::kBranchReturnPeriods * period_) : full);
}

void OrbitProblem::Returned(double period) {
  // The longest return seen: a trial point's short return never tightens the
  // bound below a period the branch has had.
  if (period > 0 && std::isfinite(period)) period_ = std::max(period_, period);
}

bool OrbitProblem::MapAt(double p, const FlowPoint& z, bool jacobian, VectorXd* r, PeriodicOrbit* o,
                         std::string* why) {
  system_->SetParameterValue(j_, p);
  *why = system_->ValidationError();
  if (!why->empty()) return false;
  shooting_.set_system(*system_);
  BoundReturn();
  if (shooting_.Map(z, SectionAt(z), jacobian, r, o)) {
    Returned(o->period);
    return true;
  }
  last_failure_ = o->status;
  opened_ = opened_ || o->status == OrbitStatus::kContactOpen;
  *why = o->message;
  return false;
}

bool OrbitProblem::FindAt(double p, const FlowPoint& z, std::string* why) {
  system_->SetParameterValue(j_, p);
  *why = system_->ValidationError();
  if (!why->empty()) return false;
  shooting_.set_system(*system_);
  BoundReturn();
  const PeriodicOrbit o = shooting_.Find(z, SectionAt(z));
  if (!o.ok()) {
    opened_ = opened_ || o.status == OrbitStatus::kContactOpen;
    *why = o.message;
    return false;
  }
  last_ = o;
  Returned(o.period);
  last_u_ = Unknowns(o.start, p);
  jac_.resize(0, 0);  // Newton's, not kept
  *why = DomainError(last_u_);
  return why->empty();
}

const System* OrbitProblem::Switches(const OrbitRow& r, std::vector<FlowSwitch>* out,
                                     const FlowObserver& steps, bool* reached) {
  if (reached) *reached = false;
  system_->SetParameterValue(j_, r.p);
  if (!system_->ValidationError().empty()) return nullptr;
  shooting_.set_system(*system_);
  FlowRequest rq;
  rq.t_max = r.start.t + r.period;
  rq.switches = out;
  rq.step_observer = steps;
  rq.switching = shooting_.options().switching;
  out->clear();
  const FlowRun run = shooting_.flow().Run(StartOf(r), rq);  // a failed run keeps the switches
  if (reached) *reached = run.status == FlowStatus::kTimeLimit;
  return system_.get();
}

double OrbitProblem::SlipGap(const VectorXd& u) const {
  const double old = system_->ParameterValue(j_);
  system_->SetParameterValue(j_, u[nu_]);
  const FlowPoint z = PointAt(u);
  double gap = std::numeric_limits<double>::infinity();
  for (int i = 0; i < system_->contacts(); ++i)
    gap = std::min(gap, std::abs(system_->Contact(i).At(z.z.data())));
  system_->SetParameterValue(j_, old);
  return gap;
}

// A row's section point as a start of the flow: on a time section its mode
// is Filippov's at the state, as the shooting takes it (one stuck on the
// surface there); an event section's point keeps its mode.
FlowPoint OrbitProblem::StartOf(const OrbitRow& r) const {
  FlowPoint z = r.start;
  if (section_.kind == SectionKind::kTime) z.mode = ModeOf(*system_, z.z);
  return z;
}

bool OrbitProblem::Settle(double p, const OrbitRow& r, int periods, FlowPoint* out) {
  if (section_.kind != SectionKind::kTime) return false;
  system_->SetParameterValue(j_, p);
  if (!system_->ValidationError().empty()) return false;
  shooting_.set_system(*system_);
  FlowRequest rq;
  rq.t_max = r.start.t + periods * SectionAt(r.start).time;
  const FlowRun run = shooting_.flow().Run(StartOf(r), rq);
  if (!run.ok()) return false;
  *out = r.start;
  const int nt = system_->tangent_dimension();
  out->z.head(nt) = run.end.z.head(nt);
  return true;
}

bool OrbitProblem::Counts(OrbitRow* r) {
  system_->SetParameterValue(j_, r->p);
  if (!system_->ValidationError().empty()) return false;
  shooting_.set_system(*system_);
  FlowRequest rq;
  rq.t_max = r->start.t + r->period;
  const FlowRun run = shooting_.flow().Run(StartOf(*r), rq);
  if (!run.ok() || run.status == FlowStatus::kContactOpen) return false;
  r->sticks = run.sticks, r->exits = run.exits, r->crossings = run.crossings;
  return true;
}

bool OrbitProblem::Evaluate(const VectorXd& u, VectorXd* f, MatrixXd* jac, std::string* why) {
  *why = DomainError(u);
  if (!why->empty()) return false;
  const double p = u[nu_];
  const FlowPoint z = PointAt(u);
  if (!MapAt(p, z, true, &r_, &last_, why)) return false;
  last_u_ = u;
  *f = r_;
  jac->resize(nu_, nu_ + 1);
  jac->leftCols(nu_) = last_.monodromy - MatrixXd::Identity(nu_, nu_);
  const bool column = shooting_.has_parameter_derivative();
  if (column) jac->col(nu_) = shooting_.parameter_derivative();
  const bool ok = column || Difference(p, z, jac, why);
  system_->SetParameterValue(j_, p);
  jac_ = ok ? *jac : MatrixXd();
  return ok;
}

bool OrbitProblem::Polish(const VectorXd* w, VectorXd* u, bool same_counts) {
  if (jac_.rows() != nu_ || last_u_ != *u) return false;
  VectorXd du = VectorXd::Zero(nu_ + 1);
  if (w) {
    MatrixXd a(nu_ + 1, nu_ + 1);
    a.topRows(nu_) = jac_;
    a.row(nu_) = w->transpose();
    VectorXd rhs = VectorXd::Zero(nu_ + 1);
    rhs.head(nu_) = -r_;
    du = a.partialPivLu().solve(rhs);
  } else {  // p held exactly
    du.head(nu_) = jac_.leftCols(nu_).partialPivLu().solve(-r_);
  }
  const VectorXd v = *u + du;
  if (!du.allFinite() || !DomainError(v).empty()) return false;
  PeriodicOrbit o;
  VectorXd r;
  std::string why;
  const bool opened = opened_;  // a failed polish is no contact's opening
  ++polishes_;
  const bool ok = MapAt(v[nu_], PointAt(v), true, &r, &o, &why) &&
                  r.lpNorm<Eigen::Infinity>() <= r_.lpNorm<Eigen::Infinity>() &&
                  (!same_counts || (o.sticks == last_.sticks && o.crossings == last_.crossings));
  system_->SetParameterValue(j_, ok ? v[nu_] : last_u_[nu_]);  // the row's p
  opened_ = opened;
  if (!ok) return false;
  last_ = o, r_ = r, last_u_ = v, *u = v;
  jac_.resize(0, 0);  // not v's
  return true;
}

// dF/dp: central differences, step ~ cbrt(eps) relative (truncation and
// rounding balanced). Where the map jumps within the step (a stick phase of
// finite length born or lost), the side with other events gives a slope of
// jump / step: then the side that keeps them (issue 20). At a kink (slopes of
// one size) the central difference stays: it turns the branch's corners.
bool OrbitProblem::Difference(double p, const FlowPoint& z, MatrixXd* jac, std::string* why) {
  const double d = Tolerances::kBranchDifference * std::max(1.0, std::abs(p));
  std::string why_up, why_down;
  const bool up = MapAt(p + d, z, false, &rp_, &plus_, &why_up);
  const bool down = MapAt(p - d, z, false, &rm_, &minus_, &why_down);
  if (!up && !down) {
    *why = why_up, last_failure_ = plus_.status;  // the failure *why tells
    return false;
  }
  if (!up || !down) {  // one-sided: beyond the domain's edge, or no return on one side
    if (!MapAt(p, z, false, up ? &rm_ : &rp_, up ? &minus_ : &plus_, why)) return false;
    jac->col(nu_) = (rp_ - rm_) / (up ? (p + d) - p : p - (p - d));
    return true;
  }
  const double hp = (p + d) - p, hm = p - (p - d);  // the steps as rounded
  jac->col(nu_) = (rp_ - rm_) / ((p + d) - (p - d));
  auto same = [&](const PeriodicOrbit& o) {
    return o.sticks == last_.sticks && o.exits == last_.exits && o.crossings == last_.crossings;
  };
  if (same(plus_) == same(minus_)) return true;
  const VectorXd sp = (rp_ - r_) / hp, sm = (r_ - rm_) / hm;
  const VectorXd& keep = same(plus_) ? sp : sm;
  const double gap = (sp - sm).lpNorm<Eigen::Infinity>();
  if (gap > Tolerances::kJumpSlopeRatio * (1 + keep.lpNorm<Eigen::Infinity>()))
    jac->col(nu_) = keep;
  return true;
}

OrbitRow RowOf(const PeriodicOrbit& o, double p) {
  OrbitRow r;
  r.p = p;
  r.start = o.start;
  r.period = o.period;
  r.sticks = o.sticks, r.exits = o.exits, r.crossings = o.crossings;
  r.lo = o.lo, r.hi = o.hi;
  r.multipliers = o.multipliers;
  r.stable = o.stable;
  return r;
}

OrbitRow OrbitProblem::Row() const { return RowOf(last_, last_u_[nu_]); }

double RowTest(const OrbitRow& r, int i) {
  std::complex<double> prod = 1;
  const auto& mu = r.multipliers;
  if (i < 2) {
    for (const auto& m : mu) prod *= i == 0 ? m - 1.0 : m + 1.0;
  } else {
    for (std::size_t a = 0; a < mu.size(); ++a)
      for (std::size_t b = a + 1; b < mu.size(); ++b) prod *= mu[a] * mu[b] - 1.0;
  }
  return prod.real();
}

bool TorusPair(const OrbitRow& r, double tol) {
  for (const auto& m : r.multipliers)
    if (std::abs(m.imag()) > tol * std::abs(m) && std::abs(std::abs(m) - 1) <= tol) return true;
  return false;
}

double MultiplierMove(const OrbitRow& a, const OrbitRow& b) {
  auto one_way = [](const OrbitRow& x, const OrbitRow& y) {
    double worst = 0;
    for (const auto& m : x.multipliers) {
      double best = INFINITY;
      for (const auto& n : y.multipliers) best = std::min(best, std::abs(m - n));
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

bool SameStructure(const OrbitRow& a, const OrbitRow& b) {
  // Not the exits: over a period they equal the sticks but for a stick phase
  // that ends on the section itself, counted on one side only.
  return a.sticks == b.sticks && a.crossings == b.crossings;
}

}  // namespace stickslip::orbit_detail
