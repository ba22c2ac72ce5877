// Private to src/forced/: one Run of the forced flow, phase by phase
// (forced_flow.cpp: slip phases through the one event loop, RunSegment, and
// the switches; forced_stick.cpp: stick phases).
#pragma once

#include <memory>
#include <string>

#include "forced_stepper.hpp"
#include "stickslip/forced/flow.hpp"

namespace stickslip::forced_detail {

class Driver {
 public:
  Driver(const ForcedModel& m, const ForcedOptions& o, const ForcedRequest& rq, ForcedRun& run)
      : m_(m), o_(o), rq_(rq), run_(run), taylor_(m, o, rq.extremes) {
    problem_.model = &m;
    problem_.variational = rq.variational;
    problem_.on_step = StepHook{&Driver::OnStep, this};
  }
  void Run(const ForcedPoint& start);

 private:
  // Each returns false when the run ends here (stop, failure).
  bool Stick();
  bool Slip();  // one slip segment, by RunSegment, to t_end or an arrival
  EventList SlipEvents() const;
  static void OnExtremum(void* self, int g, const double* y);
  static void OnStep(void* self, double t, const double* y);
  // A root of x' - v at (t, x) arriving from mode_: stick, cross or touch.
  bool Arrive(double t, double x);
  bool Exit(double t, double x);
  bool Record(ForcedEventKind kind, Mode before, Mode after);
  bool Fail(ForcedStatus s, const std::string& what);
  void Sample() {
    if (rq_.samples) rq_.samples->push_back({t_, x_, xd_, mode_});
  }

  const ForcedModel& m_;
  const ForcedOptions& o_;
  const ForcedRequest& rq_;
  ForcedRun& run_;
  // The slip phases' problem; its events are set again only when the mode changes.
  ForcedSlipProblem problem_;
  bool events_set_ = false;
  ForcedTaylorStepper taylor_;
  ForcedCvodePtr cvode_;  // with Integrator::kCvode, made at the first slip phase
  double t_ = 0, x_ = 0, xd_ = 0;
  Mode mode_ = Mode::kSlipBelow;
  Mat2 phi_ = Mat2::Identity();
  long events_ = 0;
  int stalled_events_ = 0;  // events in a row at one t
  double last_event_t_ = -1;
};

}  // namespace stickslip::forced_detail
