// Result types as Python classes: read-only attributes, arrays read-only,
// and result["name"] for result.name (the dicts of version 0.x).
#include "py_results.hpp"

#include <pybind11/complex.h>
#include <pybind11/stl.h>

namespace stickslip::python {

namespace {

py::array Matrix(const Mat2& a) {
  py::array_t<double> out({2, 2});
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) out.mutable_at(i, j) = a(i, j);
  out.attr("setflags")(py::arg("write") = false);
  return std::move(out);
}

void BindOrbits(py::module_& m) {
  Result<Equilibrium>(m, "Equilibrium", "Steady sliding (x, 0) and its eigenvalues.")
      .def_readonly("x", &Equilibrium::x, "mu(v)")
      .def_readonly("damping", &Equilibrium::damping, "2 beta + mu'(v): stable when > 0")
      .def_readonly("lambda1", &Equilibrium::lambda1)
      .def_readonly("lambda2", &Equilibrium::lambda2)
      .def_property_readonly("max_real", &Equilibrium::max_real)
      .def_property_readonly("stable", &Equilibrium::stable);
  Result<Orbit>(m, "Orbit", "A periodic orbit: period, extremes, start, multipliers.")
      .def_readonly("kind", &Orbit::kind)
      .def_readonly("period", &Orbit::period)
      .def_readonly("t_stick", &Orbit::t_stick, "time in stick per period")
      .def_property_readonly("x_min", [](const Orbit& o) { return o.extrema.x_min; })
      .def_property_readonly("x_max", [](const Orbit& o) { return o.extrema.x_max; })
      .def_property_readonly("xdot_min", [](const Orbit& o) { return o.extrema.xdot_min; })
      .def_property_readonly("xdot_max", [](const Orbit& o) { return o.extrema.xdot_max; })
      .def_property_readonly(
          "start",
          [](const Orbit& o) {
            return ReadOnly(std::vector<double>{o.start[0], o.start[1]});
          },
          "stick-slip: the exit point (x0, v); pure slip: the point on x' = 0")
      .def_readonly("modes", &Orbit::modes, "segment sequence from start")
      .def_readonly("crossings", &Orbit::crossings, "crossings of x' = v without sticking")
      .def_readonly("has_floquet", &Orbit::has_floquet)
      .def_property_readonly("monodromy", [](const Orbit& o) { return Matrix(o.monodromy); })
      .def_property_readonly(
          "eigenvalues",
          [](const Orbit& o) { return py::make_tuple(o.eigenvalues[0], o.eigenvalues[1]); })
      .def_readonly("multiplier", &Orbit::multiplier, "the nontrivial Floquet multiplier")
      .def_readonly("stable", &Orbit::stable)
      .def_readonly("newton_stalled", &Orbit::newton_stalled);
  Result<PeriodicOrbits>(m, "PeriodicOrbits", "Every periodic orbit at one parameter point.")
      .def_readonly("status", &PeriodicOrbits::status)
      .def_readonly("message", &PeriodicOrbits::message)
      .def_readonly("steady", &PeriodicOrbits::steady)
      .def_property_readonly(
          "stick_slip",
          [](const PeriodicOrbits& o) -> py::object {
            return o.has_stick_slip ? py::cast(o.stick_slip) : py::none();
          },
          "the stick-slip orbit, or None")
      .def_readonly("pure_slip", &PeriodicOrbits::pure_slip, "by increasing amplitude")
      .def_readonly("a_stick", &PeriodicOrbits::a_stick, "smallest amplitude that sticks")
      .def_readonly("a_max", &PeriodicOrbits::a_max)
      .def_readonly("returns", &PeriodicOrbits::returns, "return-map evaluations");
  Result<Disturbance>(m, "Disturbance",
                      "Smallest disturbance of steady sliding that reaches an orbit.")
      .def_readonly("x", &Disturbance::x, "along x' = 0")
      .def_readonly("xdot", &Disturbance::xdot, "along x = xbar")
      .def_readonly("energy", &Disturbance::energy, "((x - xbar)^2 + x'^2) / 2");
}

// result[param1] and result[param2] are p1 and p2; any other key as GetItem.
template <typename T>
py::object ByParamName(const py::object& self, const std::string& key) {
  const auto& c = self.cast<const T&>();
  if (key == c.param1) return self.attr("p1");
  if (key == c.param2) return self.attr("p2");
  return GetItem(self, key);
}

void BindChartAndBasins(py::module_& m) {
  py::class_<ChartCurve>(m, "ChartCurve", "One HB, GR or LP curve; curve[param1] is p1.")
      .def("__getitem__", &ByParamName<ChartCurve>, py::arg("key"))
      .def_readonly("kind", &ChartCurve::kind)
      .def_property_readonly("label",
                             [](const ChartCurve& c) { return std::string(CurveLabel(c.kind)); })
      .def_readonly("param1", &ChartCurve::param1)
      .def_readonly("param2", &ChartCurve::param2)
      .def_readonly("p1", &ChartCurve::p1)
      .def_readonly("p2", &ChartCurve::p2)
      .def_readonly("period", &ChartCurve::period)
      .def_readonly("amplitude", &ChartCurve::amplitude)
      .def_readonly("multiplier", &ChartCurve::multiplier)
      .def_readonly("l1", &ChartCurve::l1, "HB: first Lyapunov coefficient")
      .def_readonly("type", &ChartCurve::type, "supercritical/subcritical, persistence/...")
      .def_readonly("unphysical", &ChartCurve::unphysical, "orbit visits mu <= 0")
      .def_readonly("ends", &ChartCurve::ends, "how each end ended")
      .def_readonly("seconds", &ChartCurve::seconds)
      .def_readonly("evaluations", &ChartCurve::evaluations);
  py::class_<ChartPoint>(m, "ChartPoint", "A codimension-two point (GH, GR-LP).")
      .def("__getitem__", &ByParamName<ChartPoint>, py::arg("key"))
      .def_readonly("label", &ChartPoint::label)
      .def_readonly("param1", &ChartPoint::param1)
      .def_readonly("param2", &ChartPoint::param2)
      .def_readonly("p1", &ChartPoint::p1)
      .def_readonly("p2", &ChartPoint::p2)
      .def_readonly("description", &ChartPoint::description);
  Result<ChartOut>(m, "Chart", "Result of chart().")
      .def_readonly("status", &ChartOut::status)
      .def_readonly("message", &ChartOut::message)
      .def_readonly("param1", &ChartOut::param1)
      .def_readonly("param2", &ChartOut::param2)
      .def_readonly("curves", &ChartOut::curves)
      .def_readonly("codim2", &ChartOut::codim2)
      .def_readonly("region_p1", &ChartOut::region_p1, "cell centres in p1")
      .def_readonly("region_p2", &ChartOut::region_p2, "cell centres in p2")
      .def_readonly("regions", &ChartOut::regions, "(n1, n2) int(Region) codes; empty if none")
      .def_readonly("unphysical_points", &ChartOut::unphysical_points)
      .def_readonly("seconds", &ChartOut::seconds);
  Result<Basins>(m, "Basins", "Result of basins(): the fate of every start of the grid.")
      .def_readonly("status", &Basins::status)
      .def_readonly("message", &Basins::message)
      .def_readonly("orbits", &Basins::orbits)
      .def_readonly("x_lo", &Basins::x_lo)
      .def_readonly("x_hi", &Basins::x_hi)
      .def_readonly("xdot_lo", &Basins::xdot_lo)
      .def_readonly("xdot_hi", &Basins::xdot_hi)
      .def_readonly("nx", &Basins::nx)
      .def_readonly("ny", &Basins::ny)
      .def_readonly("x", &Basins::x, "starts, row by row (x' outer, x inner)")
      .def_readonly("xdot", &Basins::xdot)
      .def_readonly("fate", &Basins::fate, "'steady-sliding', 'stick-slip', ...")
      .def_readonly("orbit", &Basins::orbit, "pure slip: index into orbits.pure_slip")
      .def_readonly("t_settle", &Basins::t_settle)
      .def_readonly("counts", &Basins::counts, "Fate -> number of starts");
}

}  // namespace

BranchPoints::BranchPoints(const std::vector<BranchPoint>& pts) {
  std::vector<double> pp, per, xmin, xmax, vmin, vmax, ts, mult, amp;
  std::vector<std::string> kinds;
  std::vector<int> br;
  std::vector<bool> st, stalled;
  for (const auto& q : pts) {
    pp.push_back(q.p), per.push_back(q.period), xmin.push_back(q.extrema.x_min);
    xmax.push_back(q.extrema.x_max), vmin.push_back(q.extrema.xdot_min),
        vmax.push_back(q.extrema.xdot_max);
    ts.push_back(q.t_stick), mult.push_back(q.multiplier), amp.push_back(q.amplitude);
    kinds.push_back(Name(q.kind)), br.push_back(q.branch);
    st.push_back(q.stable), stalled.push_back(q.newton_stalled);
  }
  p = ReadOnly(pp), kind = ReadOnlyStrings(kinds), branch = ReadOnly(br), period = ReadOnly(per);
  x_min = ReadOnly(xmin), x_max = ReadOnly(xmax), xdot_min = ReadOnly(vmin);
  xdot_max = ReadOnly(vmax), t_stick = ReadOnly(ts), multiplier = ReadOnly(mult);
  stable = ReadOnlyBool(st), amplitude = ReadOnly(amp), newton_stalled = ReadOnlyBool(stalled);
  std::vector<int> rows;
  std::vector<double> xs, vs;
  for (const auto& q : pts)
    rows.push_back(static_cast<int>(rows.size()) + 1), xs.push_back(q.x_start),
        vs.push_back(q.xdot_start);
  pt = ReadOnly(rows), x_start = ReadOnly(xs), xdot_start = ReadOnly(vs);
}

ChartOut MakeChartOut(const ChartResult& r, const Plane& plane) {
  ChartOut out;
  out.status = r.status, out.message = r.message;
  const std::string p1_name = plane.p1.name(), p2_name = plane.p2.name();  // the edge: names
  out.param1 = p1_name, out.param2 = p2_name;
  for (const Curve& c : r.curves) {
    std::vector<double> p1, p2, period, amplitude, multiplier, l1;
    std::vector<std::string> type;
    std::vector<bool> unphysical;
    for (const CurvePoint& q : c.points) {
      p1.push_back(q.p1), p2.push_back(q.p2), period.push_back(q.period);
      amplitude.push_back(q.amplitude), multiplier.push_back(q.multiplier), l1.push_back(q.l1);
      type.push_back(Name(q.type)), unphysical.push_back(q.unphysical);
    }
    out.curves.push_back({c.kind, p1_name, p2_name, ReadOnly(p1), ReadOnly(p2), ReadOnly(period),
                          ReadOnly(amplitude), ReadOnly(multiplier), ReadOnly(l1),
                          ReadOnlyStrings(type), ReadOnlyBool(unphysical), c.ends.Text(), c.seconds,
                          c.evaluations});
  }
  for (const Codim2Point& c : r.codim2)
    out.codim2.push_back({Name(c.label), p1_name, p2_name, c.description, c.p1, c.p2});
  std::vector<int> cells;
  for (Region g : r.regions.cells) cells.push_back(static_cast<int>(g));
  py::array_t<int> grid({r.regions.n1, r.regions.n2});
  for (size_t i = 0; i < cells.size(); ++i) grid.mutable_data()[i] = cells[i];
  grid.attr("setflags")(py::arg("write") = false);
  out.region_p1 = ReadOnly(r.regions.x1), out.region_p2 = ReadOnly(r.regions.x2);
  out.regions = std::move(grid);
  out.unphysical_points = r.unphysical_points;
  out.seconds = r.seconds, out.region_seconds = r.region_seconds;
  return out;
}

Basins MakeBasins(const BasinResult& r) {
  Basins b;
  b.status = r.status, b.message = r.message, b.orbits = r.orbits;
  b.x_lo = r.x_lo, b.x_hi = r.x_hi, b.xdot_lo = r.xdot_lo, b.xdot_hi = r.xdot_hi;
  b.nx = r.nx, b.ny = r.ny;
  std::vector<double> x, xdot, t;
  std::vector<std::string> fate;
  std::vector<int> orbit;
  for (const BasinStart& s : r.starts) {
    x.push_back(s.x), xdot.push_back(s.xdot), t.push_back(s.t_settle);
    fate.push_back(Name(s.fate)), orbit.push_back(s.orbit);
  }
  b.x = ReadOnly(x), b.xdot = ReadOnly(xdot), b.fate = ReadOnlyStrings(fate);
  b.orbit = ReadOnly(orbit), b.t_settle = ReadOnly(t);
  for (int f = 0; f < 4; ++f) b.counts[py::cast(static_cast<Fate>(f))] = r.count[f];
  return b;
}

void BindResults(py::module_& m) {
  Result<Trajectory>(m, "Trajectory", "Result of simulate(): one row every dt and at every switch.")
      .def_readonly("t", &Trajectory::t)
      .def_readonly("x", &Trajectory::x)
      .def_readonly("xdot", &Trajectory::xdot)
      .def_readonly("mode", &Trajectory::mode, "'slip-below', 'stick' or 'slip-above'")
      .def_readonly("status", &Trajectory::status)
      .def_readonly("t_stick", &Trajectory::t_stick, "time spent in stick")
      .def_readonly("switches", &Trajectory::switches)
      .def_readonly("crossings", &Trajectory::crossings)
      .def_readonly("x_min", &Trajectory::x_min)
      .def_readonly("x_max", &Trajectory::x_max)
      .def_readonly("xdot_min", &Trajectory::xdot_min)
      .def_readonly("xdot_max", &Trajectory::xdot_max);
  BindOrbits(m);
  BindBranch(m);
  BindChartAndBasins(m);
}

}  // namespace stickslip::python
