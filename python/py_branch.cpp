// Branch, the result of continue_branch(): its rows as arrays, its special
// points with pt and lab (AUTO-07p's PT and LAB), and its tables as
// ss_continue writes them, so a Python branch can be saved and restarted from.
#include <pybind11/stl.h>

#include "continuation/labels.hpp"
#include "py_results.hpp"
#include "stickslip/io/branch_report.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/io/restart.hpp"
#include "stickslip/version.hpp"

namespace stickslip::python {

namespace {

const char* const kPointColumns[] = {
    "p",        "kind",      "branch",     "period", "x_min",     "x_max",          "xdot_min",
    "xdot_max", "t_stick",   "multiplier", "stable", "amplitude", "newton_stalled", "pt",
    "x_start",  "xdot_start"};

// The metadata lines of ss_continue's files (cli/about.cpp RunMetadata and
// ss_continue's FileMetadata); the tool names this module, which
// ReadLabelledPoint accepts as it accepts ss_continue.
std::vector<std::pair<std::string, std::string>> Metadata(const Branch& b,
                                                          const std::string& command) {
  const ContinuationOptions& o = b.options;
  const FlowOptions& flow = o.orbit.flow;
  const std::string param = o.param.name();
  std::vector<std::pair<std::string, std::string>> m = {
      {"tool", std::string(kPythonTool) + " " + Version()}};
  if (*GitCommit()) m.emplace_back("commit", GitCommit());
  m.emplace_back("command", command);
  m.emplace_back("law", Name(b.base.law));
  for (const auto& name : ParameterNames(b.base.law))
    m.emplace_back(name, name == param ? "continued" : FormatNumber(GetParameter(b.base, name)));
  m.emplace_back("integrator", flow.integrator == Integrator::kCvode
                                   ? std::string("cvode ") + Name(flow.method)
                                   : std::string(Name(flow.integrator)));
  m.insert(m.end(), {{"rtol", FormatNumber(flow.rtol)},
                     {"atol", FormatNumber(flow.atol)},
                     {"max_steps", std::to_string(flow.max_steps)},
                     {"continued", param},
                     {"from", FormatNumber(o.from)},
                     {"to", FormatNumber(o.to)},
                     {"max_step", FormatNumber(o.max_step)},
                     {"newton_tol", FormatNumber(o.orbit.EffectiveNewtonTol())},
                     {"locate_tol", FormatNumber(o.locate_tol)}});
  return m;
}

// {"branch.tsv": text, "special_points.tsv": text}, as ss_continue writes them
// (without its estimate and disturbance columns).
py::dict Tables(const Branch& b, const std::string& command) {
  if (!b.result) throw InvalidArgument("this Branch has no result to write");
  std::string model = "law=" + std::string(Name(b.base.law));
  for (const auto& name : ParameterNames(b.base.law))
    model += " " + name + "=" +
             (name == b.param
                  ? "[" + FormatNumber(b.options.from) + ", " + FormatNumber(b.options.to) + "]"
                  : FormatNumber(GetParameter(b.base, name)));
  ExtraColumn stalled{"newton_stalled", {}};
  for (const auto& pt : b.result->points) stalled.values.push_back(pt.newton_stalled ? 1 : 0);
  TsvTable branch = BranchTable(*b.result, model, {stalled});
  TsvTable special = SpecialPointTable(*b.result);
  const auto meta = Metadata(b, command);
  branch.PrependMeta(meta), special.PrependMeta(meta);
  py::dict out;
  out["branch.tsv"] = branch.str();
  out["special_points.tsv"] = special.str();
  return out;
}

}  // namespace

Branch MakeBranch(ContinuationResult r, const Params& base, ContinuationOptions options) {
  DropNonFinite(&r);  // as ss_continue: no nan or inf as a result
  options.cancelled = nullptr, options.progress = nullptr;  // they refer to the call's frame
  Branch b;
  b.param = r.param.name(), b.status = r.status, b.message = r.message, b.warnings = r.warnings;
  b.points = BranchPoints(r.points);
  const std::vector<int> rows = SpecialPointRows(r);
  const std::vector<std::string> labels = SpecialPointLabels(r);
  for (size_t i = 0; i < r.special.size(); ++i) {
    BranchSpecial s;
    static_cast<SpecialPoint&>(s) = r.special[i];
    s.pt = rows[i], s.lab = labels[i];
    b.special.push_back(std::move(s));
  }
  b.counts = r.counts, b.seconds = r.seconds, b.base = base, b.options = std::move(options);
  b.result = std::make_shared<const ContinuationResult>(std::move(r));
  return b;
}

void BindBranch(py::module_& m) {
  Result<BranchPoints>(m, "BranchPoints", "The rows of a branch, one read-only array per column.")
      .def("keys",
           [](const BranchPoints&) {
             return std::vector<std::string>(std::begin(kPointColumns), std::end(kPointColumns));
           })
      .def("items",
           [](const py::object& self) {
             py::list out;
             for (const char* k : kPointColumns) out.append(py::make_tuple(k, self.attr(k)));
             return out;
           })
      .def("__len__", [](const BranchPoints& b) { return b.p.size(); })
      .def_readonly("p", &BranchPoints::p, "the continued parameter")
      .def_readonly("kind", &BranchPoints::kind, "'stick-slip', 'pure-slip', 'equilibrium'")
      .def_readonly("branch", &BranchPoints::branch, "rows of one branch are consecutive")
      .def_readonly("period", &BranchPoints::period, "nan for the equilibrium")
      .def_readonly("x_min", &BranchPoints::x_min)
      .def_readonly("x_max", &BranchPoints::x_max)
      .def_readonly("xdot_min", &BranchPoints::xdot_min)
      .def_readonly("xdot_max", &BranchPoints::xdot_max)
      .def_readonly("t_stick", &BranchPoints::t_stick)
      .def_readonly("multiplier", &BranchPoints::multiplier, "equilibrium: largest real part")
      .def_readonly("stable", &BranchPoints::stable)
      .def_readonly("amplitude", &BranchPoints::amplitude, "pure slip: section amplitude")
      .def_readonly("newton_stalled", &BranchPoints::newton_stalled)
      .def_readonly("pt", &BranchPoints::pt, "1-based row number (branch.tsv's pt)")
      .def_readonly("x_start", &BranchPoints::x_start, "the orbit's start (restarts)")
      .def_readonly("xdot_start", &BranchPoints::xdot_start);
  Result<BranchSpecial>(m, "SpecialPoint", "A located special point (GR, HB, LP).")
      .def_readonly("kind", &BranchSpecial::kind)
      .def_property_readonly(
          "label", [](const BranchSpecial& s) { return std::string(SpecialLabel(s.kind)); },
          "the type: 'GR', 'HB', 'LP'")
      .def_readonly("lab", &BranchSpecial::lab, "'GR1', 'HB1', ...: restart(dir, lab)")
      .def_readonly("pt", &BranchSpecial::pt, "the row of points it sits on (1-based)")
      .def_readonly("p", &BranchSpecial::p)
      .def_readonly("period", &BranchSpecial::period)
      .def_property_readonly("x_min", [](const BranchSpecial& o) { return o.extrema.x_min; })
      .def_property_readonly("x_max", [](const BranchSpecial& o) { return o.extrema.x_max; })
      .def_property_readonly("xdot_min", [](const BranchSpecial& o) { return o.extrema.xdot_min; })
      .def_readonly("multiplier_before", &BranchSpecial::multiplier_before)
      .def_readonly("multiplier_after", &BranchSpecial::multiplier_after)
      .def_readonly("x_start", &BranchSpecial::x_start)
      .def_readonly("xdot_start", &BranchSpecial::xdot_start)
      .def_readonly("description", &BranchSpecial::description);
  Result<ContinuationCounts>(m, "ContinuationCounts", "Work done by a continuation.")
      .def_readonly("orbit_solves", &ContinuationCounts::orbit_solves)
      .def_readonly("return_maps", &ContinuationCounts::return_maps)
      .def_readonly("newton_iterations", &ContinuationCounts::newton_iterations)
      .def_readonly("rejected_steps", &ContinuationCounts::rejected_steps)
      .def_readonly("integrator_steps", &ContinuationCounts::integrator_steps);
  Result<ContinuationTimes>(m, "ContinuationTimes", "Wall-clock seconds per phase.")
      .def_readonly("equilibrium", &ContinuationTimes::equilibrium)
      .def_readonly("stick_slip", &ContinuationTimes::stick_slip)
      .def_readonly("pure_slip", &ContinuationTimes::pure_slip)
      .def_readonly("switching", &ContinuationTimes::switching)
      .def_readonly("discovery", &ContinuationTimes::discovery)
      .def_readonly("total", &ContinuationTimes::total);
  Result<Branch>(m, "Branch", "Result of continue_branch().")
      .def_readonly("param", &Branch::param)
      .def_readonly("status", &Branch::status)
      .def_readonly("message", &Branch::message)
      .def_readonly("warnings", &Branch::warnings)
      .def_readonly("points", &Branch::points)
      .def_readonly("special", &Branch::special)
      .def_readonly("counts", &Branch::counts)
      .def_readonly("seconds", &Branch::seconds)
      .def_readonly("params", &Branch::base, "the parameters it started from")
      .def_readonly("options", &Branch::options, "the options it ran with")
      .def_property_readonly("partial",
                             [](const Branch& b) { return b.status != ContinuationStatus::kOk; })
      .def("tables", &Tables, py::arg("command") = "continue_branch(...)",
           "{'branch.tsv': text, 'special_points.tsv': text} as ss_continue writes them, with "
           "its metadata ('# key: value'); save() and to_tsv() write them.");
}

}  // namespace stickslip::python
