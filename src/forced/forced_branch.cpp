// One-parameter continuation of the forced oscillator's periodic orbits: the
// stroboscopic residual (forced_branch_problem.hpp) through Palc, rows from
// each accepted point's run, LP and PD located on the chord between two rows.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "forced_branch_problem.hpp"
#include "stickslip/errors.hpp"
#include "numerics/numbers.hpp"

namespace stickslip {

const char* ForcedBranchStatusName(ForcedBranchStatus s) {
  switch (s) {
    case ForcedBranchStatus::kReachedEnd:
      return "reached-end";
    case ForcedBranchStatus::kUnbounded:
      return "unbounded";
    case ForcedBranchStatus::kStepTooSmall:
      return "step-too-small";
    case ForcedBranchStatus::kStartFailed:
      return "start-failed";
    case ForcedBranchStatus::kMaxPoints:
      return "max-points";
    case ForcedBranchStatus::kClosed:
      return "closed";
  }
  return "?";
}

namespace {

using Eigen::VectorXd;
using forced_detail::StrobeProblem;

// Bisection on the chord a -> b for the sign change of test(): each point is
// corrected onto the branch with the chord's direction held (Palc::Correct).
bool Locate(Palc& palc, StrobeProblem& problem, const VectorXd& a, const VectorXd& b,
            double (StrobeProblem::*test)() const, double tol, ForcedBranchRow* out) {
  const VectorXd chord =
      (b - a).cwiseQuotient(palc.options().scale.size() ? palc.options().scale : VectorXd::Ones(3));
  const VectorXd t = chord.normalized();
  auto at = [&](double s, double* g) {
    const PalcCorrection c = palc.Correct(a + s * (b - a), t);
    if (!c.ok) return false;
    *g = (problem.*test)();
    return true;
  };
  double lo = 0, hi = 1, g_lo = 0, g_hi = 0;
  if (!at(lo, &g_lo) || !at(hi, &g_hi) || (g_lo > 0) == (g_hi > 0)) return false;
  for (int it = 0; it < 60 && hi - lo > tol; ++it) {
    const double mid = 0.5 * (lo + hi);
    double g = 0;
    if (!at(mid, &g)) return false;
    ((g > 0) == (g_lo > 0) ? lo : hi) = mid;
  }
  double g = 0;
  if (!at(0.5 * (lo + hi), &g)) return false;
  *out = problem.Row();
  return true;
}

ForcedBranchStatus FromPalc(PalcStatus s) {
  switch (s) {
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
  return ForcedBranchStatus::kReachedEnd;
}

}  // namespace

ForcedBranch ContinueForced(const ForcedParams& base, ForcedAxis axis, double from, double to,
                            double x_guess, double xdot_guess, const ForcedBranchOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ForcedParams at_from = base;
  SetAxis(at_from, axis, from);
  if (const std::string e = ValidationError(at_from); !e.empty()) throw InvalidArgument(e);
  if (!(to != from) || !std::isfinite(to)) throw InvalidArgument("to must be finite and != from");
  StrobeProblem problem(base, axis, options);
  Palc palc(problem, options.palc);
  ForcedBranch out;
  out.status = ForcedBranchStatus::kMaxPoints;
  const double dir = to > from ? 1 : -1;
  VectorXd u0(3), direction = VectorXd::Unit(3, 2) * dir;
  u0 << x_guess, xdot_guess, from;
  bool stopped = false, have_tests = false;
  double last_tests[2] = {0, 0};
  double (StrobeProblem::*tests[2])() const = {&StrobeProblem::FoldTest, &StrobeProblem::FlipTest};
  const ForcedLabel labels[2] = {ForcedLabel::kLP, ForcedLabel::kPD};
  auto monitor = [&](const std::vector<PalcPoint>& curve) {
    const VectorXd* prev = curve.size() >= 2 ? &curve[curve.size() - 2].u : nullptr;
    VectorXd here = curve.back().u;
    if (prev && (here[2] - to) * dir >= 0) {  // past the end: the row at p = to instead
      VectorXd pred = *prev + (to - (*prev)[2]) / (here[2] - (*prev)[2]) * (here - *prev);
      pred[2] = to;
      const PalcCorrection c = palc.CorrectFixed(pred, 2);
      stopped = true;
      out.status = ForcedBranchStatus::kReachedEnd;
      if (!c.ok) {
        out.status = ForcedBranchStatus::kStepTooSmall;
        out.message = "the row at p = to: " + c.why;
        return false;
      }
      here = c.u;
    }
    const ForcedBranchRow row = problem.Row();
    const double now[2] = {(problem.*tests[0])(), (problem.*tests[1])()};
    for (int i = 0; i < 2 && prev && have_tests; ++i) {
      ForcedBranchRow sp;
      if ((now[i] > 0) != (last_tests[i] > 0) &&
          Locate(palc, problem, *prev, here, tests[i], options.locate_tol, &sp)) {
        sp.label = labels[i];
        out.special.push_back(sp);
        out.rows.push_back(sp);
      }
    }
    std::copy(now, now + 2, last_tests);
    have_tests = true;
    out.rows.push_back(row);
    if (std::max(std::abs(row.extremes.x_min), std::abs(row.extremes.x_max)) >
        options.max_amplitude) {
      out.status = ForcedBranchStatus::kUnbounded;
      stopped = true;
    }
    return !stopped;
  };
  const PalcResult r = palc.Trace(u0, 2, direction, monitor);
  if (!stopped) {
    out.status = FromPalc(r.status);
    out.message = r.message;
    if (out.status == ForcedBranchStatus::kStepTooSmall && !out.rows.empty())  // where it ended
      out.message += " after the row at " + std::string(ForcedAxisName(axis)) + " = " +
                     Num(out.rows.back().p, 12) + " (" + std::to_string(out.rows.back().sticks) +
                     " sticks, " + std::to_string(out.rows.back().crossings) + " crossings)";
  }
  out.evaluations = palc.evaluations();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace stickslip
