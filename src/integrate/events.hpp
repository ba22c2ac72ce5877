// Private to src/: the events of one integration segment, after heyoka's
// model (Biscani & Izzo 2021, MNRAS 504, section 4): each event watches one
// root function g_i of the stepper (stepper.hpp), in a direction, and is
// terminal (it ends the segment) or not (a hook records it and the segment
// goes on). One function may carry both: the extrema of x' (non-terminal,
// any direction) and the maximum of x' (terminal, falling).
#pragma once

#include <functional>

#include "stickslip/model/system.hpp"  // Mode

namespace stickslip {

constexpr int kNumRoots = 3;  // the stepper's root functions g_0, g_1, g_2
// A root's direction is CVODE's (CVodeGetRootInfo): +1 where g rises
// through 0, -1 where it falls; kAnyRoot stands for both.
constexpr int kAnyRoot = 2;

struct Event {
  int g = 0;                 // the root function
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

// A non-terminal event's hook: root function g_i, direction, and the full
// stepper state y at the root.
struct EventHook {
  void (*fn)(void* context, int g, const double* y) = nullptr;
  void* context = nullptr;
  void operator()(int g, const double* y) const { fn(context, g, y); }
};

class EventList {
 public:
  static constexpr int kMax = 2 * kNumRoots;
  void Add(const Event& e) { e_[n_++] = e; }
  int size() const { return n_; }
  const Event& operator[](int k) const { return e_[k]; }

  bool Terminal(int i, int dir) const { return Find(i, dir, true) != nullptr; }
  bool NonTerminal(int i, int dir) const { return Find(i, dir, false) != nullptr; }
  bool AtStart(int i, int dir) const {
    const Event* e = Find(i, dir, true);
    return e && e->at_start;
  }
  // The directions of g_i's terminal (or non-terminal) events, as a mask:
  // kAnyRoot, +1, -1, or 0 (none).
  int StopMask(int i, bool terminal = true) const {
    int mask = 0;
    for (int k = 0; k < n_; ++k) {
      const Event& e = e_[k];
      if (e.g != i || e.terminal != terminal) continue;
      mask = mask == 0 ? e.direction : (mask == e.direction ? mask : kAnyRoot);
    }
    return mask;
  }
  bool Watched(int i) const {
    for (int k = 0; k < n_; ++k)
      if (e_[k].g == i) return true;
    return false;
  }

 private:
  const Event* Find(int i, int dir, bool terminal) const {
    for (int k = 0; k < n_; ++k)
      if (e_[k].terminal == terminal && e_[k].Matches(i, dir)) return &e_[k];
    return nullptr;
  }
  Event e_[kMax];
  int n_ = 0;
};

// What the event loop (event_driver.hpp) reads of a segment's problem: its
// mode, cancel hook, events and hook. Each model's problem (SlipProblem in
// stepper.hpp, the forced oscillator's in forced_stepper.hpp) extends it with
// what its steppers need.
struct SegmentProblem {
  Mode mode = Mode::kSlipBelow;
  const std::function<bool()>* cancel = nullptr;  // polled after every step, if set
  // The segment's events; SetEvents keeps them with the stop mask of each
  // root function, which the steppers read on every step.
  EventList events{};
  EventHook on_event{};                 // called for every non-terminal event a stepper passes
  int stop_dir[kNumRoots] = {0, 0, 0};  // terminal events' directions per g_i (StopMask)
  int pass_dir[kNumRoots] = {0, 0, 0};  // non-terminal events' directions
  void SetEvents(const EventList& list, EventHook hook) {
    events = list;
    on_event = hook;
    for (int i = 0; i < kNumRoots; ++i) {
      stop_dir[i] = list.StopMask(i);
      pass_dir[i] = list.StopMask(i, false);
    }
  }
  // Whether a root of g_i in this direction (+1 or -1) is a terminal event
  // (Stops) or a non-terminal one (Passes).
  bool Stops(int i, int direction) const {
    return stop_dir[i] == kAnyRoot || stop_dir[i] == direction;
  }
  bool Passes(int i, int direction) const {
    return pass_dir[i] == kAnyRoot || pass_dir[i] == direction;
  }
};

}  // namespace stickslip
