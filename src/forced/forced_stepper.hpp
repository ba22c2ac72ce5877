// Private to src/forced/: the forced oscillator's slip steppers for the one
// event loop (integrate/event_driver.hpp). They only step, on the field of
// one slip mode with the forcing A cos(Omega t), and report the roots of the
// belt's root functions (stepper.hpp):
//   g0 = x' - v   arrival at the switching surface (terminal, towards it);
//   g1 = x''      extremum of x' (non-terminal);
//   g2 = x'       extremum of x (non-terminal);
// the driver (forced_flow.cpp) holds the events and the phase logic.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "forced_taylor.hpp"
#include "integrate/event_driver.hpp"
#include "stickslip/forced/flow.hpp"

namespace stickslip::forced_detail {

// A step end a stepper shows the driver (not one cut at a terminal root):
// each Taylor step's, CVODE's returns only.
struct StepHook {
  void (*fn)(void* context, double t, const double* y) = nullptr;
  void* context = nullptr;
  void operator()(double t, const double* y) const { fn(context, t, y); }
};

// One slip phase of the forced flow: mode, events and hooks (the loop's
// part), the model, Phi or not, and the steps the Run has left.
struct ForcedSlipProblem : SegmentProblem {
  const ForcedModel* model = nullptr;
  bool variational = false;
  long max_steps = 0;
  StepHook on_step{};
  // The direction of g0 = x' - v towards the surface from this mode.
  int Toward() const { return mode == Mode::kSlipBelow ? 1 : -1; }
};

// Taylor steps by SlipSeries; the events' roots on each step polynomial:
// the first sign change of x' - v (none missed, poly_roots.hpp) and, before
// it, every root of x' and x'' (EachRoot). Stops only at arrivals; the
// extrema go to the problem's hook.
class ForcedTaylorStepper {
 public:
  ForcedTaylorStepper(const ForcedModel& m, const ForcedOptions& o, bool extremes)
      : series_(m, o.rtol, o.atol, !extremes) {}
  void Reset(const ForcedSlipProblem& p, double t0, const double* y0) {
    p_ = &p;
    v_ = p.model->v();
    n_ = p.variational ? 6 : 2;
    for (int i = 0; i < 2; ++i) y_[i] = y0[i];
    if (n_ == 6)
      for (int i = 2; i < 6; ++i) y_[i] = y0[i];
    t_ = t0_ = t0;
    tstop_ = INFINITY;
    steps_ = 0;
    rf0_ = 0;
    arrive_ = p.Stops(0, p.Toward());
    watch_xd_ = p.events.Watched(1);
    watch_x_ = p.events.Watched(2);
    on_surface_ = y0[1] == v_;  // a start on x' = v (an arrival or a stick exit)
  }
  void SetStopTime(double t) { tstop_ = t; }
  StepOutcome Advance(double tout, double* t);
  const double* y() const { return y_; }
  void RootInfo(int* rf) const { rf[0] = rf0_, rf[1] = rf[2] = 0; }
  double CurrentTime() const { return t_; }
  double SegmentStart() const { return t0_; }
  long steps() const { return steps_; }
  const std::string& last_error() const { return error_; }

 private:
  enum class Step { kOn, kArrived, kFailed };
  Step TakeStep(double t_end);
  // u in (0, 1] of the first arrival on this step (2 if none); g is x' - v.
  double Arrival(const double* g, int n, double h);
  void Extrema(double* g0, double xd0, const double* g2, int n, double u_end, double h);

  SlipSeries series_;
  const ForcedSlipProblem* p_ = nullptr;
  double v_ = 0;
  int n_ = 2;
  bool arrive_ = false, watch_x_ = false, watch_xd_ = false;
  bool on_surface_ = false;  // the next step starts on x' = v: its root there is no event
  double t_ = 0, t0_ = 0, tstop_ = INFINITY;
  double y_[6] = {0, 0, 0, 0, 0, 0};
  int rf0_ = 0;
  long steps_ = 0;
  std::string error_;
};

// CVODE on the same field and its variational equations (forced_cvode.cpp):
// an independent path for the slip phases, to check the Taylor one against.
class ForcedCvodeStepper;
struct ForcedCvodeDeleter {
  void operator()(ForcedCvodeStepper* s) const;
};
using ForcedCvodePtr = std::unique_ptr<ForcedCvodeStepper, ForcedCvodeDeleter>;
ForcedCvodePtr MakeForcedCvode(const ForcedModel& m, const ForcedOptions& o, bool variational);
// RunSegment with that stepper; *steps its steps.
SegmentEnd RunSegment(ForcedCvodeStepper& cv, const ForcedSlipProblem& p, double t0,
                      const double* y0, double t_max, long* steps);

}  // namespace stickslip::forced_detail
