// The forced oscillator's parameters in the Python module (issue 20, item 6):
// x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t). ForcedBeltParams, the
// Parameter enum (the one lens) and BranchStatus; it runs through the
// functions of every system (simulate, periodic_orbit, periodic_orbits,
// basins: py_system_runs.cpp, py_attractors.cpp; issue 31 item 8).
#include "py_forced.hpp"

#include <pybind11/stl.h>

#include "py_common.hpp"
#include "stickslip/continuation/branch_status.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

FlowOptions FlowOf(std::optional<double> rtol, std::optional<double> atol) {
  FlowOptions o = ForcedBelt::FlowDefaults();
  if (rtol) o.rtol = *rtol;
  if (atol) o.atol = *atol;
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  return o;
}

namespace {

// The enums and ForcedBeltParams.
void BindForcedTypes(py::module_& m) {
  py::enum_<Parameter> axis(m, "Parameter",
                            "A parameter of the oscillators, the one lens: the belt's, then the "
                            "forcing's (force, omega). Functions take a member or its name.");
  for (const auto& e : EnumNames<Parameter>::kTable) axis.value(e.name, e.value);
  py::enum_<BranchStatus>(m, "BranchStatus", "How a branch ended (every system's).")
      .value("reached_end", BranchStatus::kReachedEnd)
      .value("unbounded", BranchStatus::kUnbounded)
      .value("step_too_small", BranchStatus::kStepTooSmall)
      .value("start_failed", BranchStatus::kStartFailed)
      .value("max_points", BranchStatus::kMaxPoints)
      .value("closed", BranchStatus::kClosed)
      .value("cancelled", BranchStatus::kCancelled)
      .value("left_range", BranchStatus::kLeftRange)
      .value("contact_lost", BranchStatus::kContactLost)
      .value("sequence_ended", BranchStatus::kSequenceEnded);
  py::class_<ForcedBeltParams>(
      m, "ForcedBeltParams",
      "x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t): the belt "
      "parameters (v >= 0; v = 0 is a fixed floor) plus force A and omega.")
      .def(py::init([](const Params& base, double force, double omega) {
             ForcedBeltParams p;
             p.base = base, p.force = force, p.omega = omega;
             return p;
           }),
           py::arg("params"), py::arg("force") = 0.0, py::arg("omega") = 1.0)
      .def_readwrite("params", &ForcedBeltParams::base)
      .def_readwrite("force", &ForcedBeltParams::force)
      .def_readwrite("omega", &ForcedBeltParams::omega)
      .def(
          "validation_error", [](const ForcedBeltParams& p) { return ValidationError(p); },
          "'' if valid, else one line naming the value");
}

}  // namespace

void BindForced(py::module_& m) {
  BindForcedTypes(m);
  BindChaos(m);
}

}  // namespace stickslip::python
