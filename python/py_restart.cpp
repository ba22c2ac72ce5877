// restart(): a labelled point of an earlier ss_continue run (AUTO-07p's IRS),
// read back from its directory, and the options that start a new branch or
// chart there, as ss_continue --restart and ss_chart --restart do.
#include <pybind11/stl.h>

#include <cmath>

#include "py_common.hpp"
#include "stickslip/chart/chart.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/io/restart.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

namespace {

// The new branch in `param` (default: the run's) from the point to the far
// end of the parameter's default range (`to` overrides), with the run's solver.
ContinuationOptions BranchOptions(const LabelledPoint& lp, std::optional<ParameterAxis> param,
                                  std::optional<double> to) {
  if (lp.forced)
    throw InvalidArgument(lp.label + " is a point of a forced run: continue_branch(point." +
                          "forced_params(), parameter, (*point.state, 0.0), to, m=point.m)");
  ContinuationOptions o;
  o.param = param.value_or(lp.param);
  const ParameterRange r = RangeFromPoint(lp.params, o.param);
  o.from = r.from, o.to = to.value_or(r.to);
  o.orbit.flow = lp.flow;
  const std::string err = o.ValidationError(lp.params);
  if (!err.empty()) throw InvalidArgument(err);
  return o;
}

// A chart of the run's parameter by param2 whose first curve starts at the
// point (a GR or HB point, inside the rectangle), with the run's solver.
ChartOptions ChartFrom(const LabelledPoint& lp, const ParameterAxis& param2, double from, double to,
                       double from2, double to2) {
  if (lp.forced)  // its axis is the forcing's or the forced model's: no belt chart
    throw InvalidArgument(lp.label + " is a point of a forced run: a forced chart is ss_chart " +
                          "--force A --omega W --param omega --param2 force");
  if (lp.type != "GR" && lp.type != "HB")
    throw InvalidArgument(lp.label + " is a " + lp.type + " point: a chart starts from a GR or " +
                          "HB point");
  ChartOptions o;
  o.plane.p1 = lp.param, o.plane.p2 = param2;
  o.plane.from1 = from, o.plane.to1 = to, o.plane.from2 = from2, o.plane.to2 = to2;
  const int max_steps = o.orbit.flow.max_steps;  // the chart's step cap
  o.orbit.flow = lp.flow, o.orbit.flow.max_steps = max_steps;
  const std::string err = o.ValidationError(lp.params);
  if (!err.empty()) throw InvalidArgument(err);
  ChartOptions::Seed s;
  s.kind = lp.type == "GR" ? CurveKind::kGrazing : CurveKind::kHopf;
  s.p1 = o.plane.p1.Get(lp.params), s.p2 = o.plane.p2.Get(lp.params);
  if (!o.plane.Contains(s.p1, s.p2))
    throw InvalidArgument(lp.label + ": (" + o.plane.p1.name() + ", " + o.plane.p2.name() +
                          ") = (" + Repr(s.p1) + ", " + Repr(s.p2) +
                          ") lies outside the chart's rectangle");
  o.seeds.push_back(s);
  return o;
}

}  // namespace

void BindRestart(py::module_& m) {
  const py::object none = py::none();
  py::class_<LabelledPoint>(m, "LabelledPoint",
                            "A point of an earlier ss_continue run, with everything a new run "
                            "needs to start there (restart()).")
      .def_readonly("label", &LabelledPoint::label, "'HB1', 'GR1', ... or the point number")
      .def_readonly("pt", &LabelledPoint::pt, "its row of branch.tsv (1-based)")
      .def_readonly("type", &LabelledPoint::type, "GR, HB, LP or the row's kind")
      .def_property_readonly("param", &LabelledPoint::ParamName,
                             "the name of the parameter that run continued")
      .def_readonly("p", &LabelledPoint::p, "its value at the point")
      .def_readonly("params", &LabelledPoint::params, "every parameter at the point")
      .def_readonly("flow", &LabelledPoint::flow, "that run's integrator and tolerances")
      .def_property_readonly(
          "state", [](const LabelledPoint& lp) { return py::make_tuple(lp.state[0], lp.state[1]); },
          "(x_start, xdot_start)")
      .def_property_readonly(
          "period",
          [](const LabelledPoint& lp) -> py::object {
            return std::isfinite(lp.period) ? py::object(py::float_(lp.period)) : py::none();
          },
          "the orbit's period; None for steady sliding")
      .def_readonly("forced", &LabelledPoint::forced, "a point of a forced run (--force)")
      .def_readonly("force", &LabelledPoint::force, "a forced run's A at the point")
      .def_readonly("omega", &LabelledPoint::omega, "a forced run's Omega at the point")
      .def_readonly("m", &LabelledPoint::m, "a forced run's period multiple at the point")
      .def(
          "forced_params",
          [](const LabelledPoint& lp) {
            if (!lp.forced) throw InvalidArgument(lp.label + " is a point of a belt run");
            ForcedBeltParams fp;
            fp.base = lp.params, fp.force = lp.force, fp.omega = lp.omega;
            return fp;
          },
          "A forced run's point: its ForcedBeltParams; with (*state, 0.0) (the stroboscopic point "
          "at theta = 0) and m it starts continue_branch there.")
      .def("options", &BranchOptions, py::arg("param") = none, py::arg("to") = none,
           "ContinuationOptions of a new branch in param (default: the run's) from the point "
           "to the far end of default_range (or to), with the run's solver: "
           "continue_branch(point.params, options=point.options('beta')).")
      .def("chart_options", &ChartFrom, py::arg("param2") = "beta", py::arg("from_") = 0.05,
           py::arg("to") = 0.6, py::arg("from2") = 0.0, py::arg("to2") = 0.25,
           "ChartOptions of a chart in (the run's parameter, param2) whose first curve starts "
           "at this GR or HB point: chart(point.params, options=point.chart_options()).")
      .def("__repr__", [](const LabelledPoint& lp) {
        return "LabelledPoint('" + lp.label + "', pt=" + std::to_string(lp.pt) + ", type='" +
               lp.type + "', " + lp.ParamName() + "=" + Repr(lp.p) + ")";
      });
  m.def(
      "restart",
      [](const std::string& dir, const py::object& point) {
        return ReadLabelledPoint(dir, py::str(point).cast<std::string>());
      },
      py::arg("dir"), py::arg("point"),
      "The point `point` (a label of special_points.tsv: 'HB1', 'GR1', ..., or a point "
      "number of branch.tsv) of the ss_continue run in dir, as a LabelledPoint "
      "(AUTO's IRS). A missing or corrupt run, or an unknown point, raises InvalidArgument.");
}

}  // namespace stickslip::python
