#include "stickslip/io/restart.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "io/tsv_read.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/io/report.hpp"
#include "stickslip/systems/forced/forced.hpp"

namespace stickslip {

namespace {

using Part = RestartError::Part;
using io_detail::PointRow;
using io_detail::ReadTable;
using io_detail::Table;

// The model and the solver options from the metadata (cli/about.cpp's RunMetadata).
void ReadModel(const Table& t, LabelledPoint* lp) {
  const std::string& tool = t.Meta("tool");
  if (tool.rfind("ss_continue", 0) != 0 && tool.rfind(kPythonTool, 0) != 0)
    throw RestartError(Part::kRun, "'" + t.path + "' was not written by ss_continue");
  // The parameters by name: the metadata's lines, or a system run's
  // `parameters` line ("beta=0,...,omega=1.5"; the forced oscillator's is read here).
  std::map<std::string, std::string> values = t.meta;
  bool forced_system = false;
  if (const auto system = t.meta.find("system"); system != t.meta.end()) {
    const std::string name = system->second.substr(0, system->second.find(':'));
    if (name != "forced")
      throw RestartError(Part::kRun, "'" + t.path + "' is a run of --system " + name +
                                         ": ss_continue restarts it with that system only");
    forced_system = true;
    std::istringstream items(t.Meta("parameters"));
    for (std::string item; std::getline(items, item, ',');)
      if (const auto eq = item.find('='); eq != std::string::npos)
        values[item.substr(0, eq)] = item.substr(eq + 1);
  }
  auto value = [&](const std::string& key) {
    const auto it = values.find(key);
    return it == values.end() ? t.Meta(key) : it->second;  // t.Meta: throws naming the key
  };
  try {
    lp->params.law = LawFromName(t.Meta("law"));
  } catch (const InvalidArgument& e) {
    throw RestartError(Part::kRun, "'" + t.path + "': " + e.what());
  }
  const std::string continued = t.Meta("continued");
  const auto model = t.meta.find("model");  // an older forced run's: "forced oscillator, ..."
  lp->forced =
      forced_system || (model != t.meta.end() && model->second.rfind("forced oscillator", 0) == 0);
  const std::vector<ParameterAxis> axes = ParameterAxes(lp->params.law, lp->forced);
  const auto axis = std::find_if(axes.begin(), axes.end(),
                                 [&](const ParameterAxis& a) { return a.name() == continued; });
  if (axis == axes.end())
    throw RestartError(Part::kRun, "'" + t.path + "': continued '" + continued + "' is no " +
                                       (lp->forced ? "parameter of a forced run" : "parameter") +
                                       " of the " + Name(lp->params.law) + " law");
  lp->param = *axis;
  for (const std::string& name : ParameterNames(lp->params.law))
    if (name != continued) SetParameter(lp->params, name, t.Number(value(name), name));
  if (lp->forced && continued != "force") lp->force = t.Number(value("force"), "force");
  if (lp->forced && continued != "omega") lp->omega = t.Number(value("omega"), "omega");
  lp->flow = io_detail::ReadFlowOptions(t);
  const auto from = t.meta.find("from"), to = t.meta.find("to");
  if (from != t.meta.end() && to != t.meta.end()) {
    lp->run_from = t.Number(from->second, "from");
    lp->run_to = t.Number(to->second, "to");
    if (!(std::isfinite(lp->run_from) && std::isfinite(lp->run_to)))
      throw RestartError(Part::kRun, "'" + t.path + "' is corrupt: '# from: " + from->second +
                                         "' and '# to: " + to->second + "' must be finite");
  }
}

// The row's parameter value and state.
void ReadRow(const Table& t, const std::vector<std::string>& row, LabelledPoint* lp) {
  const std::string name = lp->ParamName();
  lp->p = t.Number(row[t.Column(name)], name);
  if (lp->forced) {  // the forcing or a belt parameter of the forced model
    ForcedBeltParams fp;
    fp.base = lp->params, fp.force = lp->force, fp.omega = lp->omega;
    lp->param.Set(fp, lp->p);
    lp->params = fp.base, lp->force = fp.force, lp->omega = fp.omega;
  } else {
    lp->param.Set(lp->params, lp->p);
  }
  // A forced run's tables are the system's (x_0, xdot_0: its point at phase 0;
  // files written before they were named x0, xdot0).
  const auto& h = t.header;
  const bool older = lp->forced && std::find(h.begin(), h.end(), "x_0") == h.end() &&
                     std::find(h.begin(), h.end(), "x0") != h.end();
  const std::string x = !lp->forced ? "x_start" : older ? "x0" : "x_0";
  const std::string xdot = !lp->forced ? "xdot_start" : older ? "xdot0" : "xdot_0";
  lp->state = Vec2(t.Number(row[t.Column(x)], x), t.Number(row[t.Column(xdot)], xdot));
  const std::string& period = row[t.Column("period")];
  lp->period = t.Optional(period, "period");  // empty on steady sliding
  // Only steady sliding (an equilibrium row) has no period.
  const bool periodic = lp->type != Name(PointKind::kEquilibrium);
  if (periodic && !(std::isfinite(lp->period) && lp->period > 0))
    throw RestartError(Part::kRun, "'" + t.path + "': the point " + lp->label +
                                       " has period = " + (period.empty() ? "(empty)" : period) +
                                       ", not a finite number > 0");
  if (lp->forced)
    lp->m = static_cast<int>(t.Whole(row[t.Column("m")], "m", 1, LabelledPoint::kMaxM));
  std::string err = lp->forced ? ValidationError(ForcedBeltParams{lp->params, lp->force, lp->omega})
                               : ValidationError(lp->params);
  if (err.empty() && lp->forced && !(lp->m >= 1 && lp->m <= LabelledPoint::kMaxM))
    err = "m out of range";
  if (err.empty()) err = lp->flow.ValidationError();
  if (!err.empty() || !std::isfinite(lp->p) || !lp->state.allFinite())
    throw RestartError(Part::kRun, "'" + t.path + "': the point " + lp->label + " is invalid" +
                                       (err.empty() ? "" : ": " + err));
}

}  // namespace

LabelledPoint ReadLabelledPoint(const std::string& dir, const std::string& point) {
  LabelledPoint lp;
  lp.label = point;
  const bool number = std::regex_match(point, std::regex("[1-9][0-9]{0,8}"));
  if (!number &&
      !std::regex_match(point, std::regex("(GR|HB|LP|PD|NS|SW|AD|CR|SL)[1-9][0-9]{0,8}")))
    throw RestartError(Part::kPoint,
                       "'" + point +
                           "' is neither a label (GR1, HB1, LP1, PD1, CR1, ...) nor a point "
                           "number (1, 2, ... of branch.tsv)");
  const Table t = ReadTable(dir + (number ? "/branch.tsv" : "/special_points.tsv"));
  ReadModel(t, &lp);
  ReadRow(t, PointRow(t, point, number, &lp.type, &lp.pt), &lp);
  return lp;
}

}  // namespace stickslip
