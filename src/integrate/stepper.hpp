// Private to src/: the seam between the event driver (event_driver.hpp) and
// the integrators of one slip mode. Steppers only step. A stepper integrates z = (x, x') (and, with
// variational equations, Phi) on the smooth field of one slip mode and reports the roots of
//   g0 = x' - v   arrival at the switching surface;
//   g1 = x''      extremum of x': catches a touch of x' = v shorter than a step;
//   g2 = x'       extremum of x, and the Poincare section of pure-slip orbits,
// in CVODE's convention (CVodeGetRootInfo): +1 where g rises through 0, -1
// where it falls, 0 for no root.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "integrate/events.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/integrate/flow.hpp"
#include "stickslip/model/system.hpp"

namespace stickslip {

// One slip mode of a system (the model seam), with the noise bands of steady
// sliding; the mode, cancel hook and events are the event loop's part.
struct SlipProblem : SegmentProblem {
  SlipProblem() = default;
  SlipProblem(const FrictionSystem* m, Mode slip_mode, double r, double a,
              const std::function<bool()>* cancel_hook)
      : model(m), rtol(r), atol(a) {
    mode = slip_mode;
    cancel = cancel_hook;
  }
  const FrictionSystem* model = nullptr;
  double rtol = 0, atol = 0;
  // Steady sliding (mu(v), 0) for slip below (else 0): the Taylor step size
  // measures x by XScale, so the error of a small orbit about it is relative
  // to its amplitude, not to |mu(v)|, and never looser than relative to |x|.
  double x_center = 0;
  double XScale(double x) const { return std::min(std::abs(x), std::abs(x - x_center)); }

  double Acceleration(double x, double xdot) const { return model->Acceleration(mode, x, xdot); }
  // At rest on steady sliding to within the integration noise: x' ~ atol,
  // x'' ~ rtol |x| (the force balance -x + mu(v) of nearly equal terms). There
  // x' and x'' chatter about 0 and neither is an event.
  bool AtRest(double x, double xdot, double acc) const {
    const double scale = std::abs(x) + std::abs(model->v()) + 1.0;
    const Tolerances tol = Tolerances::From(rtol, atol);
    return std::abs(xdot) <= tol.RestBandVelocity(scale) &&
           std::abs(acc) <= tol.RestBandAcceleration(scale);
  }
};

enum class StepOutcome {
  kReached,      // reached tout or the stop time
  kRoot,         // stopped at a root of a terminal event (CVODE: of any g_i); RootInfo says which
  kTooMuchWork,  // max_steps steps without reaching tout
  kFailed,       // an error; last_error() says which
  kCancelled,    // the cancel hook returned true after a step
};

class Stepper {
 public:
  virtual ~Stepper() = default;
  // Restart at (t0, y0) on problem's field; y0 has size() entries, Phi
  // column-major after z when size() >= 6, dz/dp after Phi when size() == 8.
  virtual void Reset(const SlipProblem& problem, double t0, const double* y0) = 0;
  virtual void SetStopTime(double t) = 0;
  // Integrate towards tout; *t is where it stopped, with state y().
  virtual StepOutcome Advance(double tout, double* t) = 0;
  virtual const double* y() const = 0;
  virtual void RootInfo(int* roots_found) const = 0;
  // Dense output at t inside the last step [LastStepStart(), CurrentTime()].
  virtual bool Interpolate(double t, double* out) = 0;
  virtual double LastStepStart() = 0;
  // The stepper's own time (also after a failure).
  virtual double CurrentTime() = 0;
  // Where the stepper last (re)started: Reset's t0, or a restart of its own.
  virtual double SegmentStart() const = 0;
  virtual long steps() const = 0;  // since the last Reset
  // Their orders, since the last Reset (none: not a Taylor stepper).
  virtual TaylorOrders orders() const { return {}; }
  virtual int size() const = 0;
  virtual const std::string& last_error() const = 0;
};

// The stepper options.integrator names, for z alone or with Phi; with a
// parameter (Taylor only), also with the column dz/dp.
std::unique_ptr<Stepper> MakeStepper(const FlowOptions& options, bool variational,
                                     const std::optional<ParameterAxis>& parameter = std::nullopt);

}  // namespace stickslip
