// Private to src/forced/: one Run of the forced flow, phase by phase
// (forced_flow.cpp: slip phases and switches; forced_stick.cpp: stick phases).
#pragma once

#include <memory>
#include <string>

#include "forced_taylor.hpp"
#include "stickslip/forced/flow.hpp"

namespace stickslip::forced_detail {

class SlipCvode;  // forced_cvode.cpp

class Driver {
 public:
  // Out of line (forced_cvode.cpp), where SlipCvode is complete.
  Driver(const ForcedModel& m, const ForcedOptions& o, const ForcedRequest& rq, ForcedRun& run);
  ~Driver();
  void Run(const ForcedPoint& start);

 private:
  // Each returns false when the run ends here (stop, failure).
  bool Stick();
  bool Slip();
  bool SlipStep(double t_end);
  bool SlipByCvode();  // one slip phase by CVODE (forced_cvode.cpp)
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
  SlipSeries series_;
  std::unique_ptr<SlipCvode> cvode_;  // with Integrator::kCvode, made at the first slip phase
  double t_ = 0, x_ = 0, xd_ = 0;
  Mode mode_ = Mode::kSlipBelow;
  Mat2 phi_ = Mat2::Identity();
  bool on_surface_ = false;  // the slip phase starts on x' = v: its root at t_ is no event
  long events_ = 0;
  int stalled_events_ = 0;  // events in a row at one t
  double last_event_t_ = -1;
};

}  // namespace stickslip::forced_detail
