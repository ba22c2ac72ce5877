// branch.tsv and special_points.tsv of a system's run (system_branch_report.hpp).
#include "stickslip/io/system_branch_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "io/system_rows.hpp"

namespace stickslip {

namespace io_detail {

std::vector<SystemLine> SystemLines(const System& s, const SystemRun& run) {
  std::vector<SystemLine> out;
  for (const SteadyRow& r : run.steady.rows) {
    SystemLine l;
    l.p = r.p, l.kind = "equilibrium", l.lo = l.hi = l.z0 = r.state.z.head(s.tangent_dimension());
    l.z0 = r.state.z, l.mode = r.state.mode;
    l.max_real = r.state.max_real, l.stable = r.state.stable();
    l.label = r.label, l.description = r.description;
    out.push_back(std::move(l));
  }
  for (std::size_t b = 0; b < run.pieces.size(); ++b)
    for (const OrbitRow& r : run.pieces[b].rows) {
      SystemLine l;
      l.branch = b < run.numbers.size() ? run.numbers[b] : static_cast<int>(b) + 1, l.p = r.p;
      l.kind = r.sticks > 0 ? "stick-slip" : "pure-slip";
      l.sticks = r.sticks, l.exits = r.exits, l.crossings = r.crossings;
      l.turns = run.pieces[b].section.kind == SectionKind::kTime ? run.pieces[b].section.turns : 0;
      l.period = r.period, l.lo = r.lo, l.hi = r.hi, l.z0 = r.start.z, l.mode = r.start.mode;
      l.multipliers = r.multipliers, l.stable = r.stable;
      l.mult_max = 0;
      for (const auto& m : r.multipliers) l.mult_max = std::max(l.mult_max, std::abs(m));
      l.label = r.label, l.description = r.description;
      out.push_back(std::move(l));
    }
  return out;
}

int Multipliers(const std::vector<SystemLine>& lines) {
  std::size_t k = 0;
  for (const SystemLine& l : lines) k = std::max(k, l.multipliers.size());
  return static_cast<int>(k);
}

}  // namespace io_detail

namespace {

using io_detail::SystemLine;

std::vector<std::string> Columns(const System& s, const SystemRun& run, int k) {
  std::vector<std::string> c = {
      "branch", s.ParameterName(run.parameter), "kind", "sticks", "exits", "crossings", "period"};
  if (s.clocks() == 1) c.insert(c.begin() + 2, "m");  // the period in clock turns
  for (int i = 0; i < s.tangent_dimension(); ++i)
    c.insert(c.end(), {StateColumn(s, i) + "_min", StateColumn(s, i) + "_max"});
  for (int i = 0; i < s.dimension(); ++i) c.push_back(StateColumn(s, i) + "_0");
  c.push_back("mode_0");
  for (int j = 1; j <= k; ++j)
    c.insert(c.end(), {"mult" + std::to_string(j) + "_re", "mult" + std::to_string(j) + "_im"});
  c.insert(c.end(), {"mult_max", "max_real", "stable", "pt"});
  return c;
}

// A row's cells; what does not apply is empty (no nan): the period, the
// multipliers and mult_max on equilibrium rows, multipliers past the row's
// count, max_real on orbit rows.
std::vector<TsvTable::Cell> Cells(const System& s, const SystemLine& l, int k, int pt) {
  const bool eq = l.branch == 0;
  const TsvTable::Cell none("");
  std::vector<TsvTable::Cell> row = {
      l.branch, l.p, l.kind, l.sticks, l.exits, l.crossings, eq ? none : l.period};
  if (s.clocks() == 1) row.insert(row.begin() + 2, l.turns);
  for (Eigen::Index i = 0; i < l.lo.size(); ++i) row.insert(row.end(), {l.lo[i], l.hi[i]});
  for (Eigen::Index i = 0; i < l.z0.size(); ++i) row.emplace_back(l.z0[i]);
  row.emplace_back(ModeSetName(l.mode, s.contacts()));
  for (int j = 0; j < k; ++j) {
    if (j < static_cast<int>(l.multipliers.size()))
      row.insert(row.end(), {l.multipliers[j].real(), l.multipliers[j].imag()});
    else
      row.insert(row.end(), {none, none});
  }
  row.insert(row.end(), {eq ? none : l.mult_max, eq ? l.max_real : none, l.stable ? 1 : 0, pt});
  return row;
}

}  // namespace

std::string StateColumn(const System& s, int i) {
  std::string n = s.StateName(i);
  std::string out;
  for (char c : n) out += c == '\'' ? std::string("dot") : std::string(1, c);
  return out;
}

int StateIndex(const System& s, const std::string& name) {
  for (int i = 0; i < s.tangent_dimension(); ++i)
    if (name == s.StateName(i) || name == StateColumn(s, i)) return i;
  return -1;
}

std::string StateNameList(const System& s) {
  std::string names;
  for (int i = 0; i < s.tangent_dimension(); ++i) names += (i ? ", " : "") + s.StateName(i);
  return names;
}

TsvTable SystemBranchTable(const System& s, const SystemRun& run) {
  const std::vector<SystemLine> lines = io_detail::SystemLines(s, run);
  const int k = io_detail::Multipliers(lines);
  TsvTable t(Columns(s, run, k));
  int pt = 0;
  for (const SystemLine& l : lines) t.AddRow(Cells(s, l, k, ++pt));
  return t;
}

TsvTable SystemSpecialTable(const System& s, const SystemRun& run) {
  const std::vector<SystemLine> lines = io_detail::SystemLines(s, run);
  const int k = io_detail::Multipliers(lines);
  std::vector<std::string> c = Columns(s, run, k);
  c.insert(c.begin(), "label");
  c.insert(c.end(), {"lab", "description"});
  TsvTable t(c);
  std::map<SpecialKind, int> count;
  int pt = 0;
  for (const SystemLine& l : lines) {
    ++pt;
    if (l.label == SpecialKind::kNone) continue;
    std::vector<TsvTable::Cell> row = Cells(s, l, k, pt);
    row.insert(row.begin(), Name(l.label));
    row.emplace_back(std::string(Name(l.label)) + std::to_string(++count[l.label]));
    row.emplace_back(l.description);
    t.AddRow(row);
  }
  return t;
}

}  // namespace stickslip
