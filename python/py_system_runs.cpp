// Running any system from Python (issue 32): simulate_system (the one flow,
// flow.hpp) and steady_sliding (equilibria/steady_sliding.hpp; orbits:
// py_system_orbit.cpp), for Params, ForcedBeltParams, ChainParams and
// CouplingParams alike (SystemOf). Each computes without the GIL, with Ctrl-C.
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
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/orbits/orbit_search.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

namespace {

struct PySystemTrajectory {
  py::array t, z, mode;            // every dt and at every switch; z one row per t
  py::array section_t, section_z;  // the Poincare section's points (section != none)
  SimulationSection section = SimulationSection::kNone;
  std::vector<std::string> names;
  FlowStatus status = FlowStatus::kTimeLimit;
  std::string message;
  int opened = -1, sticks = 0, exits = 0, crossings = 0;
  double t_stick = 0;
};

struct PySteadyState {
  bool found = false, stable = false;
  py::array z, eigenvalues;
  double max_real = 0;
};

// The stroboscopic section's spacing: `period`, else one period of the
// system's clock (a forced system's 2 pi / Omega).
double SectionPeriod(const System& s, const Eigen::VectorXd& z0, std::optional<double> period) {
  if (period) return *period;  // SimulationOptions::ValidationError checks it
  if (s.clocks() != 1)
    throw InvalidArgument("section = strobe: give period, the system has no forcing clock");
  return PoincareSection::Stroboscopic(s, z0, 1).time;
}

PySystemTrajectory SimulateSystem(const py::object& system, const Eigen::VectorXd& state,
                                  double t_end, double dt, long max_rows,
                                  std::optional<double> rtol, std::optional<double> atol,
                                  SimulationSection section, std::optional<double> period) {
  const std::unique_ptr<System> s = SystemOf(system);
  const Eigen::VectorXd z0 = CheckedState(*s, state);
  if (period && section != SimulationSection::kStrobe)
    throw InvalidArgument("period = " + Repr(*period) + " needs section = strobe");
  if (!(t_end > 0) || !std::isfinite(t_end))
    throw InvalidArgument("t_end = " + Repr(t_end) + " must be a finite number > 0");
  if (!(dt > 0) || !std::isfinite(dt))
    throw InvalidArgument("dt = " + Repr(dt) + " must be a finite number > 0");
  if (max_rows < 2)
    throw InvalidArgument("max_rows = " + std::to_string(max_rows) + " must be >= 2");
  if (!(std::floor(t_end / dt) + 1 <= static_cast<double>(max_rows)))
    throw InvalidArgument("t_end / dt = " + Repr(t_end / dt) + " gives more rows than max_rows = " +
                          std::to_string(max_rows) + " (raise max_rows or dt)");
  const FlowOptions options = FlowFor(system, rtol, atol);
  const int n = s->dimension(), k = s->contacts();
  std::vector<double> t, z, st, sz;
  std::vector<std::string> mode;
  Interrupt interrupt;
  SimulationOptions o;
  o.flow = options, o.t_end = t_end, o.dt = dt, o.max_rows = max_rows, o.section = section;
  if (section == SimulationSection::kStrobe) o.period = SectionPeriod(*s, z0, period);
  const std::string e = o.ValidationError();
  if (!e.empty()) throw InvalidArgument(e);
  if (section == SimulationSection::kStrobe &&
      !(std::floor(t_end / dt) + std::floor(t_end / o.period) + 2 <= static_cast<double>(max_rows)))
    throw InvalidArgument("t_end / dt + t_end / period = " + Repr(t_end / dt + t_end / o.period) +
                          " rows and section points is more than max_rows = " +
                          std::to_string(max_rows) + " (raise max_rows, dt or period)");
  o.cancelled = [&] { return interrupt(); };
  SimulationSink sink;
  sink.row = [&](double ti, const double* zi, const ModeSet& m) {
    t.push_back(ti), z.insert(z.end(), zi, zi + n), mode.push_back(ModeSetName(m, k));
  };
  sink.section = [&](long, double ti, const double* zi, const ModeSet&) {
    st.push_back(ti), sz.insert(sz.end(), zi, zi + n);
  };
  Simulation r;
  {
    py::gil_scoped_release nogil;
    r = Simulate(*s, FlowPoint{0, z0, ModeOf(*s, z0)}, o, sink);
  }
  interrupt.RaiseIfInterrupted();
  if (r.status == SimulationStatus::kRowLimit)
    throw InvalidArgument(r.message + " (raise max_rows or dt)");
  if (!r.ok())  // contact-open is a result: the run stops there (issue 32)
    RaiseNumerical(r.message + " (at t = " + Repr(r.end.t) + " in " + ModeSetName(r.end.mode, k) +
                   ")");
  PySystemTrajectory out;
  out.t = ReadOnly(t), out.z = ReadOnlyRows(z, n), out.mode = ReadOnlyStrings(mode);
  out.section = section, out.section_t = ReadOnly(st), out.section_z = ReadOnlyRows(sz, n);
  for (int i = 0; i < n; ++i) out.names.push_back(s->StateName(i));
  out.status = r.flow, out.message = r.message;
  out.opened = r.opened;
  out.sticks = r.sticks, out.exits = r.exits, out.crossings = r.crossings, out.t_stick = r.t_stick;
  return out;
}

PySteadyState Steady(const py::object& system) {
  const std::unique_ptr<System> s = SystemOf(system);
  const SteadyState r = SteadySliding(*s);
  PySteadyState out;
  out.found = r.found, out.stable = r.stable(), out.max_real = r.max_real;
  out.z = ReadOnlyMatrix(r.z, true);
  Eigen::VectorXcd ev(static_cast<Eigen::Index>(r.eigenvalues.size()));
  for (size_t i = 0; i < r.eigenvalues.size(); ++i) ev[i] = r.eigenvalues[i];
  out.eigenvalues = ReadOnlyMatrix(ev, true);
  return out;
}

}  // namespace

void BindSystemRuns(py::module_& m) {
  using T = PySystemTrajectory;
  py::class_<T>(m, "SystemTrajectory",
                "Result of simulate(system, state) and simulate_system(): t, z (one row per t, "
                "columns `names`), mode (the "
                "mode set's name per row), how the run ended (status; contact_open: the normal "
                "force of contact `opened` reached 0 and the run stopped there).")
      .def_readonly("t", &T::t)
      .def_readonly("z", &T::z)
      .def_readonly("mode", &T::mode)
      .def_readonly("section", &T::section)
      .def_readonly("section_t", &T::section_t)
      .def_readonly("section_z", &T::section_z)
      .def_readonly("names", &T::names)
      .def_readonly("status", &T::status)
      .def_readonly("message", &T::message)
      .def_readonly("opened", &T::opened)
      .def_readonly("sticks", &T::sticks)
      .def_readonly("exits", &T::exits)
      .def_readonly("crossings", &T::crossings)
      .def_readonly("t_stick", &T::t_stick);
  using S = PySteadyState;
  py::class_<S>(m, "SteadyState", "Result of steady_sliding().")
      .def_readonly("found", &S::found)
      .def_readonly("z", &S::z)
      .def_readonly("eigenvalues", &S::eigenvalues)
      .def_readonly("max_real", &S::max_real)
      .def_readonly("stable", &S::stable);
  const py::object none = py::none();
  const char* doc =
      "One trajectory of any system (Params, ForcedBeltParams, ChainParams, CouplingParams) from "
      "`state` (its state_names' order) at t = 0, one row every dt and at every switch, and with "
      "`section` its Poincare section (strobe: every `period`, by default the forcing's 2 pi / "
      "Omega; exit: every stick exit) in section_t, section_z; the one Simulate (C++). More "
      "than max_rows rows and section points raise ValueError.";
  for (const char* name : {"simulate_system", "simulate"})
    m.def(name, &SimulateSystem, py::arg("system"), py::arg("state"), py::arg("t_end") = 100.0,
          py::arg("dt") = 0.01, py::arg("max_rows") = 1000000, py::arg("rtol") = none,
          py::arg("atol") = none, py::arg("section") = SimulationSection::kNone,
          py::arg("period") = none, doc);
  m.def("steady_sliding", &Steady, py::arg("system"),
        "Steady sliding of any system with every contact slipping below (C++ SteadySliding): "
        "its state z and the Jacobian's eigenvalues, the largest real part first.");
}

}  // namespace stickslip::python
