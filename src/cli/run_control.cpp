#include "cli/run_control.hpp"

#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "stickslip/errors.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip::cli {

namespace {

// Read by the worker thread too: a lock-free atomic, safe in a signal handler.
std::atomic<int> g_signal{0};
std::atomic<long long> g_first_ns{0};  // when the first signal came
static_assert(std::atomic<int>::is_always_lock_free);
static_assert(std::atomic<long long>::is_always_lock_free);

// A second signal within this of the first is the same interrupt delivered
// twice: timeout(1) signals the app and then its process group.
constexpr long long kSameInterruptNs = 200'000'000;

long long MonotonicNs() {  // clock_gettime is async-signal-safe (POSIX)
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<long long>(ts.tv_sec) * 1'000'000'000LL + ts.tv_nsec;
}

void OnSignal(int sig) {
  const long long now = MonotonicNs();
  if (g_signal != 0) {  // a second interrupt: the default action, at once
    if (now - g_first_ns.load() < kSameInterruptNs) return;
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_first_ns = now;
  g_signal = sig;
}

std::string Seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 100 ? "%.1f s" : "%.0f s", s);
  return buf;
}

}  // namespace

RunControl::RunControl(std::string prog, double max_time)
    : prog_(std::move(prog)),
      max_time_(max_time),
      start_(std::chrono::steady_clock::now()),
      terminal_(::isatty(STDERR_FILENO) == 1) {
  g_signal = 0;
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  std::signal(SIGPIPE, SIG_IGN);
}

double RunControl::Elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool RunControl::Signalled() const { return g_signal != 0; }

bool RunControl::Cancelled() const {
  const bool c = g_signal != 0 || (max_time_ > 0 && Elapsed() > max_time_);
  if (c && cancelled_phase_.empty()) cancelled_phase_ = phase_;
  return c;
}

std::string RunControl::Reason() const {
  if (g_signal != 0) {
    const int s = g_signal;
    return std::string("interrupted by signal ") + std::to_string(s) +
           (s == SIGINT    ? " (SIGINT)"
            : s == SIGTERM ? " (SIGTERM)"
                           : "");
  }
  if (max_time_ > 0 && Elapsed() > max_time_)
    return "time limit of " + FormatNumber(max_time_) + " s reached";
  return "";
}

void RunControl::Phase(const std::string& name) { phase_ = name; }

void RunControl::Line(const std::string& text) {
  last_line_ = Elapsed();
  std::cerr << prog_ << ": " << text << std::endl;
}

void RunControl::Progress(const std::string& what, double fraction, double count,
                          const std::string& unit) {
  if (!ProgressDue()) return;
  const double t = Elapsed();
  std::string text = what + " after " + Seconds(t);
  if (terminal_) {
    char buf[96];
    std::snprintf(buf, sizeof buf, ", %.3g %s/s", t > 0 ? count / t : 0.0, unit.c_str());
    text += buf;
    if (fraction > 0.01 && fraction <= 1) text += ", ETA " + Seconds(t * (1 - fraction) / fraction);
  }
  Line(text);
}

void RunControl::Heartbeat(const std::string& detail) {
  if (!HeartbeatDue()) return;
  Line("still " + phase_ + (detail.empty() ? "" : " (" + detail + ")") + " after " +
       Seconds(Elapsed()));
}

void CheckStdout() {
  errno = 0;
  std::cout.flush();
  const bool bad = !std::cout.good() || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (bad) {
    const int e = errno;
    std::cout.clear();
    throw Error(std::string("cannot write to standard output") +
                (e != 0 ? std::string(": ") + std::strerror(e) : ""));
  }
}

}  // namespace stickslip::cli
