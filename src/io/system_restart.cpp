// A point of a system's run read back (system_restart.hpp). The run writes
// what is read here: cli/run_system.cpp's metadata, system_branch_report.cpp's
// columns.
#include "stickslip/io/system_restart.hpp"

#include <algorithm>
#include <cmath>
#include <regex>

#include "io/tsv_read.hpp"
#include "stickslip/continuation/orbit_branch.hpp"
#include "stickslip/system/mode.hpp"

namespace stickslip {

namespace {

using Part = RestartError::Part;
using io_detail::PointRow;
using io_detail::ReadTable;
using io_detail::Table;

// The most returns a section is read with (a sanity bound on the file).
constexpr int kMaxReturns = 1 << 20;
// The most branches a run's rows are numbered with (a sanity bound).
constexpr int kMaxBranches = 1 << 20;

bool IsNumber(const std::string& point) {
  return std::regex_match(point, std::regex("[1-9][0-9]{0,8}"));
}

std::string FileOf(const std::string& dir, const std::string& point) {
  return dir + (IsNumber(point) ? "/branch.tsv" : "/special_points.tsv");
}

RestartError Corrupt(const Table& t, const std::string& why) {
  return RestartError(Part::kRun, "'" + t.path + "' is corrupt: " + why);
}

// "a=1,b=2" as (name, value) pairs, in order.
std::vector<std::pair<std::string, double>> Pairs(const Table& t, const std::string& key) {
  std::vector<std::pair<std::string, double>> out;
  const std::string& text = t.Meta(key);
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t comma = std::min(text.find(',', from), text.size());
    const std::string item = text.substr(from, comma - from);
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw Corrupt(t, key + " item '" + item + "'");
    out.emplace_back(item.substr(0, eq),
                     t.Finite(item.substr(eq + 1), key + " " + item.substr(0, eq)));
    from = comma + 1;
  }
  return out;
}

// The system, its parameters, the law and the options from the metadata.
void ReadRun(const Table& t, SystemPoint* sp) {
  const std::string& tool = t.Meta("tool");
  if (tool.rfind("ss_continue", 0) != 0)
    throw RestartError(Part::kRun, "'" + t.path + "' was not written by ss_continue");
  if (!t.meta.count("system"))
    throw RestartError(Part::kRun, "'" + t.path +
                                       "' is a run of the belt or the forced oscillator, not of "
                                       "a --system: restart it without --system");
  sp->system = t.Meta("system_name");
  if (sp->system == "chain")
    sp->blocks = static_cast<int>(t.MetaWhole("blocks", 1, ModeSet::kMaxContacts));
  try {  // a model file's run has no built-in law
    if (sp->system != "model") {
      sp->law.law = LawFromName(t.Meta("law"));
      for (const auto& [name, value] : Pairs(t, "law_parameters"))
        SetParameter(sp->law, name, value);
    }
  } catch (const RestartError&) {
    throw;
  } catch (const InvalidArgument& e) {
    throw RestartError(Part::kRun, "'" + t.path + "': " + e.what());
  }
  sp->parameters = Pairs(t, "parameters");
  sp->continued = t.Meta("continued");
  sp->flow = io_detail::ReadFlowOptions(t);
  sp->max_amplitude = t.MetaFinite("max_amplitude");
  if (!(sp->max_amplitude > 0))
    throw Corrupt(t, "max_amplitude = '" + t.Meta("max_amplitude") + "' must be > 0");
  if (t.meta.count("section_turns") &&
      (t.meta.count("section_contact") || t.meta.count("section_returns")))
    throw Corrupt(t, "section_turns and section_contact/section_returns: two sections");
  // A clock's turns: at most the branch driver's (kMaxPeriodMultiple), its time
  // set where the system is known.
  if (t.meta.count("section_turns")) {
    sp->section.kind = SectionKind::kTime;
    sp->section.turns = static_cast<int>(t.MetaWhole("section_turns", 1, kMaxPeriodMultiple));
  } else {
    const auto contact = t.MetaWhole("section_contact", 0, ModeSet::kMaxContacts - 1);
    const auto returns = t.MetaWhole("section_returns", 1, kMaxReturns);
    sp->section = PoincareSection::StickExit(static_cast<int>(contact), static_cast<int>(returns));
  }
  sp->run_from = t.MetaFinite("from");
  sp->run_to = t.MetaFinite("to");
  if (sp->run_from == sp->run_to)
    throw Corrupt(t, "from = to = '" + t.Meta("to") + "' (the run's range is empty)");
  if (const std::string e = sp->flow.ValidationError(); !e.empty()) throw Corrupt(t, e);
}

// The row's parameter value, state, mode and period.
void ReadRow(const Table& t, const std::vector<std::string>& row, SystemPoint* sp) {
  sp->branch = static_cast<int>(t.Whole(row[t.Column("branch")], "branch", 0, kMaxBranches));
  sp->p = t.Number(row[t.Column(sp->continued)], sp->continued);
  bool found = false;
  for (auto& [name, value] : sp->parameters)
    if (name == sp->continued) value = sp->p, found = true;
  if (!found) throw Corrupt(t, "continued '" + sp->continued + "' is not among its parameters");
  std::vector<double> z;
  for (std::size_t j = 0; j < t.header.size(); ++j) {
    const std::string& c = t.header[j];
    if (c.size() > 2 && c.compare(c.size() - 2, 2, "_0") == 0 && c != "mode_0")
      z.push_back(t.Number(row[j], c));
  }
  sp->start.z = Eigen::Map<Eigen::VectorXd>(z.data(), static_cast<Eigen::Index>(z.size()));
  const std::string modes = row[t.Column("mode_0")];
  sp->contacts = 0;
  for (std::size_t from = 0; from <= modes.size(); ++sp->contacts) {
    const std::size_t comma = std::min(modes.find(',', from), modes.size());
    Mode m = Mode::kSlipBelow;
    if (sp->contacts >= ModeSet::kMaxContacts || !FromName(modes.substr(from, comma - from), &m))
      throw Corrupt(t, "mode_0 = '" + modes + "'");
    sp->start.mode.set(sp->contacts, m);
    from = comma + 1;
  }
  sp->period = t.Optional(row[t.Column("period")], "period");  // empty on steady sliding
  // A clock's turns per period: the row's own (a start list's pieces differ).
  if (sp->section.kind == SectionKind::kTime &&
      std::find(t.header.begin(), t.header.end(), "m") != t.header.end())
    sp->section.turns = static_cast<int>(t.Whole(row[t.Column("m")], "m", 1, kMaxPeriodMultiple));
  // A stick-exit branch of a start list on its own section (branch_N_section_*).
  const std::string own = "branch_" + std::to_string(sp->branch) + "_section_";
  if (sp->section.kind == SectionKind::kStickExit && t.meta.count(own + "returns"))
    sp->section = PoincareSection::StickExit(
        static_cast<int>(t.MetaWhole(own + "contact", 0, ModeSet::kMaxContacts - 1)),
        static_cast<int>(t.MetaWhole(own + "returns", 1, kMaxReturns)));
  if (!std::isfinite(sp->p) || !sp->start.z.allFinite() ||
      (sp->periodic() && !(std::isfinite(sp->period) && sp->period > 0)))
    throw RestartError(Part::kRun, "'" + t.path + "': the point " + sp->label +
                                       " is invalid (parameter, state or period not finite)");
}

// A point given by its number: the type of the special point at the same pt
// in special_points.tsv (LP, GR, ...), so an LP is a fold however it is
// named. Without that file, or a special point there, the row's kind stands.
void TakeSpecialPointType(const std::string& dir, SystemPoint* sp) {
  try {
    const Table special = ReadTable(dir + "/special_points.tsv");
    const int pt = special.Column("pt"), label = special.Column("label");
    for (const auto& row : special.rows)
      if (row[pt] == std::to_string(sp->pt)) {
        sp->type = row[label];
        if (sp->type == "LP") return;  // a fold first, should a row carry two
      }
  } catch (const RestartError&) {  // no such file or columns: the row's kind
  }
}

// At an LP: the side of its value on which the first run's rows next to it
// (branch.tsv's rows pt - 1 and pt + 1, of its branch) lie; 0 if unknown or
// if they lie on both sides.
int FoldSideOfRows(const Table& rows, const SystemPoint& sp) {
  const int branch = rows.Column("branch"), p = rows.Column(sp.continued);
  int above = 0, below = 0;
  for (const int i : {sp.pt - 2, sp.pt}) {  // 0-based indices of the neighbours
    if (i < 0 || i >= static_cast<int>(rows.rows.size())) continue;
    const std::vector<std::string>& row = rows.rows[i];
    if (row[branch] != std::to_string(sp.branch)) continue;
    const double x = rows.Number(row[p], sp.continued);
    above += std::isfinite(x) && x > sp.p;
    below += std::isfinite(x) && x < sp.p;
  }
  return above && !below ? 1 : below && !above ? -1 : 0;
}

}  // namespace

bool IsSystemRun(const std::string& dir, const std::string& point) {
  try {
    return ReadTable(FileOf(dir, point)).meta.count("system") > 0;
  } catch (const RestartError&) {
    return false;
  }
}

SystemPoint ReadSystemPoint(const std::string& dir, const std::string& point) {
  SystemPoint sp;
  sp.label = point;
  const bool number = IsNumber(point);
  if (!number &&
      !std::regex_match(point, std::regex("(HB|LP|PD|NS|AD|GR|CR|SL|CL)[1-9][0-9]{0,8}")))
    throw RestartError(Part::kPoint, "'" + point +
                                         "' is neither a label (LP1, PD1, GR1, CL1, ...) nor a "
                                         "point number (1, 2, ... of branch.tsv)");
  const Table t = ReadTable(FileOf(dir, point));
  ReadRun(t, &sp);
  ReadRow(t, PointRow(t, point, number, &sp.type, &sp.pt), &sp);
  if (number) TakeSpecialPointType(dir, &sp);
  if (sp.type != "LP") return sp;
  if (number) {
    sp.fold_side = FoldSideOfRows(t, sp);
  } else {
    try {  // only for --to's default: without branch.tsv, the far end
      sp.fold_side = FoldSideOfRows(ReadTable(dir + "/branch.tsv"), sp);
    } catch (const RestartError&) {
    }
  }
  return sp;
}

}  // namespace stickslip
