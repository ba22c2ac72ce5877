// The Python module `stickslip` (pybind11): parameters, exceptions and the
// small functions; the option and result types, the computing functions and
// the chart are bound in py_options.cpp, py_results.cpp, py_compute.cpp and
// py_chart.cpp; restarts in py_restart.cpp. Library exceptions become Python exceptions with the
// same message; Ctrl-C raises KeyboardInterrupt (py_common.hpp, Interrupt).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "py_common.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/belt/params.hpp"
#include "stickslip/systems/forced/forced.hpp"
#include "stickslip/version.hpp"

namespace py = pybind11;
namespace ss = stickslip;
using namespace stickslip::python;

namespace {
std::string TypeName(const py::handle& x) {
  return py::str(py::type::of(x).attr("__name__")).cast<std::string>();
}

// A law by name ('cubic') or as stickslip.Law; anything else is a TypeError.
ss::LawKind LawOf(const py::object& law) {
  if (py::isinstance<py::str>(law)) return ss::LawFromName(law.cast<std::string>());
  if (py::isinstance<ss::LawKind>(law)) return law.cast<ss::LawKind>();
  throw py::type_error("law must be a law's name ('cubic', ...) or a stickslip.Law, not " +
                       TypeName(law) +
                       (py::isinstance<ss::Params>(law) ? " (a Params has .law)" : ""));
}

// A parameter value: a real number (int, float, NumPy scalar), else TypeError.
double NumberOf(const std::string& name, const py::handle& x) {
  if (py::isinstance<py::bool_>(x) || !PyNumber_Check(x.ptr()) || PyComplex_Check(x.ptr()))
    throw py::type_error(name + " must be a number, not " + TypeName(x));
  return py::float_(py::reinterpret_borrow<py::object>(x)).cast<double>();
}

// Every parameter set, then the whole set validated (InvalidArgument naming the
// value) by the rules every model shares: the forced model's, which also admit
// v = 0 (a fixed floor) and Coulomb's mu_k = mu_s; the belt's computations
// check those two themselves.
void ValidateAnyModel(const ss::Params& p) {
  ss::ForcedBeltParams fp;
  fp.base = p;
  const std::string err = ss::ValidationError(fp);
  if (!err.empty()) throw ss::InvalidArgument(err);
}

ss::Params MakeParams(const py::object& law, const py::kwargs& kwargs) {
  ss::Params p;
  p.law = LawOf(law);
  for (const auto& item : kwargs) {
    const std::string name = py::cast<std::string>(item.first);
    ss::SetParameter(p, name, NumberOf(name, item.second));
  }
  ValidateAnyModel(p);
  return p;
}

// Physical inputs by name (seed section 3 scaling), as ss_continue's --mass ...
ss::Params FromPhysical(const py::object& law, const py::kwargs& kwargs) {
  ss::PhysicalParams ph;
  ph.law = LawOf(law);
  const std::pair<const char*, double*> fields[] = {
      {"mass", &ph.mass},           {"damping", &ph.damping},
      {"stiffness", &ph.stiffness}, {"belt_speed", &ph.belt_speed},
      {"gravity", &ph.gravity},     {"mu_s", &ph.mu_s},
      {"mu_m", &ph.mu_m},           {"speed_m", &ph.speed_m},
      {"mu_k", &ph.mu_k},           {"speed_s", &ph.speed_s},
      {"delta", &ph.delta}};
  for (const auto& item : kwargs) {
    const std::string name = py::cast<std::string>(item.first);
    double* field = nullptr;
    for (const auto& [n, f] : fields)
      if (name == n) field = f;
    if (!field) throw ss::InvalidArgument("unknown physical input '" + name + "'");
    *field = NumberOf(name, item.second);
  }
  ss::Params p = ss::ToDimensionless(ph);
  ss::Validate(p);
  return p;
}

py::dict ParamsDict(const ss::Params& p) {
  py::dict d;
  d["law"] = ss::Name(p.law);
  for (const auto& name : ss::ParameterNames(p.law)) d[name.c_str()] = ss::GetParameter(p, name);
  return d;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "Continuation and bifurcation of the stick-slip belt model (seed eq. 3.5).";
  m.attr("__version__") = ss::Version();
  // NumPy's C API is looked up once, here, under the GIL of the importing
  // thread: a first lookup from a worker thread can deadlock against another
  // thread that returns from a computation (pybind11's static npy_api).
  py::module_::import("numpy");
  py::array_t<double> warm_up(0);
  m.attr("git_commit") = ss::GitCommit();

  static py::exception<ss::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<ss::InvalidArgument> invalid(m, "InvalidArgument", PyExc_ValueError);
  static py::object numerical = py::exception<ss::ExternalError>(m, "NumericalError", error.ptr());
  SetNumericalError(&numerical);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const py::cast_error& e) {  // pybind11's own is a RuntimeError
      PyErr_SetString(PyExc_TypeError, e.what());
    } catch (const ss::InvalidArgument& e) {
      PyErr_SetString(invalid.ptr(), e.what());
    } catch (const ss::Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });

  py::class_<ss::Params>(m, "Params",
                         "Dimensionless model parameters; defaults are the seed set "
                         "(beta 0.05, v 0.25, mu_s 0.4, mu_m 0.25, v_m 0.5).")
      .def(py::init(&MakeParams), py::arg("law") = "cubic",
           "Params(law='cubic', **values), e.g. Params(beta=0.1, v=0.3). Unknown names and "
           "invalid values raise InvalidArgument (a ValueError) naming the value; a value that "
           "is not a number raises TypeError. Attributes set later are checked by validate() "
           "and by every computation.")
      .def_property(
          "law", [](const ss::Params& p) { return std::string(ss::Name(p.law)); },
          [](ss::Params& p, const py::object& law) { p.law = LawOf(law); }, "the law's name")
      .def_readwrite("beta", &ss::Params::beta)
      .def_readwrite("v", &ss::Params::v)
      .def_readwrite("mu_s", &ss::Params::mu_s)
      .def_readwrite("mu_m", &ss::Params::mu_m)
      .def_readwrite("v_m", &ss::Params::v_m)
      .def_readwrite("mu_k", &ss::Params::mu_k)
      .def_readwrite("v_s", &ss::Params::v_s)
      .def_readwrite("delta", &ss::Params::delta)
      .def_readwrite("k5", &ss::Params::k5)
      .def_static("from_physical", &FromPhysical, py::arg("law") = "cubic",
                  "From physical inputs (mass, damping, stiffness, belt_speed, gravity=9.81, "
                  "mu_s, mu_m, speed_m, mu_k, speed_s, delta) by the seed's scaling; validated.")
      .def_property_readonly("k1", &ss::Params::k1, "cubic law: 3 (mu_s - mu_m) / (2 v_m)")
      .def_property_readonly("k3", &ss::Params::k3, "cubic law: (mu_s - mu_m) / (2 v_m^3)")
      .def("validation_error", py::overload_cast<const ss::Params&>(&ss::ValidationError),
           "'' if valid, else one line naming the value")
      .def("validate", &ss::Validate, "Raises InvalidArgument naming the offending value.")
      .def("to_dict", &ParamsDict, "The law and its parameters.")
      .def("__repr__", [](const ss::Params& p) {
        std::string s = "Params(law='" + std::string(ss::Name(p.law)) + "'";
        for (const auto& n : ss::ParameterNames(p.law))
          s += ", " + n + "=" + Repr(ss::GetParameter(p, n));
        return s + ")";
      });
  m.def(
      "parameter_names", [](const py::object& law) { return ss::ParameterNames(LawOf(law)); },
      py::arg("law") = "cubic", "Names of the parameters of a law, in a fixed order.");
  m.def(
      "default_range",
      [](const ss::Params& base, const ss::ParameterAxis& name) {
        const ss::ParameterRange r = ss::DefaultRange(base, name);
        return py::make_tuple(r.from, r.to);
      },
      py::arg("params"), py::arg("name"),
      "(from, to): the default continuation range of a parameter around params.");

  m.def(
      "scales",
      [](double mass, double stiffness, double gravity) {
        return py::make_tuple(ss::LengthScale(mass, stiffness, gravity),
                              ss::TimeScale(mass, stiffness));
      },
      py::arg("mass"), py::arg("stiffness"), py::arg("gravity") = 9.81,
      "(L, t0) = (M g / K, sqrt(M / K)): lengths and times of the dimensionless model.");

  BindOptions(m);
  BindResults(m);
  BindCompute(m);
  BindCharts(m);
  BindForced(m);
  BindRestart(m);
  BindBatch(m);
  BindSystemBatch(m);
  BindOrbitBranch(m);
  BindSystems(m);
  BindModel(m);
  BindSystemRuns(m);
  BindSystemOrbit(m);
  BindSystemBranch(m);
  BindAttractors(m);
  BindSystemChart(m);
}
