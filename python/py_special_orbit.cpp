// The located points of a branch in Python (SpecialOrbit) and the switch at a
// period doubling, continue_doubled (C++ ContinueDoubled: AUTO-07p's ISW = -1
// at a PD label), for any system, without the GIL and with Ctrl-C.
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <memory>

#include "chain/chain.hpp"
#include "mode_coupling/mode_coupling.hpp"
#include "py_orbit_branch.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

namespace {

// The run's system with its parameter j at p, as the Python type it came as.
py::object SystemAt(const py::object& system, const System& s, int j, double p) {
  std::unique_ptr<System> at = s.Clone();
  at->SetParameterValue(j, p);
  const auto copy = py::return_value_policy::copy;
  if (py::isinstance<ForcedBeltParams>(system))
    return py::cast(dynamic_cast<const ForcedBelt&>(*at).params(), copy);
  if (py::isinstance<Params>(system))
    return py::cast(dynamic_cast<const Model&>(*at).params(), copy);
  if (py::isinstance<chain::ChainParams>(system))
    return py::cast(dynamic_cast<const chain::Chain&>(*at).params(), copy);
  if (py::isinstance<mode_coupling::CouplingParams>(system))
    return py::cast(dynamic_cast<const mode_coupling::ModeCoupling&>(*at).params(), copy);
  py::object own = system.attr("copy")();  // a stickslip.System: set by name
  own.attr("__setitem__")(s.ParameterName(j), p);
  return own;
}

const char* SectionName(SectionKind k) {
  return k == SectionKind::kTime        ? "stroboscopic"
         : k == SectionKind::kStickExit ? "stick-exit"
                                        : "xdot-falling";
}

template <typename T>
py::array ArrayOf(const T& v) {
  return ReadOnly(std::vector<typename T::value_type>(v.begin(), v.end()));
}

PySpecialOrbit SpecialOf(const OrbitRow& r, const std::string& lab, const OrbitBranch& b,
                         const System& s, int j, const py::object& system, double from, double to) {
  PySpecialOrbit q;
  q.label = Name(r.label), q.lab = lab, q.description = r.description;
  q.parameter = s.ParameterName(j), q.p = r.p, q.period = r.period;
  q.run_from = from, q.run_to = to;
  q.state = ArrayOf(r.start.z), q.lo = ArrayOf(r.lo), q.hi = ArrayOf(r.hi);
  q.multipliers = ReadOnly(r.multipliers);
  q.sticks = r.sticks, q.exits = r.exits, q.crossings = r.crossings, q.stable = r.stable;
  q.cut = b.section, q.start = r.start;
  q.section = SectionName(b.section.kind), q.turns = b.section.turns;
  q.m = b.section.kind == SectionKind::kTime ? b.section.turns : b.section.returns;
  q.contact = b.section.kind == SectionKind::kStickExit ? b.section.contact : 0;
  q.system = SystemAt(system, s, j, r.p);
  return q;
}

// The 2m branch from a PD point; [lo, hi] defaults to the range of the run the
// point came from (AUTO's RL0/RL1 kept, as ss_continue --switch).
PyOrbitBranch DoubledPy(const PySpecialOrbit& pd, std::optional<double> lo,
                        std::optional<double> hi, double max_amplitude,
                        std::optional<double> max_step, std::optional<double> rtol,
                        std::optional<double> atol) {
  if (pd.label != "PD")
    throw InvalidArgument("point: label " + pd.label + " (" + pd.lab +
                          ") is not a period doubling (PD)");
  const double a = lo.value_or(std::min(pd.run_from, pd.run_to));
  const double b = hi.value_or(std::max(pd.run_from, pd.run_to));
  if (!(a < pd.p && pd.p < b))
    throw InvalidArgument("lo = " + Repr(a) + ", hi = " + Repr(b) + " must bracket the PD at " +
                          Repr(pd.p));
  const std::unique_ptr<System> s = SystemOf(pd.system);  // at the PD
  const int j = ParameterOf(pd.system, *s, pd.parameter);
  // max_step a share of hi - lo, 0.02 by default (as ss_continue --switch)
  OrbitBranchOptions o =
      BranchOptionsOf(pd.system, b - a, max_amplitude, max_step.value_or(0.02), rtol, atol);
  Interrupt interrupt;
  o.palc.cancelled = [&] { return interrupt(); };
  const FlowPoint start = pd.start;  // copies: read without the GIL
  const PoincareSection cut = pd.cut;
  OrbitBranch r;
  {
    py::gil_scoped_release nogil;
    r = ContinueDoubled(*s, j, start, cut, a, b, o);
  }
  interrupt.RaiseIfInterrupted();
  return ConvertBranch(r, *s, j, pd.system, a, b);
}

std::string SpecialRepr(const PySpecialOrbit& q) {
  return "<SpecialOrbit " + q.lab + " at " + q.parameter + " = " + Repr(q.p) + " (" + q.section +
         ", m = " + std::to_string(q.m) + "): " + q.description + ">";
}

}  // namespace

std::vector<PySpecialOrbit> SpecialOrbits(const OrbitBranch& b, const System& s, int j,
                                          const py::object& system, double from, double to) {
  std::vector<PySpecialOrbit> out;
  std::map<SpecialKind, int> count;  // LP1, PD1, PD2, ... per kind in branch order
  for (const OrbitRow& r : b.special) {
    const std::string lab = std::string(Name(r.label)) + std::to_string(++count[r.label]);
    out.push_back(SpecialOf(r, lab, b, s, j, system, from, to));
  }
  return out;
}

void BindSpecialOrbit(py::module_& m) {
  using S = PySpecialOrbit;
  py::class_<S>(m, "SpecialOrbit",
                "A located point of an OrbitBranch (LP, PD, NS, GR, AD, CR, SL, CL) with its "
                "orbit, its run and `system` at the point: continue_doubled() starts at a PD one.")
      .def_readonly("label", &S::label, "LP, PD, NS, GR, ...")
      .def_readonly("lab", &S::lab, "numbered per kind in the branch's order: PD1, PD2, ...")
      .def_readonly("description", &S::description)
      .def_readonly("parameter", &S::parameter, "the continued parameter's name")
      .def_readonly("p", &S::p, "its value at the point")
      .def_readonly("state", &S::state, "the orbit's section point (the whole state)")
      .def_readonly("period", &S::period)
      .def_readonly("sticks", &S::sticks)
      .def_readonly("exits", &S::exits)
      .def_readonly("crossings", &S::crossings)
      .def_readonly("lo", &S::lo, "the least value of each tangent component on the orbit")
      .def_readonly("hi", &S::hi, "the greatest: hi[0] is x_max")
      .def_readonly("multipliers", &S::multipliers)
      .def_readonly("stable", &S::stable)
      .def_readonly("section", &S::section, "the run's: 'stroboscopic', 'stick-exit', ...")
      .def_readonly("m", &S::m, "the run's returns (stroboscopic: forcing periods)")
      .def_readonly("turns", &S::turns, "the run's clock turns per period (0: no clock)")
      .def_readonly("contact", &S::contact, "a stick-exit section's contact")
      .def_readonly("run_from", &S::run_from, "the range of the run it was found in")
      .def_readonly("run_to", &S::run_to)
      .def_readonly("system", &S::system, "a copy of the run's system, the parameter at p")
      .def("__repr__", &SpecialRepr);
  const py::object none = py::none();
  m.def("continue_doubled", &DoubledPy, py::arg("point"), py::arg("lo") = none,
        py::arg("hi") = none, py::arg("max_amplitude") = 1e3, py::arg("max_step") = none,
        py::arg("rtol") = none, py::arg("atol") = none,
        "The branch of twice the period born at a PD point (a SpecialOrbit of an OrbitBranch), "
        "traced to lo or hi, whichever it opens toward (default: the range of the run it came "
        "from), as ss_continue --switch; max_step a share of hi - lo, default 0.02 (C++ "
        "ContinueDoubled).");
}

}  // namespace stickslip::python
