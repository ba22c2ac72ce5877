// The one flow of a friction system (system.hpp): exact event-driven
// integration of a Filippov system (docs/theory.md, "One core"). Each mode is
// integrated on its own smooth field by a stepper (Taylor series by default,
// CVODE selectable) that locates the events as roots: a slipping contact
// reaching its surface (h_i = 0), a sticking one reaching its static limit
// (|lambda_i| = mu_s N_i), the caller's sections and the extrema it asks for
// (heyoka's terminal and non-terminal events, Biscani & Izzo 2021). At every
// switch the new mode follows Filippov's rule, and the variational equations
// take the saltation matrix S = I + (f+ - f-) grad g^T / (grad g . f-) of the
// event g (Leine & Nijmeijer 2004, section 7.3; di Bernardo et al. 2008).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/flow/flow_options.hpp"
#include "stickslip/system/system.hpp"

namespace stickslip {

/// A state of the flow: time, state and mode.
struct FlowPoint {
  double t = 0;
  Eigen::VectorXd z;
  ModeSet mode;
};

/// The mode Filippov's rule gives z: each contact slips on its side of
/// h_i = 0; the contacts on their surfaces take the consistent mode
/// (ConsistentMode, switching.hpp). Where that is not unique, the contact-
/// order rule: each in turn sticks within its static limit, else slips the
/// way lambda_i points (ModeChoiceOf says which case it was).
ModeSet ModeOf(const System& s, const Eigen::VectorXd& z);

/// A hypersurface g(z) = sum w_j z_j - offset (or, with derivative, g =
/// d/dt sum w_j z_j: the extrema of that sum), crossed in a direction.
struct Section {
  ContactVelocity g;  ///< the linear functional (its speed is the offset)
  bool derivative = false;
  int direction = 0;  ///< +1 rising, -1 falling, 0 either
  /// Only while contact 0 slips below (the belt's maximum of x').
  bool slip_below_only = false;
};

enum class SwitchKind { kStickIn, kStickOut, kCrossing, kTouch };
template <>
struct EnumNames<SwitchKind> {
  static constexpr NamedValue<SwitchKind> kTable[] = {
      {SwitchKind::kStickIn, "stick-in"},
      {SwitchKind::kStickOut, "stick-out"},
      {SwitchKind::kCrossing, "crossing"},
      {SwitchKind::kTouch, "touch"},
  };
};

/// One switch of a run: where, which contact, and the modes around it.
struct FlowSwitch {
  SwitchKind kind = SwitchKind::kStickIn;
  double t = 0;
  int contact = 0;
  Eigen::VectorXd z;
  ModeSet before, after;
};

/// Called with (t, z, mode); z has dimension() entries.
using FlowObserver = std::function<void(double t, const double* z, const ModeSet& mode)>;

/// What one Run computes and where it stops. The defaults integrate to
/// t_max with all switching and nothing recorded.
struct FlowRequest {
  double t_max = std::numeric_limits<double>::infinity();
  bool switching = true;          ///< false: stay on the start mode's smooth field
  bool variational = false;       ///< FlowRun::jacobian (the tangent block)
  bool parameter_column = false;  ///< FlowRun::dzdp (Flow::set_parameter_column)
  bool stop_at_stick = false;     ///< at an arrival where the contact sticks, before sticking
  int stop_at_exit = 0;           ///< > 0: at that stick exit (after the switch)
  /// > 0: after the instant whose switches bring the run's count to this
  /// (kSwitchCount). A run continued from there integrates as one run would:
  /// every switch restarts the stepper anyway.
  int stop_after_switches = 0;
  std::vector<Section> sections;  ///< terminal; FlowRun::section says which
  /// Components whose extremes are recorded (FlowRun::lo, hi): at the roots
  /// of their derivatives when extrema_in_steps, else at step ends.
  std::vector<int> extrema;
  bool extrema_in_steps = true;
  /// Taylor, with extrema_in_steps: their roots are not sought, but every
  /// step is the one a run seeking them takes (the Taylor field keeps its
  /// order for roots inside steps), so the run ends in the same state to the
  /// bit; lo and hi then hold the start, the switches and the end only. One
  /// exception: max_steps counts a segment's steps from the last root passed,
  /// and a held run passes none of the extrema's. For Newton's evaluations
  /// before the last (Shooting::Find).
  bool hold_extrema = false;
  long max_steps = 0;  ///< > 0: at most this many steps per run (kTooMuchWork)
  /// Samples at output_origin + k output_dt (k an integer; the start's t
  /// if NaN) and at every switch, to observer; the start when it lies on
  /// that grid, and the end unless the run reaches t_max with output_end
  /// false (a run that another one continues: Simulate, simulate.hpp).
  double output_dt = 0;
  double output_origin = std::numeric_limits<double>::quiet_NaN();
  long output_index = -1;  ///< >= 0: the first k (a continued run's FlowRun::output_index)
  bool output_end = true;
  FlowObserver observer;
  FlowObserver step_observer;  ///< every step end and switch
  /// Appended to when set, each switch before its observer call.
  std::vector<FlowSwitch>* switches = nullptr;
};

struct FlowRun {
  FlowStatus status = FlowStatus::kTimeLimit;
  std::string message;  ///< for failures: where and what
  FlowPoint end;
  int section = -1;        ///< the terminal section that ended the run
  int opened = -1;         ///< kContactOpen: the contact whose normal force reached 0
  Eigen::VectorXd lo, hi;  ///< extremes of FlowRequest::extrema, with the end points
  double t_stick = 0;      ///< time with some contact sticking
  int switches = 0, sticks = 0, exits = 0, crossings = 0, touches = 0;
  std::vector<ModeSet> modes;  ///< the mode sequence, start mode first
  /// d z(t) / d z(t0) on the tangent block, saltations included (variational).
  Eigen::MatrixXd jacobian;
  /// d z(t) / dp at fixed t and start on the tangent block
  /// (parameter_column), saltations included: each switch moves it as the
  /// parameter were a state of rate 0 (System::ContactParameterDerivative).
  Eigen::VectorXd dzdp;
  bool has_dzdp = false;
  long steps = 0;
  long output_index = 0;  ///< the next output sample's k (FlowRequest::output_index)
  TaylorOrders orders;
  bool ok() const {
    return status != FlowStatus::kIntegratorFailed && status != FlowStatus::kTooManySwitches &&
           status != FlowStatus::kCancelled && status != FlowStatus::kTooMuchWork &&
           status != FlowStatus::kInconsistentMode && status != FlowStatus::kAmbiguousMode &&
           status != FlowStatus::kTooManyAtOnce;
  }
};

namespace flow_detail {
class Engine;  // src/flow/engine.hpp
}

class Flow {
 public:
  /// Any system (system.hpp). Throws InvalidArgument if the options are
  /// invalid or the system reports a validation error.
  Flow(const System& system, const FlowOptions& options);
  ~Flow();
  Flow(const Flow&) = delete;
  Flow& operator=(const Flow&) = delete;

  /// Change the system (same dimension and contacts keep the solvers).
  void set_system(const System& system);
  const System& system() const { return *system_; }
  const FlowOptions& options() const { return options_; }

  /// Integrates from `start` (its mode is trusted) until `request` says so;
  /// *out is overwritten (its storage reused: no allocation once warm).
  void Run(const FlowPoint& start, const FlowRequest& request, FlowRun* out);
  FlowRun Run(const FlowPoint& start, const FlowRequest& request) {
    FlowRun r;
    Run(start, request, &r);
    return r;
  }

  /// The parameter column: with variational runs on the Taylor integrator,
  /// dz/dp for parameter j rides in the same recurrences. Throws
  /// InvalidArgument for one the system has no column for.
  void set_parameter_column(int j);
  void clear_parameter_column() { parameter_.reset(); }
  std::optional<int> parameter() const { return parameter_; }
  bool has_parameter_column() const {
    return parameter_.has_value() && options_.integrator == Integrator::kTaylor;
  }

  long total_steps() const { return total_steps_; }
  const TaylorOrders& taylor_orders() const { return taylor_orders_; }
  /// Polled after every step: a run stops with kCancelled once it returns true.
  void set_cancel(std::function<bool()> cancel) { cancel_ = std::move(cancel); }

 private:
  friend class flow_detail::Engine;
  std::unique_ptr<System> system_;
  FlowOptions options_;
  std::optional<int> parameter_;
  std::unique_ptr<flow_detail::Engine> engine_;
  long total_steps_ = 0;
  TaylorOrders taylor_orders_;
  std::function<bool()> cancel_;
};

}  // namespace stickslip
