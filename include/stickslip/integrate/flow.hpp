// Exact event-driven integration of the Filippov belt model: each slip mode is
// integrated on its own smooth field by a stepper (Taylor series by default,
// CVODE selectable) that locates the switches as roots; stick is solved in
// closed form (x' = v). Optionally the variational equations ride along, and
// the saltation matrices are applied at every switch, giving d z(t) / d z(t0).
#pragma once

#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/integrate/extrema.hpp"
#include "stickslip/model/model.hpp"
#include "stickslip/names.hpp"

namespace stickslip {

class Stepper;  // src/integrate/stepper.hpp: private
struct SlipProblem;
struct SegmentOutput;  // src/integrate/event_driver.hpp: private

// The integrator of the slip phases.
enum class Integrator {
  kTaylor,  // Taylor series, order and step from the tolerance (Jorba & Zou 2005)
  kCvode,   // SUNDIALS CVODE with the linear multistep Method below
};
const char* IntegratorName(Integrator i);  // "taylor", "cvode"
template <>
struct EnumNames<Integrator> {
  static constexpr NamedValue<Integrator> kTable[] = {
      {Integrator::kTaylor, "taylor"},
      {Integrator::kCvode, "cvode"},
  };
};

// CVODE's linear multistep method (only with Integrator::kCvode).
enum class Method {
  kAdams,  // Adams-Moulton with fixed-point iteration: non-stiff, the default
  kBdf,    // BDF with Newton and a dense linear solver: for stiff problems
};
const char* MethodName(Method m);  // "adams", "bdf"
template <>
struct EnumNames<Method> {
  static constexpr NamedValue<Method> kTable[] = {
      {Method::kAdams, "adams"},
      {Method::kBdf, "bdf"},
  };
};

struct FlowOptions {
  // max_steps' lower bound (a stepper needs a few steps to start).
  static constexpr long kMinSteps = 10;
  double rtol = 1e-11;  // relative tolerance
  double atol = 1e-13;  // absolute tolerance
  Integrator integrator = Integrator::kTaylor;
  Method method = Method::kAdams;
  long max_steps = 200000;      // steps per call of the stepper (per output interval)
  long max_switches = 1000000;  // mode changes per run
  // Empty if valid, otherwise one line naming the offending option.
  std::string ValidationError() const;
};

// Where a run stops. The defaults integrate until t_max with all switching.
struct StopRule {
  double t_max = std::numeric_limits<double>::infinity();
  bool at_stick = false;         // on arrival in Omega, before sticking
  bool at_section = false;       // where x' crosses 0 downwards (a maximum of x)
  bool at_velocity_max = false;  // at the first maximum of x' in slip below, after the start
  bool switching = true;         // false: stay on the start mode's smooth field
};

enum class FlowStatus {
  kTimeLimit,         // reached t_max
  kStick,             // arrived in Omega (StopRule::at_stick)
  kSection,           // x' = 0 downwards (StopRule::at_section)
  kVelocityMax,       // a maximum of x' (StopRule::at_velocity_max)
  kIntegratorFailed,  // the stepper failed (e.g. step-size underflow); message says where
  kTooManySwitches,   // more than FlowOptions::max_switches mode changes
  kCancelled,         // the cancel hook returned true
};
const char* FlowStatusName(FlowStatus s);
template <>
struct EnumNames<FlowStatus> {
  static constexpr NamedValue<FlowStatus> kTable[] = {
      {FlowStatus::kTimeLimit, "time-limit"},
      {FlowStatus::kStick, "stick"},
      {FlowStatus::kSection, "section"},
      {FlowStatus::kVelocityMax, "velocity-max"},
      {FlowStatus::kIntegratorFailed, "integrator-failed"},
      {FlowStatus::kTooManySwitches, "too-many-switches"},
      {FlowStatus::kCancelled, "cancelled"},
  };
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
  // d z(t) / dp at fixed t and fixed start, for Flow's parameter column:
  // has_dzdp only on a run without switches (one smooth slip segment; the
  // saltation for a parameter is not modelled) and with the Taylor integrator.
  Vec2 dzdp = Vec2::Zero();
  bool has_dzdp = false;
  bool ok() const {
    return status != FlowStatus::kIntegratorFailed && status != FlowStatus::kTooManySwitches &&
           status != FlowStatus::kCancelled;
  }
};

// The orders of the Taylor steps taken (CVODE's steps count none): order p,
// or p + TaylorField::ExtraOrder, or p again where those extra orders overflow.
struct TaylorOrders {
  long steps = 0;        // Taylor steps
  long sum = 0;          // the sum of their orders (mean: sum / steps)
  int min = 0, max = 0;  // over those steps; 0 without steps
  long fallbacks = 0;    // steps recomputed at p: their order p + extra overflowed
  void Merge(const TaylorOrders& o) {
    fallbacks += o.fallbacks;
    if (o.steps == 0) return;
    min = steps == 0 ? o.min : std::min(min, o.min);
    max = std::max(max, o.max);
    steps += o.steps;
    sum += o.sum;
  }
};

class Flow {
 public:
  // Any system on the model seam (system.hpp; the belt: Model). Throws
  // InvalidArgument if options are invalid.
  Flow(const FrictionSystem& system, const FlowOptions& options);
  ~Flow();
  Flow(const Flow&) = delete;
  Flow& operator=(const Flow&) = delete;

  // Change the system; solvers are kept and reused.
  void set_model(const FrictionSystem& system) {
    if (!system_->Assign(system)) system_ = system.Clone();
  }
  const FrictionSystem& system() const { return *system_; }
  // The belt model; throws InvalidArgument if the system is another one.
  const Model& model() const;
  const FlowOptions& options() const { return options_; }

  // Integrate from (t0, z0) in mode m0 until `stop` says so. With variational,
  // the result carries d z / d z0. With observer and output_dt > 0, samples are
  // reported every output_dt and at every switch.
  FlowResult Run(double t0, const Vec2& z0, Mode m0, const StopRule& stop, bool variational,
                 double output_dt = 0, const Observer& observer = nullptr);
  // Same, starting in the mode the Filippov rule gives z0.
  FlowResult Run(double t0, const Vec2& z0, const StopRule& stop, bool variational = false) {
    return Run(t0, z0, system_->ModeAt(z0), stop, variational);
  }

  // The parameter column: with variational runs on the Taylor integrator,
  // dz/dp for this parameter rides in the same recurrences. Throws
  // InvalidArgument for one the system has no column for (SupportsParameterColumn).
  void set_parameter_column(const ParameterAxis& axis);
  // No column (its stepper is kept for reuse).
  void clear_parameter_column() { parameter_.reset(); }
  bool has_parameter_column() const {
    return parameter_ && options_.integrator == Integrator::kTaylor;
  }

  long total_steps() const { return total_steps_; }
  // The orders of those steps (Taylor only), accumulated like total_steps().
  const TaylorOrders& taylor_orders() const { return taylor_orders_; }
  // Polled after every step: a run stops with kCancelled once it returns true
  // (interruption, wall-time limits). Empty: never.
  void set_cancel(std::function<bool()> cancel) { cancel_ = std::move(cancel); }

 private:
  struct SlipEnd;
  struct Walk;
  SlipEnd Slip(double t0, const Vec2& z0, const StopRule& stop, bool variational,
               const SegmentOutput& out, FlowResult& r);
  bool Stick(Walk& w, const StopRule& stop, bool variational);
  void Switch(Walk& w, Mode next);
  static FlowStatus SlipStatus(int kind);
  bool Settled(const SlipProblem& problem, const double* y) const;
  std::string Where(const char* what, double t) const;
  // Sets r.message to the failure at (t, y); returns t.
  double Failed(double t, const double* y, const std::string& reason, FlowResult& r) const;
  Stepper& Solver(bool variational);

  std::unique_ptr<FrictionSystem> system_;
  FlowOptions options_;
  Mode mode_ = Mode::kSlipBelow;  // the mode being integrated
  std::unique_ptr<Stepper> plain_, var_, param_;
  std::optional<ParameterAxis> parameter_, param_axis_;  // the active column; param_'s
  long total_steps_ = 0;
  TaylorOrders taylor_orders_;
  std::function<bool()> cancel_;
};

}  // namespace stickslip
