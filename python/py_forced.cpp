// The forced oscillator in the Python module (issue 20, item 6):
// x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t). ForcedParams, the
// Parameter enum (ForcedAxis), and simulate_forced, forced_orbit and
// find_forced_orbits (branches: py_orbit_branch.cpp), each without the GIL with
// Ctrl-C polled by the library's cancel hooks (py_common.hpp, Interrupt).
#include "py_forced.hpp"

#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>

#include "py_common.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/forced/branch.hpp"
#include "stickslip/forced/flow.hpp"
#include "stickslip/forced/orbit.hpp"
#include "stickslip/orbits/orbit_search.hpp"

namespace stickslip::python {

FlowOptions FlowOf(std::optional<double> rtol, std::optional<double> atol) {
  FlowOptions o = ForcedModel::FlowDefaults();
  if (rtol) o.rtol = *rtol;
  if (atol) o.atol = *atol;
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  return o;
}

namespace {

std::string Num(double x) { return py::repr(py::float_(x)).cast<std::string>(); }

py::array Modes(const std::vector<std::uint8_t>& codes) {
  py::array names =
      ReadOnlyStrings({Name(Mode::kSlipBelow), Name(Mode::kStick), Name(Mode::kSlipAbove)});
  py::array out = names.attr("__getitem__")(ReadOnly(codes));
  out.attr("setflags")(py::arg("write") = false);
  return out;
}

struct PyForcedTrajectory {
  py::array t, x, xdot, mode, phase;  // every dt and every switch
  py::array section_t, section_x, section_xdot, section_phase;
  SimulationSection section = SimulationSection::kStrobe;
  int sticks = 0, exits = 0, crossings = 0;
  long steps = 0;
  double x_min = 0, x_max = 0, xdot_min = 0, xdot_max = 0;
};

struct PyForcedOrbit {
  int m = 1, sticks = 0, crossings = 0, iterations = 0;
  double x0 = 0, xdot0 = 0, period = 0;
  double x_min = 0, x_max = 0, xdot_min = 0, xdot_max = 0;
  py::array multipliers, monodromy, points;
  bool stable = false, from_exit_map = false;
};

PyForcedOrbit MakeOrbit(const stickslip::PeriodicOrbit& o, int m,
                        const std::vector<Eigen::VectorXd>& pts, bool exit_map) {
  PyForcedOrbit r;
  const Extrema e = OrbitExtrema(o);
  r.m = m, r.sticks = o.sticks, r.crossings = o.crossings, r.iterations = o.iterations;
  r.x0 = o.start.z[0], r.xdot0 = o.start.z[1], r.period = o.period;
  r.x_min = e.x_min, r.x_max = e.x_max;
  r.xdot_min = e.xdot_min, r.xdot_max = e.xdot_max;
  r.stable = o.stable, r.from_exit_map = exit_map;
  r.multipliers = ReadOnly(o.multipliers);
  py::array_t<double> mono({2, 2}), p({static_cast<py::ssize_t>(pts.size()), py::ssize_t(2)});
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) mono.mutable_at(i, j) = o.monodromy(i, j);
  for (size_t i = 0; i < pts.size(); ++i)
    p.mutable_at(i, 0) = pts[i][0], p.mutable_at(i, 1) = pts[i][1];
  mono.attr("setflags")(py::arg("write") = false);
  p.attr("setflags")(py::arg("write") = false);
  r.monodromy = mono, r.points = p;
  return r;
}

PyForcedTrajectory SimulateForced(const ForcedParams& p, double x0, std::optional<double> xdot0,
                                  double t_end, double dt, SimulationSection section, long max_rows,
                                  std::optional<double> rtol, std::optional<double> atol) {
  const ForcedModel model(p);  // throws InvalidArgument naming the value
  SimulationOptions o;
  o.flow = FlowOf(rtol, atol), o.t_end = t_end, o.dt = dt, o.section = section;
  o.period = model.period(), o.max_rows = max_rows, o.extrema = {0, 1};
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  if (!std::isfinite(x0) || (xdot0 && !std::isfinite(*xdot0)))
    throw InvalidArgument("x0, xdot0 must be finite");
  if (!(std::floor(t_end / dt) + 1 <= static_cast<double>(max_rows)))
    throw InvalidArgument("t_end / dt = " + Num(t_end / dt) + " gives more rows than max_rows = " +
                          std::to_string(max_rows) + " (raise max_rows or dt)");
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  std::vector<double> t, x, xd, ph, st, sx, sxd, sph;
  std::vector<std::uint8_t> mode;
  auto phase = [&](double tt) {
    const double a = std::fmod(p.omega * tt, 2 * M_PI);
    return a < 0 ? a + 2 * M_PI : a;
  };
  SimulationSink sink;
  sink.row = [&](double tt, const double* z, const ModeSet& m) {
    t.push_back(tt), x.push_back(z[0]), xd.push_back(z[1]), ph.push_back(phase(tt));
    mode.push_back(static_cast<std::uint8_t>(m[0]));
  };
  sink.section = [&](long, double tt, const double* z, const ModeSet&) {
    st.push_back(tt), sx.push_back(z[0]), sxd.push_back(z[1]), sph.push_back(phase(tt));
  };
  Simulation r;
  {
    py::gil_scoped_release nogil;
    r = Simulate(model, ForcedStart(model, 0, x0, xdot0.value_or(p.base.v)), o, sink);
  }
  interrupt.RaiseIfInterrupted();
  if (r.status == SimulationStatus::kRowLimit)
    throw InvalidArgument(r.message + " (raise max_rows or dt)");
  if (!r.ok()) RaiseNumerical(r.message);
  PyForcedTrajectory out;
  out.t = ReadOnly(t), out.x = ReadOnly(x), out.xdot = ReadOnly(xd), out.phase = ReadOnly(ph);
  out.mode = Modes(mode);
  out.section_t = ReadOnly(st), out.section_x = ReadOnly(sx), out.section_xdot = ReadOnly(sxd);
  out.section_phase = ReadOnly(sph);
  out.section = section, out.sticks = r.sticks, out.exits = r.exits, out.crossings = r.crossings;
  out.steps = r.steps;
  out.x_min = r.lo[0], out.x_max = r.hi[0], out.xdot_min = r.lo[1], out.xdot_max = r.hi[1];
  return out;
}

PyForcedOrbit Orbit(const ForcedParams& p, double x0, double xdot0, int m,
                    std::optional<double> rtol, std::optional<double> atol) {
  const ForcedModel model(p);
  const ShootingOptions o(FlowOf(rtol, atol));
  stickslip::PeriodicOrbit r;
  {
    py::gil_scoped_release nogil;
    r = ShootStroboscopic(model, x0, xdot0, m, o);
  }
  if (!r.ok()) RaiseNumerical(std::string(Name(r.status)) + ": " + r.message);
  return MakeOrbit(r, m, {r.start.z}, false);
}

std::vector<PyForcedOrbit> Scan(const ForcedParams& p, int max_m, int max_sticks, int grid,
                                int exit_samples, double radius, std::optional<double> rtol,
                                std::optional<double> atol) {
  const ForcedModel model(p);
  OrbitSearchOptions o;
  o.orbit = ShootingOptions(FlowOf(rtol, atol));
  o.max_m = max_m, o.max_sticks = max_sticks, o.grid = grid, o.exit_samples = exit_samples;
  if (!(radius >= 0) || !std::isfinite(radius))
    throw InvalidArgument("radius = " + Repr(radius) + " must be >= 0");
  o.half_width = model.SearchBox();  // radius r: x within r, x' within r max(1, Omega)
  if (radius > 0) o.half_width = {radius, radius * std::max(1.0, p.omega)};
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  FoundOrbits r;
  {
    py::gil_scoped_release nogil;
    r = FindOrbits(model, o);
  }
  interrupt.RaiseIfInterrupted();
  std::vector<PyForcedOrbit> out;
  for (const FoundOrbit& s : r.orbits)
    out.push_back(MakeOrbit(s.orbit, s.m, s.points, s.from_exit_map));
  return out;
}

}  // namespace

namespace {

// The enums, ForcedParams and the result classes.
void BindForcedTypes(py::module_& m) {
  py::enum_<Parameter> axis(m, "Parameter",
                            "A parameter of the oscillators, the one lens: the belt's, then the "
                            "forcing's (force, omega). Functions take a member or its name.");
  for (const auto& e : EnumNames<Parameter>::kTable) axis.value(e.name, e.value);
  m.attr("ForcedAxis") = axis;  // its older name
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
  py::class_<ForcedParams>(m, "ForcedParams",
                           "x'' + 2 beta x' + x = F(x' - v) + A cos(Omega t): the belt "
                           "parameters (v >= 0; v = 0 is a fixed floor) plus force A and omega.")
      .def(py::init([](const Params& base, double force, double omega) {
             ForcedParams p;
             p.base = base, p.force = force, p.omega = omega;
             return p;
           }),
           py::arg("params"), py::arg("force") = 0.0, py::arg("omega") = 1.0)
      .def_readwrite("params", &ForcedParams::base)
      .def_readwrite("force", &ForcedParams::force)
      .def_readwrite("omega", &ForcedParams::omega)
      .def(
          "validation_error", [](const ForcedParams& p) { return ValidationError(p); },
          "'' if valid, else one line naming the value");
  py::class_<PyForcedTrajectory>(m, "ForcedTrajectory",
                                 "Result of simulate_forced(): rows every dt and at every switch, "
                                 "and the Poincare section's points.")
      .def("__getitem__", &GetItem, py::arg("key"))
      .def_readonly("t", &PyForcedTrajectory::t)
      .def_readonly("x", &PyForcedTrajectory::x)
      .def_readonly("xdot", &PyForcedTrajectory::xdot)
      .def_readonly("mode", &PyForcedTrajectory::mode)
      .def_readonly("phase", &PyForcedTrajectory::phase, "Omega t mod 2 pi")
      .def_readonly("section", &PyForcedTrajectory::section)
      .def_readonly("section_t", &PyForcedTrajectory::section_t)
      .def_readonly("section_x", &PyForcedTrajectory::section_x)
      .def_readonly("section_xdot", &PyForcedTrajectory::section_xdot)
      .def_readonly("section_phase", &PyForcedTrajectory::section_phase)
      .def_readonly("sticks", &PyForcedTrajectory::sticks)
      .def_readonly("exits", &PyForcedTrajectory::exits)
      .def_readonly("crossings", &PyForcedTrajectory::crossings)
      .def_readonly("steps", &PyForcedTrajectory::steps)
      .def_readonly("x_min", &PyForcedTrajectory::x_min)
      .def_readonly("x_max", &PyForcedTrajectory::x_max)
      .def_readonly("xdot_min", &PyForcedTrajectory::xdot_min)
      .def_readonly("xdot_max", &PyForcedTrajectory::xdot_max);
  py::class_<PyForcedOrbit>(m, "ForcedOrbit", "A periodic orbit of the forced oscillator.")
      .def("__getitem__", &GetItem, py::arg("key"))
      .def_readonly("m", &PyForcedOrbit::m, "period multiple: closes after m forcing periods")
      .def_readonly("sticks", &PyForcedOrbit::sticks, "stick phases per period of the orbit")
      .def_readonly("crossings", &PyForcedOrbit::crossings)
      .def_readonly("iterations", &PyForcedOrbit::iterations)
      .def_readonly("x0", &PyForcedOrbit::x0, "the stroboscopic point at t = 0")
      .def_readonly("xdot0", &PyForcedOrbit::xdot0)
      .def_readonly("period", &PyForcedOrbit::period)
      .def_readonly("x_min", &PyForcedOrbit::x_min)
      .def_readonly("x_max", &PyForcedOrbit::x_max)
      .def_readonly("xdot_min", &PyForcedOrbit::xdot_min)
      .def_readonly("xdot_max", &PyForcedOrbit::xdot_max)
      .def_readonly("multipliers", &PyForcedOrbit::multipliers, "larger modulus first")
      .def_readonly("monodromy", &PyForcedOrbit::monodromy)
      .def_readonly("points", &PyForcedOrbit::points, "(m, 2): its stroboscopic points")
      .def_readonly("stable", &PyForcedOrbit::stable)
      .def_readonly("from_exit_map", &PyForcedOrbit::from_exit_map);
}

}  // namespace

void BindForced(py::module_& m) {
  BindForcedTypes(m);
  BindChaos(m);
  m.def("simulate_forced", &SimulateForced, py::arg("params"), py::arg("x0") = 0.0,
        py::arg("xdot0") = py::none(), py::arg("t_end") = 100.0, py::arg("dt") = 0.01,
        py::arg("section") = SimulationSection::kStrobe, py::arg("max_rows") = 1000000,
        py::arg("rtol") = py::none(), py::arg("atol") = py::none(),
        "One trajectory of the forced oscillator from (x0, xdot0 (default v)) at t = 0, as "
        "ss_simulate --force: rows every dt and at every switch, and the Poincare section.");
  m.def("forced_orbit", &Orbit, py::arg("params"), py::arg("x0"), py::arg("xdot0"),
        py::arg("m") = 1, py::arg("rtol") = py::none(), py::arg("atol") = py::none(),
        "A periodic orbit of multiple m by Newton on the stroboscopic map from (x0, xdot0); "
        "raises NumericalError if Newton fails.");
  m.def("find_forced_orbits", &Scan, py::arg("params"), py::arg("max_m") = 4,
        py::arg("max_sticks") = 4, py::arg("grid") = 5, py::arg("exit_samples") = 48,
        py::arg("radius") = 0.0, py::arg("rtol") = py::none(), py::arg("atol") = py::none(),
        "Every periodic orbit found at one parameter point (m = 1..max_m), by shooting on the "
        "stroboscopic map and on the exit-phase map; a list of ForcedOrbit.");
  // The belt's name for the forced oscillator too (issue 31 item 8), after periodic_orbits(Params).
  m.def("periodic_orbits", &Scan, py::arg("params"), py::arg("max_m") = 4,
        py::arg("max_sticks") = 4, py::arg("grid") = 5, py::arg("exit_samples") = 48,
        py::arg("radius") = 0.0, py::arg("rtol") = py::none(), py::arg("atol") = py::none(),
        "periodic_orbits(ForcedParams, ...): find_forced_orbits'.");
}

}  // namespace stickslip::python
