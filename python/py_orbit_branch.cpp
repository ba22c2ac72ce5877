// The one branch driver in the Python module: continue_orbits(system, ...)
// (also continue_branch) for any system, on a stroboscopic, stick-exit or
// x' = 0 section, without the GIL and with Ctrl-C (docs/library.md, "Python").
#include "py_orbit_branch.hpp"

#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <cmath>
#include <complex>
#include <memory>

#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

std::unique_ptr<System> SystemOf(const py::object& system) {
  if (auto several = SeveralMassSystemOf(system)) return several;  // py_systems.cpp
  if (auto own = ModelSystemOf(system)) return own;                // py_model.cpp
  if (py::isinstance<ForcedBeltParams>(system))
    return std::make_unique<ForcedBelt>(system.cast<ForcedBeltParams>());
  if (py::isinstance<Params>(system)) return std::make_unique<Model>(system.cast<Params>());
  throw py::type_error("system: " + py::repr(system).cast<std::string>() + " is a " +
                       py::str(py::type::of(system).attr("__name__")).cast<std::string>() +
                       ", not Params, ForcedBeltParams, ChainParams, CouplingParams or System");
}

std::string SectionOrDefault(const System& s, const std::optional<std::string>& section) {
  return section.value_or(s.clocks() == 1 ? "stroboscopic" : "stick-exit");
}

PoincareSection SectionOf(const System& s, const std::string& name, const Eigen::VectorXd& z, int m,
                          std::optional<int> turns, int contact) {
  if (m < 1) throw InvalidArgument("m = " + std::to_string(m) + " must be >= 1");
  if (contact < 0 || contact >= s.contacts() || (contact > 0 && name != "stick-exit"))
    throw InvalidArgument("contact = " + std::to_string(contact) +
                          ": a stick-exit section's, in [0, " + std::to_string(s.contacts() - 1) +
                          "]");
  if (turns && (*turns < 1 || s.clocks() != 1 || name != "stick-exit"))
    throw InvalidArgument("turns = " + std::to_string(*turns) +
                          ": a forced system's stick-exit section only, >= 1");
  if (name == "stroboscopic") {
    if (s.clocks() != 1)
      throw InvalidArgument("section: 'stroboscopic' needs a system with one forcing clock");
    return PoincareSection::Stroboscopic(s, z, m);
  }
  if (name == "stick-exit")  // m exits close the orbit; a clock turns `turns` (m) times
    return PoincareSection::StickExit(contact, m, s.clocks() ? turns.value_or(m) : 0);
  if (name == "xdot-falling") {  // the first velocity's zero, falling: the maxima of z_0
    if (s.clocks() != 0)
      throw InvalidArgument("section: 'xdot-falling' is an autonomous system's (no forcing)");
    PoincareSection p;
    p.kind = SectionKind::kSurface;
    p.surface = MaximaSection(s);  // attractor_basins' section
    p.returns = m;
    return p;
  }
  throw InvalidArgument("section = '" + name +
                        "' must be 'stroboscopic', 'stick-exit' or 'xdot-falling'");
}

FlowPoint SectionStart(const System& s, const PoincareSection& sec, const Eigen::VectorXd& state) {
  FlowPoint guess{0, state, ModeOf(s, state)};
  if (sec.kind != SectionKind::kStickExit) return guess;
  // The section's contact leaves into the slip lambda points to; others at
  // their limit leave with it.
  const int c = sec.contact;
  guess.mode.set(
      c, s.StickForce(ModeSet(Mode::kStick), c, state) > 0 ? Mode::kSlipBelow : Mode::kSlipAbove);
  for (int i = 0; i < s.contacts(); ++i) {
    if (i == c || !guess.mode.sticks(i)) continue;
    const double lambda = s.StickForce(guess.mode, i, state);
    if (std::abs(lambda) >= s.StaticLimit(i, state))
      guess.mode.set(i, lambda > 0 ? Mode::kSlipBelow : Mode::kSlipAbove);
  }
  return guess;
}

namespace {

template <typename T>
py::array Matrix(const std::vector<std::vector<T>>& rows, py::ssize_t cols) {
  py::array_t<T> a({static_cast<py::ssize_t>(rows.size()), cols});
  for (size_t i = 0; i < rows.size(); ++i)
    for (py::ssize_t j = 0; j < cols; ++j)
      a.mutable_at(i, j) = j < static_cast<py::ssize_t>(rows[i].size()) ? rows[i][j] : T(0);
  a.attr("setflags")(py::arg("write") = false);
  return std::move(a);
}

}  // namespace

PyOrbitBranch ConvertBranch(const OrbitBranch& b, const System& s, int j, const py::object& system,
                            double from, double to) {
  PyOrbitBranch out;
  out.status = b.status, out.message = b.message, out.parameter = s.ParameterName(j);
  out.jumps = b.jumps, out.evaluations = b.evaluations, out.seconds = b.seconds;
  for (int i = 0; i < s.dimension(); ++i) out.state_names.push_back(s.StateName(i));
  std::vector<double> p, period;
  std::vector<int> sticks, exits, crossings;
  std::vector<bool> stable;
  std::vector<std::string> label;
  std::vector<std::vector<double>> state, lo, hi;
  std::vector<std::vector<std::complex<double>>> mu;
  size_t k = 0;
  for (const OrbitRow& r : b.rows) {
    p.push_back(r.p), period.push_back(r.period), stable.push_back(r.stable);
    sticks.push_back(r.sticks), exits.push_back(r.exits), crossings.push_back(r.crossings);
    label.push_back(Name(r.label));
    state.emplace_back(r.start.z.data(), r.start.z.data() + r.start.z.size());
    lo.emplace_back(r.lo.data(), r.lo.data() + r.lo.size());
    hi.emplace_back(r.hi.data(), r.hi.data() + r.hi.size());
    mu.push_back(r.multipliers);
    k = std::max(k, r.multipliers.size());
  }
  out.p = ReadOnly(p), out.period = ReadOnly(period), out.stable = ReadOnlyBool(stable);
  out.sticks = ReadOnly(sticks), out.exits = ReadOnly(exits), out.crossings = ReadOnly(crossings);
  out.label = ReadOnlyStrings(label);
  out.state = Matrix(state, s.dimension());
  out.lo = Matrix(lo, s.tangent_dimension()), out.hi = Matrix(hi, s.tangent_dimension());
  out.multipliers = Matrix(mu, static_cast<py::ssize_t>(k));
  for (const OrbitRow& r : b.special)
    out.special.push_back(py::make_tuple(Name(r.label), r.p, r.description));
  out.special_points = SpecialOrbits(b, s, j, system, from, to);
  return out;
}

int ParameterOf(const py::object& system, const System& s, const std::string& name) {
  const bool forced = py::isinstance<ForcedBeltParams>(system);
  if (forced || py::isinstance<Params>(system)) {  // the lens: one of the law's (or the forcing's)
    const ParameterAxis axis(name);                // unknown: InvalidArgument naming it
    const LawKind law =
        forced ? system.cast<const ForcedBeltParams&>().base.law : system.cast<const Params&>().law;
    if (const std::string e = AxisError(axis, law, forced); !e.empty()) throw InvalidArgument(e);
  }
  const int j = s.ParameterIndex(name);
  if (j < 0) throw InvalidArgument("parameter = '" + name + "' is no parameter of the system");
  return j;
}

OrbitBranchOptions BranchOptionsOf(const py::object& system, double width, double max_amplitude,
                                   std::optional<double> max_step, std::optional<double> rtol,
                                   std::optional<double> atol) {
  // The forced oscillator's own tolerances (rtol = atol = 1e-12), as ss_continue --force's.
  OrbitBranchOptions o = py::isinstance<ForcedBeltParams>(system)
                             ? OrbitBranchOptions(ForcedBelt::FlowDefaults())
                             : OrbitBranchOptions();
  o.shooting.flow = Solver(o.shooting.flow, rtol, atol, py::none(), py::none());
  o.max_amplitude = max_amplitude;
  if (max_step) {
    if (!(*max_step > 0) || !std::isfinite(*max_step))
      throw InvalidArgument("max_step = " + Repr(*max_step) + " must be a finite number > 0");
    o.palc.ds_max = *max_step * width;  // a share of the range, as ss_continue's --max_step
    o.palc.ds = std::min(o.palc.ds, o.palc.ds_max);
  }
  return o;
}

namespace {

// "(x, x', ...)" with every digit.
std::string TupleText(const Eigen::VectorXd& z) {
  std::string out;
  for (Eigen::Index i = 0; i < z.size(); ++i) out += (i ? ", " : "(") + Repr(z[i]);
  return out + ")";
}

// A parameter's name, or a Parameter member's (the lens of the belt and the forced oscillator).
std::string NameOf(const py::object& parameter) {
  if (py::isinstance<py::str>(parameter)) return parameter.cast<std::string>();
  if (py::isinstance<Parameter>(parameter))
    return ParameterAxis(parameter.cast<Parameter>()).name();
  throw py::type_error("parameter must be a str or a Parameter, not " +
                       py::repr(parameter).cast<std::string>());
}

PyOrbitBranch ContinueOrbitsPy(const py::object& system, const py::object& parameter_name,
                               const Eigen::VectorXd& state, double to,
                               const std::optional<std::string>& section, int m,
                               std::optional<int> turns, double max_amplitude,
                               std::optional<double> max_step, std::optional<double> rtol,
                               std::optional<double> atol, int contact) {
  const std::unique_ptr<System> s = SystemOf(system);
  const int j = ParameterOf(system, *s, NameOf(parameter_name));
  if (state.size() != s->dimension())
    throw InvalidArgument("state: " + std::to_string(state.size()) + " values, the system has " +
                          std::to_string(s->dimension()));
  if (!state.allFinite()) throw InvalidArgument("state = " + TupleText(state) + " must be finite");
  if (m < 1 || m > kMaxPeriodMultiple)  // as the apps bound it
    throw InvalidArgument("m = " + std::to_string(m) + " must lie in [1, " +
                          std::to_string(kMaxPeriodMultiple) + "]");
  const double from = s->ParameterValue(j);
  OrbitBranchOptions o =
      BranchOptionsOf(system, std::abs(to - from), max_amplitude, max_step, rtol, atol);
  const PoincareSection sec =
      SectionOf(*s, SectionOrDefault(*s, section), state, m, turns, contact);
  const FlowPoint guess = SectionStart(*s, sec, state);
  Interrupt interrupt;
  o.palc.cancelled = [&] { return interrupt(); };
  OrbitBranch b;
  {
    py::gil_scoped_release nogil;
    b = ContinueOrbits(*s, j, guess, sec, to, o);
  }
  interrupt.RaiseIfInterrupted();
  return ConvertBranch(b, *s, j, system, from, to);
}

}  // namespace

void BindOrbitBranch(py::module_& m) {
  using B = PyOrbitBranch;
  py::class_<B> b(m, "OrbitBranch",
                  "Result of continue_orbits() (continue_branch(), continue_doubled()): one row "
                  "per orbit, the special points among them (label LP, PD, NS, GR, ...), each "
                  "whole in special_points (SpecialOrbit).");
  b.def_readonly("status", &B::status)
      .def_readonly("message", &B::message)
      .def_readonly("parameter", &B::parameter)
      .def_readonly("state_names", &B::state_names, "the names of state's columns")
      .def_readonly("p", &B::p)
      .def_readonly("state", &B::state)
      .def_readonly("period", &B::period)
      .def_readonly("sticks", &B::sticks)
      .def_readonly("exits", &B::exits)
      .def_readonly("crossings", &B::crossings)
      .def_readonly("lo", &B::lo)
      .def_readonly("hi", &B::hi)
      .def_readonly("multipliers", &B::multipliers)
      .def_readonly("stable", &B::stable)
      .def_readonly("label", &B::label)
      .def_readonly("special", &B::special, "(label, p, description) of each special point")
      .def_readonly("special_points", &B::special_points,
                    "each special point as a SpecialOrbit: continue_doubled() starts at a PD one")
      .def_readonly("jumps", &B::jumps)
      .def_readonly("evaluations", &B::evaluations)
      .def_readonly("seconds", &B::seconds)
      .def("__repr__", [](const B& x) {
        return "<OrbitBranch " + x.parameter + ", " + std::to_string(x.p.size()) + " rows, " +
               Name(x.status) + ">";
      });
  const py::object none = py::none();
  m.def("continue_orbits", &ContinueOrbitsPy, py::arg("system"), py::arg("parameter"),
        py::arg("state"), py::arg("to"), py::arg("section") = none, py::arg("m") = 1,
        py::arg("turns") = none, py::arg("max_amplitude") = 1e3, py::arg("max_step") = none,
        py::arg("rtol") = none, py::arg("atol") = none, py::arg("contact") = 0,
        "The branch of periodic orbits of `system` (Params: the belt; ForcedBeltParams: the forced "
        "oscillator; ChainParams, CouplingParams: the several-mass systems) through the one near "
        "`state` (x, x'[, theta]) on `section` "
        "('stroboscopic': m forcing periods, the default with a clock; 'stick-exit': the m-th "
        "exit, after `turns` forcing periods (default m) with a clock, the default without; "
        "'xdot-falling': the "
        "belt's x' = 0; `contact`: the stick-exit section's contact), continued in `parameter` "
        "from its value in `system` to `to`, with the "
        "LP, PD, NS, GR, ... points located (the one branch driver, C++ ContinueOrbits); "
        "max_step: a share of |to - p| (default: 0.02 absolute).");
  // The same under the belt's name (issue 31 item 8), after the belt's
  // continue_branch(params, param, from_, to, ...).
  m.def("continue_branch", &ContinueOrbitsPy, py::arg("system"), py::arg("parameter"),
        py::arg("state"), py::arg("to"), py::arg("section") = none, py::arg("m") = 1,
        py::arg("turns") = none, py::arg("max_amplitude") = 1e3, py::arg("max_step") = none,
        py::arg("rtol") = none, py::arg("atol") = none, py::arg("contact") = 0,
        "continue_branch(system, parameter, state, to, section, ...): continue_orbits', for "
        "any system.");
  BindSpecialOrbit(m);  // SpecialOrbit, continue_doubled (py_special_orbit.cpp)
}

}  // namespace stickslip::python
