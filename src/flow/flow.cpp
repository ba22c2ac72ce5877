// The one flow's public face (flow.hpp): options, the system it runs, and
// the Filippov mode of a state; one Run is the engine's (engine.cpp).
#include "stickslip/flow/flow.hpp"

#include <cmath>
#include <sstream>

#include "flow/cached_flow.hpp"
#include "flow/engine.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

// Formats only on failure: a caller may validate options per call, and
// building a stream every time cost 12 % of forced_bench (callgrind).
std::string FlowOptions::ValidationError() const {
  using T = Tolerances;
  const bool cvode_floor =
      integrator == Integrator::kCvode && !(rtol >= T::kCvodeRtolMin && atol >= T::kCvodeAtolMin);
  if ((rtol >= T::kRtolMin && rtol <= T::kTolMax) && (atol >= T::kAtolMin && atol <= T::kTolMax) &&
      !cvode_floor && max_steps >= kMinSteps && max_switches >= 1)
    return "";
  std::ostringstream os;
  if (!(rtol >= T::kRtolMin && rtol <= T::kTolMax)) {
    os << "rtol = " << rtol << " must be in [" << T::kRtolMin << ", " << T::kTolMax << "]";
  } else if (!(atol >= T::kAtolMin && atol <= T::kTolMax)) {
    os << "atol = " << atol << " must be in [" << T::kAtolMin << ", " << T::kTolMax << "]";
  } else if (cvode_floor) {
    os << "rtol = " << rtol << ", atol = " << atol << ": CVODE needs rtol >= " << T::kCvodeRtolMin
       << " and atol >= " << T::kCvodeAtolMin;
  } else if (max_steps < kMinSteps) {
    os << "max_steps = " << max_steps << " must be >= " << kMinSteps;
  } else {
    os << "max_switches = " << max_switches << " must be >= 1";
  }
  return os.str();
}

std::unique_ptr<Stepper> MakeTaylorStepper(const FlowOptions& options, bool variational,
                                           std::optional<int> parameter);
std::unique_ptr<Stepper> MakeCvodeStepper(const FlowOptions& options, const System& system,
                                          bool variational);

std::unique_ptr<Stepper> MakeStepper(const FlowOptions& options, const System& system,
                                     bool variational, std::optional<int> parameter) {
  return options.integrator == Integrator::kTaylor
             ? MakeTaylorStepper(options, variational, parameter)
             : MakeCvodeStepper(options, system, variational);
}

namespace {
// What the flow itself needs of its options: tolerances the steppers can
// meet (Taylor to kFlowRtolMin; CVODE stalls below its floors) and
// positive caps. Tools check their own, tighter, ranges at entry.
std::string CoreError(const FlowOptions& o) {
  using T = Tolerances;
  std::ostringstream os;
  if (!(o.rtol >= T::kFlowRtolMin && o.rtol <= T::kTolMax))
    os << "rtol = " << o.rtol << " must lie in [" << T::kFlowRtolMin << ", " << T::kTolMax << "]";
  else if (!(o.atol >= T::kAtolMin && o.atol <= T::kTolMax))
    os << "atol = " << o.atol << " must lie in [" << T::kAtolMin << ", " << T::kTolMax << "]";
  else if (o.integrator == Integrator::kCvode &&
           !(o.rtol >= T::kCvodeRtolMin && o.atol >= T::kCvodeAtolMin))
    os << "rtol = " << o.rtol << ", atol = " << o.atol
       << ": CVODE needs rtol >= " << T::kCvodeRtolMin << " and atol >= " << T::kCvodeAtolMin;
  else if (o.max_steps < 1)
    os << "max_steps = " << o.max_steps << " must be >= 1";
  else if (o.max_switches < 1)
    os << "max_switches = " << o.max_switches << " must be >= 1";
  return os.str();
}
}  // namespace

namespace {
// Sizes the flow can hold, then the system's own validation.
std::string SystemError(const System& s) {
  if (s.dimension() < 1 || s.clocks() < 0 || s.clocks() >= s.dimension())
    return "Flow: a system of dimension " + std::to_string(s.dimension()) + " with " +
           std::to_string(s.clocks()) + " clocks";
  if (s.contacts() < 1 || s.contacts() > ModeSet::kMaxContacts)
    return "Flow: contacts = " + std::to_string(s.contacts()) + " must lie in [1, " +
           std::to_string(ModeSet::kMaxContacts) + "]";
  const std::string e = s.ValidationError();
  return e.empty() ? ContactVelocityError(s) : e;
}
}  // namespace

Flow::Flow(const System& system, const FlowOptions& options)
    : system_(system.Clone()), options_(options) {
  std::string err = CoreError(options);
  if (err.empty()) err = SystemError(system);
  if (!err.empty()) throw InvalidArgument(err);
}

Flow::~Flow() = default;

void Flow::set_system(const System& system) {
  const std::string err = SystemError(system);
  if (!err.empty()) throw InvalidArgument(err);
  const bool same_shape = system.dimension() == system_->dimension() &&
                          system.contacts() == system_->contacts() &&
                          system.clocks() == system_->clocks();
  if (!system_->Assign(system)) system_ = system.Clone();
  if (!same_shape) engine_.reset();  // its steppers are sized for the old system
  if (engine_) engine_->Invalidate();
}

void Flow::set_parameter_column(int j) {
  if (!system_->SupportsParameterColumn(j))
    throw InvalidArgument(
        "parameter column: '" +
        (j >= 0 && j < system_->parameters() ? system_->ParameterName(j) : std::to_string(j)) +
        "' enters the friction law non-affinely (not supported)");
  parameter_ = j;
}

void Flow::Run(const FlowPoint& start, const FlowRequest& request, FlowRun* out) {
  if (!engine_) engine_ = std::make_unique<flow_detail::Engine>(*this);
  engine_->Run(start, request, out);
  total_steps_ += out->steps;  // once per run, not per segment (same sums)
  taylor_orders_.Merge(out->orders);
}

}  // namespace stickslip

namespace stickslip {

Flow& CachedFlow(const System& system, const FlowOptions& options) {
  thread_local std::unique_ptr<Flow> cached;
  if (cached && cached->options() == options) {
    cached->set_system(system);
    return *cached;
  }
  cached = std::make_unique<Flow>(system, options);
  return *cached;
}

}  // namespace stickslip
