// The switches of the flow (engine.hpp): Filippov's rule at an arrival on
// h_i = 0 (stick while |lambda_i| <= mu_s N_i, else slip the way lambda_i
// points), the exit of a stick phase at its static limit, and the saltation
// matrix of each (Leine & Nijmeijer 2004, section 7.3; di Bernardo et al.
// 2008, section 2.5): S = I + (f+ - f-) grad g^T / (grad g . f-).
#include "stickslip/flow/switching.hpp"

#include <algorithm>
#include <cmath>

#include "flow/engine.hpp"
#include "numerics/numbers.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

ModeSet ModeAfterArrival(const System& s, const ModeSet& before, int c, ConstState z) {
  ModeSet stick = before;
  stick.set(c, Mode::kStick);
  const double lambda = s.StickForce(stick, c, z);
  if (std::abs(lambda) <= s.StaticLimit(c, z)) return stick;
  ModeSet after = before;
  after.set(c, lambda > 0 ? Mode::kSlipBelow : Mode::kSlipAbove);
  return after;
}

double ExitParameterDerivative(const System& s, const ModeSet& stick, int c, int sign, int j,
                               ConstState z) {
  const ContactSensitivity d = s.ContactParameterDerivative(stick, c, j, z);
  return d.stick_force - sign * d.static_limit;
}

void ContactGradient(const System& s, int c, StateOut grad) { SurfaceGradient(s.Contact(c), grad); }

void SurfaceGradient(const ContactVelocity& h, StateOut grad) {
  grad.setZero();
  for (int t = 0; t < h.size; ++t) grad[h.terms[t].index] += h.terms[t].weight;
}

void OntoSurface(const ContactVelocity& h, StateOut z) {
  if (h.size == 1 && (h.terms[0].weight == 1 || h.terms[0].weight == -1)) {
    z[h.terms[0].index] = h.terms[0].weight * h.speed;
    return;
  }
  double norm2 = 0;
  for (int t = 0; t < h.size; ++t) norm2 += h.terms[t].weight * h.terms[t].weight;
  const double g = h.At(z.data());
  for (int t = 0; t < h.size; ++t) z[h.terms[t].index] -= g * h.terms[t].weight / norm2;
  // The projection leaves h at rounding, on either side: an arrival that
  // crossed would fire again at every segment start (a run of steps of one
  // ulp). The component of the largest weight is moved, by up to 8 ulps,
  // toward h = 0, until h is 0 or has changed sign.
  int big = 0;
  for (int t = 1; t < h.size; ++t)
    if (std::abs(h.terms[t].weight) > std::abs(h.terms[big].weight)) big = t;
  double& zb = z[h.terms[big].index];
  double r = h.At(z.data());
  const bool positive = r > 0;
  const double away = positive == (h.terms[big].weight > 0) ? -HUGE_VAL : HUGE_VAL;
  for (int ulp = 0; ulp < 8 && r != 0 && (r > 0) == positive; ++ulp) {
    zb = std::nextafter(zb, away);
    r = h.At(z.data());
  }
}

void OntoStickSurfaces(const System& s, const ModeSet& m, StateOut z) {
  for (int i = 0; i < s.contacts(); ++i)
    if (m[i] == Mode::kStick) OntoSurface(s.Contact(i), z);
}

bool Saltation(const System& s, const ModeSet& before, const ModeSet& after, ConstState z,
               ConstState grad, MatrixOut S) {
  const int n = s.dimension(), nt = s.tangent_dimension();
  Eigen::VectorXd fb(n), fa(n);
  s.Field(before, z, fb);
  s.Field(after, z, fa);
  S.setIdentity();
  const double den = grad.dot(fb);
  if (den == 0) return false;
  S += ((fa - fb).head(nt) / den) * grad.head(nt).transpose();
  return true;
}

}  // namespace stickslip

namespace stickslip::flow_detail {

bool Engine::Switch(const std::vector<int>& roots) {
  // Contact events first (several at one instant are a normal outcome: one
  // consistent mode for all, SwitchAtOnce); a section only ends the run
  // when no contact switched there.
  int section = -1;
  bool contact = false;
  for (int i = 0; i < static_cast<int>(roots.size()); ++i) {
    if (roots[i] == 0) continue;
    if (cur_->roles[i].kind == FunctionRole::kOpen) {  // the run stops there
      out_->opened = cur_->roles[i].index;
      return Fail(FlowStatus::kContactOpen, "contact " + std::to_string(out_->opened) +
                                                " opens (normal force 0)" + Place(t_, z_.data()));
    }
    if (cur_->roles[i].kind == FunctionRole::kSection) {
      if (section < 0) section = cur_->roles[i].index;
    } else if (cur_->roles[i].kind != FunctionRole::kExtremum) {
      contact = true;
    }
  }
  if (!contact) {
    out_->section = section;
    // On the section exactly where one component carries it (x' = 0).
    const Section& sec = rq_->sections[section];
    if (!sec.derivative) OntoSurface(sec.g, z_);
    return Done(FlowStatus::kSection);
  }
  const int exits_before = out_->exits;
  if (k_ == 1) {
    for (int i = 0; i < static_cast<int>(roots.size()); ++i) {
      if (roots[i] == 0) continue;
      if (cur_->roles[i].kind == FunctionRole::kArrival && !Arrive(0)) return false;
      if (cur_->roles[i].kind == FunctionRole::kExit) Exit(0, cur_->roles[i].sign, mode_);
    }
  } else if (!SwitchAtOnce(roots)) {
    return false;
  }
  // The requested exit ends the run after every switch of its instant.
  if (rq_->stop_at_exit > 0 && out_->exits >= rq_->stop_at_exit && out_->exits > exits_before)
    return Done(FlowStatus::kStickExit);
  if (rq_->stop_after_switches > 0 && out_->switches >= rq_->stop_after_switches)
    return Done(FlowStatus::kSwitchCount);
  return true;
}

// Several contacts (switching.hpp, ConsistentMode): the exits of the instant
// release their contacts, then the arriving ones and any sticking contact
// the new mode pushes past its limit take the one consistent mode; each
// change is recorded, with its saltation, in contact order.
bool Engine::SwitchAtOnce(const std::vector<int>& roots) {
  std::vector<int>& arrivals = arrivals_;
  arrivals.clear();
  const ModeSet detected = mode_;  // the mode whose events fired
  for (int c = 0; c < k_; ++c)
    for (int i = 0; i < static_cast<int>(roots.size()); ++i) {
      if (roots[i] == 0 || cur_->roles[i].index != c) continue;
      if (cur_->roles[i].kind == FunctionRole::kArrival) arrivals.push_back(c);
      if (cur_->roles[i].kind == FunctionRole::kExit) Exit(c, cur_->roles[i].sign, detected);
    }
  if (!AlsoArriving(detected, &arrivals)) return false;
  for (int c : arrivals) OntoSurface(contacts_[c], z_);
  const ModeChoiceResult r = ConsistentMode(*s_, mode_, arrivals, z_);
  if (!Resolved(r.choice)) {
    const FlowStatus st = r.choice == ModeChoice::kAmbiguous      ? FlowStatus::kAmbiguousMode
                          : r.choice == ModeChoice::kInconsistent ? FlowStatus::kInconsistentMode
                                                                  : FlowStatus::kTooManyAtOnce;
    std::string what = Name(r.choice);
    what += " mode of " + std::to_string(r.candidates) + " contacts switching at once (" +
            (r.choice == ModeChoice::kTooMany ? std::string("pivoting cycled")
                                              : std::to_string(r.consistent) + " consistent") +
            ")";
    return Fail(st, what + Place(t_, z_.data()));
  }
  if (rq_->stop_at_stick)
    for (int c : arrivals)
      if (r.mode.sticks(c)) return Done(FlowStatus::kStick);
  for (int c = 0; c < k_; ++c) {
    const bool arrival = std::binary_search(arrivals.begin(), arrivals.end(), c);
    if (!arrival && r.mode[c] == mode_[c]) continue;
    const ModeSet before = mode_;
    ModeSet after = before;
    after.set(c, r.mode[c]);
    if (!arrival) {  // released by the others' switch: no event surface of its own
      mode_ = after;
      ++out_->exits;
      Record(SwitchKind::kStickOut, c, before, after);
      continue;
    }
    if (after == before) {
      ++out_->touches;
      Record(SwitchKind::kTouch, c, before, after);
      continue;
    }
    grad_.resize(n_);
    ContactGradient(*s_, c, grad_);
    Saltation(before, after, grad_, ArrivalDp(c));
    mode_ = after;
    const bool stick = after.sticks(c);
    ++(stick ? out_->sticks : out_->crossings);
    Record(stick ? SwitchKind::kStickIn : SwitchKind::kCrossing, c, before, after);
  }
  return true;
}

// A slipping contact on or past its surface at this instant by the rounding
// of its root (which fell just after the first one's in the step and would
// be lost with the segment: two blocks arriving in step), or within rounding
// of it and approaching faster than rounding, arrives too, unless it switched
// at this instant already. Farther past, an event was lost: the run fails
// there (false).
bool Engine::AlsoArriving(const ModeSet& detected, std::vector<int>* arrivals) {
  bool field = false;
  for (int c = 0; c < k_; ++c) {
    if (detected[c] == Mode::kStick || mode_[c] == Mode::kStick) continue;
    if (std::find(arrivals->begin(), arrivals->end(), c) != arrivals->end()) continue;
    if (std::abs(t_ - switched_at_[c]) <= Tolerances::RootRepeat(t_)) continue;
    const ContactVelocity& h = contacts_[c];
    const double side = mode_[c] == Mode::kSlipBelow ? 1 : -1;  // below: h < 0
    const double g = side * h.At(z_.data()), band = Tolerances::StickStart(h.speed, 0);
    if (g > Tolerances::kLostEventBand * band)
      return Fail(FlowStatus::kIntegratorFailed, "contact " + std::to_string(c) +
                                                     " is past its surface by " + Num(g) +
                                                     " (an event lost)" + Place(t_, z_.data()));
    if (g < -band) continue;
    if (g < 0) {  // within rounding: only if approaching
      if (!field) f_before_.resize(n_), s_->Field(mode_, z_, f_before_), field = true;
      double dh = 0;
      for (int t = 0; t < h.size; ++t) dh += h.terms[t].weight * f_before_[h.terms[t].index];
      if (!(side * dh > band)) continue;
    }
    arrivals->push_back(c);
  }
  std::sort(arrivals->begin(), arrivals->end());
  return true;
}

bool Engine::Arrive(int c) {
  const ModeSet before = mode_;
  OntoSurface(contacts_[c], z_);
  const ModeSet next = ModeAfterArrival(*s_, before, c, z_);
  if (variational_) {  // the saltation's gradient (the contact's weights, as ContactGradient)
    grad_.resize(n_);
    SurfaceGradient(contacts_[c], grad_);
  }
  if (next[c] == Mode::kStick) {
    const ModeSet& stick = next;
    if (rq_->stop_at_stick) return Done(FlowStatus::kStick);
    Saltation(before, stick, grad_, ArrivalDp(c));
    mode_ = stick;
    ++out_->sticks;
    Record(SwitchKind::kStickIn, c, before, stick);
    return true;
  }
  const ModeSet& after = next;
  if (after == before) {  // a touch: the flow turns back on its side
    ++out_->touches;
    Record(SwitchKind::kTouch, c, before, after);
    return true;
  }
  Saltation(before, after, grad_, ArrivalDp(c));
  mode_ = after;
  ++out_->crossings;
  Record(SwitchKind::kCrossing, c, before, after);
  return true;
}

void Engine::Exit(int c, int sign, const ModeSet& detected) {
  const ModeSet before = mode_;
  ModeSet after = before;
  after.set(c, sign > 0 ? Mode::kSlipBelow : Mode::kSlipAbove);
  // On the band's edge exactly: the stick line there differs by the root's
  // error; kept, it left x'' of that size and either sign at the start of
  // slip (docs/theory.md, "Stick exits").
  const double limit = s_->StaticLimit(c, z_);
  s_->ProjectOnExit(detected, c, sign * limit, z_);
  OntoSurface(contacts_[c], z_);
  if (variational_) {
    grad_.resize(n_);
    grad2_.resize(n_);
    s_->StickForceGradient(detected, c, z_, grad_);
    s_->StaticLimitGradient(c, z_, grad2_);
    grad_ -= sign * grad2_;
    Saltation(before, after, grad_, ExitDp(detected, c, sign));
  }
  mode_ = after;
  ++out_->exits;
  Record(SwitchKind::kStickOut, c, before, after);
}

double Engine::ArrivalDp(int c) const {
  if (!column_) return 0;
  return -s_->ContactParameterDerivative(mode_, c, *flow_.parameter_, z_).speed;
}

double Engine::ExitDp(const ModeSet& stick, int c, int sign) const {
  return column_ ? ExitParameterDerivative(*s_, stick, c, sign, *flow_.parameter_, z_) : 0.0;
}

void Engine::Record(SwitchKind kind, int c, const ModeSet& before, const ModeSet& after) {
  FlowRun& r = *out_;
  if (kind != SwitchKind::kTouch) {
    ++r.switches;
    r.modes.push_back(after);
  }
  Extend(z_.data());
  last_switch_t_ = t_;
  switched_at_[c] = t_;
  // The switch first: an observer may read it (Simulate's exit section).
  if (rq_->switches) rq_->switches->push_back(FlowSwitch{kind, t_, c, z_, before, after});
  if (rq_->observer && rq_->output_dt > 0) rq_->observer(t_, z_.data(), after);
  if (rq_->step_observer) rq_->step_observer(t_, z_.data(), after);
}

}  // namespace stickslip::flow_detail
