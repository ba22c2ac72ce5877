#include "forced_branch_problem.hpp"

#include <cmath>

#include "forced_shooting.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

const char* ForcedAxisName(ForcedAxis a) { return Name(a); }

double GetAxis(const ForcedParams& p, ForcedAxis a) {
  switch (a) {
    case ForcedAxis::kOmega:
      return p.omega;
    case ForcedAxis::kForce:
      return p.force;
    case ForcedAxis::kV:
      return p.base.v;
    case ForcedAxis::kBeta:
      return p.base.beta;
  }
  return 0;
}

void SetAxis(ForcedParams& p, ForcedAxis a, double value) {
  switch (a) {
    case ForcedAxis::kOmega:
      p.omega = value;
      return;
    case ForcedAxis::kForce:
      p.force = value;
      return;
    case ForcedAxis::kV:
      p.base.v = value;
      return;
    case ForcedAxis::kBeta:
      p.base.beta = value;
      return;
  }
}

const char* ForcedBranchStatusName(ForcedBranchStatus s) { return Name(s); }

const char* ForcedLabelName(ForcedLabel l) { return Name(l); }

namespace forced_detail {

namespace {

OrbitBranchOptions CoreOptions(const ForcedBranchOptions& o) {
  OrbitBranchOptions c;
  c.shooting.flow = FlowOptionsOf(o.flow);
  c.shooting.max_steps = o.flow.max_steps;
  c.max_amplitude = o.max_amplitude;
  c.locate_tol = o.locate_tol;
  return c;
}

int CoreIndex(const ForcedModel& m, ForcedAxis axis) { return m.ParameterIndex(Name(axis)); }

FlowPoint StrobeStart(const ForcedModel& m) {
  return {0, Eigen::Vector3d(0, m.v(), 0), ModeSet(Mode::kSlipBelow)};
}

}  // namespace

StrobeProblem::StrobeProblem(const ForcedParams& base, ForcedAxis axis,
                             const ForcedBranchOptions& o)
    : base_(base),
      axis_(axis),
      o_(o),
      core_options_(CoreOptions(o)),
      core_(ForcedModel(base), CoreIndex(ForcedModel(base), axis), StrobeStart(ForcedModel(base)),
            PoincareSection::Stroboscopic(ForcedModel(base), StrobeStart(ForcedModel(base)).z, o.m),
            core_options_) {}

std::string StrobeProblem::DomainError(const Eigen::VectorXd& u) const {
  ForcedParams q = base_;
  SetAxis(q, axis_, u[2]);
  std::string e = ValidationError(q);
  const double bound = 2 * o_.max_amplitude;  // rows stop at max_amplitude first
  if (e.empty() && !(std::abs(u[0]) <= bound && std::abs(u[1]) <= bound))
    e = "|x| or |x'| = " + Num(std::max(std::abs(u[0]), std::abs(u[1]))) + " beyond max_amplitude";
  return e;
}

ForcedBranchRow StrobeProblem::Row() const {
  const OrbitRow c = core_.Row();
  ForcedBranchRow r;
  r.p = c.p;
  r.x0 = c.start.z[0], r.xdot0 = c.start.z[1];
  r.m = o_.m;
  r.sticks = c.sticks;
  r.crossings = c.crossings;
  r.extrema = Extrema{c.lo[0], c.hi[0], c.lo[1], c.hi[1]};
  r.multipliers[0] = c.multipliers[0], r.multipliers[1] = c.multipliers[1];
  r.stable = std::abs(r.multipliers[0]) < 1;
  return r;
}

}  // namespace forced_detail
}  // namespace stickslip
