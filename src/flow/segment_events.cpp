// The events of one segment (engine.hpp): for each slipping contact its
// arrival on h_i = 0, for each sticking one its exits at lambda_i = +-limit
// (the field's auxiliary rows), the extrema asked for, and the sections;
// and the run's shape: the system read, the request checked.
#include <algorithm>
#include <cmath>
#include <string>

#include "flow/engine.hpp"
#include "numerics/numbers.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::flow_detail {

namespace {
bool SameSection(const Section& a, const Section& b) {
  if (a.g.size != b.g.size || a.g.speed != b.g.speed || a.derivative != b.derivative ||
      a.direction != b.direction || a.slip_below_only != b.slip_below_only)
    return false;
  for (int t = 0; t < a.g.size; ++t)
    if (a.g.terms[t].index != b.g.terms[t].index || a.g.terms[t].weight != b.g.terms[t].weight)
      return false;
  return true;
}
bool SameFunctional(const ContactVelocity& a, const ContactVelocity& b) {
  if (a.size != b.size || a.speed != b.speed) return false;
  for (int t = 0; t < a.size; ++t)
    if (a.terms[t].index != b.terms[t].index || a.terms[t].weight != b.terms[t].weight)
      return false;
  return true;
}
}  // namespace

// Whether rq asks for the events of shape s (extrema, sections, switching).
bool Engine::SameShape(const Shape& s, const FlowRequest& rq) const {
  if (!s.used || rq.switching != s.switching || rq.extrema_in_steps != s.in_steps ||
      rq.hold_extrema != s.hold || variational_ != s.var || column_ != s.col ||
      rq.extrema != s.extrema || rq.sections.size() != s.sections.size())
    return false;
  for (size_t i = 0; i < rq.sections.size(); ++i)
    if (!SameSection(rq.sections[i], s.sections[i])) return false;
  return true;
}

void Engine::UseShape(const FlowRequest& rq) {
  if (SameShape(shapes_[shape_], rq)) return;
  for (int i = 0; i < kShapes; ++i)
    if (SameShape(shapes_[i], rq)) {
      shape_ = i;
      return;
    }
  Reshape(rq);
}

// The system's dimensions, contacts and derivatives (read once per system,
// Invalidate): event sets built for the same ones are kept (a parameter
// changed), their rest points recomputed.
void Engine::ReadSystem() {
  n_ = s_->dimension();
  nt_ = s_->tangent_dimension();
  k_ = s_->contacts();
  bool same =
      static_cast<int>(contacts_.size()) == k_ && static_cast<int>(derivative_of_.size()) == n_;
  for (int i = 0; same && i < k_; ++i) same = SameFunctional(s_->Contact(i), contacts_[i]);
  for (int i = 0; same && i < n_; ++i) same = derivative_of_[i] == s_->DerivativeOf(i);
  same = same && static_cast<int>(normals_.size()) == k_;
  for (int i = 0; same && i < k_; ++i) {
    const std::optional<ContactVelocity> c = s_->NormalForce(i);
    const std::optional<ContactVelocity>& o = normals_[i];
    same = c.has_value() == o.has_value();
    if (same && c) same = SameFunctional(*c, *o);
  }
  ++system_epoch_;
  system_read_ = true;
  // Per-run buffers of the system's shape (Start, Run: no resize per run).
  const int clocks = n_ - nt_;
  clock_rate_.resize(clocks);
  clock_offset_.resize(clocks);
  clock_drate_.assign(clocks, 0.0);  // read with a column only, which Start fills first
  switched_at_.resize(k_);
  z_.resize(n_);
  M_.resize(nt_, nt_);
  C_.resize(nt_);
  tangent_fresh_ = false;
  if (same) return;
  ForgetEvents();
  contacts_.resize(k_);
  for (int i = 0; i < k_; ++i) contacts_[i] = s_->Contact(i);
  normals_.resize(k_);
  for (int i = 0; i < k_; ++i) normals_[i] = s_->NormalForce(i);
  derivative_of_.resize(n_);
  for (int i = 0; i < n_; ++i) derivative_of_[i] = s_->DerivativeOf(i);
  problem_.derivative_of = derivative_of_;
  problem_.rest_speed = 0;
  for (const ContactVelocity& c : contacts_)
    problem_.rest_speed = std::max(problem_.rest_speed, std::abs(c.speed));
}

void Engine::BuildEvents(EventSet& set) {
  EventList& ev = set.events;
  ev.Clear();
  set.roles.clear();
  set.extremum_of.clear();
  set.arrival_events.clear();
  auto add = [&](const EventFunction& f) { return AddFunction(set, f); };
  const FlowRequest& rq = *rq_;
  const int aux = problem_.layout.aux_first();
  int rank = 0;  // among the sticking contacts: their aux rows
  for (int i = 0; i < k_ && rq.switching; ++i) {
    if (mode_.sticks(i)) {
      for (int sign : {1, -1}) {
        EventFunction f;
        f.size = 2;
        f.terms[0] = {aux + 2 * rank, 1.0};
        f.terms[1] = {aux + 2 * rank + 1, -static_cast<double>(sign)};
        f.zero_sign = -sign;  // inside the band
        f.deflate_at_start = false;
        f.exit_contact = i;
        f.exit_sign = sign;
        const int g = add(f);
        set.roles[g] = {FunctionRole::kExit, i, sign};
        ev.Add(Event{g, sign, true, true});
      }
      ++rank;
      continue;
    }
    const ContactVelocity& c = contacts_[i];
    EventFunction f;
    f.size = c.size;
    for (int t = 0; t < c.size; ++t) f.terms[t] = {c.terms[t].index, c.terms[t].weight};
    f.offset = c.speed;
    f.zero_sign = mode_[i] == Mode::kSlipBelow ? -1 : 1;
    f.surface = true;
    const int g = add(f);
    set.roles[g] = {FunctionRole::kArrival, i, 0};
    // Arrival ends the segment (at_start: set per segment, Segment()).
    set.arrival_events.push_back(ev.events());
    ev.Add(Event{g, kAnyRoot, true, false});
  }
  AddExtremumEvents(set);
  AddOpenEvents(set);
  for (int sx = 0; sx < static_cast<int>(rq.sections.size()); ++sx) {
    const Section& sec = rq.sections[sx];
    if (sec.slip_below_only && mode_[0] != Mode::kSlipBelow) continue;
    EventFunction f;
    f.size = sec.g.size;
    for (int t = 0; t < sec.g.size; ++t) f.terms[t] = {sec.g.terms[t].index, sec.g.terms[t].weight};
    f.offset = sec.g.speed;
    f.derivative = sec.derivative;
    const int g = add(f);
    set.roles[g] = {FunctionRole::kSection, sx, 0};
    ev.Add(Event{g, sec.direction == 0 ? kAnyRoot : sec.direction, true});
  }
}

}  // namespace stickslip::flow_detail

namespace stickslip::flow_detail {

int Engine::AddFunction(EventSet& set, const EventFunction& f) {
  const int i = set.events.Add(f);
  if (i == static_cast<int>(set.roles.size())) {
    set.roles.emplace_back();
    set.extremum_of.emplace_back();
  }
  return i;
}

void Engine::AddExtremumEvents(EventSet& set) {
  const FlowRequest& rq = *rq_;
  EventList& ev = set.events;
  for (int p = 0; rq.extrema_in_steps && p < static_cast<int>(rq.extrema.size()); ++p) {
    const int j = rq.extrema[p];
    EventFunction f;
    f.size = 1;
    f.terms[0] = {derivative_of_[j] >= 0 ? derivative_of_[j] : j, 1.0};
    f.derivative = derivative_of_[j] < 0;
    // The extremum of x where x' = v is an arrival (v = 0: a floor): the
    // switch there records it (Extend), and its roots are not sought twice.
    bool arrival = false;
    for (int i = 0; i < ev.functions(); ++i)
      arrival = arrival || (set.roles[i].kind == FunctionRole::kArrival &&
                            ev.function(i).SameShape(f) && ev.function(i).offset == f.offset);
    if (arrival) continue;
    if (rq.hold_extrema) {  // left out; the steps as with them
      ev.HoldPassing();
      continue;
    }
    const int g = AddFunction(set, f);
    set.extremum_of[g].push_back(p);
    ev.Add(Event{g, kAnyRoot, false});
  }
}

// A normal force falling to 0 ends the run (kContactOpen), in every mode.
void Engine::AddOpenEvents(EventSet& set) {
  EventList& ev = set.events;
  for (int i = 0; i < k_; ++i) {
    if (!normals_[i]) continue;
    const ContactVelocity& c = *normals_[i];
    EventFunction f;
    f.size = c.size;
    for (int t = 0; t < c.size; ++t) f.terms[t] = {c.terms[t].index, c.terms[t].weight};
    f.offset = c.speed;
    const int g = AddFunction(set, f);
    set.roles[g] = {FunctionRole::kOpen, i, 0};
    ev.Add(Event{g, -1, true});
  }
}

// Out of line, as the other rare parts of a run's start: the run's set-up
// is hot code of every repeated run (docs/benchmarks.md, "Where the fetch
// cliff is").
[[gnu::noinline]] void Engine::CheckRun(const FlowPoint& start, const FlowRequest& rq) const {
  if (start.z.size() != n_)
    throw InvalidArgument("Flow::Run: the start has " + std::to_string(start.z.size()) +
                          " components, the system " + std::to_string(n_));
  if (!start.z.allFinite()) throw InvalidArgument("Flow::Run: start state is not finite");
  if (!(rq.t_max > start.t)) throw InvalidArgument("Flow::Run: t_max must be > t0");
  if (!rq.switching && start.mode.AnySticks())
    throw InvalidArgument("Flow::Run: a run without switching needs a slip start");
  if (rq.parameter_column && !flow_.has_parameter_column())
    throw InvalidArgument("Flow::Run: a parameter column needs set_parameter_column and Taylor");
  for (int j : rq.extrema)
    if (j < 0 || j >= n_) throw InvalidArgument("Flow::Run: extremum of no component " + Num(j));
  CheckStart(*s_, start);
  for (int i = 0; i < k_; ++i)
    if (normals_[i] && !(normals_[i]->At(start.z.data()) > 0))
      throw InvalidArgument("Flow::Run: contact " + std::to_string(i) +
                            " is open at the start (normal force <= 0)");
}

[[gnu::noinline]] void Engine::Reshape(const FlowRequest& rq) {
  shape_ = next_shape_;
  next_shape_ = (next_shape_ + 1) % kShapes;
  for (EventSet& e : sets_)
    if (e.shape == shape_) e.used = false;
  Shape& s = shapes_[shape_];
  s.used = true;
  s.switching = rq.switching, s.in_steps = rq.extrema_in_steps, s.hold = rq.hold_extrema;
  s.var = variational_, s.col = column_;
  s.extrema = rq.extrema;
  s.sections = rq.sections;
}

// A clock's rate is its field's entry, the same in every mode.
[[gnu::noinline]] void Engine::ReadClockRates() {
  f_before_.resize(n_);
  s_->Field(mode_, z_, f_before_);
  for (int j = nt_; j < n_; ++j) clock_rate_[j - nt_] = f_before_[j];
  clock_epoch_ = system_epoch_;
}

}  // namespace stickslip::flow_detail
