// Interruption, time limit and progress for an app's long run.
//
// RunControl installs SIGINT and SIGTERM handlers (a second signal ends the
// process at once, by the default action) and ignores SIGPIPE, so a closed
// stdout cannot kill a run before its files are written (CheckStdout then
// reports it). Cancelled() is true once a signal arrived or --max_time passed;
// an app polls it in every phase (computing, estimates, writing, gnuplot).
//
// Progress goes to stderr, at most one line a second. On a terminal a line
// carries the rate and an ETA; otherwise it is a plain line. Heartbeat() is
// for callbacks polled inside a computation that reports nothing else (the
// grid search of a continuation): after 2 s without a line it prints one
// naming the phase, so no phase is silent for long.
#pragma once

#include <chrono>
#include <string>

namespace stickslip::cli {

class RunControl {
 public:
  // max_time <= 0: no limit.
  RunControl(std::string prog, double max_time);
  bool Cancelled() const;
  // Whether a signal arrived (no clock read: for hooks polled very often).
  bool Signalled() const;
  // Why Cancelled() is true: "interrupted by signal 2" or "time limit of 2 s
  // reached". Empty if it is not.
  std::string Reason() const;
  double Elapsed() const;
  // Names the phase for progress lines ("continuing", "estimates", "plotting").
  void Phase(const std::string& name);
  const std::string& phase() const { return phase_; }
  // The phase in which Cancelled() was first true (else the current one).
  const std::string& cancelled_phase() const {
    return cancelled_phase_.empty() ? phase_ : cancelled_phase_;
  }
  // A progress line "<prog>: <what>" (plus the rate in `unit`s per second
  // and the ETA on a terminal); fraction in [0, 1] of the phase done, or
  // negative if unknown; count: units done so far.
  void Progress(const std::string& what, double fraction, double count, const std::string& unit);
  // Whether Progress would print now (at most one line a second).
  bool ProgressDue() const { return Elapsed() >= last_line_ + 1.0; }
  // Prints "<prog>: still <phase> (<detail>) after N s" if no line came for 2 s.
  void Heartbeat(const std::string& detail);
  // Whether Heartbeat would print now: a hook polled after every integration
  // step builds its detail only then.
  bool HeartbeatDue() const { return Elapsed() >= last_line_ + kHeartbeatSeconds; }

 private:
  static constexpr double kHeartbeatSeconds = 2.0;
  void Line(const std::string& text);
  std::string prog_;
  double max_time_;
  std::chrono::steady_clock::time_point start_;
  std::string phase_ = "working";
  mutable std::string cancelled_phase_;  // set by the main thread's first true Cancelled()
  double last_line_ = 0;
  bool terminal_;
};

// Flushes stdout; throws Error naming the reason if anything written to it
// was lost (closed pipe, full disk, /dev/full).
void CheckStdout();

}  // namespace stickslip::cli
