// One-parameter continuation of the forced oscillator's periodic orbits: the stroboscopic
// residual (forced_branch_problem.hpp) through Palc, rows from each accepted point's run; LP,
// PD, NS and sliding points located on the chord between two rows; a jump: forced_sliding.hpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

#include "forced_branch_problem.hpp"
#include "forced_locate.hpp"
#include "forced_sliding.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/errors.hpp"

namespace stickslip {

namespace {

using Eigen::VectorXd;
using forced_detail::Bracket;
using forced_detail::Locate;
using forced_detail::StrobeProblem;

ForcedBranchStatus FromPalc(const PalcResult& r) {
  switch (r.status) {
    case PalcStatus::kClosed:
      return ForcedBranchStatus::kClosed;
    case PalcStatus::kMaxPoints:
      return ForcedBranchStatus::kMaxPoints;
    case PalcStatus::kStepTooSmall:
      return ForcedBranchStatus::kStepTooSmall;
    case PalcStatus::kStartFailed:
      return ForcedBranchStatus::kStartFailed;
    case PalcStatus::kStopped:
      break;
  }
  return r.message == "cancelled" ? ForcedBranchStatus::kCancelled
                                  : ForcedBranchStatus::kReachedEnd;
}

// One Palc trace's monitor: rows, the end at p = to, and the special points
// between consecutive rows (LP, PD, NS by their test functions; the sliding
// points by a change of the stick structure).
class Monitor {
 public:
  Monitor(Palc& palc, StrobeProblem& problem, const ForcedParams& base, ForcedAxis axis,
          double from, double to, const ForcedBranchOptions& o, ForcedBranch& out)
      : palc_(palc),
        problem_(problem),
        base_(base),
        axis_(axis),
        from_(from),
        to_(to),
        dir_(to > from ? 1 : -1),
        o_(o),
        out_(out) {}
  bool stopped() const { return stopped_; }
  // After a jump of the map the trace turned away from `to`: restart here.
  const VectorXd* TurnedBack() const { return turned_ ? &turned_at_ : nullptr; }
  void Restart() {  // Palc's next trace starts at turned_at_ and writes its row again
    if (turned_ && !out_.rows.empty()) out_.rows.pop_back();
    have_prev_ = turned_ = false;
  }
  bool operator()(const std::vector<PalcPoint>& curve);

 private:
  void Special(const VectorXd& a, const VectorXd& b, const ForcedBranchRow& row);
  Bracket AcrossEdge(const Bracket& br, bool chord, double span, const ForcedBranchRow& row);

  Palc& palc_;
  StrobeProblem& problem_;
  const ForcedParams& base_;
  ForcedAxis axis_;
  double from_, to_, dir_;
  const ForcedBranchOptions& o_;
  ForcedBranch& out_;
  bool stopped_ = false, have_prev_ = false, jumped_ = false, turned_ = false;
  VectorXd turned_at_;
  ForcedBranchRow prev_;
};

// The edge behind a failed or far-apart chord bracket br (span: the chord's
// parameter span): along the chord, or behind a corner of the branch (two
// branches meeting at the edge), so both ways; row is the chord's far end.
Bracket Monitor::AcrossEdge(const Bracket& br, bool chord, double span,
                            const ForcedBranchRow& row) {
  Bracket out = br, fine;
  std::string why;
  const double step =
      std::max(std::abs(span) / 8, Tolerances::kBranchEdgeStep * (1 + std::abs(out.lo.p)));
  bool found_edge = false, edge_only = false;
  for (const double sign : {1.0, -1.0})
    if (!found_edge && !edge_only) {
      const double d = sign * (span > 0 ? 1 : -1);
      // Never past the branch's range (validated; beyond it the model may not be).
      const double limit =
          std::clamp(out.lo.p + d * 256 * step, std::min(from_, to_), std::max(from_, to_));
      fine.lo.p = NAN;
      found_edge = forced_detail::JumpAcross(base_, axis_, o_, out.lo, d, step, limit,
                                             o_.locate_tol, &fine.lo, &fine.hi, &why);
      // The edge bisected, no orbit of the same m just beyond (the branch
      // went on to one far away): the edge is the point, row the far side.
      edge_only = !found_edge && std::isfinite(fine.lo.p);
    }
  if (found_edge) {
    out = fine;
  } else if (edge_only) {
    out.lo = fine.lo, out.hi = row;
  } else if (!chord) {
    out.hi = row;
  }
  return out;
}

void Monitor::Special(const VectorXd& a, const VectorXd& b, const ForcedBranchRow& row) {
  std::vector<ForcedBranchRow> found;
  // The pieces of one stick structure between a and b, split at the sliding
  // points: every sign change of the test functions on each (issue 35).
  std::vector<std::pair<forced_detail::BranchPoint, forced_detail::BranchPoint>> pieces;
  forced_detail::BranchPoint piece{a, prev_};
  ForcedBranchRow ref = prev_, first_lo;
  VectorXd from = a;
  for (int k = 0; k < 4 && !forced_detail::SameStructure(ref, row); ++k) {  // one edge each
    auto test = [&] { return forced_detail::SameStructure(problem_.Row(), ref) ? 1.0 : -1.0; };
    Bracket br;
    // On the chord; where the corrector fails there, the edge of the orbits
    // of ref's structure (a jump of the map).
    const bool chord = Locate(palc_, problem_, from, b, test, o_.locate_tol, &br);
    if (!chord && !Locate(palc_, problem_, from, b, test, o_.locate_tol, &br, true)) break;
    // Where the map jumps, the corrector fails short of the edge or lands on
    // either side of it far apart: refine in the parameter, by Newton from
    // the last orbit of ref's structure.
    const double far = chord ? br.hi.p : br.p_hi;
    const double gap = std::max({std::abs(far - br.lo.p), std::abs(br.hi.x0 - br.lo.x0),
                                 std::abs(br.hi.xdot0 - br.lo.xdot0)});
    const double edge_gap = Tolerances::kBranchEdgeGap * o_.locate_tol;
    if (!chord || gap > edge_gap * (1 + std::abs(far) + std::abs(br.lo.x0)))
      br = AcrossEdge(br, chord, b[2] - from[2], row), jumped_ = true;
    // Edges within the tolerance are one point (the two halves of a
    // symmetric orbit on a floor reach the band together).
    const bool same =
        k > 0 && std::abs(br.lo.p - found.back().p) <= edge_gap * (1 + std::abs(br.lo.p));
    if (same) found.pop_back();
    ForcedBranchRow point = same ? first_lo : br.lo;
    if (!same) first_lo = br.lo;
    forced_detail::ClassifySliding(base_, axis_, o_, first_lo, br.hi, &point);
    found.push_back(point);
    pieces.push_back({piece, forced_detail::PointOf(br.lo)});
    piece = forced_detail::PointOf(br.hi);
    if (forced_detail::SameStructure(br.hi, ref)) break;
    ref = br.hi;
    from = Eigen::Vector3d(br.hi.x0, br.hi.xdot0, br.hi.p);
  }
  pieces.push_back({piece, {b, row}});
  for (const auto& [lo, hi] : pieces)
    forced_detail::TestPoints(palc_, problem_, lo, hi, o_.locate_tol, &found);
  std::sort(found.begin(), found.end(), [&](const ForcedBranchRow& x, const ForcedBranchRow& y) {
    return std::abs(x.p - prev_.p) < std::abs(y.p - prev_.p);
  });
  for (const ForcedBranchRow& sp : found) out_.special.push_back(sp), out_.rows.push_back(sp);
}

bool Monitor::operator()(const std::vector<PalcPoint>& curve) {
  const VectorXd* prev = curve.size() >= 2 ? &curve[curve.size() - 2].u : nullptr;
  VectorXd here = curve.back().u;
  if (prev && (here[2] - to_) * dir_ >= 0) {  // past the end: the row at p = to instead
    VectorXd pred = *prev + (to_ - (*prev)[2]) / (here[2] - (*prev)[2]) * (here - *prev);
    pred[2] = to_;
    const PalcCorrection c = palc_.CorrectFixed(pred, 2);
    stopped_ = true;
    out_.status = ForcedBranchStatus::kReachedEnd;
    if (!c.ok) {
      out_.status = ForcedBranchStatus::kStepTooSmall;
      out_.message = "the row at p = to: " + c.why;
      return false;
    }
    here = c.u;
  }
  const ForcedBranchRow row = problem_.Row();
  jumped_ = false;
  if (prev && have_prev_) Special(*prev, here, row);
  prev_ = row;
  have_prev_ = true;
  out_.rows.push_back(row);
  if (std::max(std::abs(row.extrema.x_min), std::abs(row.extrema.x_max)) > o_.max_amplitude) {
    out_.status = ForcedBranchStatus::kUnbounded;
    stopped_ = true;
  } else if ((row.p - from_) * dir_ < -Tolerances::kBranchTurnBack * std::abs(to_ - from_)) {
    out_.status = ForcedBranchStatus::kLeftRange;
    out_.message = "the branch turned back past " + std::string(ForcedAxisName(axis_)) + " = " +
                   Num(from_, 12);
    stopped_ = true;
  }
  // Across a jump Palc orients the far family's tangent by the near one's,
  // which can point back: the sweep goes on toward `to` (issue 20, v from 0).
  if (!stopped_ && jumped_ && curve.back().tangent[2] * dir_ < 0) turned_ = true, turned_at_ = here;
  return !stopped_ && !turned_;
}

}  // namespace

namespace forced_detail {

ForcedBranch TraceBranch(const ForcedParams& base, ForcedAxis axis, double from, double to,
                         const Eigen::Vector3d& first, int fixed, const Eigen::Vector3d& direction,
                         const ForcedBranchOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  StrobeProblem problem(base, axis, options);
  Palc palc(problem, options.palc);
  ForcedBranch out;
  out.status = ForcedBranchStatus::kMaxPoints;
  const double dir = to > from ? 1 : -1;
  Monitor monitor(palc, problem, base, axis, from, to, options, out);
  VectorXd u0 = first, along = direction;
  double trace_dir = dir;
  int fixed_now = fixed;
  for (;;) {
    const PalcResult r = palc.Trace(u0, fixed_now, along, std::ref(monitor));
    if (const VectorXd* at = monitor.TurnedBack()) {
      if (out.jumps >= options.max_jumps) {  // cut short: never "reached-end"
        out.status = ForcedBranchStatus::kStepTooSmall;
        out.message = "turned back after a jump, max_jumps = " + std::to_string(options.max_jumps);
        break;
      }
      ++out.jumps;
      u0 = *at, fixed_now = 2, along = VectorXd::Unit(3, 2) * dir, trace_dir = dir;
      monitor.Restart();
      continue;
    }
    if (monitor.stopped()) {
      if (out.status == ForcedBranchStatus::kReachedEnd) out.message.clear();
      break;
    }
    out.status = FromPalc(r);
    out.message = r.message;
    if (out.status != ForcedBranchStatus::kStepTooSmall || out.rows.empty()) break;
    // A jump of the stroboscopic map: locate its edge, go on from the orbit beyond.
    const ForcedBranchRow last = out.rows.back();
    const ForcedBranchRow* prev = out.rows.size() >= 2 ? &out.rows[out.rows.size() - 2] : nullptr;
    const double dp = prev ? last.p - prev->p : 0;
    const double pdir = dp != 0 ? (dp > 0 ? 1 : -1) : trace_dir;
    const double step = std::max(std::abs(dp), Tolerances::kBranchEdgeStep * std::abs(to - from));
    ForcedBranchRow before, after;
    after.p = last.p, before.p = NAN;  // before.p: set where the edge is bisected
    std::string why = "more than max_jumps = " + std::to_string(options.max_jumps) + " jumps";
    if (out.jumps >= options.max_jumps) {
      out.message += "; " + why;
      break;
    }
    if (forced_detail::JumpAcross(base, axis, options, last, pdir, step, pdir == dir ? to : from,
                                  options.locate_tol, &before, &after, &why)) {
      out.special.push_back(before);
      forced_detail::ClassifySliding(base, axis, options, before, after, &out.special.back());
      out.rows.push_back(out.special.back());
    } else if (after.p == last.p) {
      out.message += "; " + why;
      if (std::isfinite(before.p)) {  // the edge located, no orbit beyond: one point
        out.special.push_back(forced_detail::EdgeWithoutOrbit(base, axis, options, before, pdir));
        out.rows.push_back(out.special.back());
      }
      break;
    }  // else: the orbit goes on past the failure (natural steps); on from there
    ++out.jumps;
    u0 << after.x0, after.xdot0, after.p;
    trace_dir = pdir;
    fixed_now = 2;  // from the orbit beyond: the parameter held, along pdir
    along = VectorXd::Unit(3, 2) * trace_dir;
    monitor.Restart();
  }
  if (out.status == ForcedBranchStatus::kStepTooSmall && !out.rows.empty())  // where it ended
    out.message += " after the row at " + std::string(ForcedAxisName(axis)) + " = " +
                   Num(out.rows.back().p, 12) + " (" + std::to_string(out.rows.back().sticks) +
                   " sticks, " + std::to_string(out.rows.back().crossings) + " crossings)";
  out.evaluations = palc.evaluations();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace forced_detail

ForcedBranch ContinueForced(const ForcedParams& base, ForcedAxis axis, double from, double to,
                            double x_guess, double xdot_guess, const ForcedBranchOptions& options) {
  const std::string e = options.ValidationError(base, axis, from, to, x_guess, xdot_guess);
  if (!e.empty()) throw InvalidArgument(e);
  return forced_detail::TraceBranch(base, axis, from, to,
                                    Eigen::Vector3d(x_guess, xdot_guess, from), 2,
                                    Eigen::Vector3d::Unit(2) * (to > from ? 1 : -1), options);
}

}  // namespace stickslip
