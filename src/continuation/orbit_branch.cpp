// One branch driver for the periodic orbits of any system (orbit_branch.hpp):
// the map's fixed points (orbit_problem.hpp) through Palc, a row per accepted
// point, the special points between two rows (orbit_locate.hpp).
#include "stickslip/continuation/orbit_branch.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "orbit_locate.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

using Eigen::VectorXd;
using orbit_detail::OrbitProblem;
using orbit_detail::TracePoint;

namespace {

// One trace's monitor: rows, the end at p = to, the special points between
// consecutive rows, and the ends (unbounded, back past the start).
class Monitor {
 public:
  Monitor(Palc& palc, OrbitProblem& problem, const System& system, int j, double from, double to,
          const OrbitBranchOptions& o, OrbitBranch& out)
      : palc_(palc),
        problem_(problem),
        system_(system),
        j_(j),
        from_(from),
        to_(to),
        dir_(to > from ? 1 : -1),
        k_(problem.parameter_index()),
        o_(o),
        out_(out) {}
  bool operator()(const std::vector<PalcPoint>& curve);
  bool stopped() const { return stopped_; }
  // After a jump inside a step the trace turned away from `to`: restart here.
  const VectorXd* TurnedBack() const { return turned_ ? &turned_at_ : nullptr; }
  void Restart() {  // the next trace's first row starts anew
    if (turned_ && !out_.rows.empty()) out_.rows.pop_back();  // written again
    have_prev_ = turned_ = false;
  }

 private:
  bool Special(const TracePoint& a, const TracePoint& b);
  bool Repeats(const OrbitRow& sp, std::size_t earlier);
  bool Ends(const OrbitRow& row);

  Palc& palc_;
  OrbitProblem& problem_;
  const System& system_;
  int j_;
  double from_, to_, dir_;
  int k_;  // p's component of u
  const OrbitBranchOptions& o_;
  OrbitBranch& out_;
  bool have_prev_ = false, stopped_ = false, turned_ = false, closed_ = false;
  TracePoint prev_;
  VectorXd turned_at_;
};

// The special points between a and b; true if the step crossed a jump.
bool Monitor::Special(const TracePoint& a, const TracePoint& b) {
  std::vector<OrbitRow> found;
  std::vector<std::pair<TracePoint, TracePoint>> pieces;
  const double range[2] = {std::min(from_, to_), std::max(from_, to_)};
  const bool jumped =
      orbit_detail::Sliding(palc_, problem_, a, b, range, o_.locate_tol, &found, &pieces);
  for (const auto& [lo, hi] : pieces)
    orbit_detail::TestPoints(palc_, problem_, lo, hi, o_.locate_tol, &found);
  std::sort(found.begin(), found.end(), [&](const OrbitRow& x, const OrbitRow& y) {
    return std::abs(x.p - a.row.p) < std::abs(y.p - a.row.p);
  });
  const std::size_t earlier = out_.special.size();
  for (const OrbitRow& sp : found) {
    if (Repeats(sp, earlier)) return jumped;
    out_.special.push_back(sp), out_.rows.push_back(sp);
  }
  return jumped;
}

// A special point found before: the branch came around a closed curve.
bool Monitor::Repeats(const OrbitRow& sp, std::size_t earlier) {
  const double tol = Tolerances::kBranchSamePoint;
  for (std::size_t i = 0; i < earlier; ++i) {  // not this step's: two edges may coincide
    const OrbitRow& s = out_.special[i];
    if (s.label != sp.label || std::abs(s.p - sp.p) > tol * (1 + std::abs(sp.p))) continue;
    const double dz = (s.start.z - sp.start.z).lpNorm<Eigen::Infinity>();
    if (dz > tol * (1 + sp.start.z.lpNorm<Eigen::Infinity>())) continue;
    closed_ = true, out_.status = BranchStatus::kClosed;
    out_.message = std::string("came back to its ") + Name(sp.label) + " at " +
                   system_.ParameterName(j_) + " = " + Num(sp.p, 12);
    return true;
  }
  return false;
}

// The ends at a row: unbounded (a displacement beyond max_amplitude) or back past the start.
bool Monitor::Ends(const OrbitRow& row) {
  const std::vector<bool> displacement = orbit_detail::Displacements(system_);
  double size = 0;
  for (int i = 0; i < static_cast<int>(displacement.size()) && i < row.lo.size(); ++i)
    if (displacement[i]) size = std::max({size, std::abs(row.lo[i]), std::abs(row.hi[i])});
  if (size > o_.max_amplitude) {
    out_.status = BranchStatus::kUnbounded;
    out_.message = "the orbit passed max_amplitude = " + Num(o_.max_amplitude);
    return true;
  }
  if ((row.p - from_) * dir_ < -Tolerances::kBranchTurnBack * std::abs(to_ - from_)) {
    out_.status = BranchStatus::kLeftRange;
    out_.message =
        "the branch turned back past " + system_.ParameterName(j_) + " = " + Num(from_, 12);
    return true;
  }
  return false;
}

bool Monitor::operator()(const std::vector<PalcPoint>& curve) {
  const VectorXd* prev = curve.size() >= 2 ? &curve[curve.size() - 2].u : nullptr;
  VectorXd here = curve.back().u;
  bool end = false;
  if (prev && (here[k_] - to_) * dir_ >= 0) {  // past the end: the row at p = to instead
    VectorXd pred = *prev + (to_ - (*prev)[k_]) / (here[k_] - (*prev)[k_]) * (here - *prev);
    pred[k_] = to_;
    const PalcCorrection c = palc_.CorrectFixed(pred, k_);
    end = true;
    out_.status = BranchStatus::kReachedEnd;
    out_.message.clear();  // a failure before a jump's restart is not the end
    if (!c.ok) {
      out_.status = BranchStatus::kStepTooSmall;
      out_.message = "the row at " + system_.ParameterName(j_) + " = to: " + c.why;
      stopped_ = true;
      return false;
    }
    here = c.u;
  }
  // The row one Newton step further, across the curve (p held at a trace's
  // first row and at the end, where p is given).
  if (end || curve.size() == 1) {
    problem_.Polish(nullptr, &here);
  } else {
    const VectorXd& scale = palc_.options().scale;
    const VectorXd& t = curve.back().tangent;
    const VectorXd w = scale.size() ? VectorXd(t.cwiseQuotient(scale)) : t;
    problem_.Polish(&w, &here);
  }
  const TracePoint point{here, problem_.Row()};
  const bool jumped = prev && have_prev_ && Special(prev_, point);
  prev_ = point;
  have_prev_ = true;
  out_.rows.push_back(point.row);
  stopped_ = closed_ || Ends(point.row) || end;
  // Across a jump Palc orients the far family's tangent by the near one's,
  // which can point back: the sweep goes on toward `to`.
  if (!stopped_ && jumped && curve.back().tangent[k_] * dir_ < 0) turned_ = true, turned_at_ = here;
  return !stopped_ && !turned_;
}

BranchStatus FromPalc(const PalcResult& r) {
  switch (r.status) {
    case PalcStatus::kClosed:
      return BranchStatus::kClosed;
    case PalcStatus::kMaxPoints:
      return BranchStatus::kMaxPoints;
    case PalcStatus::kStepTooSmall:
      return BranchStatus::kStepTooSmall;
    case PalcStatus::kStartFailed:
      return BranchStatus::kStartFailed;
    case PalcStatus::kStopped:
      break;
  }
  return r.message == "cancelled" ? BranchStatus::kCancelled : BranchStatus::kReachedEnd;
}

// The step of the last two plain rows (special rows sit within locate_tol of one).
double LastStep(const std::vector<OrbitRow>& rows) {
  const OrbitRow* later = nullptr;
  for (auto it = rows.rbegin(); it != rows.rend(); ++it) {
    if (it->label != SpecialKind::kNone) continue;
    if (later) return later->p - it->p;
    later = &*it;
  }
  return 0;
}

// Palc traces from u0 (its component `fixed` held by the first correction,
// along `along`), and from the orbit beyond each corner or jump where the
// corrector fails (JumpAcross) or where a trace turned back after one.
void Trace(Palc& palc, OrbitProblem& problem, Monitor& monitor, VectorXd u0, int fixed,
           VectorXd along, double from, double to, const OrbitBranchOptions& o, OrbitBranch* out) {
  const int k = problem.parameter_index();
  const double dir = to > from ? 1 : -1;
  const auto cancelled = [&] { return o.palc.cancelled && o.palc.cancelled(); };
  for (;;) {
    const PalcResult r = palc.Trace(u0, fixed, along, std::ref(monitor));
    if (const VectorXd* at = monitor.TurnedBack()) {
      if (out->jumps >= o.max_jumps) {  // cut short: never "reached-end"
        out->status = BranchStatus::kStepTooSmall;
        out->message = "turned back after a jump, max_jumps = " + std::to_string(o.max_jumps);
        return;
      }
      ++out->jumps;
      u0 = *at, fixed = k, along = VectorXd::Unit(k + 1, k) * dir;
      monitor.Restart();
      continue;
    }
    if (monitor.stopped()) return;
    out->status = FromPalc(r);
    out->message = r.message;
    if (out->jumps > 0 && out->status == BranchStatus::kStartFailed) {  // the orbit beyond
      out->status = BranchStatus::kStepTooSmall;
      out->message = "the orbit beyond the last jump: " + r.message;
    }
    if (out->status != BranchStatus::kStepTooSmall || out->rows.empty()) return;
    if (out->jumps >= o.max_jumps) {
      out->message += "; more than max_jumps = " + std::to_string(o.max_jumps) + " restarts";
      return;
    }
    const OrbitRow last = out->rows.back();
    const double dp = LastStep(out->rows);
    const double pdir = dp != 0 ? (dp > 0 ? 1 : -1) : dir;
    const double step = std::max(std::abs(dp), Tolerances::kBranchEdgeStep * std::abs(to - from));
    OrbitRow before, after;
    std::string why;
    problem.ClearOpened();
    const bool across = orbit_detail::JumpAcross(problem, last, pdir, step, pdir == dir ? to : from,
                                                 o.locate_tol, &before, &after, &why);
    if (cancelled()) {
      out->status = BranchStatus::kCancelled;
      out->message = "cancelled";
      return;
    }
    if (across) {
      out->special.push_back(before);
      out->rows.push_back(before);
    } else if (after.p == last.p) {  // no orbit beyond: the branch ends at the edge
      return orbit_detail::EndAtEdge(problem, before, pdir, o.locate_tol, why, out);
    }  // else: the orbit goes on past the failure (natural steps); on from there
    ++out->jumps;
    u0 = problem.Unknowns(after.start, after.p);
    fixed = k;
    along = VectorXd::Unit(k + 1, k) * pdir;
    monitor.Restart();
  }
}

}  // namespace

namespace orbit_detail {

OrbitBranch TraceBranch(OrbitProblem& problem, const System& system, int parameter,
                        const VectorXd& u0, int fixed, const VectorXd& along, double from,
                        double to, const OrbitBranchOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Palc palc(problem, options.palc);
  if (options.palc.cancelled) problem.shooting().flow().set_cancel(options.palc.cancelled);
  OrbitBranch out;
  out.status = BranchStatus::kMaxPoints;
  out.section = problem.section();
  Monitor monitor(palc, problem, system, parameter, from, to, options, out);
  Trace(palc, problem, monitor, u0, fixed, along, from, to, options, &out);
  if (out.status == BranchStatus::kStepTooSmall && !out.rows.empty())  // where it ended
    out.message += " after the row at " + system.ParameterName(parameter) + " = " +
                   Num(out.rows.back().p, 12) + " (" + std::to_string(out.rows.back().sticks) +
                   " sticks, " + std::to_string(out.rows.back().crossings) + " crossings)";
  out.evaluations = palc.evaluations() + problem.polishes();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace orbit_detail

OrbitBranch ContinueOrbits(const System& system, int parameter, const FlowPoint& guess,
                           const PoincareSection& section, double to,
                           const OrbitBranchOptions& options) {
  orbit_detail::CheckInputs(system, parameter, guess, section, to, options);
  const auto start = std::chrono::steady_clock::now();
  const double from = system.ParameterValue(parameter);
  OrbitProblem problem(system, parameter, guess, section, options);
  if (options.palc.cancelled) problem.shooting().flow().set_cancel(options.palc.cancelled);
  const PeriodicOrbit first =  // a stroboscopic section's time at this clock's frequency
      problem.shooting().Find(guess, orbit_detail::SectionFor(system, section, guess.z));
  const auto cancelled = [&] { return options.palc.cancelled && options.palc.cancelled(); };
  if (!first.ok()) {
    OrbitBranch out;  // a cancel inside Newton's runs shows as another failure: cancelled
    out.section = section;
    out.status = first.status == OrbitStatus::kCancelled || cancelled()
                     ? BranchStatus::kCancelled
                     : BranchStatus::kStartFailed;
    out.message = "no periodic orbit at " + system.ParameterName(parameter) + " = " + Num(from) +
                  " near the guess (" + Name(first.status) + ": " + first.message + ")";
    return out;
  }
  const int k = problem.parameter_index();
  OrbitBranch out =
      orbit_detail::TraceBranch(problem, system, parameter, problem.Unknowns(first.start, from), k,
                                VectorXd::Unit(k + 1, k) * (to > from ? 1 : -1), from, to, options);
  if (cancelled() && !Complete(out.status))
    out.status = BranchStatus::kCancelled;  // cut short by the cancel, whatever failed first
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace stickslip
