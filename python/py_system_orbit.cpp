// Periodic orbits of any system in the Python module (issue 31 item 8,
// issue 32): periodic_orbit(system, state) on a Poincare section (the one
// shooting, shooting.hpp) and periodic_orbits(system) for a system with a
// forcing clock (FindOrbits, orbit_search.hpp), as SystemOrbit; without the
// GIL, with Ctrl-C.
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "py_common.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/model/forced.hpp"
#include "stickslip/orbits/orbit_search.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip::python {

namespace {

struct PySystemOrbit {
  OrbitStatus status = OrbitStatus::kNotConverged;
  std::string message, mode;
  py::array start, monodromy, multipliers, lo, hi;
  py::array points;  // its section points over its period, one row each
  std::vector<std::string> modes;
  double period = 0, update = 0;
  bool stable = false, from_exit_map = false;
  int sticks = 0, exits = 0, crossings = 0, iterations = 0;
  int turns = 0;  // the clock's turns per period (0 without a clock)
};

PySystemOrbit OrbitOf(const System& s, const PeriodicOrbit& r,
                      const std::vector<Eigen::VectorXd>& points) {
  PySystemOrbit out;
  const int k = s.contacts();
  out.status = r.status, out.message = r.message, out.mode = ModeSetName(r.start.mode, k);
  out.start = ReadOnlyMatrix(r.start.z, true);
  out.monodromy = ReadOnlyMatrix(r.monodromy, false);
  Eigen::VectorXcd mu(static_cast<Eigen::Index>(r.multipliers.size()));
  for (size_t i = 0; i < r.multipliers.size(); ++i) mu[i] = r.multipliers[i];
  out.multipliers = ReadOnlyMatrix(mu, true);
  out.lo = ReadOnlyMatrix(r.lo, true), out.hi = ReadOnlyMatrix(r.hi, true);
  Eigen::MatrixXd rows(static_cast<Eigen::Index>(points.size()), r.start.z.size());
  for (size_t i = 0; i < points.size(); ++i) rows.row(static_cast<Eigen::Index>(i)) = points[i];
  out.points = ReadOnlyMatrix(rows, false);
  for (const ModeSet& ms : r.modes) out.modes.push_back(ModeSetName(ms, k));
  out.period = r.period, out.update = r.update, out.stable = r.stable;
  out.sticks = r.sticks, out.exits = r.exits, out.crossings = r.crossings;
  out.iterations = r.iterations;
  if (s.clocks() == 1)  // the clock's turns in one period
    out.turns = static_cast<int>(
        std::lround(r.period / PoincareSection::Stroboscopic(s, r.start.z, 1).time));
  return out;
}

PySystemOrbit Orbit(const py::object& system, const Eigen::VectorXd& state,
                    const std::optional<std::string>& section, int m, std::optional<int> turns,
                    std::optional<double> rtol, std::optional<double> atol, int contact) {
  const std::unique_ptr<System> s = SystemOf(system);
  const Eigen::VectorXd z0 = CheckedState(*s, state);
  const ShootingOptions o(FlowFor(system, rtol, atol));
  const std::string err = o.ValidationError();
  if (!err.empty()) throw InvalidArgument(err);
  const PoincareSection sec = SectionOf(*s, SectionOrDefault(*s, section), z0, m, turns, contact);
  const FlowPoint guess = SectionStart(*s, sec, z0);
  Interrupt interrupt;
  PeriodicOrbit r;
  {
    py::gil_scoped_release nogil;
    Shooting shooting(*s, o);
    shooting.flow().set_cancel([&] { return interrupt(); });
    r = shooting.Find(guess, sec);
  }
  interrupt.RaiseIfInterrupted();
  if (!r.ok()) RaiseNumerical(std::string(Name(r.status)) + ": " + r.message);
  return OrbitOf(*s, r, {r.start.z});
}

// Every orbit of a system with one clock at its parameter point (FindOrbits):
// the box the forced oscillator's SearchBox gives, or +- radius.
std::vector<PySystemOrbit> Scan(const py::object& system, int max_m, int max_sticks, int grid,
                                int exit_samples, double radius, std::optional<double> rtol,
                                std::optional<double> atol) {
  const std::unique_ptr<System> s = SystemOf(system);
  if (s->clocks() != 1)
    throw InvalidArgument("periodic_orbits(system): the system has no forcing clock");
  OrbitSearchOptions o;
  o.orbit = ShootingOptions(FlowFor(system, rtol, atol));
  o.max_m = max_m, o.max_sticks = max_sticks, o.grid = grid, o.exit_samples = exit_samples;
  if (!(radius >= 0) || !std::isfinite(radius))
    throw InvalidArgument("radius = " + Repr(radius) + " must be >= 0");
  const auto* forced = dynamic_cast<const ForcedModel*>(s.get());
  if (forced) o.half_width = forced->SearchBox();
  if (radius > 0)  // x within r, x' within r max(1, Omega)
    o.half_width = {radius, radius * (forced ? std::max(1.0, forced->omega()) : 1.0)};
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  FoundOrbits r;
  {
    py::gil_scoped_release nogil;
    r = FindOrbits(*s, o);
  }
  interrupt.RaiseIfInterrupted();
  std::vector<PySystemOrbit> out;
  for (const FoundOrbit& f : r.orbits) {
    out.push_back(OrbitOf(*s, f.orbit, f.points));
    out.back().from_exit_map = f.from_exit_map;
  }
  return out;
}

}  // namespace

void BindSystemOrbit(py::module_& m) {
  using O = PySystemOrbit;
  py::class_<O>(m, "SystemOrbit",
                "Result of periodic_orbit(system, state) and periodic_orbits(system): a periodic "
                "orbit of any system, its section point `start` (the full state, a clock's phase "
                "last), `points` (periodic_orbits: a forced orbit's m stroboscopic points; "
                "periodic_orbit: its start), `turns` of the clock per period.")
      .def_readonly("status", &O::status)
      .def_readonly("message", &O::message)
      .def_readonly("start", &O::start)
      .def_readonly("mode", &O::mode)
      .def_readonly("period", &O::period)
      .def_readonly("monodromy", &O::monodromy)
      .def_readonly("multipliers", &O::multipliers)
      .def_readonly("stable", &O::stable)
      .def_readonly("sticks", &O::sticks)
      .def_readonly("exits", &O::exits)
      .def_readonly("crossings", &O::crossings)
      .def_readonly("modes", &O::modes)
      .def_readonly("lo", &O::lo)
      .def_readonly("hi", &O::hi)
      .def_readonly("iterations", &O::iterations)
      .def_readonly("update", &O::update)
      .def_readonly("points", &O::points)
      .def_readonly("turns", &O::turns)
      .def_readonly("from_exit_map", &O::from_exit_map,
                    "periodic_orbits(): first found on the exit-phase map (else by the strobe)");
  const py::object none = py::none();
  const char* orbit_doc =
      "The periodic orbit of any system through the one near `state` (its state_names' order, a "
      "clock's phase last) on `section` ('stroboscopic': m forcing periods, the default with a "
      "clock; 'stick-exit': the m-th exit of `contact`, after `turns` forcing periods with a "
      "clock, the default without; 'xdot-falling'), by the one shooting (C++ Shooting::Find), "
      "with its monodromy and multipliers. NumericalError where Newton fails.";
  // periodic_orbit(system, state, ...) after the belt's periodic_orbit(params, a_guess, ...).
  for (const char* name : {"system_orbit", "periodic_orbit"})
    m.def(name, &Orbit, py::arg("system"), py::arg("state"), py::arg("section") = none,
          py::arg("m") = 1, py::arg("turns") = none, py::arg("rtol") = none, py::arg("atol") = none,
          py::arg("contact") = 0, orbit_doc);
  // After the belt's periodic_orbits(params, ...).
  m.def("periodic_orbits", &Scan, py::arg("system"), py::arg("max_m") = 4,
        py::arg("max_sticks") = 4, py::arg("grid") = 5, py::arg("exit_samples") = 48,
        py::arg("radius") = 0.0, py::arg("rtol") = none, py::arg("atol") = none,
        "Every periodic orbit of a system with a forcing clock (ForcedParams, a model file's "
        "System with a clock) at one parameter point, m = 1..max_m forcing periods (C++ "
        "FindOrbits): Newton on the stroboscopic map from a grid x grid box of starts (the "
        "forced oscillator's linear response box, or +- radius) and on the exit-phase map; a "
        "list of SystemOrbit, by m.");
}

}  // namespace stickslip::python
