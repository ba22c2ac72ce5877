// The library's enums and option structs as Python types. Each enum's str()
// is the library's name ("slip-below", "ok", ...), as in the TSV files.
#include <pybind11/stl.h>

#include <algorithm>
#include <string>

#include "py_common.hpp"
#include "stickslip/basin/basin.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/orbits/orbit_scan.hpp"

namespace stickslip::python {

namespace {

template <typename E>
py::enum_<E> Enum(py::module_& m, const char* name, const char* doc, const char* (*label)(E)) {
  py::enum_<E> e(m, name, doc);
  // Replaces enum_'s __str__ ("Mode.stick"): a def() would only add an overload.
  e.attr("__str__") = py::cpp_function([label](E v) { return std::string(label(v)); },
                                       py::name("__str__"), py::is_method(e));
  return e;
}

void BindEnums(py::module_& m) {
  Enum<LawKind>(m, "Law", "Friction law mu(s), s = |x' - v| (Params.law takes its name).", &Name)
      .value("cubic", LawKind::kCubic, "mu_s - k1 s + k3 s^3 - k5 s^5 (seed eq. 3.3)")
      .value("coulomb", LawKind::kCoulomb, "mu_k in slip, static mu_s")
      .value("stribeck", LawKind::kStribeck, "mu_k + (mu_s - mu_k) exp(-s / v_s)")
      .value("leine", LawKind::kLeine, "mu_s / (1 + delta s) (Leine et al. 1998)");
  Enum<Integrator>(m, "Integrator", "Integrator of the slip phases.", &Name)
      .value("taylor", Integrator::kTaylor, "Taylor series (Jorba & Zou 2005), the default")
      .value("cvode", Integrator::kCvode, "SUNDIALS CVODE with Method adams or bdf");
  Enum<Method>(m, "Method", "CVODE's linear multistep method.", &Name)
      .value("adams", Method::kAdams, "Adams-Moulton: non-stiff")
      .value("bdf", Method::kBdf, "BDF with Newton: stiff problems");
  Enum<Mode>(m, "Mode", "Mode of the Filippov system (seed eq. 3.6-3.8).", &Name)
      .value("slip_below", Mode::kSlipBelow, "x' < v")
      .value("stick", Mode::kStick, "x' = v, |x + 2 beta v| <= mu_s")
      .value("slip_above", Mode::kSlipAbove, "x' > v");
  Enum<FlowStatus>(m, "FlowStatus", "How a simulation ended.", &Name)
      .value("time_limit", FlowStatus::kTimeLimit)
      .value("stick", FlowStatus::kStick)
      .value("section", FlowStatus::kSection)
      .value("velocity_max", FlowStatus::kVelocityMax)
      .value("integrator_failed", FlowStatus::kIntegratorFailed)
      .value("too_many_switches", FlowStatus::kTooManySwitches)
      .value("cancelled", FlowStatus::kCancelled)
      .value("stick_exit", FlowStatus::kStickExit)
      .value("too_much_work", FlowStatus::kTooMuchWork)
      .value("inconsistent_mode", FlowStatus::kInconsistentMode)
      .value("ambiguous_mode", FlowStatus::kAmbiguousMode)
      .value("too_many_at_once", FlowStatus::kTooManyAtOnce)
      .value("contact_open", FlowStatus::kContactOpen, "a normal force reached 0");
  Enum<OrbitKind>(m, "OrbitKind", "Kind of periodic orbit.", &Name)
      .value("stick_slip", OrbitKind::kStickSlip, "one stick phase per period")
      .value("pure_slip", OrbitKind::kPureSlip, "never sticks");
  {  // every value of its name table, "no-return" as no_return: complete by construction
    auto e = Enum<OrbitStatus>(m, "OrbitStatus",
                               "How an orbit search ended (orbits()' status codes).", &Name);
    for (const auto& [value, name] : EnumNames<OrbitStatus>::kTable) {
      std::string id(name);
      std::replace(id.begin(), id.end(), '-', '_');
      e.value(id.c_str(), value);
    }
  }
  Enum<PointKind>(m, "PointKind", "Kind of branch point.", &Name)
      .value("stick_slip", PointKind::kStickSlip)
      .value("pure_slip", PointKind::kPureSlip)
      .value("equilibrium", PointKind::kEquilibrium, "steady sliding");
  Enum<SpecialKind>(
      m, "SpecialKind",
      "Special point of a branch (label GR, HB, LP, PD, NS, SL, AD, CR, CL; none: a plain row).",
      &SpecialLabel)
      .value("grazing", SpecialKind::kGrazing, "GR: the stick phase shrinks to zero")
      .value("hopf", SpecialKind::kHopf, "HB: 2 beta + mu'(v) = 0")
      .value("fold", SpecialKind::kFold, "LP: the branch turns back")
      .value("period_doubling", SpecialKind::kPeriodDoubling, "PD: a multiplier at -1")
      .value("torus", SpecialKind::kTorus, "NS: a complex pair on the unit circle")
      .value("sliding", SpecialKind::kSliding, "SL: the switching sequence changes")
      .value("adding", SpecialKind::kAdding, "AD: a stick phase splits, or two merge")
      .value("crossing", SpecialKind::kCrossing, "CR: a crossing reaches the static limit")
      .value("contact_loss", SpecialKind::kContactLoss, "CL: a normal force reaches 0")
      .value("none", SpecialKind::kNone, "a plain row");
  Enum<ContinuationStatus>(m, "ContinuationStatus", "How a continuation ended.", &Name)
      .value("ok", ContinuationStatus::kOk)
      .value("failed", ContinuationStatus::kFailed, "a numerical failure: message says where")
      .value("cancelled", ContinuationStatus::kCancelled);
  Enum<CurveKind>(m, "CurveKind", "Curve of a stability chart (label HB, GR, LP, PD, NS).",
                  &CurveLabel)
      .value("hopf", CurveKind::kHopf)
      .value("grazing", CurveKind::kGrazing)
      .value("fold", CurveKind::kFold)
      .value("period_doubling", CurveKind::kPeriodDoubling, "PD: a forced orbit's")
      .value("torus", CurveKind::kTorus, "NS: a forced orbit's");
  Enum<ChartStatus>(m, "ChartStatus", "How a chart ended.", &Name)
      .value("ok", ChartStatus::kOk)
      .value("failed", ChartStatus::kFailed, "a numerical failure: message says where")
      .value("partial", ChartStatus::kPartial, "a curve cut short or a region cell failed")
      .value("cancelled", ChartStatus::kCancelled);
  Enum<Region>(m, "Region", "Region of the stability chart.", &Name)
      .value("steady_only", Region::kSteadyOnly, "stable steady sliding, no oscillation")
      .value("stick_slip", Region::kStickSlip, "stick-slip, steady sliding unstable")
      .value("pure_slip", Region::kPureSlip, "pure-slip oscillation, steady sliding unstable")
      .value("bistable", Region::kBistable, "an oscillation beside stable steady sliding");
  Enum<Fate>(m, "Fate", "Where a start of the basin grid settles.", &Name)
      .value("steady_sliding", Fate::kSteadySliding)
      .value("stick_slip", Fate::kStickSlip)
      .value("pure_slip", Fate::kPureSlip)
      .value("undecided", Fate::kUndecided, "not settled by t_cap");
  Enum<OrbitScanStatus>(m, "OrbitScanStatus", "How periodic_orbits() ended.", &Name)
      .value("ok", OrbitScanStatus::kOk)
      .value("failed", OrbitScanStatus::kFailed)
      .value("cancelled", OrbitScanStatus::kCancelled);
  Enum<BasinStatus>(m, "BasinStatus", "How a basin classification ended.", &Name)
      .value("ok", BasinStatus::kOk)
      .value("failed", BasinStatus::kFailed)
      .value("cancelled", BasinStatus::kCancelled);
}

template <typename T>
py::class_<T> Options(py::module_& m, const char* name, const char* doc) {
  py::class_<T> c(m, name, doc);
  c.def(py::init<>(), "The library's defaults.");
  c.def("__copy__", [](const T& o) { return T(o); });
  return c;
}

}  // namespace

void BindOptions(py::module_& m) {
  BindEnums(m);
  py::enum_<SimulationSection>(m, "SimulationSection", "The Poincare section of a simulation.")
      .value("strobe", SimulationSection::kStrobe)
      .value("exit", SimulationSection::kExit)
      .value("none", SimulationSection::kNone);
  Options<FlowOptions>(m, "FlowOptions", "Integrator settings of every run.")
      .def_readwrite("rtol", &FlowOptions::rtol, "relative tolerance (1e-11)")
      .def_readwrite("atol", &FlowOptions::atol, "absolute tolerance (1e-13)")
      .def_readwrite("integrator", &FlowOptions::integrator, "Integrator.taylor (default)")
      .def_readwrite("method", &FlowOptions::method, "CVODE's method (Method.adams)")
      .def_readwrite("max_steps", &FlowOptions::max_steps, "steps per output interval")
      .def_readwrite("max_switches", &FlowOptions::max_switches, "mode changes per run")
      .def("validation_error", &FlowOptions::ValidationError, "'' if valid, else why not");
  Options<OrbitOptions>(m, "OrbitOptions", "Orbit search: integration and Newton settings.")
      .def_readwrite("flow", &OrbitOptions::flow)
      .def_readwrite("floquet", &OrbitOptions::floquet, "variational equations, multipliers")
      .def_readwrite("max_return_time", &OrbitOptions::max_return_time)
      .def_readwrite("max_newton", &OrbitOptions::max_newton)
      .def_readwrite("newton_tol", &OrbitOptions::newton_tol)
      .def("validation_error", &OrbitOptions::ValidationError);
  Options<ContinuationOptions>(m, "ContinuationOptions", "Settings of continue_branch().")
      .def_property(
          "param", [](const ContinuationOptions& o) { return o.param.name(); },
          [](ContinuationOptions& o, const ParameterAxis& a) { o.param = a; },
          "the continued parameter (a Parameter or its name; an unknown one raises ValueError)")
      .def_readwrite("from_", &ContinuationOptions::from, "first value of the parameter")
      .def_readwrite("to", &ContinuationOptions::to, "last value of the parameter")
      .def_readwrite("orbit", &ContinuationOptions::orbit)
      .def_readwrite("max_step", &ContinuationOptions::max_step, "fraction of |to - from|")
      .def_readwrite("min_step", &ContinuationOptions::min_step)
      .def_readwrite("locate_tol", &ContinuationOptions::locate_tol)
      .def_readwrite("max_points", &ContinuationOptions::max_points, "per branch")
      .def_readwrite("stick_slip_floquet", &ContinuationOptions::stick_slip_floquet)
      .def("validation_error", &ContinuationOptions::ValidationError, py::arg("params"));
  Options<Plane>(m, "Plane", "The rectangle of a chart: p1 in [from1, to1], p2 in [from2, to2].")
      .def_property(
          "p1", [](const Plane& pl) { return pl.p1.name(); },
          [](Plane& pl, const ParameterAxis& a) { pl.p1 = a; })
      .def_property(
          "p2", [](const Plane& pl) { return pl.p2.name(); },
          [](Plane& pl, const ParameterAxis& a) { pl.p2 = a; })
      .def_readwrite("from1", &Plane::from1)
      .def_readwrite("to1", &Plane::to1)
      .def_readwrite("from2", &Plane::from2)
      .def_readwrite("to2", &Plane::to2)
      .def("validation_error",
           py::overload_cast<const Params&>(&Plane::ValidationError, py::const_),
           py::arg("params"));
  Options<ChartOptions>(m, "ChartOptions", "Settings of chart().")
      .def_readwrite("plane", &ChartOptions::plane)
      .def_readwrite("orbit", &ChartOptions::orbit)
      .def_readwrite("max_step", &ChartOptions::max_step, "fraction of the rectangle")
      .def_readwrite("samples", &ChartOptions::samples, "test-function samples per line")
      .def_readwrite("hopf_curves", &ChartOptions::hopf_curves)
      .def_readwrite("grazing_curves", &ChartOptions::grazing_curves)
      .def_readwrite("fold_curves", &ChartOptions::fold_curves)
      .def_readwrite("region_n1", &ChartOptions::region_n1, "region grid; 0: none")
      .def_readwrite("region_n2", &ChartOptions::region_n2)
      .def("validation_error", &ChartOptions::ValidationError, py::arg("params"));
  Options<OrbitScanOptions>(m, "OrbitScanOptions", "Settings of periodic_orbits().")
      .def_readwrite("orbit", &OrbitScanOptions::orbit)
      .def_readwrite("samples", &OrbitScanOptions::samples, "section amplitudes sampled")
      .def_readwrite("a_min", &OrbitScanOptions::a_min, "relative to mu_s + |v|")
      .def("validation_error", &OrbitScanOptions::ValidationError);
  Options<BasinOptions>(m, "BasinOptions", "Settings of basins().")
      .def_readwrite("scan", &BasinOptions::scan)
      .def_readwrite("auto_range", &BasinOptions::auto_range, "box around the orbits")
      .def_readwrite("x_lo", &BasinOptions::x_lo)
      .def_readwrite("x_hi", &BasinOptions::x_hi)
      .def_readwrite("xdot_lo", &BasinOptions::xdot_lo)
      .def_readwrite("xdot_hi", &BasinOptions::xdot_hi)
      .def_readwrite("nx", &BasinOptions::nx)
      .def_readwrite("ny", &BasinOptions::ny)
      .def_readwrite("t_cap", &BasinOptions::t_cap, "a start not settled by then: undecided")
      .def_readwrite("settle", &BasinOptions::settle)
      .def("validation_error", &BasinOptions::ValidationError);
}

}  // namespace stickslip::python
