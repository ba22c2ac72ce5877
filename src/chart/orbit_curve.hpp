// Two-parameter curves of any system's periodic orbits (system_chart.hpp):
// the branch problem F(u, p1) = P(u; p1, p2) - u = 0 of the one branch driver
// (continuation/orbit_problem.hpp), with p2 as one more unknown, bordered by
// one test function of the monodromy (Kuznetsov 2004, ch. 10; the branch
// driver's RowTest, so a curve passes through its located points):
//   LP  prod (mu_i - 1),  PD  prod (mu_i + 1),  NS  prod_{i<j} (mu_i mu_j - 1);
//   GR  the boundary of the orbits that arrive on a contact's surface and
//       cross it: min over the arrivals (crossings and stick entries) of
//       |lambda_i| - mu_s N_i (> 0 crossing, <= 0 sticking: crossing-sliding
//       where it reaches 0), or, for an orbit that reaches no surface, the gap
//       of the contacts' relative velocities to 0 (-max h_i below the
//       surface, min h_i above), on the smooth field continued across the
//       surfaces, smooth through 0 (grazing; the true flow's margin past it
//       grows like a square root: di Bernardo et al. 2008, ch. 8).
// Unknowns (u, p1, p2). dF/du = DP - I from the variational run, dF/dp1 as
// the branch driver has it, dF/dp2 and the test's row by central differences
// (each a run with the monodromy; an exact row would need second-order
// variational equations).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "continuation/orbit_problem.hpp"
#include "stickslip/chart/chart.hpp"

namespace stickslip {

/// A GR curve's test (the header's GR): an arrival's margin to the static
/// limit, or the gap of the smooth field's orbit to the surfaces.
enum class GrazingMargin { kArrival, kGap };

class OrbitCurveProblem final : public PalcProblem {
 public:
  /// `start` the seed's section point (its clock and mode); p1 the branch's
  /// parameter, p2 the held one. kind LP, PD, NS or GR (with `margin`; kGap
  /// maps on the smooth fields: ShootingOptions::switching false).
  OrbitCurveProblem(const System& system, int p1, int p2, const FlowPoint& start,
                    const PoincareSection& section, CurveKind kind,
                    const OrbitBranchOptions& options,
                    GrazingMargin margin = GrazingMargin::kArrival);
  int unknowns() const override { return nu_ + 2; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  std::string DomainError(const Eigen::VectorXd& u) const override;
  /// u of a row (its start and p) at p2.
  Eigen::VectorXd Unknowns(const OrbitRow& row, double p2) const;
  /// The orbit at u (with its multipliers, counts and extremes) as a row; its
  /// test function in *test, its mode sequence in *modes if given. False
  /// with *why where the map fails.
  bool Sample(const Eigen::VectorXd& u, OrbitRow* row, double* test, std::string* why,
              std::vector<ModeSet>* modes = nullptr);
  /// An accepted point's residuals at u (max norm): the map's |P(z) - z|,
  /// the test's |test| and, at the point last evaluated (the corrector
  /// accepts that one), |test| / max(1, |grad test|), its distance to the
  /// test's zero to first order (else |test|).
  struct Residuals {
    double map = 0, test = 0, distance = 0;
  };
  bool ResidualsAt(const Eigen::VectorXd& u, Residuals* r, std::string* why);
  /// A system with a clock: the point of the orbit through u, over one
  /// period, whose contacts all slip farthest from their surfaces (the
  /// largest min |h_i| at a step end), its clock in [0, 2 pi): a section
  /// start where the stroboscopic map is smooth (a stick phase at the
  /// section is not). False with *why where the run fails or every step
  /// end sticks.
  bool Rephase(const Eigen::VectorXd& u, FlowPoint* start, std::string* why);
  /// A stroboscopic section of m > 1 clock turns: k > 1 where row r's orbit
  /// (just sampled: its p2 held) comes back to its start, within
  /// Tolerances::curve_lower_period, after m / k turns (it has a shorter
  /// period); else 0.
  int ShorterPeriod(const OrbitRow& r);
  /// The smallest |h_i| at u's section point (orbit_problem.hpp).
  double SlipGap(const Eigen::VectorXd& u) const {
    DomainError(u);  // the held p2 at u's
    return orbit_.SlipGap(u.head(nu_ + 1));
  }
  /// This curve's test function of a row just mapped (its p2 held):
  /// RowTest's LP, PD or NS, or GR's margin (NaN where the orbit has no
  /// arrival, or a contact's velocity has more than one term).
  double Test(const OrbitRow& r);
  GrazingMargin margin() const { return margin_; }
  CurveKind kind() const { return kind_; }
  int plane_index() const { return nu_; }  ///< u[nu], u[nu + 1] are (p1, p2)
  /// The status of the last map that failed, in any call.
  OrbitStatus last_map_failure() const { return orbit_.last_failure(); }
  /// The status of the orbit of the last Evaluate that failed with `why`
  /// (kContactOpen: a normal force at 0 on the orbit; kModeChanged: the
  /// return's mode differs, the switching sequence changed), else kOk.
  OrbitStatus FailureOf(const std::string& why) const {
    return why == last_failure_ ? last_status_ : OrbitStatus::kOk;
  }

 private:
  // Test(r) into *test; false with *why where it is not finite.
  bool TestOf(const OrbitRow& r, double* test, std::string* why);
  // The map at u: the residual and the test (the orbit's multipliers).
  bool At(const Eigen::VectorXd& u, Eigen::VectorXd* r, double* test, std::string* why);
  OrbitBranchOptions options_;  // before orbit_, which holds a reference to it
  // Mutable: DomainError sets the held p2 on its system before checking.
  mutable orbit_detail::OrbitProblem orbit_;
  int p2_, nu_;
  CurveKind kind_;
  GrazingMargin margin_;
  std::vector<FlowSwitch> switches_;  // GR kArrival: one period's
  Eigen::VectorXd last_u_;            // the last point evaluated and its test's gradient (max norm)
  double test_gradient_ = 0;
  std::string last_failure_;  // the last failed Evaluate's why and its orbit's status
  OrbitStatus last_status_ = OrbitStatus::kOk;
};

}  // namespace stickslip
