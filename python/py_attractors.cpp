// Basins and orbit diagrams of any system on a Poincare section in the Python
// module (issue 31 items 6 and 8, issue 32 item 3; basin/attractors.hpp,
// chaos/orbit_diagram.hpp): basins(system, ...) and orbit_diagram(system,
// parameter, ...) for every system but the belt's Params (its basins and the
// forced oscillator's orbit_diagram keep their own), and attractor_basins(system,
// ...) for every system, the belt included. Results are bound types of read-only arrays;
// the classification runs without the GIL, with Ctrl-C.
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "py_forced.hpp"
#include "stickslip/basin/attractors.hpp"
#include "stickslip/chaos/orbit_diagram.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/attractor_report.hpp"
#include "stickslip/io/system_branch_report.hpp"

namespace stickslip::python {

namespace {

struct PyAttractor {
  std::string kind, label;
  int m = 0, sticks = 0, starts = 0;
  double sticks_per_period = 0, lyapunov = 0;
  py::array z, cycle;  // the section point (tangent block); the cycle, one row per point
};

struct PyAttractorBasins {
  std::vector<std::string> slice, state_names;  // the grid's two components; z's
  py::array u, w, attractor, lyapunov;          // per start, the slice's first component fastest
  std::vector<PyAttractor> attractors;
  std::vector<std::string> failures;  // "u = ..., w = ...: why" per failed start
  int failed = 0;
  double seconds = 0;
};

py::array Vector(const Eigen::VectorXd& z) {
  return ReadOnly(std::vector<double>(z.data(), z.data() + z.size()));
}

// The component a slice name gives (its state name or column name).
int Component(const System& s, const std::string& name) {
  const int i = StateIndex(s, name);
  if (i < 0)
    throw InvalidArgument("slice: no state component '" + name + "' (" + StateNameList(s) + ")");
  return i;
}

// The starts' slice: components by name, base (default: steady sliding of an
// autonomous system, zeros with a clock), ranges (default: base +- 1, or +-1.5
// with a clock as ss_basin --force).
StartSlice Slice(const System& s, const std::optional<std::pair<std::string, std::string>>& names,
                 const std::optional<Eigen::VectorXd>& base,
                 const std::optional<std::pair<double, double>>& u_range,
                 const std::optional<std::pair<double, double>>& w_range, int nx, int ny) {
  StartSlice g;
  if (names) g.components = {Component(s, names->first), Component(s, names->second)};
  const bool clock = s.clocks() > 0;
  const SteadyState rest = clock ? SteadyState() : SteadySliding(s);
  if (base) CheckedState(s, *base, "base");  // its size, every value finite
  g.base = base ? *base : (rest.found ? rest.z : Eigen::VectorXd::Zero(s.dimension()));
  const double half = clock ? 1.5 : 1.0;
  for (int c = 0; c < 2; ++c) {
    const double mid = clock || g.base.size() == 0 ? 0.0 : g.base[g.components[c]];
    const auto& r = c == 0 ? u_range : w_range;
    g.lo[c] = r ? r->first : mid - half;
    g.hi[c] = r ? r->second : mid + half;
  }
  g.n = {nx, ny};
  return g;
}

PyAttractorBasins Result(const System& s, const AttractorBasins& r, const StartSlice& g) {
  PyAttractorBasins out;
  out.slice = {s.StateName(g.components[0]), s.StateName(g.components[1])};
  for (int i = 0; i < s.tangent_dimension(); ++i) out.state_names.push_back(s.StateName(i));
  std::vector<double> u, w, lyap;
  std::vector<int> att;
  for (const AttractorStart& a : r.starts) {
    u.push_back(a.at[0]), w.push_back(a.at[1]), att.push_back(a.attractor);
    lyap.push_back(a.lyapunov);
    if (!a.message.empty())
      out.failures.push_back(out.slice[0] + " = " + Repr(a.at[0]) + ", " + out.slice[1] + " = " +
                             Repr(a.at[1]) + ": " + a.message);
  }
  out.u = ReadOnly(u), out.w = ReadOnly(w), out.attractor = ReadOnly(att);
  out.lyapunov = ReadOnly(lyap);
  for (const Attractor& a : r.attractors) {
    PyAttractor p;
    p.kind = Name(a.kind), p.label = AttractorLabel(a);
    p.m = a.m, p.sticks = a.sticks, p.starts = a.starts;
    p.sticks_per_period = a.sticks_per_period, p.lyapunov = a.lyapunov;
    p.z = Vector(a.z);
    const int n = s.tangent_dimension();
    py::array_t<double> cycle(
        {static_cast<py::ssize_t>(a.cycle.size()), static_cast<py::ssize_t>(n)});
    auto c = cycle.mutable_unchecked<2>();
    for (size_t k = 0; k < a.cycle.size(); ++k)
      for (int i = 0; i < n; ++i) c(k, i) = a.cycle[k][i];
    cycle.attr("setflags")(py::arg("write") = false);
    p.cycle = cycle;
    out.attractors.push_back(p);
  }
  out.failed = r.failed, out.seconds = r.seconds;
  return out;
}

PyAttractorBasins AttractorBasinsOf(const py::object& system, int nx, int ny,
                                    const std::optional<std::pair<std::string, std::string>>& slice,
                                    const std::optional<Eigen::VectorXd>& base,
                                    const std::optional<std::pair<double, double>>& x_range,
                                    const std::optional<std::pair<double, double>>& y_range,
                                    std::optional<int> transient, std::optional<int> keep,
                                    std::optional<int> max_period, int threads,
                                    std::optional<double> rtol, std::optional<double> atol) {
  const std::unique_ptr<System> s = SystemOf(system);
  AttractorOptions o;
  o.slice = Slice(*s, slice, base, x_range, y_range, nx, ny);
  o.threads = threads;
  o.iterate = IterateOptions(o.iterate, transient, keep, rtol, atol);
  o.max_period = max_period.value_or(std::clamp(o.iterate.keep / 2, 1, o.max_period));
  const std::string e = o.ValidationError(*s);
  if (!e.empty()) throw InvalidArgument(e);
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  AttractorBasins r;
  {
    py::gil_scoped_release nogil;
    r = ClassifyAttractors(*s, o);
  }
  interrupt.RaiseIfInterrupted();
  if (!r.error.empty()) RaiseNumerical("basins: " + r.error);
  if (r.cancelled) RaiseNumerical("basins: cancelled");
  return Result(*s, r, o.slice);
}

py::dict SystemDiagram(const py::object& system, const std::string& parameter, double from,
                       double to, int n, std::optional<int> transient, std::optional<int> keep,
                       bool up, bool down, int chunks, double max_amplitude,
                       std::optional<double> rtol, std::optional<double> atol) {
  const std::unique_ptr<System> s = SystemOf(system);
  const int j = s->ParameterIndex(parameter);
  if (j < 0) throw InvalidArgument("parameter '" + parameter + "' is no parameter of this system");
  OrbitDiagramOptions o;
  o.from = from, o.to = to, o.n = n, o.up = up, o.down = down;
  o.chunks = chunks, o.max_amplitude = max_amplitude;
  o.iterate = IterateOptions(o.iterate, transient, keep, rtol, atol);
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  OrbitDiagram r;
  {
    py::gil_scoped_release nogil;
    r = ComputeOrbitDiagram(*s, j, o);  // throws InvalidArgument before computing
  }
  interrupt.RaiseIfInterrupted();
  if (!r.error.empty()) RaiseNumerical("orbit_diagram: " + r.error);
  const int nt = s->tangent_dimension();
  std::vector<double> value, lyap, err, point_value, z;
  std::vector<std::string> dir, point_dir, names;
  std::vector<int> sticks, exits;
  py::list failed, contact_lost;  // a contact opening is where the model ends, not a failure
  for (const DiagramColumn& c : r.columns) {
    if (!c.computed) continue;
    if (!c.settled()) {
      (c.run.status == LyapunovStatus::kContactOpen ? contact_lost : failed)
          .append(py::make_tuple(Name(c.direction), c.value, Name(c.run.status), c.run.message));
      continue;
    }
    value.push_back(c.value), dir.push_back(Name(c.direction));
    lyap.push_back(c.run.lyapunov), err.push_back(c.run.lyapunov_err);
    for (const SectionPoint& q : c.run.points) {
      point_value.push_back(c.value), point_dir.push_back(dir.back());
      z.insert(z.end(), q.z.data(), q.z.data() + nt);
      sticks.push_back(q.sticks), exits.push_back(q.exits);
    }
  }
  for (int i = 0; i < nt; ++i) names.push_back(s->StateName(i));
  py::dict d, per_value;
  per_value["value"] = ReadOnly(value), per_value["direction"] = ReadOnlyStrings(dir);
  per_value["lyapunov"] = ReadOnly(lyap), per_value["lyapunov_err"] = ReadOnly(err);
  d["columns"] = per_value;
  d["value"] = ReadOnly(point_value), d["direction"] = ReadOnlyStrings(point_dir);
  d["z"] = ReadOnlyRows(z, nt), d["names"] = names;
  d["sticks"] = ReadOnly(sticks), d["exits"] = ReadOnly(exits);
  d["failed"] = failed, d["contact_lost"] = contact_lost;
  d["seconds"] = r.seconds, d["steps"] = r.steps;
  return d;
}

}  // namespace

void BindAttractors(py::module_& m) {
  py::class_<PyAttractor>(
      m, "Attractor",
      "One attractor of attractor_basins(): kind (periodic, rest, chaotic, "
      "undecided, unbounded, failed, contact-lost, settling), m (returns per period), sticks, its "
      "section point z (the state but the phase) and cycle (m rows).")
      .def_readonly("kind", &PyAttractor::kind)
      .def_readonly("label", &PyAttractor::label)
      .def_readonly("m", &PyAttractor::m)
      .def_readonly("sticks", &PyAttractor::sticks)
      .def_readonly("sticks_per_period", &PyAttractor::sticks_per_period)
      .def_readonly("lyapunov", &PyAttractor::lyapunov)
      .def_readonly("starts", &PyAttractor::starts)
      .def_readonly("z", &PyAttractor::z)
      .def_readonly("cycle", &PyAttractor::cycle);
  using B = PyAttractorBasins;
  py::class_<B>(m, "AttractorBasins",
                "Result of attractor_basins(): per start (the slice's first component fastest) "
                "u, w (its two components, named in `slice`), attractor (index into "
                "`attractors`; a failed start's is a `failed` one; -1: not run) and lyapunov; "
                "`failures` says why a start failed, never returned or lost contact.")
      .def_readonly("slice", &B::slice)
      .def_readonly("state_names", &B::state_names)
      .def_readonly("u", &B::u)
      .def_readonly("w", &B::w)
      .def_readonly("attractor", &B::attractor)
      .def_readonly("lyapunov", &B::lyapunov)
      .def_readonly("attractors", &B::attractors)
      .def_readonly("failures", &B::failures)
      .def_readonly("failed", &B::failed)
      .def_readonly("seconds", &B::seconds);
  const py::object none = py::none();
  const char* doc =
      "Basins of any system on a Poincare section (as ss_basin --force / --system; the one "
      "classifier, C++ ClassifyAttractors): nx x ny starts on the slice of two state "
      "components (`slice`, names; default the first two) through `base` (default steady "
      "sliding, or zeros with a forcing phase), over x_range and y_range (default base +- 1; "
      "+-1.5 with a phase). A forced system's section is the stroboscopic one, an autonomous "
      "system's the returns to its first velocity's zero, falling (a first-order state first: "
      "contact 0's velocity through its value at steady sliding, falling).";
  for (const char* name : {"attractor_basins", "basins"})
    m.def(name, &AttractorBasinsOf, py::arg("system"), py::arg("nx") = 41, py::arg("ny") = 41,
          py::arg("slice") = none, py::arg("base") = none, py::arg("x_range") = none,
          py::arg("y_range") = none, py::arg("transient") = none, py::arg("keep") = none,
          py::arg("max_period") = none, py::arg("threads") = 2, py::arg("rtol") = none,
          py::arg("atol") = none, doc);
  // After the forced oscillator's orbit_diagram(ForcedBeltParams, axis, ...).
  m.def("orbit_diagram", &SystemDiagram, py::arg("system"), py::arg("parameter"), py::arg("from_"),
        py::arg("to"), py::arg("n") = 200, py::arg("transient") = none, py::arg("keep") = none,
        py::arg("up") = true, py::arg("down") = true, py::arg("chunks") = 1,
        py::arg("max_amplitude") = 50.0, py::arg("rtol") = none, py::arg("atol") = none,
        "orbit_diagram(system, parameter, from_, to, ...) for ChainParams and CouplingParams "
        "(as ss_orbit_diagram --system): a row per kept section point (value, direction, z "
        "with columns `names`, sticks, exits) on the returns to x1' = 0 falling; per value "
        "`columns` (lyapunov; a value settled on steady sliding: one point, the largest real "
        "part there); the values whose contact opened (contact_lost: the model ends there) "
        "and those that failed (failed), each with why.");
}

}  // namespace stickslip::python
