// The belt's view of the one flow (stickslip/flow/flow.hpp) for a one-contact
// system with state (x, x') (friction_system.hpp): runs with a StopRule, and
// results in 2-D types (Vec2, Mat2, Mode). The flow itself, its events and
// switching are the one flow's; this class only translates.
#pragma once

#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/flow/flow.hpp"
#include "stickslip/integrate/extrema.hpp"
#include "stickslip/names.hpp"
#include "stickslip/systems/belt/model.hpp"

namespace stickslip {

// Where a run stops. The defaults integrate until t_max with all switching.
struct StopRule {
  double t_max = std::numeric_limits<double>::infinity();
  bool at_stick = false;         // on arrival in Omega, before sticking
  bool at_section = false;       // where x' crosses 0 downwards (a maximum of x)
  bool at_velocity_max = false;  // at the first maximum of x' in slip below, after the start
  bool switching = true;         // false: stay on the start mode's smooth field
};

// One output point of a simulation.
struct Sample {
  double t;
  Vec2 z;
  Mode mode;
};
using Observer = std::function<void(const Sample&)>;

struct FlowResult {
  FlowStatus status = FlowStatus::kTimeLimit;
  std::string message;  // for kIntegratorFailed / kTooManySwitches: where and what
  double t = 0;
  Vec2 z = Vec2::Zero();
  Mode mode = Mode::kSlipBelow;
  // Extremes over the run, located as roots (x' = 0 for x, x'' = 0 for x'),
  // together with the segment end points.
  Extrema extrema;
  double t_stick = 0;       // time spent in stick
  int switches = 0;         // mode changes
  int crossings = 0;        // crossings of x' = v without sticking
  std::vector<Mode> modes;  // the mode sequence, start mode first
  // d z(t) / d z(t0), saltation matrices included; only with variational.
  Mat2 jacobian = Mat2::Identity();
  // d z(t) / dp at fixed t and fixed start, for the parameter column:
  // has_dzdp only on a run without switches (one smooth slip segment; the
  // saltation for a parameter is not modelled) and with the Taylor integrator.
  Vec2 dzdp = Vec2::Zero();
  bool has_dzdp = false;
  bool ok() const {
    return status != FlowStatus::kIntegratorFailed && status != FlowStatus::kTooManySwitches &&
           status != FlowStatus::kCancelled;
  }
};

class BeltFlow {
 public:
  // Any one-contact system (friction_system.hpp; the belt: Model). Throws
  // InvalidArgument if options are invalid.
  BeltFlow(const FrictionSystem& system, const FlowOptions& options);

  // Change the system; solvers are kept and reused.
  void set_model(const FrictionSystem& system) { flow_.set_system(system); }
  const FrictionSystem& system() const {
    return static_cast<const FrictionSystem&>(flow_.system());
  }
  // The belt model; throws InvalidArgument if the system is another one.
  const Model& model() const;
  const FlowOptions& options() const { return flow_.options(); }

  // Integrate from (t0, z0) in mode m0 until `stop` says so. With variational,
  // the result carries d z / d z0. With observer and output_dt > 0, samples are
  // reported every output_dt and at every switch.
  FlowResult Run(double t0, const Vec2& z0, Mode m0, const StopRule& stop, bool variational,
                 double output_dt = 0, const Observer& observer = nullptr);
  // Same, starting in the mode the Filippov rule gives z0.
  FlowResult Run(double t0, const Vec2& z0, const StopRule& stop, bool variational = false) {
    return Run(t0, z0, system().ModeAt(z0), stop, variational);
  }

  // The parameter column: with variational runs on the Taylor integrator,
  // dz/dp for this parameter rides in the same recurrences. Throws
  // InvalidArgument for one the system has no column for.
  void set_parameter_column(const ParameterAxis& axis);
  // No column (its stepper is kept for reuse).
  void clear_parameter_column() { flow_.clear_parameter_column(); }
  bool has_parameter_column() const { return flow_.has_parameter_column(); }

  long total_steps() const { return flow_.total_steps(); }
  // The orders of those steps (Taylor only), accumulated like total_steps().
  const TaylorOrders& taylor_orders() const { return flow_.taylor_orders(); }
  // Polled after every step: a run stops with kCancelled once it returns true
  // (interruption, wall-time limits). Empty: never.
  void set_cancel(std::function<bool()> cancel) { flow_.set_cancel(std::move(cancel)); }

 private:
  Flow flow_;
  FlowPoint start_;
  FlowRequest request_;
  FlowRun run_;
};

}  // namespace stickslip
