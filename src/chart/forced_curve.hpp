// Two-parameter curves of the forced oscillator's periodic orbits (issue 21
// item 3): the stroboscopic residual P^m(z; p1, p2) - z = 0 (forced/orbit.hpp)
// bordered by one test function of the orbit, in u = (x, x', p1, p2):
//   LP  det(DP^m - I) = 0  (a multiplier at +1),
//   PD  det(DP^m + I) = 0  (a multiplier at -1),
//   NS  det(DP^m) - 1 = 0  (|mu|^2 = 1 for a complex pair; with real
//       multipliers mu1 mu2 = 1 this is a neutral saddle, flagged),
//   GR  the boundary of non-stop motion: the margin of the orbit's arrivals
//       at x' = v outside the stick band, |x + 2 beta v - A cos Omega t| - mu_s
//       at a crossing (a crossing reaching the band's edge; Den Hartog's stop
//       condition on a floor; past it |force| - mu_s at the stick-in, <= 0),
//       or v - max x' (slip below; min x' - v above) for an orbit that never
//       reaches x' = v (grazing-sliding, docs/theory.md "Continuation"), on the orbit of
//       that slip field continued across x' = v (FlowRequest::switching
//       false): smooth through 0, as the belt's grazing gap. (The true flow's
//       margin past grazing, minus the stick time, grows like a square root:
//       the corrector stalled on it after 2-3 points.)
// The Jacobian: DP^m - I from the variational run at every evaluation; the
// parameter columns and the test function's row by central differences at
// every evaluation (a chord held over a correction converges too slowly:
// measured, 12 iterations without reaching the tolerance).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "stickslip/chart/forced_chart.hpp"
#include "stickslip/continuation/palc.hpp"

namespace stickslip {

// One evaluation of the orbit map and the test functions at u.
struct ForcedCurveSample {
  // The run over m forcing periods (variational, with extremes): its end,
  // state transition matrix, extremes and switch counts.
  Vec2 end;  // (x, x') at its end
  Mat2 jacobian = Mat2::Identity();
  Extrema extrema = Extrema::Empty();
  int sticks = 0, crossings = 0;
  double lp = 0, pd = 0, ns = 0;
  double margin = 0;      // the GR test (header)
  bool crossing = false;  // the margin is a crossing's (else a grazing's)
};

class ForcedCurveProblem final : public PalcProblem {
 public:
  ForcedCurveProblem(const ForcedParams& base, const Plane& plane, CurveKind kind, int m,
                     const FlowOptions& flow)
      : base_(base), plane_(plane), kind_(kind), m_(m), flow_(flow) {}
  int unknowns() const override { return 4; }
  const Plane& plane() const { return plane_; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  std::string DomainError(const Eigen::VectorXd& u) const override;
  // The orbit and its tests at u (after the trace, for the rows).
  bool Sample(const Eigen::VectorXd& u, ForcedCurveSample* s, std::string* why) const;
  // The GR margin's kind: chosen at the seed, held along the curve.
  void set_crossing(bool crossing) { crossing_ = crossing; }
  // Runs without switching: a grazing GR curve (the header's GR).
  bool smooth() const { return kind_ == CurveKind::kGrazing && !crossing_; }
  // This curve's test function of a sample.
  double TestOf(const ForcedCurveSample& s) const { return Test(s); }
  // The section: forcing phase theta (z at t = theta / Omega), 0 by default.
  // A stick-slip orbit stuck at the section makes the map non-smooth there,
  // so the tracer moves the section into a slip phase (Rephase).
  double phase() const { return phase_; }
  void set_phase(double theta) { phase_ = theta; }
  // The state at the section phase where |x' - v| is largest over the orbit
  // through u (step ends of one run): u's (x, x') replaced, phase set.
  bool Rephase(Eigen::VectorXd* u, std::string* why);
  // Whether `next` continues `last` (TraceOptions::same_branch): the corrector
  // stayed near the predictor, the stick structure is the same and the orbit
  // has no shorter period than m. kNone if so, else kBranchJump or kSliding
  // (the stick structure changed: a sliding point lies between).
  CurveEnd SameBranch(const PalcPoint& last, const PalcPoint& next,
                      const Eigen::VectorXd& scale) const;

 private:
  double Test(const ForcedCurveSample& s) const;
  // ForcedStart, or with smooth() the slip mode of x''s side.
  FlowPoint Start(const ForcedModel& m, double t, double x, double xdot) const;
  // A run to t_end as the tests need it: variational, extremes in steps,
  // switching unless smooth(), the switches appended to `events` if given.
  FlowRequest Request(double t_end, std::vector<FlowSwitch>* events) const;
  ForcedParams base_;
  Plane plane_;
  CurveKind kind_;
  int m_;
  FlowOptions flow_;
  bool crossing_ = true;
  double phase_ = 0;
  Eigen::MatrixXd chord_;  // 3 x 4: the difference columns and row
};

}  // namespace stickslip
