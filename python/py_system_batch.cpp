// stickslip.orbits(system, columns): the periodic orbits of any system of the
// one core at many parameter points in one call. A system with a clock takes
// the stroboscopic batch (orbits/system_batch.hpp), an autonomous one the
// settled stick-slip batch (orbits/settled_batch.hpp). The belt's Params and
// the forced oscillator's ForcedBeltParams keep their own overloads (py_batch.cpp),
// bound first.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

#include "py_columns.hpp"
#include "stickslip/equilibria/steady_sliding.hpp"
#include "stickslip/orbits/settled_batch.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

namespace {

SystemColumn SystemColumnOf(const System& s, const py::handle& key, const py::handle& values) {
  const std::string name = KeyOf(key);
  const int j = s.ParameterIndex(name);
  if (j < 0) throw InvalidArgument("orbits: column '" + name + "' is no parameter of the system");
  return {j, Values(name, values)};
}

// The keyword arguments, checked under the GIL: each refusal names its
// argument (a TypeError for a wrong type, a ValueError for a bad value).
struct Args {
  int threads = 0;
  std::optional<double> transient;
  std::optional<int> max_m;
  std::optional<double> recurrence;
  Eigen::VectorXd start;
};

// An integer (a Python or NumPy one: __index__), never a bool.
int Integer(const char* name, const py::object& x) {
  if (py::isinstance<py::bool_>(x) || !PyIndex_Check(x.ptr()))
    throw py::type_error(std::string("orbits: ") + name + " must be an integer, not " +
                         py::repr(x).cast<std::string>());
  const py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(x.ptr()));
  if (!i) throw py::error_already_set();
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  if (overflow || v < 0 || v > (1 << 30))
    throw InvalidArgument(std::string("orbits: ") + name + " = " + py::repr(x).cast<std::string>() +
                          " must lie in [0, 2^30]");
  return static_cast<int>(v);
}

// A real number (Python's or NumPy's), never a bool, a str or a complex.
std::optional<double> Number(const char* name, const py::object& x) {
  if (x.is_none()) return std::nullopt;
  if (py::isinstance<py::bool_>(x) || PyComplex_Check(x.ptr()) || !PyNumber_Check(x.ptr()) ||
      py::isinstance<py::str>(x))
    throw py::type_error(std::string("orbits: ") + name + " must be a number, not " +
                         py::repr(x).cast<std::string>());
  return py::float_(x).cast<double>();
}

Args ArgsOf(const System& s, const py::object& threads, const py::object& state,
            const py::object& transient, const py::object& max_m, const py::object& recurrence) {
  Args a;
  a.threads = Integer("threads", threads);
  a.transient = Number("transient", transient);
  if (!max_m.is_none()) {
    a.max_m = Integer("max_m", max_m);
    if (*a.max_m < 1) throw InvalidArgument("orbits: max_m = 0 must be >= 1");
  }
  a.recurrence = Number("recurrence", recurrence);
  if (a.recurrence && s.clocks() == 0)
    throw InvalidArgument("orbits: recurrence applies to a system with a clock (its periods)");
  if (state.is_none()) return a;
  const py::array arr = py::module_::import("numpy").attr("asarray")(state);
  const char kind = arr.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error("orbits: state must hold real numbers, not " +
                         py::repr(state).cast<std::string>());
  if (arr.ndim() != 1 || arr.shape(0) != s.dimension()) {
    std::string names;
    for (int i = 0; i < s.dimension(); ++i) names += (i ? ", " : "") + s.StateName(i);
    throw InvalidArgument("orbits: state must be " + std::to_string(s.dimension()) + " numbers (" +
                          names + "), not of shape " +
                          py::str(arr.attr("shape")).cast<std::string>());
  }
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(arr);
  a.start = Eigen::Map<const Eigen::VectorXd>(d.data(), d.size());
  return a;
}

// The batch without the GIL, with Ctrl-C.
SystemBatch Run(const System& s, const std::vector<SystemColumn>& cols, const Args& a,
                const FlowOptions& flow) {
  Interrupt interrupt;
  SystemBatch b;
  if (s.clocks() > 0) {
    SystemBatchOptions o;
    o.shooting.flow = flow;
    o.start = a.start;
    if (a.transient) {
      if (!(*a.transient >= 0 && *a.transient == std::floor(*a.transient)))
        throw InvalidArgument(
            "orbits: transient = " + py::repr(py::float_(*a.transient)).cast<std::string>() +
            " must be a whole number of clock periods >= 0");
      o.transient = static_cast<int>(std::min(*a.transient, 2e9));
    }
    if (a.max_m) o.max_m = *a.max_m;
    if (a.recurrence) o.recurrence = *a.recurrence;
    o.threads = a.threads;
    o.cancelled = [&] { return interrupt(); };
    py::gil_scoped_release nogil;
    b = StroboscopicOrbits(s, cols, o);  // InvalidArgument before any work
  } else {
    SettledBatchOptions o;
    o.settle.shooting.flow = flow;
    o.start = a.start;
    o.start_of = [](const System& row) { return NearSteadySliding(row, 0.01); };
    if (a.transient) o.settle.transient = *a.transient;
    if (a.max_m) o.settle.max_returns = *a.max_m;
    o.threads = a.threads;
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

py::dict SystemOrbits(const py::object& system, const py::object& columns,
                      const py::object& threads, const py::object& state,
                      const py::object& transient, const py::object& max_m,
                      const py::object& recurrence, std::optional<double> rtol,
                      std::optional<double> atol) {
  // Params and ForcedBeltParams have overloads of their own (py_batch.cpp), which
  // this one, of loose types, may catch first (a NumPy or int value where
  // they take a double): forwarded with the keywords they share, else a
  // TypeError that names theirs.
  const py::module_ core = py::module_::import("stickslip._core");
  if (py::isinstance<Params>(system)) {
    if (!state.is_none() || !transient.is_none() || !max_m.is_none() || !recurrence.is_none())
      throw py::type_error(
          "orbits(Params, columns, ...) takes threads, floquet, rtol, atol, integrator and "
          "method (its stick-slip orbits); for a settled orbit of the belt give a System");
    return core
        .attr("_orbits_belt")(system, columns, py::arg("threads") = Integer("threads", threads),
                              py::arg("rtol") = rtol, py::arg("atol") = atol)
        .cast<py::dict>();
  }
  if (py::isinstance<ForcedBeltParams>(system)) {
    if (!state.is_none())
      throw py::type_error(
          "orbits(ForcedBeltParams, columns, ...) takes threads, x0, xdot0, transient (a whole "
          "number of periods), max_m, recurrence, rtol, atol, integrator and method");
    py::dict kw;
    kw["threads"] = Integer("threads", threads);
    if (!transient.is_none()) kw["transient"] = Integer("transient", transient);
    if (!max_m.is_none()) kw["max_m"] = Integer("max_m", max_m);
    if (!recurrence.is_none()) kw["recurrence"] = *Number("recurrence", recurrence);
    kw["rtol"] = rtol, kw["atol"] = atol;
    return core.attr("_orbits_forced")(system, columns, **kw).cast<py::dict>();
  }
  if (!py::isinstance<py::dict>(columns))
    throw py::type_error("orbits: columns must be a dict {parameter name: 1-D values}, not " +
                         TypeName(columns));
  const std::unique_ptr<System> s = SystemOf(system);
  std::vector<SystemColumn> cols;
  for (const auto& item : columns.cast<py::dict>())
    cols.push_back(SystemColumnOf(*s, item.first, item.second));
  const FlowOptions flow = Solver(ShootingOptions().flow, rtol, atol, py::none(), py::none());
  const Args args = ArgsOf(*s, threads, state, transient, max_m, recurrence);
  SystemBatch b = Run(*s, cols, args, flow);
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
  m.def(
      "orbits", &SystemOrbits, py::arg("system"), py::arg("columns"),
      py::arg("threads") = py::int_(0), py::arg("state") = none, py::arg("transient") = none,
      py::arg("max_m") = none, py::arg("recurrence") = none, py::arg("rtol") = none,
      py::arg("atol") = none,
      "The periodic orbit of any system (ChainParams, CouplingParams, a model file's System, "
      "...) at every row of columns, e.g. orbits(System.from_file('drill.ini'), {'T_m': t}): "
      "row i is the system with each column's value i, every row started from `state` "
      "(default: the row's steady sliding with its first component moved by 0.01, or the "
      "origin so moved where there is none; a system with a clock: the origin). An autonomous "
      "system settles for `transient` time units (default 3000) on "
      "the stick-slip orbit whose stick exit recurs within max_m exits (default 32), refined "
      "by Newton (C++ SettledOrbits); a system with a clock integrates `transient` clock "
      "periods (default 20) and shoots the least m <= max_m (default 4) that recurs within "
      "recurrence (C++ StroboscopicOrbits). Returns a dict of read-only arrays, one entry per "
      "row: status (OrbitStatus codes: ok; no-return where the run has fewer than two stick "
      "exits; aperiodic where none recurs; ...), found, stick_slip, stable, m (stick exits or "
      "clock periods per period), contact (the contact whose stick exit is the section, -1 on "
      "a stroboscopic one), sticks, period, then per state component its value at the orbit's "
      "start and its extremes (NAME, NAME_min, NAME_max), and multiplier (the largest "
      "|Floquet multiplier|). A row without an orbit holds zeros. recurrence applies to a "
      "system with a clock only. Unknown names and invalid values raise ValueError before any "
      "work; Ctrl-C raises KeyboardInterrupt. Params and ForcedBeltParams have their own overloads "
      "(a keyword of this one given to them is a TypeError).");
}

}  // namespace stickslip::python
