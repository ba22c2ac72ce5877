// The computing functions of the Python module: simulation, periodic orbits,
// continuation and basins. Each validates its arguments under the GIL, then
// computes without it; the library's cancel hook watches for Ctrl-C
// (Interrupt), and a numerical failure raises NumericalError.
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>

#include "py_results.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/orbits/orbit_scan.hpp"

namespace stickslip::python {

namespace {

// simulate(): rows are t_end / dt + 1 plus one per switch, at most max_rows.
Trajectory Simulate(const Params& p, double x0, double xdot0, double t_end, double dt,
                    long max_rows, std::optional<double> rtol, std::optional<double> atol,
                    const py::object& integrator, const py::object& method) {
  if (!std::isfinite(x0) || !std::isfinite(xdot0))
    throw InvalidArgument("x0, xdot0 = " + Repr(x0) + ", " + Repr(xdot0) + " must be finite");
  if (!(t_end > 0)) throw InvalidArgument("t_end = " + Repr(t_end) + " must be > 0");
  if (!(dt > 0)) throw InvalidArgument("dt = " + Repr(dt) + " must be > 0");
  if (max_rows < 2)
    throw InvalidArgument("max_rows = " + std::to_string(max_rows) + " must be >= 2");
  const double grid_rows = std::floor(t_end / dt) + 1;
  if (!(grid_rows <= static_cast<double>(max_rows)))
    throw InvalidArgument("t_end / dt = " + Repr(t_end / dt) + " gives more rows than max_rows = " +
                          std::to_string(max_rows) + " (raise max_rows or dt)");
  const FlowOptions options = Solver(FlowOptions(), rtol, atol, integrator, method);
  const Model model(p);
  std::vector<double> t, x, xdot;
  std::vector<std::uint8_t> mode;
  Interrupt interrupt;
  SimulationOptions o;
  o.flow = options, o.t_end = t_end, o.dt = dt, o.max_rows = max_rows, o.extrema = {0, 1};
  o.cancelled = [&] { return interrupt(); };
  SimulationSink sink;
  sink.row = [&](double ti, const double* z, const ModeSet& m) {
    t.push_back(ti), x.push_back(z[0]), xdot.push_back(z[1]);
    mode.push_back(static_cast<std::uint8_t>(m[0]));
  };
  Simulation r;
  {
    py::gil_scoped_release nogil;
    const Vec2 z0(x0, xdot0);
    r = stickslip::Simulate(model, FlowPoint{0, z0, ModeSet(model.ModeAt(z0))}, o, sink);
  }
  interrupt.RaiseIfInterrupted();
  if (r.status == SimulationStatus::kRowLimit)
    throw InvalidArgument("the switches took the rows past max_rows = " + std::to_string(max_rows) +
                          " at t = " + Repr(t.back()) + " (raise max_rows or dt)");
  if (!r.ok())
    RaiseNumerical(r.message + " (at t = " + Repr(r.end.t) + " in " + Name(r.end.mode[0]) + ")");
  Trajectory out;
  out.t = ReadOnly(t), out.x = ReadOnly(x), out.xdot = ReadOnly(xdot);
  py::array names =
      ReadOnlyStrings({Name(Mode::kSlipBelow), Name(Mode::kStick), Name(Mode::kSlipAbove)});
  out.mode = names.attr("__getitem__")(ReadOnly(mode));  // codes to names
  out.mode.attr("setflags")(py::arg("write") = false);
  out.status = r.flow, out.t_stick = r.t_stick, out.switches = r.switches;
  out.crossings = r.crossings, out.x_min = r.lo[0], out.x_max = r.hi[0];
  out.xdot_min = r.lo[1], out.xdot_max = r.hi[1];
  return out;
}

// A stick-slip orbit (a_guess None) or a pure-slip orbit by Newton from xbar + a_guess.
Orbit PeriodicOrbit(const Params& p, std::optional<double> a_guess, bool floquet,
                    std::optional<double> rtol, std::optional<double> atol,
                    const py::object& integrator, const py::object& method) {
  OrbitOptions options;
  options.flow = Solver(options.flow, rtol, atol, integrator, method);
  options.floquet = floquet;
  const std::string err = options.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  if (a_guess && !(*a_guess > 0))
    throw InvalidArgument("a_guess = " + Repr(*a_guess) + " must be > 0");
  const Model model(p);
  Interrupt interrupt;
  OrbitResult r;
  {
    py::gil_scoped_release nogil;
    OrbitFinder finder(model, options);
    finder.flow().set_cancel([&] { return interrupt(); });
    r = a_guess ? finder.PureSlip(*a_guess) : finder.StickSlip();
  }
  interrupt.RaiseIfInterrupted();
  if (!r.ok()) RaiseNumerical(std::string(Name(r.status)) + ": " + r.message);
  return r.orbit;
}

// progress: None or a callable (TypeError otherwise).
void CheckCallable(const py::object& progress) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be a callable, not " +
                         py::str(py::type::of(progress).attr("__name__")).cast<std::string>());
}

Branch ContinueBranch(const Params& base, std::optional<ParameterAxis> param,
                      std::optional<double> from, std::optional<double> to,
                      std::optional<double> max_step, std::optional<bool> floquet,
                      std::optional<double> rtol, std::optional<double> atol,
                      const py::object& integrator, const py::object& method,
                      std::optional<ContinuationOptions> options, const py::object& progress) {
  CheckCallable(progress);
  ContinuationOptions opts = options.value_or(ContinuationOptions());
  if (param) opts.param = *param;  // a member or a name (py_common.hpp)
  if (!options) {                  // the library's range for this parameter around base
    const ParameterRange range = DefaultRange(base, opts.param);
    opts.from = range.from, opts.to = range.to;
  }
  if (from) opts.from = *from;
  if (to) opts.to = *to;
  if (max_step) opts.max_step = *max_step;
  if (floquet) opts.stick_slip_floquet = *floquet;
  opts.orbit.flow = Solver(opts.orbit.flow, rtol, atol, integrator, method);
  Interrupt interrupt;
  ProgressCall call(progress);
  opts.cancelled = [&] { return call.failed() || interrupt(); };
  if (!progress.is_none()) {
    long n = 0;
    opts.progress = [&](const BranchPoint& q) { call(++n, q.p, Name(q.kind), q.stable); };
  }
  ContinuationResult r;
  {
    py::gil_scoped_release nogil;
    r = Continue(base, opts);  // throws InvalidArgument on bad options
  }
  interrupt.RaiseIfInterrupted();
  call.RaiseIfFailed();
  if (r.status == ContinuationStatus::kFailed) RaiseNumerical(r.message);
  return MakeBranch(std::move(r), base, std::move(opts));
}

OrbitScanOptions ScanOptions(std::optional<OrbitScanOptions> options, std::optional<int> samples,
                             std::optional<double> rtol, std::optional<double> atol,
                             const py::object& integrator, const py::object& method) {
  OrbitScanOptions scan = options.value_or(OrbitScanOptions());
  if (samples) scan.samples = *samples;
  scan.orbit.flow = Solver(scan.orbit.flow, rtol, atol, integrator, method);
  return scan;
}

PeriodicOrbits PeriodicOrbitsAt(const Params& p, std::optional<int> samples,
                                std::optional<double> rtol, std::optional<double> atol,
                                const py::object& integrator, const py::object& method,
                                std::optional<OrbitScanOptions> options) {
  OrbitScanOptions scan = ScanOptions(options, samples, rtol, atol, integrator, method);
  const std::string err = scan.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  const Model model(p);
  Interrupt interrupt;
  scan.cancelled = [&] { return interrupt(); };
  PeriodicOrbits r;
  {
    py::gil_scoped_release nogil;
    r = FindPeriodicOrbits(model, scan);
  }
  interrupt.RaiseIfInterrupted();
  if (r.status == OrbitScanStatus::kFailed) RaiseNumerical(r.message);
  return r;
}

using Range = std::optional<std::pair<double, double>>;

Basins BasinsOf(const Params& p, std::optional<int> nx, std::optional<int> ny, Range x_range,
                Range xdot_range, std::optional<double> t_cap, std::optional<double> rtol,
                std::optional<double> atol, const py::object& integrator, const py::object& method,
                std::optional<BasinOptions> options, const py::object& progress) {
  CheckCallable(progress);
  BasinOptions o = options.value_or(BasinOptions());
  o.scan = ScanOptions(o.scan, std::nullopt, rtol, atol, integrator, method);
  if (nx) o.nx = *nx;
  if (ny) o.ny = *ny;
  if (t_cap) o.t_cap = *t_cap;
  if (x_range.has_value() != xdot_range.has_value())
    throw InvalidArgument("x_range and xdot_range go together (or neither: the orbits' box)");
  if (x_range) {
    o.auto_range = false;
    o.x_lo = x_range->first, o.x_hi = x_range->second;
    o.xdot_lo = xdot_range->first, o.xdot_hi = xdot_range->second;
  }
  const std::string err = o.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  const Model model(p);
  Interrupt interrupt;
  ProgressCall call(progress);
  o.cancelled = [&] { return call.failed() || interrupt(); };
  if (!progress.is_none()) o.progress = [&](int done, int total) { call(done, total); };
  BasinResult r;
  {
    py::gil_scoped_release nogil;
    r = ClassifyBasins(model, o);
  }
  interrupt.RaiseIfInterrupted();
  call.RaiseIfFailed();
  if (r.status == BasinStatus::kFailed) RaiseNumerical(r.message);
  return MakeBasins(r);
}

py::array CurveOf(const Params& p, const Orbit& orbit, int n) {
  if (n < 2) throw InvalidArgument("n = " + std::to_string(n) + " must be >= 2");
  const Model model(p);
  std::vector<Vec2> pts;
  {
    py::gil_scoped_release nogil;
    pts = OrbitCurve(model, orbit, FlowOptions(), n);
  }
  py::array_t<double> out({static_cast<py::ssize_t>(pts.size()), py::ssize_t{2}});
  for (size_t i = 0; i < pts.size(); ++i)
    out.mutable_at(i, 0) = pts[i][0], out.mutable_at(i, 1) = pts[i][1];
  out.attr("setflags")(py::arg("write") = false);
  return std::move(out);
}

}  // namespace

void BindCompute(py::module_& m) {
  const py::object none = py::none();
  m.def("simulate", &Simulate, py::arg("params"), py::arg("x0") = 0.0, py::arg("xdot0") = 0.25,
        py::arg("t_end") = 100.0, py::arg("dt") = 0.01, py::arg("max_rows") = 1000000,
        py::arg("rtol") = none, py::arg("atol") = none, py::arg("integrator") = none,
        py::arg("method") = none,
        "One trajectory (as ss_simulate): a Trajectory with arrays t, x, xdot, mode, one row "
        "every dt and at every switch. More than max_rows rows raise ValueError (up front for "
        "t_end / dt). integrator 'taylor' (default) or 'cvode'; method 'adams' or 'bdf' "
        "(CVODE's; alone it selects CVODE).");
  m.def("periodic_orbit", &PeriodicOrbit, py::arg("params"), py::arg("a_guess") = none,
        py::arg("floquet") = false, py::arg("rtol") = none, py::arg("atol") = none,
        py::arg("integrator") = none, py::arg("method") = none,
        "The stick-slip orbit (a_guess None) or the pure-slip orbit by Newton from the section "
        "point xbar + a_guess, as an Orbit.");
  m.def("continue_branch", &ContinueBranch, py::arg("params"), py::arg("param") = none,
        py::arg("from_") = none, py::arg("to") = none, py::arg("max_step") = none,
        py::arg("floquet") = none, py::arg("rtol") = none, py::arg("atol") = none,
        py::arg("integrator") = none, py::arg("method") = none, py::arg("options") = none,
        py::arg("progress") = none,
        "Branches in one parameter (as ss_continue) from from_ to to: a Branch with points "
        "(arrays), special (GR/HB/LP SpecialPoints), status and message. param defaults to "
        "'v'; from_/to to default_range(params, param), or to options' values. Keywords "
        "override options (a ContinuationOptions). progress(pt, p, kind, stable) is called "
        "after every point; an exception it raises stops the run and is raised again.");
  m.def("periodic_orbits", &PeriodicOrbitsAt, py::arg("params"), py::arg("samples") = none,
        py::arg("rtol") = none, py::arg("atol") = none, py::arg("integrator") = none,
        py::arg("method") = none, py::arg("options") = none,
        "Every periodic orbit at one parameter point (steady sliding, stick-slip, every "
        "pure-slip orbit), as PeriodicOrbits.");
  m.def("basins", &BasinsOf, py::arg("params"), py::arg("nx") = none, py::arg("ny") = none,
        py::arg("x_range") = none, py::arg("xdot_range") = none, py::arg("t_cap") = none,
        py::arg("rtol") = none, py::arg("atol") = none, py::arg("integrator") = none,
        py::arg("method") = none, py::arg("options") = none, py::arg("progress") = none,
        "Basins of attraction (as ss_basin): the fate of each start of an nx by ny grid on "
        "x_range by xdot_range (default: the orbits' box widened by a quarter). "
        "progress(done, total) is called after every start; an exception it raises stops the "
        "run and is raised again.");
  m.def("orbit_curve", &CurveOf, py::arg("params"), py::arg("orbit"), py::arg("n") = 400,
        "One period of an orbit at n + 1 points, as an (n + 1, 2) array of (x, x').");
  m.def(
      "smallest_disturbance",
      [](const Params& p, const Orbit& orbit, int n) {
        const Model model(p);
        Interrupt interrupt;
        Disturbance d;
        {
          py::gil_scoped_release nogil;
          d = SmallestDisturbance(model, orbit, FlowOptions(), n, [&] { return interrupt(); });
        }
        interrupt.RaiseIfInterrupted();
        return d;
      },
      py::arg("params"), py::arg("orbit"), py::arg("n") = 4000,
      "The smallest disturbance of steady sliding that reaches a pure-slip orbit, from n "
      "samples of one period (16 <= n <= 10**8).");
}

}  // namespace stickslip::python
