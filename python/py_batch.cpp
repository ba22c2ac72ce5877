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

#include "py_common.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit_batch.hpp"

namespace stickslip::python {

namespace {

std::string TypeName(const py::handle& x) {
  return py::str(py::type::of(x).attr("__name__")).cast<std::string>();
}

// A read-only array that owns v's buffer (no copy).
template <typename T>
py::array Owned(std::vector<T>&& v) {
  auto* heap = new std::vector<T>(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  py::array_t<T> a(static_cast<py::ssize_t>(heap->size()), heap->data(), owner);
  a.attr("setflags")(py::arg("write") = false);
  return std::move(a);
}

// One column: a str key naming a parameter (ValueError if it is none) and a
// 1-D sequence of real numbers (TypeError for other types, ValueError for
// another shape).
ParameterColumn ColumnOf(const py::handle& key, const py::handle& values) {
  if (!py::isinstance<py::str>(key))
    throw py::type_error("orbits: column names must be parameter names (str), not " +
                         TypeName(key));
  const std::string name = key.cast<std::string>();
  ParameterColumn c{ParameterAxis(name), {}};  // InvalidArgument for an unknown name
  const py::array a = py::module_::import("numpy").attr("asarray")(values);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error("orbits: column '" + name + "' must hold real numbers, not " +
                         (py::isinstance<py::array>(values)
                              ? "an array of dtype " + py::str(a.dtype()).cast<std::string>()
                              : TypeName(values)));
  if (a.ndim() != 1)
    throw InvalidArgument("orbits: column '" + name + "' must be 1-D, not of shape " +
                          py::str(a.attr("shape")).cast<std::string>());
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  c.values.assign(d.data(), d.data() + d.size());
  return c;
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

// x as Python's repr writes it: the shortest digits that read back exactly
// (std::to_chars), in exponent form for x < 1e-4 or x >= 1e16, else fixed
// with ".0" on whole numbers.
void AppendRepr(double x, std::string& out) {
  if (std::isnan(x)) {
    out += "nan";
    return;
  }
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific);
  const char* e = std::find(buf, r.ptr, 'e');
  int exponent = 0;
  if (e != r.ptr) std::from_chars(e + (e[1] == '+' ? 2 : 1), r.ptr, exponent);
  if (std::isinf(x) || exponent >= 16 || exponent < -4) {
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
  m.def("_tsv_rows", &TsvRows, py::arg("data"),
        "Rows of a 2-D float array as TSV bytes, each value as repr() writes it.");
}

}  // namespace stickslip::python
