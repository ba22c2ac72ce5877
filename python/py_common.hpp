// Shared pieces of the Python module: read-only arrays, the solver keywords,
// Ctrl-C from the library's cancel hooks, and the binding entry points of the
// module's source files.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

// The one lens (parameter_axis.hpp) in Python: a Parameter member or its
// name in, a Parameter out. An unknown name raises ValueError (InvalidArgument).
namespace pybind11::detail {
template <>
class type_caster<stickslip::ParameterAxis> {
 public:
  static constexpr auto name = const_name("Parameter");
  bool load(handle src, bool convert) {
    if (isinstance<str>(src)) {
      value_.emplace(src.cast<std::string>());
      return true;
    }
    make_caster<stickslip::Parameter> id;
    if (!id.load(src, convert)) return false;
    value_.emplace(cast_op<stickslip::Parameter>(id));
    return true;
  }
  static handle cast(const stickslip::ParameterAxis& a, return_value_policy, handle parent) {
    return make_caster<stickslip::Parameter>::cast(a.id(), return_value_policy::copy, parent);
  }
  template <typename T>
  using cast_op_type = movable_cast_op_type<T>;
  operator stickslip::ParameterAxis*() { return &*value_; }
  operator stickslip::ParameterAxis&() { return *value_; }
  operator stickslip::ParameterAxis&&() && { return std::move(*value_); }

 private:
  std::optional<stickslip::ParameterAxis> value_;
};
}  // namespace pybind11::detail

namespace stickslip::python {

namespace py = pybind11;

// A NumPy copy of v, marked read-only (issue 23, N17).
template <typename T>
py::array ReadOnly(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()), v.data());
  a.attr("setflags")(py::arg("write") = false);
  return std::move(a);
}
py::array ReadOnlyBool(const std::vector<bool>& v);
// Row-major values, `cols` per row, as a read-only 2-D array (rows x cols).
py::array ReadOnlyRows(const std::vector<double>& flat, int cols);
// A read-only copy of an Eigen matrix or vector (rows x cols).
// (vector: its values as a 1-D array).
template <typename M>
py::array ReadOnlyMatrix(const M& a, bool vector) {
  using T = typename M::Scalar;
  py::array_t<T> out = vector ? py::array_t<T>(a.size())
                              : py::array_t<T>({static_cast<py::ssize_t>(a.rows()),
                                                static_cast<py::ssize_t>(a.cols())});
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      out.mutable_data()[i * a.cols() + j] = a(i, j);  // row-major
  out.attr("setflags")(py::arg("write") = false);
  return std::move(out);
}

// A read-only NumPy array of strings (dtype U).
py::array ReadOnlyStrings(const std::vector<std::string>& v);

// Python's repr of x (every digit, as a message shows a value).
inline std::string Repr(double x) { return py::repr(py::float_(x)).cast<std::string>(); }

// Raises stickslip.NumericalError (a RuntimeError) with the message.
[[noreturn]] void RaiseNumerical(const std::string& message);
void SetNumericalError(py::object* type);

// The solver keywords of every computing function, applied over `base`:
// integrator 'taylor' (default) or 'cvode'; method 'adams' or 'bdf' (CVODE's;
// given alone it selects CVODE). Each accepts the enum or its name; None
// keeps base's value.
FlowOptions Solver(FlowOptions base, std::optional<double> rtol, std::optional<double> atol,
                   const py::object& integrator, const py::object& method);

// Ctrl-C during a computation that runs without the GIL: the library's cancel
// hook calls operator() (from any thread, without the GIL). At most every
// 20 ms it takes the GIL and runs PyErr_CheckSignals; once that raised
// (KeyboardInterrupt from SIGINT) the hook returns true for good, and
// RaiseIfInterrupted() re-raises the exception after the call returns.
class Interrupt {
 public:
  Interrupt();
  ~Interrupt();
  Interrupt(const Interrupt&) = delete;
  Interrupt& operator=(const Interrupt&) = delete;
  bool operator()();
  bool fired() const { return fired_.load(); }
  // With the GIL held: throws py::error_already_set if a signal handler raised.
  void RaiseIfInterrupted();

 private:
  std::atomic<bool> fired_{false};
  std::chrono::steady_clock::time_point next_check_;
  PyObject *type_ = nullptr, *value_ = nullptr, *trace_ = nullptr;
};

// A Python progress callback called from a computation that runs without the
// GIL: each call takes the GIL; the first exception it raises is kept, failed()
// turns true (the cancel hook stops the run) and RaiseIfFailed() raises it
// again once the GIL is back. None: calls do nothing.
class ProgressCall {
 public:
  explicit ProgressCall(py::object fn) : fn_(std::move(fn)) {}
  ~ProgressCall();
  template <typename... A>
  void operator()(A&&... args) {
    if (fn_.is_none() || failed_.load()) return;
    py::gil_scoped_acquire gil;
    try {
      fn_(std::forward<A>(args)...);
    } catch (py::error_already_set& e) {
      error_ = std::make_unique<py::error_already_set>(std::move(e));
      failed_ = true;
    }
  }
  bool failed() const { return failed_.load(); }
  void RaiseIfFailed();  // with the GIL held

 private:
  py::object fn_;
  std::unique_ptr<py::error_already_set> error_;
  std::atomic<bool> failed_{false};
};

// Binding entry points, one per source file.
void BindOptions(py::module_& m);
void BindResults(py::module_& m);
void BindCompute(py::module_& m);
void BindCharts(py::module_& m);
void BindForced(py::module_& m);  // py_forced.cpp
void BindRestart(py::module_& m);
void BindBatch(py::module_& m);        // py_batch.cpp: orbits()
void BindSystemBatch(py::module_& m);  // py_system_batch.cpp: orbits(system, ...) (after BindBatch)
void BindOrbitBranch(py::module_& m);  // py_orbit_branch.cpp: continue_orbits, continue_doubled
void BindSystems(py::module_& m);      // py_systems.cpp: ChainParams, CouplingParams (issue 32)
void BindSystemRuns(py::module_& m);   // py_system_runs.cpp: simulate_system, steady_sliding
void BindSystemOrbit(py::module_& m);  // py_system_orbit.cpp: periodic_orbit(s)(system, ...)
void BindSystemBranch(py::module_& m);  // py_system_branch.cpp: steady_branch, settle
void BindAttractors(py::module_& m);    // py_attractors.cpp: basins(system), attractor_basins
void BindSystemChart(py::module_& m);  // py_system_chart.cpp: chart(system, ...) (after BindCharts)
void BindModel(py::module_& m);        // py_model.cpp: System (a model file's system, issue 33)

// The System a Python parameter object stands for (Params, ForcedBeltParams,
// ChainParams, CouplingParams, System); TypeError for anything else.
std::unique_ptr<System> SystemOf(const py::object& system);
// The several-mass systems (py_systems.cpp): nullptr for another object.
std::unique_ptr<System> SeveralMassSystemOf(const py::object& system);
/// A stickslip.System's (py_model.cpp), else nullptr.
std::unique_ptr<System> ModelSystemOf(const py::object& system);
// The Poincare section named `name` ('stroboscopic', 'stick-exit',
// 'xdot-falling') through z, closing after m returns (py_orbit_branch.cpp);
// a stick exit is that of `contact`.
PoincareSection SectionOf(const System& s, const std::string& name, const Eigen::VectorXd& z, int m,
                          std::optional<int> turns, int contact = 0);
// The section a name gives; none: a clock's stroboscopic one, else the stick exit.
std::string SectionOrDefault(const System& s, const std::optional<std::string>& section);
// The start point on `section` at `state`: Filippov's mode, and on a stick
// exit its contact in the slip it leaves into (the way lambda points).
FlowPoint SectionStart(const System& s, const PoincareSection& section,
                       const Eigen::VectorXd& state);

// `state` as a system's: its size, every value finite (InvalidArgument naming it).
Eigen::VectorXd CheckedState(const System& s, const Eigen::VectorXd& state,
                             const std::string& name = "state");
// The flow's options for a system: the forced oscillator's own tolerances
// (rtol = atol = 1e-12, ForcedBelt::FlowDefaults), else the flow's; rtol and
// atol over them.
FlowOptions FlowFor(const py::object& system, std::optional<double> rtol,
                    std::optional<double> atol);

// `result["name"]` for `result.name`: the dicts of earlier versions.
py::object GetItem(const py::object& self, const std::string& key);

}  // namespace stickslip::python
