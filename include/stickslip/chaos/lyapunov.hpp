// Iterates of a Poincare map of any system (system.hpp) and its largest
// Lyapunov exponent (issue 21 items 1-2, issue 31 item 6): the stroboscopic
// map of a forced system (the state at clock phase 0 -> one clock period
// later) or the returns to a surface of an autonomous one, with the stick
// count and first stick-exit phase of each return, and the exponent from the
// variational equations with saltation at every switch (docs/theory.md
// "Lyapunov exponents").
//
// The exponent: J_k = DP(z_k) is the map's Jacobian on the tangent block over
// return k (saltations included: S_in = diag(1, 0) entering stick, so a
// return with a stick phase of the 1-DOF oscillator has rank(J_k) <= 1; on a
// surface J_k = (I - f g^T / (g . f)) Phi, Leine & Nijmeijer 2004 ch. 7). A
// normalised tangent matrix M is carried, M <- J_k M / |J_k M|_F, and lambda
// = sum ln|J_k M|_F / (the kept returns' time); M is first aligned over the
// last `align` transient returns, so on a periodic orbit the sum is ln|mu_max|
// per period from the first kept return on. A matrix rather than one vector:
// the rank-1 collapse at stick then loses no growing direction (a vector in
// the kernel of S_in would). If J_k M = 0 exactly (the tangent space collapsed
// onto zero, e.g. a superstable stick-slip orbit) the true contribution is
// -infinity; it is counted as a factor DBL_EPSILON (the smallest contraction a
// double-precision product resolves), M is reseeded with J_k, and `collapses`
// counts it: the estimate is then an upper bound.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/names.hpp"
#include "stickslip/orbits/shooting.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip {

struct LyapunovOptions {
  /// transient's and keep's upper bound (1e6 returns each), as the apps'.
  static constexpr int kMaxPeriods = 1000000;
  FlowOptions flow = ForcedBelt::FlowDefaults();
  int transient = 500;   ///< returns (forcing periods) discarded
  int keep = 200;        ///< returns recorded (section points, exponent)
  int align = 50;        ///< last transient returns that align the tangent matrix
  int batches = 10;      ///< batch means for the exponent's standard error
  bool exponent = true;  ///< carry the variational equations
  /// Surface sections: no return within this time ends the run (a settled
  /// rest, or kNoReturn).
  double max_return_time = 2e3;
  /// Empty if valid, else one line naming the offending value.
  std::string ValidationError() const;
};

/// One point of the section, after return k of the kept ones.
struct SectionPoint {
  Eigen::VectorXd z;  ///< the tangent block (clocks left out)
  ModeSet mode;       ///< contact i sticks at the section: mode[i] == Mode::kStick
  int sticks = 0;     ///< stick phases begun during the return that ends here
  int exits = 0;      ///< stick exits during that return
  /// The clock's phase in [0, 2 pi) of the return's first stick exit; -1 if
  /// none or the system has no clock.
  float first_exit_phase = -1;
  double dt = 0;  ///< the return's time
};

enum class LyapunovStatus {
  kDone,
  kFlowFailed,  ///< the flow failed or ran out of work (message says where)
  kDiverged,    ///< a state component passed max_amplitude
  kCancelled,
  kNoReturn,     ///< a surface section: no return within max_return_time (not at rest)
  kRest,         ///< a surface section: settled at a stable rest point (end), no more
                 ///< returns; lyapunov is steady sliding's largest real part there
  kContactOpen,  ///< a contact's normal force reached 0 (end; message says where)
};
template <>
struct EnumNames<LyapunovStatus> {
  static constexpr NamedValue<LyapunovStatus> kTable[] = {
      {LyapunovStatus::kDone, "done"},
      {LyapunovStatus::kFlowFailed, "flow-failed"},
      {LyapunovStatus::kDiverged, "diverged"},
      {LyapunovStatus::kCancelled, "cancelled"},
      {LyapunovStatus::kNoReturn, "no-return"},
      {LyapunovStatus::kRest, "rest"},
      {LyapunovStatus::kContactOpen, "contact-open"},
  };
};

struct SectionRun {
  LyapunovStatus status = LyapunovStatus::kDone;
  std::string message;
  std::vector<SectionPoint> points;  ///< the kept returns' section points
  FlowPoint end;                     ///< the last state (time section: at t = 0, phase 0)
  double lyapunov = 0;               ///< largest exponent, per unit time
  double lyapunov_err = 0;           ///< standard error of the batch means
  int collapses = 0;                 ///< returns with J_k M = 0 (see above)
  long steps = 0;
};

/// IterateSection's default max_amplitude: far beyond any bounded orbit.
constexpr double kStroboscopicMaxAmplitude = 1e6;

/// Iterates the map of `section` (SectionKind::kTime: one clock period,
/// PoincareSection::Stroboscopic; kSurface: a hyperplane of an autonomous
/// system) from `start`. A time section restarts every return at t = 0 with
/// the start's clocks (the field is periodic in them). `cancelled` is polled
/// once per return. A tangent component above max_amplitude ends the run as
/// kDiverged. Throws InvalidArgument for invalid options, a stick-exit
/// section, or a surface section of a system with a clock.
SectionRun IterateSection(const System& system, const FlowPoint& start,
                          const PoincareSection& section, const LyapunovOptions& options,
                          const std::function<bool()>& cancelled = {},
                          double max_amplitude = kStroboscopicMaxAmplitude);

/// The stroboscopic map of a system with one clock: IterateSection on one
/// clock period (from start's phase).
SectionRun IterateStroboscopic(const System& system, const FlowPoint& start,
                               const LyapunovOptions& options,
                               const std::function<bool()>& cancelled = {},
                               double max_amplitude = kStroboscopicMaxAmplitude);

/// Whether the field of mode m vanishes at z on the tangent block, to tol
/// relative to 1 + |z|: a rest point.
bool FieldVanishes(const System& system, const ModeSet& m, ConstState z, double tol);

/// The default section of an autonomous system: the maxima of component 0
/// (its velocity, DerivativeOf(0), falling through 0); where component 0 is
/// a first-order state (no velocity: a drill string's twist), contact 0's
/// relative velocity falling through its value at steady sliding (0 where
/// there is none), which a stick-slip orbit crosses once a period.
Section MaximaSection(const System& system);

}  // namespace stickslip
