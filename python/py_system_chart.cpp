// chart(system, ...) for ForcedBeltParams, ChainParams and CouplingParams in the
// Python module (chart/system_chart.hpp; as ss_chart --system): HB curves of steady
// sliding and LP, PD and NS curves of periodic orbits in two parameters, as
// bound types of read-only arrays; the tracing runs without the GIL, with
// Ctrl-C; with grid = N, the response grid of N x N cells (response_grid.hpp).
// The belt's chart(params, ...) keeps its own.
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "py_common.hpp"
#include "stickslip/chart/response_grid.hpp"
#include "stickslip/chart/system_chart.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/io/system_branch_report.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip::python {

namespace {

struct PySystemCurve {
  std::string kind, seed, ends;
  int m = 0;
  bool gap = false;
  py::array p1, p2, period, sticks, crossings, lo, hi, mult_max, test;
  int evaluations = 0;
  double seconds = 0;
};

struct PyCodim2 {
  std::string label, on, description, located;
  int curve = 0;
  double p1 = 0, p2 = 0;
};

// The response grid's cells as (n2, n1) arrays, p1 fastest along a row.
struct PyResponse {
  py::array p1, p2;                     // cell centres, n1 and n2
  py::array kind, m, sticks, lyapunov;  // (n2, n1)
  int failed = 0;
  std::string failure;
  double seconds = 0;
};

struct PySystemChart {
  std::string param, param2, status, message;
  std::vector<std::string> state_names;
  std::vector<PySystemCurve> curves;
  std::vector<PyCodim2> codim2;
  std::optional<PyResponse> response;
  int seed_runs = 0, failed_seed_runs = 0, seeds_not_traced = 0, cut_curves = 0, duplicates = 0;
  double seconds = 0;
};

PySystemCurve CurveOf(const SystemCurve& c, int nt) {
  PySystemCurve out;
  out.kind = CurveLabel(c.kind), out.seed = c.seed, out.ends = c.ends.Text();
  out.evaluations = c.evaluations, out.seconds = c.seconds;
  out.m = c.kind == CurveKind::kHopf ? 0 : PeriodMultiple(c.section), out.gap = c.gap;
  std::vector<double> p1, p2, period, lo, hi, mult, test;
  std::vector<int> sticks, crossings;
  for (const SystemCurvePoint& p : c.points) {
    p1.push_back(p.p1), p2.push_back(p.p2), period.push_back(p.orbit.period);
    sticks.push_back(p.orbit.sticks), crossings.push_back(p.orbit.crossings);
    const bool hb = c.kind == CurveKind::kHopf;
    for (int i = 0; i < nt; ++i) {
      lo.push_back(hb ? p.orbit.start.z[i] : p.orbit.lo[i]);
      hi.push_back(hb ? p.orbit.start.z[i] : p.orbit.hi[i]);
    }
    double m = 0;
    for (const auto& mu : p.orbit.multipliers) m = std::max(m, std::abs(mu));
    mult.push_back(m), test.push_back(p.test);
  }
  out.p1 = ReadOnly(p1), out.p2 = ReadOnly(p2), out.period = ReadOnly(period);
  out.sticks = ReadOnly(sticks), out.crossings = ReadOnly(crossings);
  out.lo = ReadOnlyRows(lo, nt), out.hi = ReadOnlyRows(hi, nt);
  out.mult_max = ReadOnly(mult), out.test = ReadOnly(test);
  return out;
}

// A 1-D array as n2 rows of n1, read-only.
py::array Grid(const py::array& flat, int n2, int n1) {
  py::array a = flat.attr("reshape")(n2, n1);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

PyResponse ResponseOf(const ResponseGrid& g) {
  PyResponse r;
  std::vector<std::string> kind;
  std::vector<int> m, sticks;
  std::vector<double> lyapunov;
  for (const Attractor& a : g.cells) {
    kind.push_back(Name(a.kind));
    m.push_back(a.kind == AttractorKind::kPeriodic ? a.m : 0), sticks.push_back(a.sticks);
    lyapunov.push_back(HasExponent(a.kind) && std::isfinite(a.lyapunov) ? a.lyapunov : 0.0);
  }
  r.p1 = ReadOnly(g.x1), r.p2 = ReadOnly(g.x2);
  r.kind = Grid(ReadOnlyStrings(kind), g.n2, g.n1), r.m = Grid(ReadOnly(m), g.n2, g.n1);
  r.sticks = Grid(ReadOnly(sticks), g.n2, g.n1);
  r.lyapunov = Grid(ReadOnly(lyapunov), g.n2, g.n1);
  r.failed = g.failed, r.failure = g.failure, r.seconds = g.seconds;
  return r;
}

PySystemChart SystemChartOf(const py::object& system, const std::string& param, double from,
                            double to, const std::string& param2, double from2, double to2,
                            int seed_lines, double max_step, bool hopf, bool orbits, int max_m,
                            std::optional<double> rtol, std::optional<double> atol, int grid) {
  const std::unique_ptr<System> s = SystemOf(system);  // TypeError for another object
  SystemChartOptions o;
  SystemPlane& pl = o.plane;
  pl.p1 = s->ParameterIndex(param), pl.p2 = s->ParameterIndex(param2);
  for (const auto& [j, name] : {std::pair{pl.p1, param}, std::pair{pl.p2, param2}})
    if (j < 0) throw InvalidArgument("'" + name + "' is no parameter of this system");
  pl.from1 = from, pl.to1 = to, pl.from2 = from2, pl.to2 = to2;
  o.seed_lines = seed_lines, o.max_step = max_step, o.max_m = max_m;
  o.hopf_curves = hopf, o.orbit_curves = orbits;
  // The forced oscillator's own tolerances (rtol = atol = 1e-12), as ss_chart's.
  if (py::isinstance<ForcedBeltParams>(system))
    o.branch = OrbitBranchOptions(ForcedBelt::FlowDefaults());
  FlowOptions& flow = o.branch.shooting.flow;
  if (rtol) flow.rtol = *rtol;
  if (atol) flow.atol = *atol;
  if (const std::string e = o.ValidationError(*s); !e.empty()) throw InvalidArgument(e);
  ResponseOptions ro;
  ro.n1 = ro.n2 = grid;
  ro.attractor.iterate.flow = flow, ro.attractor.max_amplitude = o.branch.max_amplitude;
  if (const std::string e = ro.ValidationError(*s); grid != 0 && !e.empty())
    throw InvalidArgument("grid = " + std::to_string(grid) + ": " + e);
  Interrupt interrupt;
  o.cancelled = ro.cancelled = [&] { return interrupt(); };
  o.branch.palc.cancelled = o.cancelled;
  SystemChart r;
  ResponseGrid g;
  {
    py::gil_scoped_release nogil;
    r = ChartSystem(*s, o);
    if (grid > 0 && !interrupt()) g = Responses(*s, o.plane, ro);
  }
  interrupt.RaiseIfInterrupted();
  PySystemChart out;
  out.param = param, out.param2 = param2;
  out.status = Name(r.status), out.message = r.message;
  out.seed_runs = r.seed_runs, out.seconds = r.seconds;
  out.failed_seed_runs = r.failed_seed_runs, out.seeds_not_traced = r.seeds_not_traced;
  out.cut_curves = r.cut_curves, out.duplicates = r.duplicates;
  const int nt = s->tangent_dimension();
  for (int i = 0; i < nt; ++i) out.state_names.push_back(s->StateName(i));
  for (const SystemCurve& c : r.curves) out.curves.push_back(CurveOf(c, nt));
  for (const SystemCodim2& p : r.codim2)
    out.codim2.push_back(
        {Name(p.label), CurveLabel(p.on), p.description, Name(p.method), p.curve, p.p1, p.p2});
  if (grid > 0) {
    out.response = ResponseOf(g);
    if (g.failed > 0 && r.status == ChartStatus::kOk) {
      out.status = Name(ChartStatus::kPartial), out.message = g.failure;
    } else if (g.failed > 0) {
      out.message += "; " + g.failure;
    }
  }
  return out;
}

}  // namespace

void BindSystemChart(py::module_& m) {
  py::class_<PySystemCurve>(m, "SystemCurve",
                            "One curve of chart(system, ...): kind (HB, LP, PD, NS, GR), m (the "
                            "period in forcing periods or section returns), gap (GR: the gap "
                            "margin, else an arrival's), per point p1, p2, period, sticks, "
                            "crossings, lo and hi (rows: the state components' extremes; HB: "
                            "the rest point), mult_max and test; seed and ends say where it "
                            "started and how each end ended.")
      .def_readonly("kind", &PySystemCurve::kind)
      .def_readonly("m", &PySystemCurve::m)
      .def_readonly("gap", &PySystemCurve::gap)
      .def_readonly("seed", &PySystemCurve::seed)
      .def_readonly("ends", &PySystemCurve::ends)
      .def_readonly("p1", &PySystemCurve::p1)
      .def_readonly("p2", &PySystemCurve::p2)
      .def_readonly("period", &PySystemCurve::period)
      .def_readonly("sticks", &PySystemCurve::sticks)
      .def_readonly("crossings", &PySystemCurve::crossings)
      .def_readonly("lo", &PySystemCurve::lo)
      .def_readonly("hi", &PySystemCurve::hi)
      .def_readonly("mult_max", &PySystemCurve::mult_max)
      .def_readonly("test", &PySystemCurve::test)
      .def_readonly("evaluations", &PySystemCurve::evaluations)
      .def_readonly("seconds", &PySystemCurve::seconds);
  py::class_<PyCodim2>(m, "SystemCodim2",
                       "A codimension-two point of chart(system, ...): label (SL, LPPD, R1, R2, "
                       "CP, GG), on (the curve's kind), curve (its index), p1, p2, description, "
                       "located (end, refined, chord or point).")
      .def_readonly("label", &PyCodim2::label)
      .def_readonly("on", &PyCodim2::on)
      .def_readonly("curve", &PyCodim2::curve)
      .def_readonly("p1", &PyCodim2::p1)
      .def_readonly("p2", &PyCodim2::p2)
      .def_readonly("description", &PyCodim2::description)
      .def_readonly("located", &PyCodim2::located);
  py::class_<PyResponse>(
      m, "ResponseGrid",
      "The response grid of chart(system, ..., grid=N): p1 and p2 the cell "
      "centres, and per cell (rows along p2, p1 fastest: shape (N, N)) "
      "kind (periodic, rest, settling, undecided: quasi-periodic, chaotic, "
      "unbounded, contact-lost, failed), m (periodic: returns per period, else 0), "
      "sticks (per m returns) and lyapunov (the largest exponent, 0 where "
      "not measured); failed counts failed cells, failure names the first.")
      .def_readonly("p1", &PyResponse::p1)
      .def_readonly("p2", &PyResponse::p2)
      .def_readonly("kind", &PyResponse::kind)
      .def_readonly("m", &PyResponse::m)
      .def_readonly("sticks", &PyResponse::sticks)
      .def_readonly("lyapunov", &PyResponse::lyapunov)
      .def_readonly("failed", &PyResponse::failed)
      .def_readonly("failure", &PyResponse::failure)
      .def_readonly("seconds", &PyResponse::seconds);
  py::class_<PySystemChart>(
      m, "SystemChart",
      "Result of chart(system, ...): param, param2, curves (SystemCurve), "
      "codim2 (SystemCodim2), status (ok; partial where a curve was cut "
      "short or a seed run failed, message says which; cancelled), "
      "seed_runs, failed_seed_runs, seeds_not_traced, cut_curves, duplicates (curves "
      "dropped: most of their points on one drawn), seconds; response (a ResponseGrid with "
      "grid=N, else None).")
      .def_readonly("param", &PySystemChart::param)
      .def_readonly("param2", &PySystemChart::param2)
      .def_readonly("state_names", &PySystemChart::state_names)
      .def_readonly("curves", &PySystemChart::curves)
      .def_readonly("codim2", &PySystemChart::codim2)
      .def_readonly("status", &PySystemChart::status)
      .def_readonly("message", &PySystemChart::message)
      .def_readonly("seed_runs", &PySystemChart::seed_runs)
      .def_readonly("failed_seed_runs", &PySystemChart::failed_seed_runs)
      .def_readonly("seeds_not_traced", &PySystemChart::seeds_not_traced)
      .def_readonly("cut_curves", &PySystemChart::cut_curves)
      .def_readonly("duplicates", &PySystemChart::duplicates)
      .def_readonly("seconds", &PySystemChart::seconds)
      .def_readonly("response", &PySystemChart::response);
  // After the belt's chart(params, ...).
  m.def("chart", &SystemChartOf, py::arg("system"), py::arg("param"), py::arg("from_"),
        py::arg("to"), py::arg("param2"), py::arg("from2"), py::arg("to2"),
        py::arg("seed_lines") = 3, py::arg("max_step") = 0.01, py::arg("hopf") = true,
        py::arg("orbits") = true, py::arg("max_m") = 2, py::arg("rtol") = py::none(),
        py::arg("atol") = py::none(), py::arg("grid") = 0,
        "chart(system, param, from_, to, param2, from2, to2, ...) for ForcedBeltParams, "
        "ChainParams and CouplingParams (as ss_chart --system): HB curves of steady sliding "
        "and LP, PD, NS curves of periodic orbits (a forced system's on its stroboscopic "
        "section, with GR curves and rtol = atol = 1e-12 by default) in two of the system's "
        "parameters, seeded by one-parameter runs on seed_lines lines per axis and the "
        "doubled branches from their PD points (orbits of up to max_m forcing periods, or "
        "doublings while 2^doublings <= max_m without a clock); with grid=N (0: none, else 1 "
        "to 1000) also the attractor reached at N x N cell centres, each row swept along "
        "param (SystemChart.response); a SystemChart.");
}

}  // namespace stickslip::python
