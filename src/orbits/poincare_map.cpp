// One evaluation of a Poincare map on the one flow, its Jacobian DP and the
// orbit's Floquet data (shooting.hpp; docs/theory.md, "One shooting"); the
// multipliers themselves are floquet.cpp's.
#include <algorithm>
#include <cmath>

#include "numerics/dense_copy.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "orbits/floquet.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/switching.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip {

void Shooting::Prepare(const FlowPoint& z, const PoincareSection& p, bool variational,
                       bool column) {
  const System& s = system();
  FlowRequest& rq = request_;
  rq.t_max = z.t + (p.kind == SectionKind::kTime ? p.time : options_.max_return_time);
  rq.variational = variational;
  rq.switching = options_.switching;
  rq.parameter_column = column && variational && flow_.has_parameter_column();
  rq.stop_at_exit = p.kind == SectionKind::kStickExit ? p.returns : 0;
  rq.sections.clear();
  if (p.kind == SectionKind::kSurface) rq.sections.push_back(p.surface);
  rq.extrema.clear();
  if (options_.extrema && variational)
    for (int i = 0; i < s.tangent_dimension(); ++i) rq.extrema.push_back(i);
  rq.extrema_in_steps = options_.flow.integrator == Integrator::kTaylor;
  rq.hold_extrema = false;
  rq.max_steps = options_.max_steps;
}

namespace {
// A map without switching (a grazing curve's gap margin) follows its start's
// slip field; a start whose state sticks (a time section's mode is Filippov's
// at the state) has none to follow: a numerical outcome, not misuse.
[[gnu::cold, gnu::noinline]] bool SticksAtStart(const System& s, const FlowPoint& z,
                                                PeriodicOrbit* o) {
  o->status = OrbitStatus::kSticks;
  o->message = "the start at t = " + Num(z.t) + " is in mode " + ModeSetName(z.mode, s.contacts()) +
               ", and a map without switching (a grazing curve's gap) needs a slip start";
  return false;
}
}  // namespace

bool Shooting::Evaluate(const FlowPoint& z, const PoincareSection& p, PeriodicOrbit* o) {
  has_dpdp_ = false;
  if (!request_.switching && z.mode.AnySticks()) return SticksAtStart(system(), z, o);
  flow_.Run(z, request_, &run_);
  const FlowStatus want = p.kind == SectionKind::kTime        ? FlowStatus::kTimeLimit
                          : p.kind == SectionKind::kStickExit ? FlowStatus::kStickExit
                                                              : FlowStatus::kSection;
  const FlowStatus got = run_.status;
  if (got != want) {
    o->status = got == FlowStatus::kCancelled     ? OrbitStatus::kCancelled
                : got == FlowStatus::kTimeLimit   ? OrbitStatus::kNoReturn
                : got == FlowStatus::kContactOpen ? OrbitStatus::kContactOpen
                                                  : OrbitStatus::kIntegratorFailed;
    o->message = got == FlowStatus::kTimeLimit
                     ? std::string("no ") + Name(p.kind) +
                           " within t = " + Num(options_.max_return_time) + " of t = " + Num(z.t)
                     : (run_.message.empty() ? std::string(Name(got)) : run_.message) +
                           " (shooting from t = " + Num(z.t) + ")";
    return false;
  }
  if (p.kind != SectionKind::kTime && run_.end.mode != z.mode) {
    o->status = OrbitStatus::kModeChanged;
    o->message = "the return at t = " + Num(run_.end.t) + " is in mode " +
                 ModeSetName(run_.end.mode, system().contacts()) + ", the start in " +
                 ModeSetName(z.mode, system().contacts());
    return false;
  }
  if (request_.variational) MapJacobian(z, p);
  return true;
}

void Shooting::Residual(const FlowPoint& z, const PoincareSection& p) {
  const System& s = system();
  const int n = s.dimension(), nt = s.tangent_dimension();
  const int nu = p.kind == SectionKind::kTime ? nt : n;  // the unknowns
  r_.resize(nu);
  for (int i = 0; i < nu; ++i) r_[i] = run_.end.z[i] - z.z[i];
  if (nu > nt) r_[nt] -= 2 * M_PI * p.turns;
}

namespace {

// A contact other than the section's that sticks at the section point stays
// on its stick set when a parameter moves that set (a chain's block at belt
// speed v, continued in v): the map starts on it. True if a start moved.
bool OntoStickSets(const System& s, const PoincareSection& section, FlowPoint* at) {
  if (section.kind == SectionKind::kTime) return false;  // its mode follows the state
  bool moved = false;
  for (int c = 0; c < s.contacts(); ++c) {
    if (!at->mode.sticks(c) || (section.kind == SectionKind::kStickExit && c == section.contact))
      continue;
    const ContactVelocity h = s.Contact(c);
    const double slack = Tolerances::StickStart(h.speed, s.StaticLimit(c, at->z));
    if (std::abs(h.At(at->z.data())) <= slack) continue;  // on it, as the flow takes it
    OntoSurface(h, at->z);
    moved = true;
  }
  return moved;
}

}  // namespace

bool Shooting::Map(const FlowPoint& z, const PoincareSection& section, bool jacobian,
                   Eigen::VectorXd* residual, PeriodicOrbit* orbit) {
  Check(section);
  const System& s = system();
  if (z.z.size() != s.dimension())
    throw InvalidArgument("the point has " + std::to_string(z.z.size()) +
                          " components, the system " + std::to_string(s.dimension()));
  FlowPoint at = z;
  if (section.kind == SectionKind::kTime) at.mode = ModeOf(s, at.z);
  // A start on a stick exit within rounding of its contact's surface lies on
  // it: a corrector's rounding (h = -5e-39 for a contact speed of 0) would
  // arrive at once and close a cycle of period 1e-20 through stick (a drill
  // bit, docs/model_files.md). Farther off (a parameter moved under a fixed
  // start), the map starts where it is given.
  if (section.kind == SectionKind::kStickExit) {
    const ContactVelocity h = s.Contact(section.contact);
    if (std::abs(h.At(at.z.data())) <= Tolerances::StickStart(h.speed, 0)) OntoSurface(h, at.z);
  }
  const bool moved = OntoStickSets(s, section, &at);
  Prepare(at, section, jacobian, true);
  if (!Evaluate(at, section, orbit)) return false;
  if (jacobian) {
    Describe(at, section, orbit);
  } else {
    Residual(at, section);
    orbit->start = at;
    orbit->period = run_.end.t - at.t;
    orbit->sticks = run_.sticks, orbit->exits = run_.exits, orbit->crossings = run_.crossings;
    orbit->modes = run_.modes;
    orbit->steps = run_.steps;
  }
  orbit->status = OrbitStatus::kOk;
  if (moved) r_ += at.z - z.z;  // P(at) - z: the corrector moves the stuck components too
  *residual = r_;
  return true;
}

void Shooting::EventGradient(const PoincareSection& p) {
  const System& s = system();
  const int n = s.dimension();
  grad_.resize(n);
  if (p.kind == SectionKind::kSurface) {
    SurfaceGradient(p.surface.g, grad_);
    return;
  }
  // The exit event lambda_c - sign mu_s N_c = 0 of the stick mode it left.
  const int c = p.contact;
  ModeSet stick = run_.end.mode;
  stick.set(c, Mode::kStick);
  const double sign = run_.end.mode[c] == Mode::kSlipBelow ? 1 : -1;
  grad2_.resize(n);
  s.StickForceGradient(stick, c, run_.end.z, grad_);
  s.StaticLimitGradient(c, run_.end.z, grad2_);
  for (int i = 0; i < n; ++i) grad_[i] -= sign * grad2_[i];
}

void Shooting::MapJacobian(const FlowPoint& z, const PoincareSection& p) {
  const System& s = system();
  const int n = s.dimension(), nt = s.tangent_dimension();
  if (p.kind == SectionKind::kTime) {
    CopyInto(run_.jacobian, &dp_);
    Residual(z, p);
    MapParameterDerivative(z, p);
    return;
  }
  f0_.resize(n);
  f1_.resize(n);
  s.Field(z.mode, z.z, f0_);
  s.Field(run_.end.mode, run_.end.z, f1_);
  const Eigen::MatrixXd& J = run_.jacobian;
  full_.resize(n, n);  // [J 0; 0 I], by a loop: one small copy, not Eigen's two
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) full_(i, j) = i < nt && j < nt ? J(i, j) : (i == j ? 1.0 : 0.0);
  if (n > nt)  // the clock's column: Phi f(z0) = f(z(T)), theta' = omega
    for (int i = 0; i < nt; ++i) {
      double Jf0 = 0;
      for (int k = 0; k < nt; ++k) Jf0 += J(i, k) * f0_[k];
      full_(i, nt) = (f1_[i] - Jf0) / f0_[nt];
    }
  EventGradient(p);
  // DP = (I - f g^T / (g . f)) Phi at the arrival, by loops: Eigen's products
  // would take their temporaries from the heap.
  const double gf = grad_.dot(f1_);
  dp_.resize(n, n);
  for (int j = 0; j < n; ++j) {
    double gPhi = 0;  // (g^T Phi)_j
    for (int k = 0; k < n; ++k) gPhi += grad_[k] * full_(k, j);
    for (int i = 0; i < n; ++i) dp_(i, j) = full_(i, j) - f1_[i] * gPhi / gf;
  }
  Residual(z, p);
  MapParameterDerivative(z, p);
}

// dP/dp from the column dz/dp at fixed t: a time section adds f dT/dp (T =
// 2 pi m / omega); an event section projects as DP does, less f g_p / (g .
// f) for the event's own motion g_p (the clock's column: T d omega / dp).
void Shooting::MapParameterDerivative(const FlowPoint& z, const PoincareSection& p) {
  has_dpdp_ = run_.has_dzdp;
  if (!has_dpdp_) return;
  const System& s = system();
  const int n = s.dimension(), nt = s.tangent_dimension();
  const int j = *flow_.parameter();
  const double T = run_.end.t - z.t;
  const double drate = n > nt ? s.ClockRateDerivative(0, j) : 0.0;
  if (p.kind == SectionKind::kTime) {
    dpdp_ = run_.dzdp;
    if (p.turns < 1 || drate == 0) return;
    f1_.resize(n);
    s.Field(run_.end.mode, run_.end.z, f1_);
    dpdp_ -= f1_.head(nt) * (T / f1_[nt] * drate);
    return;
  }
  // An event section: f1_ and grad_ are MapJacobian's, at the arrival.
  col_.resize(n);
  col_.head(nt) = run_.dzdp;
  if (n > nt) col_[nt] = T * drate;
  double g_p = 0;
  if (p.kind == SectionKind::kStickExit) {
    ModeSet stick = run_.end.mode;
    stick.set(p.contact, Mode::kStick);
    const int sign = run_.end.mode[p.contact] == Mode::kSlipBelow ? 1 : -1;
    g_p = ExitParameterDerivative(s, stick, p.contact, sign, j, run_.end.z);
  }
  dpdp_ = col_ - f1_ * ((grad_.dot(col_) + g_p) / grad_.dot(f1_));
}

void Shooting::OntoSection(const PoincareSection& p, FlowPoint* z) const {
  const System& s = system();
  if (p.kind == SectionKind::kTime) {
    // A return in stick stays on its surface: DP's rows there are 0.
    for (int c = 0; c < s.contacts(); ++c)
      if (run_.end.mode.sticks(c)) OntoSurface(s.Contact(c), z->z);
    z->mode = ModeOf(s, z->z);
    return;
  }
  if (p.kind == SectionKind::kSurface) {
    OntoSurface(p.surface.g, z->z);
    return;
  }
  const int c = p.contact;
  OntoSurface(s.Contact(c), z->z);
  ModeSet stick = z->mode;
  stick.set(c, Mode::kStick);
  const double sign = z->mode[c] == Mode::kSlipBelow ? 1 : -1;
  s.ProjectOnExit(stick, c, sign * s.StaticLimit(c, z->z), z->z);
}

void Shooting::Describe(const FlowPoint& z, const PoincareSection& p, PeriodicOrbit* o) {
  o->start.t = z.t;  // one out-of-line copy per vector (dense_copy.hpp)
  CopyInto(z.z, &o->start.z);
  o->start.mode = z.mode;
  o->period = run_.end.t - z.t;
  CopyInto(dp_, &o->monodromy);
  if (p.kind == SectionKind::kTime) {
    o->multipliers = floquet_detail::Eigenvalues(dp_);
  } else {
    const int n = static_cast<int>(dp_.rows());
    floquet_detail::Deflate(dp_, grad_, &hdph_, &house_, &hw_);
    o->multipliers = floquet_detail::Eigenvalues(hdph_.bottomRightCorner(n - 1, n - 1));
  }
  o->stable = true;
  for (const auto& mu : o->multipliers) o->stable = o->stable && std::abs(mu) < 1;
  o->sticks = run_.sticks;
  o->exits = run_.exits;
  o->crossings = run_.crossings;
  o->modes = run_.modes;
  CopyInto(run_.lo, &o->lo);
  CopyInto(run_.hi, &o->hi);
  o->steps = run_.steps;
}

}  // namespace stickslip
