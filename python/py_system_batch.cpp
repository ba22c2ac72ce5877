// stickslip.orbits(system, columns): the periodic orbits of any system of the
// one core at many parameter points in one call. A system with a clock takes
// the stroboscopic batch (orbits/system_batch.hpp), an autonomous one the
// settled stick-slip batch (orbits/settled_batch.hpp). The belt's Params and
// the forced oscillator's ForcedParams keep their own overloads (py_batch.cpp),
// bound first.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

#include "py_columns.hpp"
#include "stickslip/orbits/settled_batch.hpp"

namespace stickslip::python {

namespace {

SystemColumn SystemColumnOf(const System& s, const py::handle& key, const py::handle& values) {
  const std::string name = KeyOf(key);
  const int j = s.ParameterIndex(name);
  if (j < 0) throw InvalidArgument("orbits: column '" + name + "' is no parameter of the system");
  return {j, Values(name, values)};
}

// The batch without the GIL, with Ctrl-C.
SystemBatch Run(const System& s, const std::vector<SystemColumn>& cols, const py::object& state,
                int threads, std::optional<double> transient, std::optional<int> max_m,
                double recurrence, const FlowOptions& flow) {
  Eigen::VectorXd start;
  if (!state.is_none()) start = state.cast<Eigen::VectorXd>();
  Interrupt interrupt;
  SystemBatch b;
  if (s.clocks() > 0) {
    SystemBatchOptions o;
    o.shooting.flow = flow;
    o.start = start;
    if (transient) {
      if (!(*transient >= 0 && *transient == std::floor(*transient)))
        throw InvalidArgument(
            "orbits: transient = " + py::repr(py::float_(*transient)).cast<std::string>() +
            " must be a whole number of clock periods >= 0");
      o.transient = static_cast<int>(std::min(*transient, 2e9));
    }
    if (max_m) o.max_m = *max_m;
    o.recurrence = recurrence, o.threads = threads;
    o.cancelled = [&] { return interrupt(); };
    py::gil_scoped_release nogil;
    b = StroboscopicOrbits(s, cols, o);  // InvalidArgument before any work
  } else {
    SettledBatchOptions o;
    o.settle.shooting.flow = flow;
    o.start = start;
    if (transient) o.settle.transient = *transient;
    if (max_m) o.settle.max_returns = *max_m;
    o.threads = threads;
    o.cancelled = [&] { return interrupt(); };
    py::gil_scoped_release nogil;
    b = SettledOrbits(s, cols, o);
  }
  interrupt.RaiseIfInterrupted();
  if (!b.error.empty()) throw Error("orbits: " + b.error);
  return b;
}

// Column k of a row-major block of `tangent` columns.
std::vector<double> Column(const std::vector<double>& block, int tangent, int k) {
  std::vector<double> c(block.size() / tangent);
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = block[i * tangent + k];
  return c;
}

py::dict SystemOrbits(const py::object& system, const py::object& columns, int threads,
                      const py::object& state, std::optional<double> transient,
                      std::optional<int> max_m, double recurrence, std::optional<double> rtol,
                      std::optional<double> atol) {
  if (!py::isinstance<py::dict>(columns))
    throw py::type_error("orbits: columns must be a dict {parameter name: 1-D values}, not " +
                         TypeName(columns));
  const std::unique_ptr<System> s = SystemOf(system);
  std::vector<SystemColumn> cols;
  for (const auto& item : columns.cast<py::dict>())
    cols.push_back(SystemColumnOf(*s, item.first, item.second));
  const FlowOptions flow = Solver(ShootingOptions().flow, rtol, atol, py::none(), py::none());
  SystemBatch b = Run(*s, cols, state, threads, transient, max_m, recurrence, flow);
  const std::size_t n = b.rows();
  std::vector<bool> found(n), stick_slip(n), stable(n);
  std::vector<std::uint8_t> status(n);
  for (std::size_t i = 0; i < n; ++i) {
    status[i] = static_cast<std::uint8_t>(b.status[i]);
    found[i] = b.status[i] == OrbitStatus::kOk;
    stick_slip[i] = found[i] && b.sticks[i] > 0;
    stable[i] = b.stable[i] != 0;
  }
  py::dict out;
  out["status"] = Owned(std::move(status));
  out["found"] = ReadOnlyBool(found);
  out["stick_slip"] = ReadOnlyBool(stick_slip);
  out["stable"] = ReadOnlyBool(stable);
  out["m"] = Owned(std::move(b.m));
  out["contact"] = Owned(std::move(b.contact));
  out["sticks"] = Owned(std::move(b.sticks));
  out["period"] = Owned(std::move(b.period));
  for (int k = 0; k < b.tangent; ++k) {
    const std::string name = s->StateName(k);
    out[py::str(name)] = Owned(Column(b.start, b.tangent, k));
    out[py::str(name + "_min")] = Owned(Column(b.lo, b.tangent, k));
    out[py::str(name + "_max")] = Owned(Column(b.hi, b.tangent, k));
  }
  out["multiplier"] = Owned(std::move(b.multiplier));
  return out;
}

}  // namespace

void BindSystemBatch(py::module_& m) {
  const py::object none = py::none();
  m.def("orbits", &SystemOrbits, py::arg("system"), py::arg("columns"), py::arg("threads") = 0,
        py::arg("state") = none, py::arg("transient") = none, py::arg("max_m") = none,
        py::arg("recurrence") = 1e-3, py::arg("rtol") = none, py::arg("atol") = none,
        "The periodic orbit of any system (ChainParams, CouplingParams, a model file's System, "
        "...) at every row of columns, e.g. orbits(System.from_file('drill.ini'), {'T_m': t}): "
        "row i is the system with each column's value i, every row started from `state` (default "
        "the origin). An autonomous system settles for `transient` time units (default 3000) on "
        "the stick-slip orbit whose stick exit recurs within max_m exits (default 32), refined "
        "by Newton (C++ SettledOrbits); a system with a clock integrates `transient` clock "
        "periods (default 20) and shoots the least m <= max_m (default 4) that recurs within "
        "recurrence (C++ StroboscopicOrbits). Returns a dict of read-only arrays, one entry per "
        "row: status (OrbitStatus codes: ok; no-return where the run has fewer than two stick "
        "exits; aperiodic where none recurs; ...), found, stick_slip, stable, m (stick exits or "
        "clock periods per period), contact (the contact whose stick exit is the section, -1 on "
        "a stroboscopic one), sticks, period, then per state component its value at the orbit's "
        "start and its extremes (NAME, NAME_min, NAME_max), and multiplier (the largest "
        "|Floquet multiplier|). A row without an orbit holds zeros. Unknown names and invalid "
        "values raise ValueError before any work; Ctrl-C raises KeyboardInterrupt.");
}

}  // namespace stickslip::python
