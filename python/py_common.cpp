// Read-only arrays, the solver keywords and Ctrl-C for the Python module.
#include "py_common.hpp"

#include <pybind11/stl.h>

#include <cmath>

#include "stickslip/errors.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

namespace {

py::object* g_numerical_error = nullptr;

// How often the cancel hook may take the GIL to look for signals: a SIGINT
// is seen within this (plus one integration step) of its arrival.
constexpr std::chrono::milliseconds kSignalPoll(20);

template <typename Enum>
Enum EnumArg(const py::object& value, const char* what, Enum (*from_name)(const std::string&)) {
  if (py::isinstance<py::str>(value)) return from_name(value.cast<std::string>());
  try {
    return value.cast<Enum>();
  } catch (const py::cast_error&) {
    throw InvalidArgument(std::string(what) + " = " + py::repr(value).cast<std::string>() +
                          " is neither a name nor a stickslip enum value");
  }
}

Integrator IntegratorFromName(const std::string& s) {
  if (s == "taylor") return Integrator::kTaylor;
  if (s == "cvode") return Integrator::kCvode;
  throw InvalidArgument("integrator = '" + s + "' (expected taylor or cvode)");
}

Method MethodFromName(const std::string& s) {
  if (s == "adams") return Method::kAdams;
  if (s == "bdf") return Method::kBdf;
  throw InvalidArgument("method = '" + s + "' (expected adams or bdf)");
}

}  // namespace

py::array ReadOnlyBool(const std::vector<bool>& v) {
  py::array_t<bool> a(static_cast<py::ssize_t>(v.size()));
  for (size_t i = 0; i < v.size(); ++i) a.mutable_at(static_cast<py::ssize_t>(i)) = v[i];
  a.attr("setflags")(py::arg("write") = false);
  return std::move(a);
}

py::array ReadOnlyStrings(const std::vector<std::string>& v) {
  py::array a = py::module_::import("numpy").attr("array")(py::cast(v), "U");
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

void SetNumericalError(py::object* type) { g_numerical_error = type; }

void RaiseNumerical(const std::string& message) {
  PyErr_SetString(g_numerical_error->ptr(), message.c_str());
  throw py::error_already_set();
}

FlowOptions Solver(FlowOptions f, std::optional<double> rtol, std::optional<double> atol,
                   const py::object& integrator, const py::object& method) {
  if (rtol) f.rtol = *rtol;
  if (atol) f.atol = *atol;
  if (!method.is_none()) {
    f.method = EnumArg<Method>(method, "method", &MethodFromName);
    if (integrator.is_none()) f.integrator = Integrator::kCvode;  // method= names CVODE's
  }
  if (!integrator.is_none())
    f.integrator = EnumArg<Integrator>(integrator, "integrator", &IntegratorFromName);
  if (!method.is_none() && f.integrator != Integrator::kCvode)
    throw InvalidArgument("method = '" + std::string(Name(f.method)) +
                          "' applies to integrator = 'cvode' only");
  const std::string err = f.ValidationError();
  if (!err.empty()) throw InvalidArgument("invalid solver options: " + err);
  return f;
}

Interrupt::Interrupt() : next_check_(std::chrono::steady_clock::now()) {}

Interrupt::~Interrupt() {
  if (type_ || value_ || trace_) {  // never raised: drop the exception (under the GIL)
    py::gil_scoped_acquire gil;
    Py_XDECREF(type_), Py_XDECREF(value_), Py_XDECREF(trace_);
  }
}

bool Interrupt::operator()() {
  if (fired_.load()) return true;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_check_) return false;
  next_check_ = now + kSignalPoll;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) {  // a handler raised (SIGINT: KeyboardInterrupt)
    PyErr_Fetch(&type_, &value_, &trace_);
    fired_.store(true);
  }
  return fired_.load();
}

void Interrupt::RaiseIfInterrupted() {
  if (!fired_.load() || !type_) return;
  PyErr_Restore(type_, value_, trace_);
  type_ = value_ = trace_ = nullptr;
  throw py::error_already_set();
}

py::object GetItem(const py::object& self, const std::string& key) {
  if (!py::hasattr(self, key.c_str())) throw py::key_error(key);
  return self.attr(key.c_str());
}

ProgressCall::~ProgressCall() = default;  // with the GIL: the caller's frame holds it

void ProgressCall::RaiseIfFailed() {
  if (!error_) return;
  py::error_already_set e = std::move(*error_);
  error_.reset();
  throw e;
}

py::array ReadOnlyRows(const std::vector<double>& flat, int cols) {
  const auto rows = static_cast<py::ssize_t>(cols ? flat.size() / cols : 0);
  py::array_t<double> a({rows, static_cast<py::ssize_t>(cols)}, flat.data());
  a.attr("setflags")(py::arg("write") = false);
  return std::move(a);
}

Eigen::VectorXd CheckedState(const System& s, const Eigen::VectorXd& state,
                             const std::string& name) {
  if (state.size() != s.dimension())
    throw InvalidArgument(name + ": " + std::to_string(state.size()) + " values, the system has " +
                          std::to_string(s.dimension()));
  for (Eigen::Index i = 0; i < state.size(); ++i)
    if (!std::isfinite(state[i]))
      throw InvalidArgument(name + "[" + std::to_string(i) + "] = " + Repr(state[i]) +
                            " must be finite");
  return state;
}

FlowOptions FlowFor(const py::object& system, std::optional<double> rtol,
                    std::optional<double> atol) {
  const FlowOptions base =
      py::isinstance<ForcedBeltParams>(system) ? ForcedBelt::FlowDefaults() : FlowOptions();
  return Solver(base, rtol, atol, py::none(), py::none());
}

}  // namespace stickslip::python
