// chart(): the stability chart in two parameters (as ss_chart).
#include <pybind11/stl.h>

#include "py_results.hpp"
#include "stickslip/errors.hpp"

namespace stickslip::python {

namespace {

ChartOut ChartOf(const Params& base, std::optional<ParameterAxis> param, std::optional<double> from,
                 std::optional<double> to, std::optional<ParameterAxis> param2,
                 std::optional<double> from2, std::optional<double> to2,
                 std::optional<double> max_step, std::optional<std::pair<int, int>> regions,
                 std::optional<double> rtol, std::optional<double> atol,
                 const py::object& integrator, const py::object& method,
                 std::optional<ChartOptions> options) {
  ChartOptions opts = options.value_or(ChartOptions());
  Plane& pl = opts.plane;
  if (param) pl.p1 = *param;  // a member or a name (py_common.hpp)
  if (from) pl.from1 = *from;
  if (to) pl.to1 = *to;
  if (param2) pl.p2 = *param2;
  if (from2) pl.from2 = *from2;
  if (to2) pl.to2 = *to2;
  if (max_step) opts.max_step = *max_step;
  if (regions) opts.region_n1 = regions->first, opts.region_n2 = regions->second;
  opts.orbit.flow = Solver(opts.orbit.flow, rtol, atol, integrator, method);
  const std::string err = opts.ValidationError(base);
  if (!err.empty()) throw InvalidArgument(err);
  Interrupt interrupt;
  opts.cancelled = [&] { return interrupt(); };
  ChartResult r;
  {
    py::gil_scoped_release nogil;
    r = Chart(base, opts);
  }
  interrupt.RaiseIfInterrupted();
  if (r.status == ChartStatus::kFailed) RaiseNumerical(r.message);
  return MakeChartOut(r, opts.plane);
}

}  // namespace

void BindCharts(py::module_& m) {
  const py::object none = py::none();
  m.def("chart", &ChartOf, py::arg("params"), py::arg("param") = none, py::arg("from_") = none,
        py::arg("to") = none, py::arg("param2") = none, py::arg("from2") = none,
        py::arg("to2") = none, py::arg("max_step") = none, py::arg("regions") = none,
        py::arg("rtol") = none, py::arg("atol") = none, py::arg("integrator") = none,
        py::arg("method") = none, py::arg("options") = none,
        "The stability chart in two parameters (as ss_chart): a Chart with curves (HB, GR, LP "
        "ChartCurves; curve[param] is its array of that parameter) and codim2 points (GH, "
        "GR-LP). The rectangle defaults to v in [0.05, 0.6] by beta in [0, 0.25]; regions=(n1, "
        "n2) also classifies a grid of cells (Chart.regions).");
}

}  // namespace stickslip::python
