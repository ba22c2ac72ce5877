// The Python module `stickslip` (pybind11): parameters, simulation, periodic
// orbits and continuation, results as NumPy arrays or dicts of them. The GIL
// is released while the library computes; library exceptions become Python
// exceptions with the same message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "stickslip/chart.hpp"
#include "stickslip/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/flow.hpp"
#include "stickslip/model.hpp"
#include "stickslip/orbit.hpp"
#include "stickslip/params.hpp"
#include "stickslip/version.hpp"

namespace py = pybind11;
namespace ss = stickslip;

namespace {

// Raised for a numerical failure (a status that is not ok), with its message.
py::object* g_numerical_error = nullptr;

[[noreturn]] void RaiseNumerical(const std::string& message) {
  PyErr_SetString(g_numerical_error->ptr(), message.c_str());
  throw py::error_already_set();
}

py::array_t<double> Array(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

py::object StringArray(const std::vector<std::string>& v) {
  return py::module_::import("numpy").attr("array")(py::cast(v), "U");
}

// Solver settings shared by every computing function, as keyword arguments.
ss::FlowOptions Solver(double rtol, double atol, const std::string& method) {
  ss::FlowOptions f;
  f.rtol = rtol;
  f.atol = atol;
  if (method == "adams") {
    f.method = ss::Method::kAdams;
  } else if (method == "bdf") {
    f.method = ss::Method::kBdf;
  } else {
    throw ss::InvalidArgument("unknown method '" + method + "' (expected adams or bdf)");
  }
  const std::string err = f.ValidationError();
  if (!err.empty()) throw ss::InvalidArgument("invalid solver options: " + err);
  return f;
}

ss::Params MakeParams(const std::string& law, const py::kwargs& kwargs) {
  ss::Params p;
  p.law = ss::LawFromName(law);
  for (const auto& item : kwargs)
    ss::SetParameter(p, py::cast<std::string>(item.first), py::cast<double>(item.second));
  return p;
}

// Physical inputs by name (seed section 3 scaling), as ss_continue's --mass ...
ss::Params FromPhysical(const std::string& law, const py::kwargs& kwargs) {
  ss::PhysicalParams ph;
  ph.law = ss::LawFromName(law);
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
    *field = py::cast<double>(item.second);
  }
  ss::Params p = ss::ToDimensionless(ph);
  ss::Validate(p);
  return p;
}

py::dict ParamsDict(const ss::Params& p) {
  py::dict d;
  d["law"] = ss::LawName(p.law);
  for (const auto& name : ss::ParameterNames(p.law)) d[name.c_str()] = ss::GetParameter(p, name);
  return d;
}

py::dict Simulate(const ss::Params& p, double x0, double xdot0, double t_end, double dt,
                  double rtol, double atol, const std::string& method) {
  if (!(t_end > 0)) throw ss::InvalidArgument("t_end = " + std::to_string(t_end) + " must be > 0");
  if (!(dt > 0)) throw ss::InvalidArgument("dt = " + std::to_string(dt) + " must be > 0");
  const ss::FlowOptions options = Solver(rtol, atol, method);
  const ss::Model model(p);
  std::vector<double> t, x, xdot;
  std::vector<std::string> mode;
  ss::FlowResult r;
  {
    py::gil_scoped_release nogil;
    ss::Flow flow(model, options);
    const ss::Vec2 z0(x0, xdot0);
    ss::StopRule stop;
    stop.t_max = t_end;
    auto observer = [&](const ss::Sample& s) {
      if (!t.empty() && s.t == t.back() && s.z[0] == x.back() && s.z[1] == xdot.back() &&
          ss::ModeName(s.mode) == mode.back())
        return;  // a repeated point (as in ss_simulate)
      t.push_back(s.t);
      x.push_back(s.z[0]);
      xdot.push_back(s.z[1]);
      mode.push_back(ss::ModeName(s.mode));
    };
    r = flow.Run(0.0, z0, model.ModeAt(z0), stop, false, dt, observer);
  }
  if (!r.ok())
    RaiseNumerical(std::string(ss::FlowStatusName(r.status)) + ": " + r.message +
                   " (at t = " + std::to_string(r.t) + " in " + ss::ModeName(r.mode) + ")");
  py::dict d;
  d["t"] = Array(t);
  d["x"] = Array(x);
  d["xdot"] = Array(xdot);
  d["mode"] = StringArray(mode);
  d["t_stick"] = r.t_stick;
  d["switches"] = r.switches;
  return d;
}

py::dict OrbitDict(const ss::Orbit& o) {
  py::dict d;
  d["kind"] = ss::OrbitKindName(o.kind);
  d["period"] = o.period;
  d["t_stick"] = o.t_stick;
  d["x_min"] = o.x_min;
  d["x_max"] = o.x_max;
  d["xdot_min"] = o.xdot_min;
  d["xdot_max"] = o.xdot_max;
  d["start"] = Array({o.start[0], o.start[1]});
  d["multiplier"] = o.multiplier;
  d["stable"] = o.stable;
  std::vector<std::string> modes;
  for (ss::Mode m : o.modes) modes.push_back(ss::ModeName(m));
  d["modes"] = modes;
  return d;
}

// A stick-slip orbit (a_guess None) or a pure-slip orbit by Newton from xbar + a_guess.
py::dict PeriodicOrbit(const ss::Params& p, std::optional<double> a_guess, bool floquet,
                       double rtol, double atol, const std::string& method) {
  ss::OrbitOptions options;
  options.flow = Solver(rtol, atol, method);
  options.floquet = floquet;
  const std::string err = options.ValidationError();
  if (!err.empty()) throw ss::InvalidArgument(err);
  if (a_guess && !(*a_guess > 0))
    throw ss::InvalidArgument("a_guess = " + std::to_string(*a_guess) + " must be > 0");
  const ss::Model model(p);
  ss::OrbitResult r;
  {
    py::gil_scoped_release nogil;
    ss::OrbitFinder finder(model, options);
    r = a_guess ? finder.PureSlip(*a_guess) : finder.StickSlip();
  }
  if (!r.ok()) RaiseNumerical(std::string(ss::OrbitStatusName(r.status)) + ": " + r.message);
  return OrbitDict(r.orbit);
}

py::dict PointsDict(const std::vector<ss::BranchPoint>& pts) {
  std::vector<double> p, period, x_min, x_max, xdot_min, xdot_max, t_stick, mult, amp;
  std::vector<std::string> kind;
  std::vector<int> branch;
  std::vector<bool> stable;
  for (const auto& q : pts) {
    p.push_back(q.p), period.push_back(q.period), x_min.push_back(q.x_min);
    x_max.push_back(q.x_max), xdot_min.push_back(q.xdot_min), xdot_max.push_back(q.xdot_max);
    t_stick.push_back(q.t_stick), mult.push_back(q.multiplier), amp.push_back(q.amplitude);
    kind.push_back(ss::PointKindName(q.kind)), branch.push_back(q.branch);
    stable.push_back(q.stable);
  }
  py::dict d;
  d["p"] = Array(p);
  d["kind"] = StringArray(kind);
  d["branch"] = py::array_t<int>(static_cast<py::ssize_t>(branch.size()), branch.data());
  d["period"] = Array(period);
  d["x_min"] = Array(x_min);
  d["x_max"] = Array(x_max);
  d["xdot_min"] = Array(xdot_min);
  d["xdot_max"] = Array(xdot_max);
  d["t_stick"] = Array(t_stick);
  d["multiplier"] = Array(mult);
  d["stable"] = py::module_::import("numpy").attr("array")(py::cast(stable), "bool");
  d["amplitude"] = Array(amp);
  return d;
}

py::dict ContinueBranch(const ss::Params& base, const std::string& param,
                        std::optional<double> from, std::optional<double> to, double max_step,
                        bool floquet, double rtol, double atol, const std::string& method) {
  ss::ContinuationOptions opts;
  opts.param = param;
  // No range for an unknown name: the options say why.
  if (!ss::IsParameterName(param)) throw ss::InvalidArgument(opts.ValidationError(base));
  const ss::ParameterRange range = ss::DefaultRange(base, param);
  opts.from = from.value_or(range.from);
  opts.to = to.value_or(range.to);
  opts.max_step = max_step;
  opts.stick_slip_floquet = floquet;
  opts.orbit.flow = Solver(rtol, atol, method);
  ss::ContinuationResult r;
  {
    py::gil_scoped_release nogil;
    r = ss::Continue(base, opts);  // throws InvalidArgument on bad options
  }
  py::dict d;
  d["param"] = param;
  d["status"] = ss::ContinuationStatusName(r.status);
  d["message"] = r.message;
  d["points"] = PointsDict(r.points);
  py::list special;
  for (const auto& s : r.special) {
    py::dict e;
    e["label"] = ss::SpecialLabel(s.kind);
    e["p"] = s.p;
    e["period"] = s.period;
    e["x_min"] = s.x_min;
    e["x_max"] = s.x_max;
    e["xdot_min"] = s.xdot_min;
    e["multiplier_before"] = s.multiplier_before;
    e["multiplier_after"] = s.multiplier_after;
    e["description"] = s.description;
    special.append(e);
  }
  d["special"] = special;
  if (r.status == ss::ContinuationStatus::kFailed) RaiseNumerical(r.message);
  return d;
}

// The two-parameter chart (as ss_chart, without regions): curves and codim-2 points.
py::dict ChartOf(const ss::Params& base, const std::string& param, double from_, double to,
                 const std::string& param2, double from2, double to2, double max_step) {
  ss::ChartOptions opts;
  opts.plane = ss::Plane{param, param2, from_, to, from2, to2};
  opts.max_step = max_step;
  const std::string err = opts.ValidationError(base);
  if (!err.empty()) throw ss::InvalidArgument(err);
  ss::ChartResult r;
  {
    py::gil_scoped_release nogil;
    r = ss::Chart(base, opts);
  }
  py::list curves, codim2;
  for (const ss::Curve& c : r.curves) {
    std::vector<double> p1, p2, period, amplitude, multiplier, l1;
    std::vector<std::string> type;
    for (const ss::CurvePoint& q : c.points) {
      p1.push_back(q.p1), p2.push_back(q.p2), period.push_back(q.period);
      amplitude.push_back(q.amplitude), multiplier.push_back(q.multiplier), l1.push_back(q.l1);
      type.push_back(q.type);
    }
    py::dict d;
    d["label"] = ss::CurveLabel(c.kind);
    d[param.c_str()] = Array(p1);
    d[param2.c_str()] = Array(p2);
    d["period"] = Array(period), d["amplitude"] = Array(amplitude);
    d["multiplier"] = Array(multiplier), d["l1"] = Array(l1), d["type"] = StringArray(type);
    d["ends"] = c.ends;
    curves.append(d);
  }
  for (const ss::Codim2Point& c : r.codim2)
    codim2.append(py::dict(py::arg("label") = c.label, py::arg(param.c_str()) = c.p1,
                           py::arg(param2.c_str()) = c.p2, py::arg("description") = c.description));
  py::dict d;
  d["status"] = ss::ChartStatusName(r.status);
  d["message"] = r.message;
  d["curves"] = curves;
  d["codim2"] = codim2;
  if (r.status == ss::ChartStatus::kFailed) RaiseNumerical(r.message);
  return d;
}

}  // namespace

PYBIND11_MODULE(stickslip, m) {
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
  g_numerical_error = &numerical;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
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
           "Params(law='cubic', **values), e.g. Params(beta=0.1, v=0.3). Unknown names raise "
           "InvalidArgument.")
      .def_property(
          "law", [](const ss::Params& p) { return std::string(ss::LawName(p.law)); },
          [](ss::Params& p, const std::string& s) { p.law = ss::LawFromName(s); })
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
      .def("validation_error", &ss::ValidationError, "'' if valid, else one line naming the value")
      .def("validate", &ss::Validate, "Raises InvalidArgument naming the offending value.")
      .def("to_dict", &ParamsDict, "The law and its parameters.")
      .def("__repr__", [](const ss::Params& p) {
        std::string s = "Params(law='" + std::string(ss::LawName(p.law)) + "'";
        for (const auto& n : ss::ParameterNames(p.law))
          s += ", " + n + "=" + py::repr(py::float_(ss::GetParameter(p, n))).cast<std::string>();
        return s + ")";
      });
  m.def(
      "parameter_names",
      [](const std::string& law) { return ss::ParameterNames(ss::LawFromName(law)); },
      py::arg("law") = "cubic", "Names of the parameters of a law, in a fixed order.");
  m.def(
      "default_range",
      [](const ss::Params& base, const std::string& name) {
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

  const double rtol = ss::FlowOptions().rtol, atol = ss::FlowOptions().atol;
  m.def("simulate", &Simulate, py::arg("params"), py::arg("x0") = 0.0, py::arg("xdot0") = 0.25,
        py::arg("t_end") = 100.0, py::arg("dt") = 0.01, py::arg("rtol") = rtol,
        py::arg("atol") = atol, py::arg("method") = "adams",
        "One trajectory (as ss_simulate): dict of arrays t, x, xdot, mode (one row every dt "
        "and at every switch), plus t_stick and switches.");
  m.def("periodic_orbit", &PeriodicOrbit, py::arg("params"), py::arg("a_guess") = py::none(),
        py::arg("floquet") = false, py::arg("rtol") = rtol, py::arg("atol") = atol,
        py::arg("method") = "adams",
        "The stick-slip orbit (a_guess None) or the pure-slip orbit by Newton from the "
        "section point xbar + a_guess, as a dict (period, extremes, start, multiplier, ...).");
  m.def("continue_branch", &ContinueBranch, py::arg("params"), py::arg("param") = "v",
        py::arg("from_") = py::none(), py::arg("to") = py::none(), py::arg("max_step") = 0.01,
        py::arg("floquet") = false, py::arg("rtol") = rtol, py::arg("atol") = atol,
        py::arg("method") = "adams",
        "Branches in one parameter (as ss_continue): dict with 'points' (dict of arrays), "
        "'special' (list of dicts: label GR/HB/LP, p, ...), 'status' and 'message'. "
        "from_/to default to default_range(param).");
  m.def("chart", &ChartOf, py::arg("params"), py::arg("param") = "v", py::arg("from_") = 0.05,
        py::arg("to") = 0.6, py::arg("param2") = "beta", py::arg("from2") = 0.0,
        py::arg("to2") = 0.25, py::arg("max_step") = 0.01,
        "The stability chart in two parameters (as ss_chart): dict with 'curves' (list of dicts: "
        "label HB/GR/LP, arrays named for the two parameters, period, amplitude, multiplier, "
        "l1, type) and 'codim2' (list of dicts: label GH/GR-LP, the two parameters).");
}
