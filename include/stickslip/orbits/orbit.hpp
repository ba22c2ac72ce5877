// Periodic orbits of a friction system (the belt model, or any other on the
// model seam, system.hpp) and their Floquet multipliers.
//
// Stick-slip orbits: every stick segment leaves Omega at the same point
// (x0, v), so the return map of Omega is constant (seed, case 1) and an orbit
// costs one slip integration from (x0, v) to the next arrival in Omega.
// Pure-slip orbits: Newton on the return map P of the section x' = 0 (x'
// decreasing, a maximum of x), desingularised at the equilibrium as
// G(a) = (P(xbar + a) - xbar - a) / a so that Newton cannot fall onto it.
#pragma once

#include <algorithm>
#include <complex>
#include <string>
#include <vector>

#include "stickslip/names.hpp"
#include "stickslip/orbits/orbit_status.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"

namespace stickslip {

/// Stick-slip (one stick phase per period) or pure slip (never sticks).
enum class OrbitKind { kStickSlip, kPureSlip };
template <>
struct EnumNames<OrbitKind> {
  static constexpr NamedValue<OrbitKind> kTable[] = {
      {OrbitKind::kStickSlip, "stick-slip"},
      {OrbitKind::kPureSlip, "pure-slip"},
  };
};

/// A periodic orbit: period, extremes, start point, segments and multipliers.
struct Orbit {
  OrbitKind kind = OrbitKind::kStickSlip;
  double period = 0;
  double t_stick = 0;
  Extrema extrema;
  /// Stick-slip: the exit point (x0, v). Pure-slip: the point on x' = 0.
  Vec2 start = Vec2::Zero();
  std::vector<Mode> modes;  // segment sequence from start
  int crossings = 0;        // crossings of x' = v without sticking
  /// Floquet data, only when OrbitOptions::floquet is set.
  bool has_floquet = false;
  Mat2 monodromy = Mat2::Identity();
  std::complex<double> eigenvalues[2];
  /// The nontrivial multiplier: 0 for stick-slip (superstable); for pure slip
  /// P'(x*), which equals exp(oint(-2 beta + F'(x' - v)) dt) (trace formula)
  /// when the orbit stays below the belt.
  double multiplier = 0;
  bool stable = false;
  // Pure slip: Newton was accepted where its steps stalled at the integration
  // noise floor (below 1000 x the tolerance and no longer shrinking) instead
  // of falling below the tolerance; newton_step is its last step |da|.
  bool newton_stalled = false;
  double newton_step = 0;
};

/// Integration and Newton settings of the orbit search, validated once.
struct OrbitOptions {
  FlowOptions flow;
  bool floquet = false;          // variational equations and multipliers
  double max_return_time = 2e3;  // give up on a return after this time
  int max_newton = 40;
  /// On the section coordinate, relative to max(1, |a|). Newton cannot beat the
  /// integration error, so the tolerance used is max(newton_tol, 10 rtol).
  double newton_tol = 1e-11;
  double EffectiveNewtonTol() const { return std::max(newton_tol, 10 * flow.rtol); }
  std::string ValidationError() const;
};

/// The outcome of one orbit search: status, message, the orbit, Newton steps.
struct OrbitResult {
  OrbitStatus status = OrbitStatus::kOk;
  std::string message;
  Orbit orbit;
  int iterations = 0;
  double gap = 0;  // kMissed: largest x' on the first return minus v (< 0)
  bool ok() const { return status == OrbitStatus::kOk; }
};

/// One application of the pure-slip return map.
struct ReturnMap {
  OrbitStatus status = OrbitStatus::kOk;
  std::string message;
  double x = 0;       // P(x0)
  double dpdx = 0;    // P'(x0), with derivative
  double period = 0;  // return time
  // dP/dp at fixed x0, with derivative and the flow's parameter column.
  double dpdp = 0;
  bool has_dpdp = false;
  FlowResult flow;
};

/// Finds periodic orbits of one system on the model seam (the belt: Model);
/// reuses its integrator between calls.
class OrbitFinder {
 public:
  /// Throws InvalidArgument if options are invalid.
  OrbitFinder(const FrictionSystem& system, const OrbitOptions& options);
  void set_model(const FrictionSystem& system);
  const FrictionSystem& system() const { return flow_.system(); }
  /// The belt model (throws InvalidArgument for another system).
  const Model& model() const { return flow_.model(); }
  const OrbitOptions& options() const { return options_; }
  void set_floquet(bool on) { options_.floquet = on; }

  /// The stick-slip orbit, if the slip from the exit point returns to Omega.
  /// With first_return_only, give up (kMissed, gap set) at the first maximum of
  /// x' below the belt: the slip phase then makes more than one revolution.
  OrbitResult StickSlip(bool first_return_only = false);
  /// A pure-slip orbit by Newton from the section point xbar + a_guess, a_guess > 0.
  OrbitResult PureSlip(double a_guess);
  /// Every pure-slip orbit whose section point lies in (xbar + a_lo, xbar + a_hi):
  /// G sampled at n points, sign changes refined. Orbits that stick are skipped.
  std::vector<Orbit> PureSlipScan(double a_lo, double a_hi, int n);

  /// The return map of the section x' = 0 from (x, 0).
  ReturnMap Return(double x, bool derivative);
  /// G(a) = (P(xbar + a) - xbar - a) / a and, optionally, G'(a).
  OrbitStatus Desingularised(double a, double* g, double* dg, ReturnMap* map = nullptr);

  /// Grazing test function: (largest x' on the first return of the slip-below
  /// field from the exit point, switching ignored) - v. Positive where the slip
  /// phase reaches the belt speed (stick-slip), zero at grazing.
  /// With run, also the whole first-return run (variational if floquet is on):
  /// at grazing it is the grazing orbit, and det of its Jacobian the pure-slip
  /// side's multiplier.
  OrbitStatus GrazingGap(double* gap, FlowResult* run = nullptr);

  BeltFlow& flow() { return flow_; }

 private:
  void Floquet(Orbit& o, const Mat2& M) const;
  // Fills o for the pure-slip orbit through section amplitude a (PureSlip).
  void AcceptPureSlip(Orbit& o, double a, double step, bool stalled, const ReturnMap& map) const;

  OrbitOptions options_;
  BeltFlow flow_;
};

}  // namespace stickslip
