// One shooting for every system (docs/theory.md, "One shooting"): a periodic
// orbit is a fixed point of a Poincare map P on a section, found by Newton on
// P(z) - z = 0 with DP from the variational equations and the saltations of
// the one flow (flow.hpp). Three sections cover the friction systems:
//  - a time: the stroboscopic map of a forced system (m forcing periods);
//  - a stick exit: stick phases collapse the state (the seed's case 1, where
//    the belt's map is constant; the forced oscillator's exit-phase map);
//  - a hyperplane crossed in one direction (the belt's x' = 0 falling).
// On an event section DP = (I - f g^T / (g . f)) Phi at the arrival (the
// Poincare map's Jacobian; Leine & Nijmeijer 2004, ch. 7), where g is the
// event's gradient; a clock's column of Phi follows from the flow identity
// Phi f(z0) = f(z(T)). The Floquet multipliers are DP's eigenvalues, less
// the 0 of the flow direction on an event section (deflated exactly: g^T DP
// = 0; docs/theory.md, "One shooting").
#pragma once

#include <complex>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "stickslip/flow/flow.hpp"
#include "stickslip/names.hpp"
#include "stickslip/orbits/orbit_status.hpp"

namespace stickslip {

/// Where the Poincare map cuts the orbit.
enum class SectionKind {
  kTime,       ///< after a fixed time (a forced system's stroboscopic map)
  kStickExit,  ///< at a stick exit (the start leaves a contact's stick phase)
  kSurface,    ///< at a crossing of a hyperplane in its direction
};
template <>
struct EnumNames<SectionKind> {
  static constexpr NamedValue<SectionKind> kTable[] = {
      {SectionKind::kTime, "time"},
      {SectionKind::kStickExit, "stick-exit"},
      {SectionKind::kSurface, "surface"},
  };
};

/// A Poincare section and how many returns close the orbit.
struct PoincareSection {
  SectionKind kind = SectionKind::kTime;
  double time = 0;  ///< kTime: the map's time (> 0)
  /// kStickExit: the contact whose exit cuts the orbit (the run ends at the
  /// returns-th stick exit, of any contact). The start's mode is the slip
  /// mode it leaves into.
  int contact = 0;
  Section surface;  ///< kSurface: a plain hyperplane (no derivative section)
  int returns = 1;  ///< event sections: the orbit closes at this arrival
  /// Event sections of a system with a clock: its turns per period of the
  /// orbit (the clock's residual is theta(T) - theta(0) - 2 pi turns).
  int turns = 0;

  /// The stroboscopic section of m periods of the system's clock at z.
  static PoincareSection Stroboscopic(const System& s, const Eigen::VectorXd& z, int m);
  /// The stick exit of `contact`, closing after `returns` exits and `turns`
  /// clock turns.
  static PoincareSection StickExit(int contact, int returns = 1, int turns = 0);
};

/// Newton settings, validated once.
struct ShootingOptions {
  ShootingOptions() = default;
  /// On `flow`, whose step cap is also the cap per evaluation (max_steps).
  explicit ShootingOptions(const FlowOptions& f) : flow(f), max_steps(f.max_steps) {}
  FlowOptions flow;
  int max_newton = 40;
  /// Converged when the Newton update is below tol (1 + |z|) (max norm).
  double tol = 1e-12;
  /// Event sections: no arrival within this time is kNoReturn.
  double max_return_time = 2e3;
  bool extrema = true;  ///< PeriodicOrbit::lo, hi
  /// false: every run stays on its start mode's smooth field, continued
  /// across the contacts' surfaces (a grazing curve's orbits: the gap to a
  /// surface is smooth through 0 there). A start that sticks then has no
  /// such field: the map ends there with OrbitStatus::kSticks.
  bool switching = true;
  long max_steps = 1000000;  ///< flow steps per evaluation of the map
  std::string ValidationError() const;
};

/// A periodic orbit through a point of its section, with its Floquet data.
struct PeriodicOrbit {
  OrbitStatus status = OrbitStatus::kNotConverged;
  std::string message;
  FlowPoint start;  ///< on the section, with its mode
  double period = 0;
  /// DP at the fixed point: kTime on the tangent block, else n x n.
  Eigen::MatrixXd monodromy;
  /// The nontrivial multipliers by modulus, the largest first: kTime's
  /// tangent_dimension(), an event section's dimension() - 1.
  std::vector<std::complex<double>> multipliers;
  bool stable = false;                       ///< every |multiplier| < 1
  int sticks = 0, exits = 0, crossings = 0;  ///< per period
  std::vector<ModeSet> modes;                ///< the mode sequence from start
  Eigen::VectorXd lo, hi;                    ///< extremes of the tangent components (extrema)
  int iterations = 0;
  double update = 0;  ///< the last Newton update (max norm)
  long steps = 0;     ///< flow steps of the last evaluation
  bool ok() const { return status == OrbitStatus::kOk; }
};

/// Finds periodic orbits of one system; reuses its flow between calls.
class Shooting {
 public:
  /// Throws InvalidArgument if the options or the system are invalid.
  Shooting(const System& system, const ShootingOptions& options);
  void set_system(const System& system) { flow_.set_system(system); }
  const System& system() const { return flow_.system(); }
  const ShootingOptions& options() const { return options_; }
  /// Event sections: give up after this time (throws InvalidArgument unless
  /// finite and > 0).
  void set_max_return_time(double t);
  /// Newton iterations per Find (throws InvalidArgument unless >= 1).
  void set_max_newton(int n);

  /// Newton from `guess` (kTime: its mode is Filippov's at the state; event
  /// sections: its mode is trusted). Throws InvalidArgument for a section
  /// the system cannot have (a contact out of range, an event section on a
  /// system with several clocks, returns < 1). Only the evaluations near
  /// convergence seek the extremes (ShootingOptions::extrema): the orbit's
  /// are those of the evaluation at its start.
  PeriodicOrbit Find(const FlowPoint& guess, const PoincareSection& section);

  /// One evaluation of the map at z, no Newton (a continuation's residual):
  /// *residual = P(z) - z on the unknowns (kTime: the tangent block, z's
  /// mode set by Filippov's rule; event sections: all n, a clock's less 2 pi
  /// turns). With `jacobian`, *orbit holds what Find gives at a fixed point
  /// (DP, multipliers, extremes); without, only the counts, modes and
  /// period. False, with orbit->status and message, where the map fails.
  bool Map(const FlowPoint& z, const PoincareSection& section, bool jacobian,
           Eigen::VectorXd* residual, PeriodicOrbit* orbit);

  /// The parameter column: a Map with its Jacobian then also gives dP/dp
  /// for parameter j (parameter_derivative), by the flow's column with its
  /// saltations and the section's own motion (a clock's time 2 pi m / omega,
  /// an exit's limit). Taylor only; throws InvalidArgument where the system
  /// has no column for j.
  void set_parameter_column(int j) { flow_.set_parameter_column(j); }
  void clear_parameter_column() { flow_.clear_parameter_column(); }
  bool has_parameter_column() const { return flow_.has_parameter_column(); }
  /// d(P(z) - z)/dp on the unknowns, of the last Map with its Jacobian while
  /// a column was set, where has_parameter_derivative() (not where the run
  /// settled on a rest point: FlowRun::has_dzdp).
  const Eigen::VectorXd& parameter_derivative() const { return dpdp_; }
  bool has_parameter_derivative() const { return has_dpdp_; }

  Flow& flow() { return flow_; }

 private:
  void Check(const PoincareSection& s) const;
  void Prepare(const FlowPoint& z, const PoincareSection& s, bool variational = true,
               bool column = false);
  bool Evaluate(const FlowPoint& z, const PoincareSection& s, PeriodicOrbit* o);
  void Residual(const FlowPoint& z, const PoincareSection& s);
  void MapJacobian(const FlowPoint& z, const PoincareSection& s);
  void MapParameterDerivative(const FlowPoint& z, const PoincareSection& s);
  void EventGradient(const PoincareSection& s);
  void OntoSection(const PoincareSection& s, FlowPoint* z) const;
  bool NewtonStep();  // dz_ from dp_ (DP - I) and r_; false where singular
  void Describe(const FlowPoint& z, const PoincareSection& s, PeriodicOrbit* o);

  ShootingOptions options_;
  Flow flow_;
  FlowRequest request_;
  FlowRun run_;
  Eigen::MatrixXd dp_, full_;   // DP; Phi with the clock's column
  Eigen::VectorXd r_;           // P(z) - z on the unknowns
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;  // DP - I, kept: no allocation per step
  Eigen::VectorXd dz_;
  Eigen::VectorXd dpdp_, col_;  // dP/dp; the column with the clock's entry
  bool has_dpdp_ = false;
  Eigen::VectorXd f0_, f1_, grad_, grad2_;
  Eigen::MatrixXd hdph_;        // Describe's deflation: H DP H,
  Eigen::VectorXd house_, hw_;  // its reflection's v and c DP v
};

}  // namespace stickslip
