// Steady sliding along a parameter and the attractor a run settles on, for
// any system (issue 32): steady_branch (C++ ContinueSteadySliding) and settle
// (C++ SettleOnStickSlip), as ss_continue --system uses them. Each computes
// without the GIL, with Ctrl-C.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "py_common.hpp"
#include "stickslip/equilibria/steady_branch.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/settle.hpp"

namespace stickslip::python {

namespace {

struct PySteadyBranch {
  BranchStatus status = BranchStatus::kStartFailed;
  std::string message, parameter;
  py::array p, z, max_real, stable, label;
  std::vector<py::tuple> special;  // (label, p, description)
};

struct PySettled {
  bool found = false, stable = false;
  std::string message;
  int contact = 0, returns = 0, turns = 0, stick_exits = 0, sticks = 0;
  py::array start, multipliers;
  double period = 0;
};

int ParameterOf(const System& s, const std::string& name) {
  const int j = s.ParameterIndex(name);
  if (j < 0) throw InvalidArgument("parameter = '" + name + "' is no parameter of the system");
  return j;
}

PySteadyBranch SteadyBranchPy(const py::object& system, const std::string& parameter, double to,
                              int points) {
  const std::unique_ptr<System> s = SystemOf(system);
  const int j = ParameterOf(*s, parameter);
  SteadyBranchOptions o;
  o.points = points;
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  SteadyBranch b;
  {
    py::gil_scoped_release nogil;
    b = ContinueSteadySliding(*s, j, to, o);
  }
  interrupt.RaiseIfInterrupted();
  PySteadyBranch out;
  out.status = b.status, out.message = b.message, out.parameter = parameter;
  std::vector<double> p, max_real, z;
  std::vector<bool> stable;
  std::vector<std::string> label;
  for (const SteadyRow& r : b.rows) {
    p.push_back(r.p), max_real.push_back(r.state.max_real), stable.push_back(r.state.stable());
    label.push_back(Name(r.label));
    z.insert(z.end(), r.state.z.data(), r.state.z.data() + r.state.z.size());
  }
  out.p = ReadOnly(p), out.max_real = ReadOnly(max_real), out.stable = ReadOnlyBool(stable);
  out.label = ReadOnlyStrings(label);
  py::array_t<double> zz(
      {static_cast<py::ssize_t>(p.size()), static_cast<py::ssize_t>(s->dimension())});
  std::copy(z.begin(), z.end(), zz.mutable_data());
  zz.attr("setflags")(py::arg("write") = false);
  out.z = std::move(zz);
  for (const SteadyRow& r : b.special)
    out.special.push_back(py::make_tuple(Name(r.label), r.p, r.description));
  return out;
}

PySettled SettlePy(const py::object& system, const Eigen::VectorXd& state, double transient,
                   int max_returns, std::optional<double> rtol, std::optional<double> atol) {
  const std::unique_ptr<System> s = SystemOf(system);
  SettleOptions o;
  o.shooting.flow = Solver(o.shooting.flow, rtol, atol, py::none(), py::none());
  o.transient = transient;
  o.max_returns = max_returns;
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  SettledOrbit r;
  {
    py::gil_scoped_release nogil;
    r = SettleOnStickSlip(*s, state, o);
  }
  interrupt.RaiseIfInterrupted();
  PySettled out;
  out.found = r.found, out.message = r.message, out.stick_exits = r.stick_exits;
  out.start = ReadOnly(std::vector<double>());  // read-only even when empty
  py::array_t<std::complex<double>> none(0);
  none.attr("setflags")(py::arg("write") = false);
  out.multipliers = std::move(none);
  if (!r.found) return out;
  if (r.section.kind == SectionKind::kTime)
    out.turns = r.section.turns;
  else
    out.contact = r.section.contact, out.returns = r.section.returns;
  out.period = r.orbit.period, out.stable = r.orbit.stable, out.sticks = r.orbit.sticks;
  out.start = ReadOnly(
      std::vector<double>(r.orbit.start.z.data(), r.orbit.start.z.data() + r.orbit.start.z.size()));
  py::array_t<std::complex<double>> mu(static_cast<py::ssize_t>(r.orbit.multipliers.size()));
  std::copy(r.orbit.multipliers.begin(), r.orbit.multipliers.end(), mu.mutable_data());
  mu.attr("setflags")(py::arg("write") = false);
  out.multipliers = std::move(mu);
  return out;
}

}  // namespace

void BindSystemBranch(py::module_& m) {
  using B = PySteadyBranch;
  py::class_<B>(m, "SteadyBranch",
                "Result of steady_branch(): steady sliding per row (p, z, max_real, stable), the "
                "located points among the rows (label HB or LP) and in `special` as (label, p, "
                "description).")
      .def_readonly("status", &B::status)
      .def_readonly("message", &B::message)
      .def_readonly("parameter", &B::parameter)
      .def_readonly("p", &B::p)
      .def_readonly("z", &B::z)
      .def_readonly("max_real", &B::max_real)
      .def_readonly("stable", &B::stable)
      .def_readonly("label", &B::label)
      .def_readonly("special", &B::special);
  using S = PySettled;
  py::class_<S>(m, "SettledOrbit",
                "Result of settle(): the stick-slip orbit a run settles on (found), on the stick "
                "exit of `contact` closing after `returns` exits: system_orbit(system, start, "
                "m=returns, contact=contact) and continue_orbits take the same section. A system "
                "with a clock: the periodic orbit of its stroboscopic map, `turns` clock turns "
                "(returns 0).")
      .def_readonly("found", &S::found)
      .def_readonly("message", &S::message)
      .def_readonly("contact", &S::contact)
      .def_readonly("returns", &S::returns)
      .def_readonly("turns", &S::turns)
      .def_readonly("stick_exits", &S::stick_exits)
      .def_readonly("start", &S::start)
      .def_readonly("period", &S::period)
      .def_readonly("multipliers", &S::multipliers)
      .def_readonly("stable", &S::stable)
      .def_readonly("sticks", &S::sticks);
  const py::object none = py::none();
  m.def("steady_branch", &SteadyBranchPy, py::arg("system"), py::arg("parameter"), py::arg("to"),
        py::arg("points") = 101,
        "Steady sliding of any system along `parameter` from its value in `system` to `to`, on "
        "`points` even rows, with its HB and LP points bisected (C++ ContinueSteadySliding).");
  m.def("settle", &SettlePy, py::arg("system"), py::arg("state"), py::arg("transient") = 3000.0,
        py::arg("max_returns") = 32, py::arg("rtol") = none, py::arg("atol") = none,
        "The stick-slip orbit a run of an autonomous system from `state` settles on after "
        "`transient` time units, refined by Newton on its stick-exit section (C++ "
        "SettleOnStickSlip); with a clock, the periodic orbit its stroboscopic map settles on; "
        "found False with the reason in message otherwise.");
}

}  // namespace stickslip::python
