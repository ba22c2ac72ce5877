// Private to src/: the events of one integration segment, after heyoka's
// model (Biscani & Izzo 2021, MNRAS 504, section 4): each event watches one
// root function g_i of the stepper (stepper.hpp), in a direction, and is
// terminal (it ends the segment) or not (a hook records it and the segment
// goes on). One function may carry both: the extrema of x' (non-terminal,
// any direction) and the maximum of x' (terminal, falling).
#pragma once

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
  // The directions of g_i's terminal events, as a stepper's stop mask:
  // kAnyRoot, +1, -1, or 0 (none).
  int StopMask(int i) const {
    int mask = 0;
    for (int k = 0; k < n_; ++k) {
      const Event& e = e_[k];
      if (e.g != i || !e.terminal) continue;
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

}  // namespace stickslip
