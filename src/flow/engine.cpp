// One Run of the flow: segments through the one event loop (RunSegment), each
// in one mode with the events that mode needs (events.hpp): the arrivals of
// its slipping contacts, the exits of its sticking ones, the caller's
// sections and the extrema asked for.
#include "flow/engine.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "numerics/dense_copy.hpp"
#include "numerics/numbers.hpp"
#include "numerics/stall.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/switching.hpp"

namespace stickslip::flow_detail {

Engine::Engine(Flow& flow) : flow_(flow) {}

Stepper& Engine::Solver(EventSet& set) {
  const int kind = column_ ? 2 : variational_ ? 1 : 0;
  std::unique_ptr<Stepper>& slot = set.steppers[kind];
  if (!slot || (column_ && set.column_param != flow_.parameter_)) {
    const std::optional<int> param = column_ ? flow_.parameter_ : std::nullopt;
    slot = MakeStepper(flow_.options_, *s_, variational_, param);
    if (column_) set.column_param = param;
  }
  return *slot;
}

void Engine::Start(const FlowPoint& start, const FlowRequest& rq, FlowRun* out) {
  s_ = flow_.system_.get();
  rq_ = &rq;
  out_ = out;
  if (!system_read_) ReadSystem();  // and n_, nt_, k_ and the run's buffers
  CheckRun(start, rq);
  variational_ = rq.variational || rq.parameter_column;
  column_ = rq.parameter_column;
  UseShape(rq);
  FlowRun& r = *out;
  r.status = FlowStatus::kTimeLimit;
  r.message.clear();
  r.section = -1;
  r.opened = -1;
  r.t_stick = 0;
  r.switches = r.sticks = r.exits = r.crossings = r.touches = 0;
  const int ne = static_cast<int>(rq.extrema.size());
  r.lo.resize(ne), r.hi.resize(ne);
  for (int p = 0; p < ne; ++p) r.lo[p] = r.hi[p] = start.z[rq.extrema[p]];
  t_start_ = start.t, column_lost_ = false;
  r.steps = 0, r.orders = TaylorOrders();
  t_ = start.t;
  std::copy(start.z.data(), start.z.data() + n_, z_.data());  // z_ sized by ReadSystem
  // An exit at t = 0 is taken now. A slip start has none, and is not even
  // passed to ReleasedAtEdge (its copy and view cost 9 hot lines a period).
  mode_ = start.mode.AnySticks() ? ReleasedAtEdge(*s_, start.mode, start.z) : start.mode;
  r.modes.resize(1);  // not assign(1, .): no out-of-line fill per run
  r.modes[0] = mode_;
  // M_ = I, C_ = 0 (r.dzdp and has_dzdp are set by Done): a run without
  // Phi leaves them so, and the next needs no reset.
  if (variational_ || !tangent_fresh_) ResetTangent();
  // Clocks as exact functions of t (their rate is their field's entry).
  const int clocks = n_ - nt_;
  if (column_)
    for (int j = 0; j < clocks; ++j)
      clock_drate_[j] = s_->ClockRateDerivative(j, *flow_.parameter_);
  if (clocks > 0 && clock_epoch_ != system_epoch_) ReadClockRates();
  for (int j = 0; j < clocks; ++j) clock_offset_[j] = z_[nt_ + j] - clock_rate_[j] * t_;
  if (variational_) ProjectStartTangent();
  StartProblem();
}

// The grid origin + k dt (FlowRequest::output_origin): the start is sampled
// when it lies on it, to rounding.
void Engine::StartOutput(const FlowRequest& rq) {
  output_origin_ = std::isnan(rq.output_origin) ? t_ : rq.output_origin;
  next_output_ =
      rq.output_index >= 0 ? rq.output_index : FirstSample(output_origin_, rq.output_dt, t_);
  if (output_origin_ + next_output_ * rq.output_dt <= t_ + Tolerances::OutputAtStart(t_)) {
    rq.observer(t_, z_.data(), mode_);
    ++next_output_;
  }
}

void Engine::Run(const FlowPoint& start, const FlowRequest& rq, FlowRun* out) {
  Start(start, rq, out);
  FlowRun& r = *out;
  last_switch_t_ = NAN;
  std::fill(switched_at_.begin(), switched_at_.end(), NAN);  // sized by ReadSystem
  if (rq.observer && rq.output_dt > 0) StartOutput(rq);
  if (rq.step_observer) rq.step_observer(t_, z_.data(), mode_);
  // k contacts in step may each stick or leave in turn at one t (to rounding).
  RootRepeats stalls(Tolerances::kSwitchStalls + 2 * k_);
  for (;;) {
    if (r.switches > flow_.options_.max_switches) {
      Fail(FlowStatus::kTooManySwitches,
           "more than " + Num(flow_.options_.max_switches) + " mode changes by t = " + Num(t_));
      return;
    }
    const int before = r.switches;
    // A switch exactly at t_max (a stick exit there) ends the run in the
    // new mode: no segment of zero length.
    if (t_ >= rq.t_max) {
      Done(FlowStatus::kTimeLimit);
      return;
    }
    if (!Segment()) return;
    if (r.switches > before && stalls.Stuck(t_)) {
      Fail(FlowStatus::kIntegratorFailed, "switching does not advance t at t = " + Num(t_, 17));
      return;
    }
    if (rq.max_steps > 0 && r.steps >= rq.max_steps) {
      Fail(FlowStatus::kTooMuchWork, "max_steps = " + Num(rq.max_steps) + " by t = " + Num(t_));
      return;
    }
  }
}

void Engine::UseEvents() {
  EventSet* set = nullptr;
  for (EventSet& e : sets_)
    if (e.used && e.mode == mode_ && e.shape == shape_) set = &e;
  if (!set) {
    set = &sets_[next_set_];
    next_set_ = (next_set_ + 1) % kEventSets;
    set->mode = mode_;
    set->shape = shape_;
    BuildEvents(*set);
    set->used = true;
    set->key = ++keys_;
    set->rest_epoch = -1;
  }
  if (set->rest_epoch != system_epoch_) {
    set->rest.setZero(n_);  // no guess (System::Rest reads one)
    set->has_rest = !mode_.AnySticks() && s_->Rest(mode_, set->rest, &set->rest_stable);
    set->rest_epoch = system_epoch_;
  }
  // The set's own list, in place (no copy per segment).
  cur_ = set;
  problem_.shared = &set->events;
  // A start just off a surface that reaches it at once arrives there.
  for (int k : set->arrival_events) {
    const int c = set->roles[set->events.event(k).g].index;
    set->events.SetAtStart(k, contacts_[c].At(z_.data()) != 0);
  }
}

[[gnu::noinline]] void Engine::ResetTangent() {
  M_.setIdentity();  // sized by ReadSystem
  C_.setZero();
  tangent_fresh_ = !variational_;
}

// The segment problem's parts that hold for the whole run.
void Engine::StartProblem() {
  const FlowOptions& o = flow_.options_;
  SegmentProblem& p = problem_;
  p.system = s_;
  p.system_epoch = system_epoch_;
  p.contacts = k_;
  p.rtol = o.rtol;
  p.atol = o.atol;
  p.layout = TaylorLayout{n_, nt_, variational_, column_, 0};
  p.cancel = flow_.cancel_ ? &flow_.cancel_ : nullptr;
  p.on_event = EventHook{&Engine::OnEvent, this};
  p.on_step =
      (!rq_->extrema_in_steps || rq_->step_observer) ? StepHook{&Engine::OnStep, this} : StepHook{};
  p.clock_rate = clock_rate_.data();
  p.clock_offset = clock_offset_.data();
}

bool Engine::Segment() {
  SegmentProblem& p = problem_;
  p.mode = mode_;
  UseEvents();  // and the mode's rest point
  p.has_rest = cur_->has_rest;
  const bool stable = cur_->rest_stable;
  SegmentOutput out;
  if (rq_->observer && rq_->output_dt > 0)
    out = SegmentOutput{rq_->output_dt, output_origin_, &next_output_, &Engine::OnOutput, this};
  p.setup = cur_->key;
  Stepper& cv = Solver(*cur_);
  const double t0 = t_;
  // Without Phi or the column the rows are the state itself: no copy.
  const double* y0 = variational_ ? InitialRows(p.layout) : z_.data();
  const SegmentEnd e = RunSegment(cv, p, t_, y0, rq_->t_max, out, &roots_);
  FlowRun& r = *out_;
  r.steps += cv.steps();
  r.orders.Merge(cv.orders());  // the flow's totals take the run's (Flow::Run)
  const double* y = e.y;
  t_ = e.t;
  std::copy(y, y + n_, z_.data());
  for (int j = 0; j < n_ - nt_; ++j) z_[nt_ + j] = clock_rate_[j] * t_ + clock_offset_[j];
  if (mode_.AnySticks()) r.t_stick += t_ - t0;
  if (variational_) AdvanceTangent(y, p.layout);
  switch (e.kind) {
    case SegmentEnd::kEvent:
      Extend(z_.data());
      return Switch(roots_);
    case SegmentEnd::kTime:
      return Done(FlowStatus::kTimeLimit);
    case SegmentEnd::kCancelled:
      return Fail(FlowStatus::kCancelled,
                  "cancelled at t = " + Num(t_) + " in " + ModeSetName(mode_, k_));
    case SegmentEnd::kTooMuchWork:
      if (p.has_rest && stable && Settled(y)) {
        // Settled on stable steady sliding, where it stays: the rest of the
        // segment is that rest point, and no event can follow.
        z_ = cur_->rest;
        const double t_rest = std::isfinite(rq_->t_max) ? rq_->t_max : e.t_end;
        for (; out.on() && out.at() < t_rest; ++next_output_)
          rq_->observer(out.at(), z_.data(), mode_);
        t_ = t_rest;
        column_lost_ = column_;  // the segment's column is not the rest's
        return Done(FlowStatus::kTimeLimit);
      }
      return Fail(FlowStatus::kIntegratorFailed, Where(cv.CurrentTime(), y, cv.last_error()));
    case SegmentEnd::kFailed:
      return Fail(FlowStatus::kIntegratorFailed, Where(e.t, y, e.reason));
  }
  return Fail(FlowStatus::kIntegratorFailed, "unknown segment end");
}

// y0: the state, Phi = I, the column (0 but its clocks' (t - t0) d omega / dp).
const double* Engine::InitialRows(const TaylorLayout& layout) {
  const size_t m = layout.aux_first();
  AtLeast(y0_, m);
  std::copy(z_.data(), z_.data() + n_, y0_.begin());
  std::fill(y0_.begin() + n_, y0_.begin() + m, 0.0);
  if (variational_)
    for (int j = 0; j < nt_; ++j) y0_[n_ + j * nt_ + j] = 1.0;
  if (column_)
    for (int j = 0; j < n_ - nt_; ++j)
      y0_[layout.param() + nt_ + j] = (t_ - t_start_) * clock_drate_[j];
  return y0_.data();
}

std::string Engine::Where(double t, const double* y, const std::string& reason) const {
  return Name(flow_.options_.integrator) + std::string(" failed") + Place(t, y, 6) + ": " + reason;
}

std::string Engine::Place(double t, const double* y, int digits) const {
  std::ostringstream os;
  os.precision(digits);
  os << " at t = " << t << " in " << ModeSetName(mode_, k_) << " at";
  for (int i = 0; i < nt_; ++i) os << (i ? ", " : " ") << s_->StateName(i) << " = " << y[i];
  return os.str();
}

bool Engine::Settled(const double* y) const {
  Eigen::VectorXd f(n_);
  s_->Field(mode_, Eigen::Map<const Eigen::VectorXd>(y, n_), f);
  return problem_.AtRest(y, f.data());
}

void Engine::Extend(const double* z) {
  FlowRun& r = *out_;
  for (int p = 0; p < static_cast<int>(rq_->extrema.size()); ++p) {
    const double v = z[rq_->extrema[p]];
    r.lo[p] = std::min(r.lo[p], v);
    r.hi[p] = std::max(r.hi[p], v);
  }
}

bool Engine::Done(FlowStatus s) {
  FlowRun& r = *out_;
  r.status = s;
  r.end.t = t_;
  CopyInto(z_, &r.end.z);
  r.end.mode = mode_;
  CopyInto(M_, &r.jacobian);
  r.has_dzdp = column_ && !column_lost_;
  CopyInto(C_, &r.dzdp);  // 0 without a column (Start)
  Extend(z_.data());
  // The end's sample, unless a switch there just gave it.
  const bool sampled = r.switches > 0 && last_switch_t_ == t_;
  const bool continued = !rq_->output_end && s == FlowStatus::kTimeLimit;
  if (rq_->observer && rq_->output_dt > 0 && !continued && !sampled)
    rq_->observer(t_, z_.data(), mode_);
  r.output_index = next_output_;
  if (rq_->step_observer && !sampled) rq_->step_observer(t_, z_.data(), mode_);
  return false;
}

bool Engine::Fail(FlowStatus s, const std::string& why) {
  out_->message = why;
  return Done(s);
}

void Engine::OnEvent(void* self, int g, const double* y) {
  auto& e = *static_cast<Engine*>(self);
  FlowRun& r = *e.out_;
  for (int p : e.cur_->extremum_of[g]) {
    const double v = y[e.rq_->extrema[p]];
    r.lo[p] = std::min(r.lo[p], v);
    r.hi[p] = std::max(r.hi[p], v);
  }
}

void Engine::OnStep(void* self, double t, const double* y) {
  auto& e = *static_cast<Engine*>(self);
  if (!e.rq_->extrema_in_steps) e.Extend(y);
  if (e.rq_->step_observer) e.rq_->step_observer(t, y, e.mode_);
}

void Engine::OnOutput(void* self, double t, const double* y) {
  auto& e = *static_cast<Engine*>(self);
  e.rq_->observer(t, y, e.mode_);
}

}  // namespace stickslip::flow_detail
