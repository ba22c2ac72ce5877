// Private to src/continuation/: the fixed points of a Poincare map of any
// system as a PalcProblem in (u, p) (orbit_branch.hpp), and the rows and test
// functions of its points.
#pragma once

#include <memory>
#include <vector>

#include "stickslip/continuation/orbit_branch.hpp"

namespace stickslip::orbit_detail {

class OrbitProblem final : public PalcProblem {
 public:
  OrbitProblem(const System& system, int parameter, const FlowPoint& start,
               const PoincareSection& section, const OrbitBranchOptions& o);
  OrbitProblem(const OrbitProblem&) = delete;  // holds o by reference
  OrbitProblem& operator=(const OrbitProblem&) = delete;
  int unknowns() const override { return nu_ + 1; }
  bool Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* f, Eigen::MatrixXd* jac,
                std::string* why) override;
  std::string DomainError(const Eigen::VectorXd& u) const override;
  /// The row of the last point evaluated.
  OrbitRow Row() const;
  /// One more Newton step from the last point evaluated (the corrector's last
  /// iterate, whose update fell below its tol but was not evaluated): the
  /// bordered step with constraint row w . du = 0 (null: p held), and the map
  /// with its Jacobian there, so that Row() is the orbit at *u. Kept only
  /// where the residual does not grow and (same_counts) the switching
  /// counts stay; else false, with Row() and *u unchanged.
  bool Polish(const Eigen::VectorXd* w, Eigen::VectorXd* u, bool same_counts = true);
  /// Runs of the map with its Jacobian that Polish made (PALC counts its own).
  int polishes() const { return polishes_; }
  /// The orbit at parameter p by the shooting's damped Newton from z (p
  /// held); on success Row() is its row. False, with *why, if none.
  bool FindAt(double p, const FlowPoint& z, std::string* why);
  /// Whether a map or Newton failed with a contact's normal force at 0
  /// since the last ClearOpened().
  bool Opened() const { return opened_; }
  void ClearOpened() { opened_ = false; }
  /// u of an orbit found at parameter p.
  Eigen::VectorXd Unknowns(const FlowPoint& z, double p) const;
  int parameter_index() const { return nu_; }  ///< p's component in u
  const PoincareSection& section() const { return section_; }
  /// The state after `periods` of row r's periods at parameter p from r's
  /// start, with r's clock (a guess for FindAt). Stroboscopic sections only;
  /// false where the run fails.
  bool Settle(double p, const OrbitRow& r, int periods, FlowPoint* out);
  /// The switching counts of one period of r.period from r.start at r.p
  /// into *r. False where the system is invalid there or the run fails.
  bool Counts(OrbitRow* r);
  /// One period of row r's orbit with its switches recorded in *out (those
  /// before a failure, where the run fails: at a sliding point the orbit
  /// itself is degenerate), and its step ends passed to `steps` if given;
  /// *reached (if given): whether the run reached the period's end. The
  /// system at r.p (null where it is invalid).
  const System* Switches(const OrbitRow& r, std::vector<FlowSwitch>* out,
                         const FlowObserver& steps = nullptr, bool* reached = nullptr);
  /// The smallest |h_i| of the contacts at u's section point, with the
  /// system at u's p (0 where a contact sticks there).
  double SlipGap(const Eigen::VectorXd& u) const;
  Shooting& shooting() { return shooting_; }
  /// The system with parameter p set (and the held ones).
  const System& SystemAt(double p) {
    system_->SetParameterValue(j_, p);
    return *system_;
  }
  /// Sets another parameter of the system (a chart's second axis), held by
  /// every later map until set again.
  void set_held(int parameter, double value) { system_->SetParameterValue(parameter, value); }
  /// The map at u (p = u's last component), without the branch's caches:
  /// *r = P(z) - z and *o its orbit (with the monodromy if `jacobian`).
  bool MapOf(const Eigen::VectorXd& u, bool jacobian, Eigen::VectorXd* r, PeriodicOrbit* o,
             std::string* why) {
    return MapAt(u[nu_], PointAt(u), jacobian, r, o, why);
  }
  /// The status of the last map that failed (kOk: none yet).
  OrbitStatus last_failure() const { return last_failure_; }

 private:
  FlowPoint PointAt(const Eigen::VectorXd& u) const;
  FlowPoint StartOf(const OrbitRow& r) const;
  PoincareSection SectionAt(const FlowPoint& z) const;
  bool MapAt(double p, const FlowPoint& z, bool jacobian, Eigen::VectorXd* r, PeriodicOrbit* o,
             std::string* why);
  bool Difference(double p, const FlowPoint& z, Eigen::MatrixXd* jac, std::string* why);
  // An event section's return is looked for within kBranchReturnPeriods of
  // the longest period of the maps that returned (period_; none yet: the
  // shooting's max_return_time): a map that has not returned by then is far
  // from the branch, as a run beyond a grazing edge that slips on.
  void BoundReturn();
  void Returned(double period);

  std::unique_ptr<System> system_;
  int j_, nu_;
  FlowPoint start_;  // the clock (stroboscopic) and the mode (event sections)
  PoincareSection section_;
  const OrbitBranchOptions& o_;
  Shooting shooting_;
  PeriodicOrbit last_, plus_, minus_;
  Eigen::VectorXd last_u_, r_, rp_, rm_;
  Eigen::MatrixXd jac_;  // dF/du at last_u_ (Evaluate's)
  bool opened_ = false;
  OrbitStatus last_failure_ = OrbitStatus::kOk;
  int polishes_ = 0;
  double period_ = 0;  // the longest of the maps that returned (BoundReturn)
};

/// The section at system s for the state z: a stroboscopic section's time
/// follows the clock's frequency (a parameter may set it).
PoincareSection SectionFor(const System& s, const PoincareSection& section,
                           const Eigen::VectorXd& z);
/// Which tangent components are displacements: none of the others is their
/// rate (x, not x'; System::DerivativeOf).
std::vector<bool> Displacements(const System& s);

/// Throws InvalidArgument, naming it, on a parameter index out of range or
/// one the system does not depend on (System::ParameterError).
void CheckParameter(const System& system, int parameter);
/// ContinueOrbits' checks (orbit_inputs.cpp): throws InvalidArgument, naming
/// the value, on an invalid system, options (PALC's on the section's
/// unknowns), parameter, guess, end `to` or section turns.
void CheckInputs(const System& system, int parameter, const FlowPoint& guess,
                 const PoincareSection& section, double to, const OrbitBranchOptions& options);

/// The branch from u0 (its component `fixed` held by the first correction,
/// traced along `along`, unscaled) of `parameter` between from and to:
/// ContinueOrbits' rows, special points, jumps and ends (orbit_branch.cpp).
OrbitBranch TraceBranch(OrbitProblem& problem, const System& system, int parameter,
                        const Eigen::VectorXd& u0, int fixed, const Eigen::VectorXd& along,
                        double from, double to, const OrbitBranchOptions& options);

/// An orbit as a row at parameter p (no label).
OrbitRow RowOf(const PeriodicOrbit& o, double p);
/// A test function of a row's multipliers: 0 LP prod (mu - 1), 1 PD
/// prod (mu + 1), 2 NS prod_{i<j} (mu_i mu_j - 1).
double RowTest(const OrbitRow& r, int i);
/// A complex pair within tol of the unit circle (an NS point's multipliers).
bool TorusPair(const OrbitRow& r, double tol);
/// The largest distance from a multiplier of a to the nearest of b's.
double MultiplierMove(const OrbitRow& a, const OrbitRow& b);
/// The same switching sequence counts (sticks and crossings per period).
bool SameStructure(const OrbitRow& a, const OrbitRow& b);

}  // namespace stickslip::orbit_detail
