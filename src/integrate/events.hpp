// Private to src/: the events of one integration segment, after heyoka's
// model (Biscani & Izzo 2021, MNRAS 504, section 4). An event function g is
// a linear functional of the step's rows (the state, or a field's auxiliary
// rows: a stick force and its limit), or the time derivative of one; an
// event watches one function in a direction and is terminal (it ends the
// segment) or not (a hook records it and the segment goes on). One function
// may carry both: the extrema of x' (non-terminal) and a maximum of x'
// (terminal, falling).
#pragma once

#include <functional>
#include <vector>

#include "stickslip/system/mode.hpp"

namespace stickslip {

// A root's direction is CVODE's (CVodeGetRootInfo): +1 where g rises
// through 0, -1 where it falls; kAnyRoot stands for both.
constexpr int kAnyRoot = 2;

struct EventFunction {
  static constexpr int kMaxTerms = 4;
  struct Term {
    int row = 0;
    double weight = 1;
  };
  Term terms[kMaxTerms];
  int size = 0;
  double offset = 0;        // g = sum weight row - offset
  bool derivative = false;  // g = d/dt sum weight row
  // An exact 0 counts as this sign (an arrival: the mode's side).
  int zero_sign = 1;
  // A contact's arrival (h_i = 0) from slip: a start on the surface with a
  // deflated constant within rounding counts as 0 (the next order decides).
  bool surface = false;
  // A root exactly at the segment start is the start surface (g / u from
  // there); false for a stick exit: a stick that starts on the edge of its
  // band and leaves it exits at once.
  bool deflate_at_start = true;
  // For steppers that evaluate g from the state (CVODE): a stick exit of
  // this contact is lambda - exit_sign StaticLimit (rows are then aux rows).
  int exit_contact = -1;
  int exit_sign = 0;
  // The polynomial this function shares with the functions before it (same
  // terms and derivative; EventList::Add sets it): computed once per step.
  int base = 0;
  bool SameShape(const EventFunction& o) const {
    if (size != o.size || derivative != o.derivative) return false;
    for (int t = 0; t < size; ++t)
      if (terms[t].row != o.terms[t].row || terms[t].weight != o.terms[t].weight) return false;
    return true;
  }
};

struct Event {
  int g = 0;                 // the function
  int direction = kAnyRoot;  // +1, -1 or kAnyRoot
  bool terminal = false;
  // A root at the segment start (to rounding, Tolerances::EventAtStart) is
  // the start surface, not an event, unless this is set: a start just off
  // the surface that reaches it at once.
  bool at_start = false;
  bool Matches(int i, int dir) const {
    return g == i && (direction == kAnyRoot || direction == dir);
  }
};

// A non-terminal event's hook: function g, direction, and the stepper's
// state y at the root (its first n rows, the state; the Taylor stepper
// leaves the variational rows after them out).
struct EventHook {
  void (*fn)(void* context, int g, const double* y) = nullptr;
  void* context = nullptr;
  void operator()(int g, const double* y) const { fn(context, g, y); }
};

// A segment's functions and events, with each function's terminal and
// non-terminal directions as masks (kAnyRoot, +1, -1 or 0) for the steppers.
class EventList {
 public:
  void Clear() {
    functions_.clear();
    events_.clear();
    stop_.clear();
    pass_.clear();
    passing_ = false;
    count_ = 0;
  }
  // Returns the function's index: an identical function's if there is one
  // (one function may carry a terminal and a non-terminal event).
  int Add(EventFunction f) {
    for (int i = 0; i < static_cast<int>(functions_.size()); ++i) {
      const EventFunction& o = functions_[i];
      if (o.SameShape(f) && o.offset == f.offset && o.zero_sign == f.zero_sign &&
          o.surface == f.surface && o.deflate_at_start == f.deflate_at_start &&
          o.exit_contact == f.exit_contact && o.exit_sign == f.exit_sign)
        return i;
    }
    f.base = static_cast<int>(functions_.size());
    for (int i = 0; i < static_cast<int>(functions_.size()); ++i)
      if (functions_[i].SameShape(f)) {
        f.base = functions_[i].base;
        break;
      }
    functions_.push_back(f);
    stop_.push_back(0);
    pass_.push_back(0);
    return count_++;
  }
  void Add(const Event& e) {
    events_.push_back(e);
    passing_ = passing_ || !e.terminal;
    int& mask = e.terminal ? stop_[e.g] : pass_[e.g];
    mask = mask == 0 ? e.direction : (mask == e.direction ? mask : kAnyRoot);
  }
  // A count, not functions_.size(): no division by the function's size at
  // every loop over them (the hot code's footprint, docs/benchmarks.md).
  int functions() const { return count_; }
  const EventFunction& function(int i) const { return functions_[i]; }
  int events() const { return static_cast<int>(events_.size()); }
  // Whether some event is not terminal (a stepper finds roots inside its steps).
  bool AnyPassing() const { return passing_; }
  // Steps as AnyPassing's, for non-terminal events held back (left out).
  void HoldPassing() { passing_ = true; }
  void SetAtStart(int k, bool at_start) { events_[k].at_start = at_start; }
  const Event& event(int k) const { return events_[k]; }
  bool Stops(int i, int direction) const { return Has(stop_[i], direction); }
  bool Passes(int i, int direction) const { return Has(pass_[i], direction); }
  bool AtStart(int i, int dir) const {
    for (const Event& e : events_)
      if (e.terminal && e.at_start && e.Matches(i, dir)) return true;
    return false;
  }

 private:
  static bool Has(int mask, int direction) { return mask == kAnyRoot || mask == direction; }
  std::vector<EventFunction> functions_;
  std::vector<Event> events_;
  std::vector<int> stop_, pass_;
  bool passing_ = false;
  int count_ = 0;  // functions_.size()
};

}  // namespace stickslip
