// The forced oscillator's chaos tools in the Python module (issue 21):
// stroboscopic (iterates of the stroboscopic map with the largest Lyapunov
// exponent) and orbit_diagram (as ss_orbit_diagram; basins: basins(system),
// py_attractors.cpp), each without the GIL with Ctrl-C polled by the cancel
// hooks. Values are only those the library computed: a failed value is a
// status with its message, never a NaN.
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "py_forced.hpp"
#include "stickslip/chaos/orbit_diagram.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip::python {

LyapunovOptions IterateOptions(LyapunovOptions o, std::optional<int> transient,
                               std::optional<int> keep, std::optional<double> rtol,
                               std::optional<double> atol) {
  o.flow = FlowOf(rtol, atol);
  if (transient) o.transient = *transient;
  if (keep) o.keep = *keep;
  // As the apps: the tangent aligns over the transient's last min(align, transient) periods.
  o.align = std::clamp(o.align, 0, std::max(o.transient, 0));
  if (o.keep >= 1) o.batches = std::min(o.batches, o.keep);  // as ss_basin --force
  return o;
}

namespace {

void Check(const std::string& error) {
  if (!error.empty()) throw InvalidArgument(error);
}

// The kept section points of runs, one row per point.
struct Points {
  std::vector<double> x, xdot, exit_phase;
  std::vector<int> sticks, exits;
  std::vector<bool> stuck;
  void Add(const SectionRun& r) {
    for (const SectionPoint& q : r.points) {
      x.push_back(q.z[0]), xdot.push_back(q.z[1]), stuck.push_back(q.mode[0] == Mode::kStick);
      sticks.push_back(q.sticks), exits.push_back(q.exits);
      exit_phase.push_back(q.first_exit_phase);
    }
  }
  void To(py::dict& d) const {
    d["x"] = ReadOnly(x), d["xdot"] = ReadOnly(xdot), d["stuck"] = ReadOnlyBool(stuck);
    d["sticks"] = ReadOnly(sticks), d["exits"] = ReadOnly(exits);
    d["exit_phase"] = ReadOnly(exit_phase);
  }
};

py::dict Stroboscopic(const ForcedBeltParams& p, double x0, std::optional<double> xdot0,
                      std::optional<int> transient, std::optional<int> keep, double max_amplitude,
                      std::optional<double> rtol, std::optional<double> atol) {
  const ForcedBelt model(p);  // throws InvalidArgument naming the value
  const LyapunovOptions o = IterateOptions(LyapunovOptions(), transient, keep, rtol, atol);
  Check(o.ValidationError());
  const double xd0 = xdot0.value_or(p.base.v);
  if (!(std::isfinite(x0) && std::isfinite(xd0)))
    throw InvalidArgument("x0 = " + FormatNumber(x0) + ", xdot0 = " + FormatNumber(xd0) +
                          ": both must be finite");
  if (!(max_amplitude > 0))
    throw InvalidArgument("max_amplitude = " + FormatNumber(max_amplitude) + " must be > 0");
  Interrupt interrupt;
  SectionRun r;
  {
    py::gil_scoped_release nogil;
    r = IterateStroboscopic(
        model, ForcedStart(model, 0, x0, xd0), o, [&] { return interrupt(); }, max_amplitude);
  }
  interrupt.RaiseIfInterrupted();
  if (r.status != LyapunovStatus::kDone)
    RaiseNumerical(std::string(Name(r.status)) + ": " + r.message);
  py::dict d;
  Points pts;
  pts.Add(r);
  pts.To(d);
  d["lyapunov"] = r.lyapunov, d["lyapunov_err"] = r.lyapunov_err;
  d["collapses"] = r.collapses, d["steps"] = r.steps;
  d["end"] = py::make_tuple(r.end.z[0], r.end.z[1]);
  return d;
}

py::dict Diagram(ForcedBeltParams base, ParameterAxis axis, double from, double to, int n,
                 std::optional<int> transient, std::optional<int> keep, bool up, bool down,
                 int chunks, double max_amplitude, std::optional<double> rtol,
                 std::optional<double> atol) {
  OrbitDiagramOptions o;
  o.axis = axis, o.from = from, o.to = to, o.n = n, o.up = up, o.down = down;
  o.chunks = chunks, o.max_amplitude = max_amplitude;
  o.iterate = IterateOptions(o.iterate, transient, keep, rtol, atol);
  Check(o.ValidationError());
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  OrbitDiagram r;
  {
    py::gil_scoped_release nogil;
    r = ComputeOrbitDiagram(base, o);
  }
  interrupt.RaiseIfInterrupted();
  if (!r.error.empty()) RaiseNumerical("orbit_diagram: " + r.error);
  Points pts;
  std::vector<double> value, lyap, lyap_err, point_value;
  std::vector<std::string> dir, point_dir;
  py::list failed;
  for (const DiagramColumn& c : r.columns) {
    if (!c.computed) continue;
    if (c.run.status != LyapunovStatus::kDone) {
      failed.append(py::make_tuple(Name(c.direction), c.value, Name(c.run.status), c.run.message));
      continue;
    }
    value.push_back(c.value), dir.push_back(Name(c.direction));
    lyap.push_back(c.run.lyapunov), lyap_err.push_back(c.run.lyapunov_err);
    pts.Add(c.run);
    point_value.insert(point_value.end(), c.run.points.size(), c.value);
    point_dir.insert(point_dir.end(), c.run.points.size(), dir.back());
  }
  py::dict d, per_value;
  per_value["value"] = ReadOnly(value), per_value["direction"] = ReadOnlyStrings(dir);
  per_value["lyapunov"] = ReadOnly(lyap), per_value["lyapunov_err"] = ReadOnly(lyap_err);
  d["columns"] = per_value;
  d["value"] = ReadOnly(point_value), d["direction"] = ReadOnlyStrings(point_dir);
  pts.To(d);
  d["failed"] = failed, d["seconds"] = r.seconds, d["steps"] = r.steps;
  return d;
}

}  // namespace

void BindChaos(py::module_& m) {
  const py::object none = py::none();
  m.def("stroboscopic", &Stroboscopic, py::arg("params"), py::arg("x0") = 0.0,
        py::arg("xdot0") = none, py::arg("transient") = none, py::arg("keep") = none,
        py::arg("max_amplitude") = 1e6, py::arg("rtol") = none, py::arg("atol") = none,
        "Iterates of the stroboscopic map (phase 0, cos Omega t = 1) from (x0, xdot0 (default "
        "v)): a dict of the kept points (x, xdot, stuck, sticks, exits, exit_phase) and the "
        "largest Lyapunov exponent with its standard error (lyapunov, lyapunov_err).");
  m.def("orbit_diagram", &Diagram, py::arg("params"), py::arg("axis"), py::arg("from_"),
        py::arg("to"), py::arg("n") = 200, py::arg("transient") = none, py::arg("keep") = none,
        py::arg("up") = true, py::arg("down") = true, py::arg("chunks") = 1,
        py::arg("max_amplitude") = 50.0, py::arg("rtol") = none, py::arg("atol") = none,
        "The orbit diagram (as ss_orbit_diagram): one row per kept section point (value, "
        "direction, x, xdot, stuck, sticks, exits, exit_phase), per value the exponent "
        "(columns), and the values that failed with why (failed).");
}

}  // namespace stickslip::python
