// Periodic orbits of any system in the Python module (issue 31 item 8,
// issue 32): periodic_orbit(system, state) on a Poincare section (the one
// shooting, shooting.hpp) and periodic_orbits(system) for a system with a
// forcing clock (FindOrbits, orbit_search.hpp) or none (FindAutonomousOrbits),
// as SystemOrbit; without the GIL, with Ctrl-C.
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
#include "stickslip/orbits/orbit_search.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/forced/forced.hpp"

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
  // periodic_orbits() of an autonomous system: its section, its stick
  // phases per contact, and the start of the run it came from.
  int contact = 0, returns = 0, origin_mode = -1;
  std::vector<int> contact_sticks;
  py::array origin;
  bool origin_imaginary = false;
  double origin_amplitude = 0;
  double largest = 0;  // the largest |multiplier| (0 if none), for the repr
};

std::string OrbitRepr(const PySystemOrbit& o) {
  std::string r = "<SystemOrbit " + std::string(Name(o.status));
  if (o.status != OrbitStatus::kOk) return r + ": " + o.message + ">";
  r += ": period " + Repr(o.period);
  if (o.turns > 0) r += ", m = " + std::to_string(o.turns);
  r += ", sticks " + std::to_string(o.sticks) + ", largest |multiplier| " + Repr(o.largest);
  return r + (o.stable ? ", stable>" : ", unstable>");
}

PySystemOrbit OrbitOf(const System& s, const PeriodicOrbit& r,
                      const std::vector<Eigen::VectorXd>& points) {
  PySystemOrbit out;
  const int k = s.contacts();
  out.status = r.status, out.message = r.message, out.mode = ModeSetName(r.start.mode, k);
  out.origin = ReadOnlyMatrix(Eigen::VectorXd(), true);  // autonomous scans set it
  out.start = ReadOnlyMatrix(r.start.z, true);
  out.monodromy = ReadOnlyMatrix(r.monodromy, false);
  Eigen::VectorXcd mu(static_cast<Eigen::Index>(r.multipliers.size()));
  for (size_t i = 0; i < r.multipliers.size(); ++i) mu[i] = r.multipliers[i];
  out.largest = mu.size() > 0 ? mu.cwiseAbs().maxCoeff() : 0.0;
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

template <typename T>
void Reject(const std::optional<T>& given, const char* name, const char* kind) {
  if (given) throw InvalidArgument(std::string(name) + " is an option of " + kind + " only");
}

// Every orbit of a system with one clock at its parameter point (FindOrbits):
// the box the forced oscillator's SearchBox gives, or +- radius.
std::vector<PySystemOrbit> ForcedScan(const py::object& system, const System& s, int max_m,
                                      int max_sticks, int grid, int exit_samples, double radius,
                                      std::optional<double> rtol, std::optional<double> atol) {
  OrbitSearchOptions o;
  o.orbit = ShootingOptions(FlowFor(system, rtol, atol));
  o.max_m = max_m, o.max_sticks = max_sticks, o.grid = grid, o.exit_samples = exit_samples;
  if (!(radius >= 0) || !std::isfinite(radius))
    throw InvalidArgument("radius = " + Repr(radius) + " must be >= 0");
  const auto* forced = dynamic_cast<const ForcedBelt*>(&s);
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
    r = FindOrbits(s, o);
  }
  interrupt.RaiseIfInterrupted();
  std::vector<PySystemOrbit> out;
  for (const FoundOrbit& f : r.orbits) {
    out.push_back(OrbitOf(s, f.orbit, f.points));
    out.back().from_exit_map = f.from_exit_map;
  }
  return out;
}

// An empty scan says why, as a RuntimeWarning: its counts and the first
// failed run's message (an error if warnings are errors).
void WarnNoOrbit(const AutonomousOrbits& r) {
  std::string w =
      "periodic_orbits: no periodic orbit found (" + std::to_string(r.starts.size()) + " starts" +
      (r.starts.empty() ? ": no steady sliding to start from and no starts given" : "") + ", " +
      std::to_string(r.failed) + " runs failed, " + std::to_string(r.shots) + " Newton solves, " +
      std::to_string(r.converged) + " converged)";
  if (!r.message.empty()) w += "; first failed run: " + r.message;
  if (PyErr_WarnEx(PyExc_RuntimeWarning, w.c_str(), 1) != 0) throw py::error_already_set();
}

// Every orbit of an autonomous system (FindAutonomousOrbits).
std::vector<PySystemOrbit> AutonomousScan(const System& s, AutonomousSearchOptions o) {
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  AutonomousOrbits r;
  {
    py::gil_scoped_release nogil;
    r = FindAutonomousOrbits(s, o);
  }
  interrupt.RaiseIfInterrupted();
  if (r.orbits.empty()) WarnNoOrbit(r);
  std::vector<PySystemOrbit> out;
  for (const AutonomousOrbit& f : r.orbits) {
    PySystemOrbit p = OrbitOf(s, f.orbit, f.points);
    p.contact = f.section.contact, p.returns = f.section.returns, p.contact_sticks = f.sticks;
    const ScanStart& from = r.starts[f.start];
    p.origin = ReadOnlyMatrix(from.z, true), p.origin_mode = from.mode;
    p.origin_imaginary = from.imaginary, p.origin_amplitude = from.amplitude;
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<PySystemOrbit> Scan(const py::object& system, std::optional<int> max_m,
                                std::optional<int> max_sticks, std::optional<int> grid,
                                std::optional<int> exit_samples, std::optional<double> radius,
                                std::optional<double> rtol, std::optional<double> atol,
                                std::optional<std::vector<double>> amplitudes,
                                std::optional<double> transient,
                                std::optional<std::vector<Eigen::VectorXd>> starts,
                                std::optional<int> max_returns, std::optional<double> scale) {
  const std::unique_ptr<System> s = SystemOf(system);
  const char *forced = "a system with a forcing clock", *autonomous = "an autonomous system";
  if (s->clocks() > 1)
    throw InvalidArgument("periodic_orbits(system): the system has " + std::to_string(s->clocks()) +
                          " clocks");
  if (s->clocks() == 1) {
    Reject(amplitudes, "amplitudes", autonomous), Reject(transient, "transient", autonomous);
    Reject(starts, "starts", autonomous), Reject(max_returns, "max_returns", autonomous);
    Reject(scale, "scale", autonomous);
    return ForcedScan(system, *s, max_m.value_or(4), max_sticks.value_or(4), grid.value_or(5),
                      exit_samples.value_or(48), radius.value_or(0), rtol, atol);
  }
  Reject(max_m, "max_m", forced), Reject(max_sticks, "max_sticks", forced);
  Reject(grid, "grid", forced), Reject(exit_samples, "exit_samples", forced);
  Reject(radius, "radius", forced);
  AutonomousSearchOptions o;
  o.orbit = ShootingOptions(FlowFor(system, rtol, atol));
  if (amplitudes) o.amplitudes = *amplitudes;
  if (starts) o.starts = *starts;  // checked by FindAutonomousOrbits, by name
  o.transient = transient.value_or(o.transient), o.scale = scale.value_or(o.scale);
  o.max_returns = max_returns.value_or(o.max_returns);
  return AutonomousScan(*s, std::move(o));
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
                    "periodic_orbits(): first found on the exit-phase map (else by the strobe)")
      .def_readonly("contact", &O::contact, "autonomous periodic_orbits(): the section's contact")
      .def_readonly("returns", &O::returns, "... and its stick exits per period")
      .def_readonly("contact_sticks", &O::contact_sticks, "... stick phases per contact")
      .def_readonly("origin", &O::origin, "... the start of the run it was found from")
      .def_readonly("origin_mode", &O::origin_mode,
                    "... that start's mode of steady sliding (eigenvalue index; -1: given)")
      .def_readonly("origin_imaginary", &O::origin_imaginary,
                    "... along its eigenvector's imaginary part (else the real part)")
      .def_readonly("origin_amplitude", &O::origin_amplitude, "... times the scale")
      .def("__repr__", &OrbitRepr);
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
  m.def("periodic_orbits", &Scan, py::arg("system"), py::arg("max_m") = none,
        py::arg("max_sticks") = none, py::arg("grid") = none, py::arg("exit_samples") = none,
        py::arg("radius") = none, py::arg("rtol") = none, py::arg("atol") = none,
        py::arg("amplitudes") = none, py::arg("transient") = none, py::arg("starts") = none,
        py::arg("max_returns") = none, py::arg("scale") = none,
        "Every periodic orbit of a system at one parameter point, a list of SystemOrbit. With a "
        "forcing clock (ForcedBeltParams, a model file's System with a clock; C++ FindOrbits): m = "
        "1..max_m (4) forcing periods, Newton on the stroboscopic map from a grid x grid (5) box "
        "of starts (the forced oscillator's linear response box, or +- radius) and on the "
        "exit-phase map (max_sticks 4, exit_samples 48); by m. Autonomous (ChainParams, "
        "ModeCouplingParams, a model file's System; C++ FindAutonomousOrbits): runs of "
        "`transient` (300) time units from steady sliding + a scale d along each mode "
        "(amplitudes a, default [0.01, 0.1, 0.3]; scale 0: max(1, |steady sliding|)) and from "
        "`starts`, then Newton on each contact's stick-exit section from the runs' last exits "
        "(recurrences up to max_returns 16 exits); each orbit once, by period. The options of "
        "the other kind raise ValueError.");
}

}  // namespace stickslip::python
