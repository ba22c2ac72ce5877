// The belt's view of the one flow (systems/belt/belt_flow.hpp): a StopRule as a
// request, the run as 2-D results.
#include "stickslip/systems/belt/belt_flow.hpp"

#include "stickslip/errors.hpp"

namespace stickslip {

namespace {
// The sections of a StopRule, in the order their roots were dispatched
// before: the maximum of x' in slip below, then x' = 0 downwards.
constexpr int kVelocityMaxSection = 0;

Section VelocitySection(bool derivative) {
  Section s;
  s.g.terms[0] = {1, 1.0};
  s.g.size = 1;
  s.derivative = derivative;
  s.direction = -1;
  s.slip_below_only = derivative;
  return s;
}
}  // namespace

namespace {
const FlowOptions& Checked(const FlowOptions& o) {
  const std::string err = o.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  return o;
}
}  // namespace

BeltFlow::BeltFlow(const FrictionSystem& system, const FlowOptions& options)
    : flow_(system, Checked(options)) {
  request_.extrema = {0, 1};
  start_.z.resize(2);
}

const Model& BeltFlow::model() const {
  const auto* belt = dynamic_cast<const Model*>(&flow_.system());
  if (!belt) throw InvalidArgument("Flow::model: the system is not the belt model");
  return *belt;
}

void BeltFlow::set_parameter_column(const ParameterAxis& axis) {
  const auto* belt = dynamic_cast<const Model*>(&flow_.system());
  if (belt && !belt->SupportsParameterColumn(axis))
    throw InvalidArgument("parameter column: '" + axis.name() +
                          "' enters the friction law non-affinely (not supported)");
  const int j = flow_.system().ParameterIndex(axis.name());
  if (j < 0) throw InvalidArgument("parameter column: the system has no parameter " + axis.name());
  flow_.set_parameter_column(j);
}

FlowResult BeltFlow::Run(double t0, const Vec2& z0, Mode m0, const StopRule& stop, bool variational,
                         double output_dt, const Observer& observer) {
  FlowRequest& rq = request_;
  rq.t_max = stop.t_max;
  rq.switching = stop.switching;
  rq.variational = variational;
  rq.parameter_column = variational && has_parameter_column() && m0 != Mode::kStick;
  rq.stop_at_stick = stop.at_stick;
  rq.sections.clear();
  if (stop.at_velocity_max) rq.sections.push_back(VelocitySection(true));
  if (stop.at_section) rq.sections.push_back(VelocitySection(false));
  rq.output_dt = output_dt;
  if (observer && output_dt > 0)
    rq.observer = [&observer](double t, const double* z, const ModeSet& m) {
      observer(Sample{t, Vec2(z[0], z[1]), m[0]});
    };
  else
    rq.observer = nullptr;
  start_.t = t0;
  start_.z[0] = z0[0];
  start_.z[1] = z0[1];
  start_.mode = ModeSet(m0);
  flow_.Run(start_, rq, &run_);
  FlowResult r;
  r.status = run_.status;
  if (r.status == FlowStatus::kSection) {
    const int which = stop.at_velocity_max ? run_.section : run_.section + 1;
    r.status = which == kVelocityMaxSection ? FlowStatus::kVelocityMax : FlowStatus::kSection;
  }
  r.message = run_.message;
  r.t = run_.end.t;
  r.z = Vec2(run_.end.z[0], run_.end.z[1]);
  r.mode = run_.end.mode[0];
  r.extrema = Extrema{run_.lo[0], run_.hi[0], run_.lo[1], run_.hi[1]};
  r.t_stick = run_.t_stick;
  r.switches = run_.switches;
  r.crossings = run_.crossings;
  r.modes.reserve(run_.modes.size());
  for (const ModeSet& m : run_.modes) r.modes.push_back(m[0]);
  if (variational) r.jacobian = run_.jacobian;
  r.has_dzdp = run_.has_dzdp;
  if (r.has_dzdp) r.dzdp = Vec2(run_.dzdp[0], run_.dzdp[1]);
  return r;
}

}  // namespace stickslip
