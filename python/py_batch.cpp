// stickslip.orbits: the belt's stick-slip orbits at many parameter points in
// one call (orbits/orbit_batch.hpp). The columns are checked and copied under
// the GIL, the batch runs once without it (Ctrl-C through the cancel hook,
// which the library calls on this thread), and the result columns are moved
// into read-only NumPy arrays without a copy.
#include <pybind11/stl.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>

#include "py_columns.hpp"
#include "py_common.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit_batch.hpp"
#include "stickslip/orbits/system_batch.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

namespace {

ParameterColumn ColumnOf(const py::handle& key, const py::handle& values) {
  const std::string name = KeyOf(key);
  ParameterColumn c{ParameterAxis(name), {}};  // InvalidArgument for an unknown name
  c.values = Values(name, values);
  return c;
}

// A forced column: a parameter of the law, force or omega.
SystemColumn ForcedColumnOf(const ForcedBelt& model, const py::handle& key,
                            const py::handle& values) {
  const std::string name = KeyOf(key);
  const int j = model.ParameterIndex(name);
  const auto axes = ParameterAxes(model.params().base.law);
  const bool of_law = std::any_of(axes.begin(), axes.end(),
                                  [&](const ParameterAxis& a) { return a.name() == name; });
  if (j < 0 || (j < ForcedBelt::kForceIndex && !of_law))
    throw InvalidArgument("orbits: column '" + name + "' is not a parameter of the forced " +
                          Name(model.params().base.law) + " oscillator");
  return {j, Values(name, values)};
}

py::dict Orbits(const Params& base, const py::object& columns, int threads, bool floquet,
                std::optional<double> rtol, std::optional<double> atol,
                const py::object& integrator, const py::object& method) {
  if (!py::isinstance<py::dict>(columns))
    throw py::type_error("orbits: columns must be a dict {parameter name: 1-D values}, not " +
                         TypeName(columns));
  std::vector<ParameterColumn> cols;
  for (const auto& item : columns.cast<py::dict>())
    cols.push_back(ColumnOf(item.first, item.second));
  OrbitBatchOptions o;
  o.orbit.flow = Solver(o.orbit.flow, rtol, atol, integrator, method);
  o.orbit.floquet = floquet;
  o.threads = threads;
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  OrbitBatch b;
  {
    py::gil_scoped_release nogil;
    b = StickSlipOrbits(base, cols, o);  // InvalidArgument before any work
  }
  interrupt.RaiseIfInterrupted();
  if (!b.error.empty()) throw Error("orbits: " + b.error);
  const auto n = static_cast<py::ssize_t>(b.rows());
  py::array_t<std::uint8_t> status(n);
  py::array_t<bool> found(n), stable(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    status.mutable_data()[i] = static_cast<std::uint8_t>(b.status[i]);
    found.mutable_data()[i] = b.status[i] == OrbitStatus::kOk;
    stable.mutable_data()[i] = b.stable[i] != 0;
  }
  for (py::array* a : std::initializer_list<py::array*>{&status, &found, &stable})
    a->attr("setflags")(py::arg("write") = false);
  py::dict out;
  out["status"] = status;
  out["stick_slip"] = found;
  out["period"] = Owned(std::move(b.period));
  out["t_stick"] = Owned(std::move(b.t_stick));
  out["x_min"] = Owned(std::move(b.x_min));
  out["x_max"] = Owned(std::move(b.x_max));
  out["xdot_min"] = Owned(std::move(b.xdot_min));
  out["xdot_max"] = Owned(std::move(b.xdot_max));
  if (floquet) out["multiplier"] = Owned(std::move(b.multiplier));
  out["stable"] = stable;
  return out;
}

// The forced oscillator's stroboscopic orbits (orbits/system_batch.hpp).
py::dict ForcedOrbits(const ForcedBeltParams& base, const py::object& columns, int threads,
                      double x0, double xdot0, int transient, int max_m, double recurrence,
                      std::optional<double> rtol, std::optional<double> atol,
                      const py::object& integrator, const py::object& method) {
  if (!py::isinstance<py::dict>(columns))
    throw py::type_error("orbits: columns must be a dict {parameter name: 1-D values}, not " +
                         TypeName(columns));
  const ForcedBelt model(base);  // InvalidArgument for an invalid base
  std::vector<SystemColumn> cols;
  for (const auto& item : columns.cast<py::dict>())
    cols.push_back(ForcedColumnOf(model, item.first, item.second));
  SystemBatchOptions o;
  o.shooting.flow = Solver(ForcedBelt::FlowDefaults(), rtol, atol, integrator, method);
  o.start = Eigen::Vector3d(x0, xdot0, 0);
  o.transient = transient, o.max_m = max_m, o.recurrence = recurrence;
  o.threads = threads;
  Interrupt interrupt;
  o.cancelled = [&] { return interrupt(); };
  SystemBatch b;
  {
    py::gil_scoped_release nogil;
    b = StroboscopicOrbits(model, cols, o);  // InvalidArgument before any work
  }
  interrupt.RaiseIfInterrupted();
  if (!b.error.empty()) throw Error("orbits: " + b.error);
  const std::size_t n = b.rows();
  std::vector<std::uint8_t> status(n);
  std::vector<bool> flags[3];    // found, stick_slip, stable
  std::vector<double> cols2[6];  // x0, xdot0, x_min, x_max, xdot_min, xdot_max
  for (auto& f : flags) f.resize(n);
  for (auto& c : cols2) c.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    status[i] = static_cast<std::uint8_t>(b.status[i]);
    flags[0][i] = b.status[i] == OrbitStatus::kOk;
    flags[1][i] = flags[0][i] && b.sticks[i] > 0;
    flags[2][i] = b.stable[i] != 0;
    for (int k = 0; k < 2; ++k) {
      cols2[k][i] = b.start[2 * i + k];
      cols2[2 + 2 * k][i] = b.lo[2 * i + k];
      cols2[3 + 2 * k][i] = b.hi[2 * i + k];
    }
  }
  py::dict out;
  out["status"] = Owned(std::move(status));
  const char* flag_names[] = {"found", "stick_slip", "stable"};
  for (int k = 0; k < 3; ++k) {
    py::array_t<bool> a(static_cast<py::ssize_t>(n));
    std::copy(flags[k].begin(), flags[k].end(), a.mutable_data());
    a.attr("setflags")(py::arg("write") = false);
    out[flag_names[k]] = a;
  }
  out["m"] = Owned(std::move(b.m));
  out["sticks"] = Owned(std::move(b.sticks));
  out["period"] = Owned(std::move(b.period));
  const char* names[] = {"x0", "xdot0", "x_min", "x_max", "xdot_min", "xdot_max"};
  for (int k = 0; k < 6; ++k) out[names[k]] = Owned(std::move(cols2[k]));
  out["multiplier"] = Owned(std::move(b.multiplier));
  return out;
}

// x as Python's repr writes it: the shortest digits that read back exactly
// (std::to_chars), in exponent form for x < 1e-4 or x >= 1e16, else fixed
// with ".0" on whole numbers. NaN (does not apply) is an empty cell; inf is
// refused (no nan or inf is written, docs/formats.md).
void AppendRepr(double x, std::string& out) {
  if (std::isnan(x)) return;
  if (std::isinf(x))
    throw InvalidArgument("_tsv_rows: " + std::string(x > 0 ? "inf" : "-inf") +
                          " is not a finite number");
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific);
  const char* e = std::find(buf, r.ptr, 'e');
  int exponent = 0;
  if (e != r.ptr) std::from_chars(e + (e[1] == '+' ? 2 : 1), r.ptr, exponent);
  if (exponent >= 16 || exponent < -4) {
    out.append(buf, r.ptr);
    return;
  }
  r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed);
  out.append(buf, r.ptr);
  if (std::find(buf, r.ptr, '.') == r.ptr) out += ".0";
}

// The rows of a 2-D float array as TSV text, each value as repr() writes it:
// SweepResult.to_tsv's rows at C speed.
py::bytes TsvRows(const py::array_t<double, py::array::c_style | py::array::forcecast>& a) {
  if (a.ndim() != 2) throw InvalidArgument("_tsv_rows: a 2-D array is needed");
  const py::ssize_t rows = a.shape(0), cols = a.shape(1);
  std::string out;
  out.reserve(static_cast<std::size_t>(rows * cols) * 20);
  const double* d = a.data();
  for (py::ssize_t i = 0; i < rows; ++i)
    for (py::ssize_t j = 0; j < cols; ++j) {
      AppendRepr(d[i * cols + j], out);
      out += j + 1 < cols ? '\t' : '\n';
    }
  return py::bytes(out);
}

}  // namespace

void BindBatch(py::module_& m) {
  const py::object none = py::none();
  m.def("orbits", &Orbits, py::arg("params"), py::arg("columns"), py::arg("threads") = 0,
        py::arg("floquet") = false, py::arg("rtol") = none, py::arg("atol") = none,
        py::arg("integrator") = none, py::arg("method") = none,
        "The stick-slip orbit at every row of columns, e.g. orbits(Params(), {'v': v, 'mu_s': "
        "mu_s}): row i is params with each column's value i. Returns a dict of read-only arrays "
        "(one entry per row): status (OrbitStatus codes: ok, or missed where the slip phase's "
        "first return stays below the belt speed, ...), stick_slip (status == ok), period, "
        "t_stick, x_min, x_max, xdot_min, xdot_max, stable, and multiplier with floquet=True. "
        "A row without an orbit holds zeros and stable False. threads: worker threads, capped by "
        "the hardware threads (0: all). Unknown names, columns of different lengths and invalid "
        "values raise ValueError before any work; Ctrl-C raises KeyboardInterrupt.");
  m.def("orbits", &ForcedOrbits, py::arg("params"), py::arg("columns"), py::arg("threads") = 0,
        py::arg("x0") = 0.0, py::arg("xdot0") = 0.0, py::arg("transient") = 20,
        py::arg("max_m") = 4, py::arg("recurrence") = 1e-3, py::arg("rtol") = none,
        py::arg("atol") = none, py::arg("integrator") = none, py::arg("method") = none,
        "The forced oscillator's periodic orbit at every row of columns, e.g. "
        "orbits(ForcedBeltParams(Params(), force=0.3), {'omega': w, 'mu_s': mu_s}); columns name a "
        "parameter of the law, force or omega. Each row integrates `transient` forcing periods "
        "from (x0, xdot0) at phase 0, takes the least m <= max_m whose stroboscopic point "
        "recurs within recurrence (1 + |z|), and shoots the m-periodic orbit from it "
        "(transient=0: Newton on P^max_m from (x0, xdot0)). Returns a dict of read-only arrays: "
        "status (OrbitStatus: ok, aperiodic where no m recurs, ...), found (status == ok), "
        "stick_slip (found with a stick phase), m, sticks, period, x0, xdot0 (the orbit at phase "
        "0), x_min, x_max, xdot_min, xdot_max, multiplier (the largest |Floquet multiplier|), "
        "stable. A row without an orbit holds zeros. Unknown names and invalid values raise "
        "ValueError before any work; Ctrl-C raises KeyboardInterrupt.");
  // The two overloads above by name, for orbits(system)'s forwarding (py_system_batch.cpp).
  m.def("_orbits_belt", &Orbits, py::arg("params"), py::arg("columns"), py::arg("threads") = 0,
        py::arg("floquet") = false, py::arg("rtol") = none, py::arg("atol") = none,
        py::arg("integrator") = none, py::arg("method") = none);
  m.def("_orbits_forced", &ForcedOrbits, py::arg("params"), py::arg("columns"),
        py::arg("threads") = 0, py::arg("x0") = 0.0, py::arg("xdot0") = 0.0,
        py::arg("transient") = 20, py::arg("max_m") = 4, py::arg("recurrence") = 1e-3,
        py::arg("rtol") = none, py::arg("atol") = none, py::arg("integrator") = none,
        py::arg("method") = none);
  m.def("_tsv_rows", &TsvRows, py::arg("data"),
        "Rows of a 2-D float array as TSV bytes, each value as repr() writes it.");
}

}  // namespace stickslip::python
