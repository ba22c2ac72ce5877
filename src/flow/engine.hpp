// Private to src/flow/: one Run of the flow (flow.hpp), segment by segment.
// engine.cpp: the loop, the segments and their events; switching.cpp: the
// Filippov rule at every event; tangent.cpp: M = dz/dz0 (and the column)
// across segments and saltations.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "integrate/event_driver.hpp"
#include "integrate/stepper.hpp"
#include "stickslip/flow/flow.hpp"

namespace stickslip::flow_detail {

// What a terminal event function of a segment stands for.
struct FunctionRole {
  enum Kind { kArrival, kExit, kSection, kExtremum, kOpen } kind = kExtremum;
  int index = 0;  // the contact, or the section
  int sign = 0;   // an exit: +1 at lambda = +limit, -1 at -limit
};

// Throws InvalidArgument unless the start lies where its mode says: each
// sticking contact on its surface, within its static limit (mode_choice.cpp).
void CheckStart(const System& s, const FlowPoint& p);

class Engine {
 public:
  explicit Engine(Flow& flow);
  void Run(const FlowPoint& start, const FlowRequest& rq, FlowRun* out);
  // The system changed (Flow::set_system): its contacts are read again.
  void Invalidate() { system_read_ = false; }
  void ForgetEvents() {
    for (EventSet& e : sets_) e.used = false;
  }

 private:
  struct EventSet;
  // Checks the start (InvalidArgument) and sets the run's state and result.
  void Start(const FlowPoint& start, const FlowRequest& rq, FlowRun* out);
  void CheckRun(const FlowPoint& start, const FlowRequest& rq) const;  // InvalidArgument
  void Reshape(const FlowRequest& rq);  // a new shape: its slot's event sets rebuilt
  void ReadClockRates();
  void StartProblem();
  void ResetTangent();  // M_ = I, C_ = 0
  // One segment in the current mode; false when the run ends.
  bool Segment();
  void BuildEvents(EventSet& set);
  int AddFunction(EventSet& set, const EventFunction& f);  // its index; roles grown
  void AddExtremumEvents(EventSet& set);  // rq_'s extrema (held back: none, the steps kept)
  void AddOpenEvents(EventSet& set);
  // The events of the current mode (built or reused), shared with problem_.
  void UseEvents();
  void ReadSystem();
  // The switches at a terminal root (switching.cpp); false when the run ends.
  bool Switch(const std::vector<int>& roots);
  bool Arrive(int contact);
  // The exit of `contact`, whose event fired in mode `detected` (its lambda
  // there is at the limit); mode_ is the mode it leaves, with the instant's
  // earlier switches.
  void Exit(int contact, int sign, const ModeSet& detected);
  bool SwitchAtOnce(const std::vector<int>& roots);
  bool AlsoArriving(const ModeSet& detected, std::vector<int>* arrivals);
  // S = I + (f+ - f-) grad^T / (grad . f-) on the tangent block, M = S M.
  // M <- S M, and the column with the event's own d g / dp (g_p).
  void Saltation(const ModeSet& before, const ModeSet& after, const Eigen::VectorXd& grad,
                 double g_p);
  // d g / dp of contact c's arrival (its velocity) or exit (sign: the slip
  // side), for the column.
  double ArrivalDp(int c) const;
  double ExitDp(const ModeSet& stick, int c, int sign) const;
  void Record(SwitchKind kind, int contact, const ModeSet& before, const ModeSet& after);
  bool Done(FlowStatus s);
  void StartOutput(const FlowRequest& rq);
  [[gnu::cold]] bool Fail(FlowStatus s, const std::string& why);
  void Extend(const double* z);
  bool Settled(const double* y) const;
  // "taylor failed at t = ... in <mode> at x = ..., x' = ...: reason".
  std::string Where(double t, const double* y, const std::string& reason) const;
  // " at t = ... in <mode> at x = ..., x' = ...".
  std::string Place(double t, const double* y, int digits = 17) const;
  // The stepper of set's mode, made for the run's kind (plain, Phi, column).
  Stepper& Solver(EventSet& set);
  const double* InitialRows(const TaylorLayout& layout);  // y0_, filled
  // tangent.cpp: M (and C) at a start in stick, across a segment.
  void ProjectStartTangent();
  void AdvanceTangent(const double* y, const TaylorLayout& layout);
  static void OnEvent(void* self, int g, const double* y);
  static void OnStep(void* self, double t, const double* y);
  static void OnOutput(void* self, double t, const double* y);

  Flow& flow_;
  const System* s_ = nullptr;
  const FlowRequest* rq_ = nullptr;
  FlowRun* out_ = nullptr;
  int n_ = 0, nt_ = 0, k_ = 0;
  bool variational_ = false, column_ = false;
  std::vector<ContactVelocity> contacts_;
  std::vector<std::optional<ContactVelocity>> normals_;  // System::NormalForce
  std::vector<int> derivative_of_;
  bool system_read_ = false;  // contacts_, derivative_of_ are the system's
  long system_epoch_ = 0;     // counts the systems read (rest points, Taylor binds)
  // The request shapes the event sets were built for, the last two (a
  // Newton solve's runs hold their extrema back, then seek them: Find).
  struct Shape {
    bool used = false;
    bool switching = true, in_steps = true, hold = false, var = false, col = false;
    std::vector<int> extrema;
    std::vector<Section> sections;
  };
  static constexpr int kShapes = 2;
  Shape shapes_[kShapes];
  int shape_ = 0, next_shape_ = 0;  // the run's shape; the one a new shape replaces
  bool SameShape(const Shape& s, const FlowRequest& rq) const;
  void UseShape(const FlowRequest& rq);  // shape_: rq's, kept or new
  // The run's state between segments.
  double t_ = 0;
  Eigen::VectorXd z_;
  ModeSet mode_;
  Eigen::MatrixXd M_;                              // d z / d z0 on the tangent block
  bool tangent_fresh_ = false;                     // M_ = I and C_ = 0 (ResetTangent)
  Eigen::VectorXd C_, ctmp_;                       // d z / dp on the tangent block (column_)
  double t_start_ = 0;                             // the run's start (a clock's column)
  bool column_lost_ = false;                       // settled at rest: no column reported
  std::vector<double> clock_drate_;                // d omega / dp of each clock (column_)
  std::vector<double> clock_rate_, clock_offset_;  // clocks = rate t + offset
  long clock_epoch_ = -1;                          // clock_rate_ is of this system epoch
  double output_origin_ = 0;                       // samples at origin + k output_dt
  long next_output_ = 0;                           // the next sample's k
  double last_switch_t_ = 0;                       // where the last switch was recorded
  std::vector<double> switched_at_;                // per contact: its last switch's t
  // The segment's problem; the events of the last few modes (a mode's
  // events, the roles of its functions, the extremum components each
  // records, its arrivals), reused by runs of the shape it was built for.
  SegmentProblem problem_;
  struct EventSet {
    bool used = false;
    ModeSet mode;
    int shape = 0;  // the slot of shapes_ it was built for
    EventList events;
    std::vector<FunctionRole> roles;
    std::vector<std::vector<int>> extremum_of;
    std::vector<int> arrival_events;             // indexes into events, one per arrival
    bool has_rest = false, rest_stable = false;  // System::Rest of the mode
    Eigen::VectorXd rest;
    long rest_epoch = -1;  // rest is of the system read at this epoch
    // Its own steppers, one per kind (0 plain, 1 Phi, 2 the column), each
    // bound to the mode once (SegmentProblem::setup = key): a segment in a
    // mode met before only restarts one, and runs that alternate kinds keep
    // each.
    long key = -1;
    std::unique_ptr<Stepper> steppers[3];
    std::optional<int> column_param;  // steppers[2]'s parameter
  };
  static constexpr int kEventSets = 4 * kShapes;
  EventSet sets_[kEventSets];
  int next_set_ = 0;
  EventSet* cur_ = nullptr;
  std::vector<int> roots_;
  std::vector<double> y0_;
  long keys_ = 0;  // the setup keys given out (EventSet::key)
  // Scratch for switches.
  Eigen::VectorXd f_before_, f_after_, grad_, grad2_, jump_;
  Eigen::MatrixXd S_, tmp_;
  Eigen::RowVectorXd row_;  // grad^T M in a saltation (tmp_ keeps its n x n)
  std::vector<int> arrivals_;
};

}  // namespace stickslip::flow_detail
