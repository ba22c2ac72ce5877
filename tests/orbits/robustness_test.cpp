// Randomized robustness: a few hundred random valid models, over the four
// friction laws, through simulation (BeltFlow::Run, with and without output
// samples), orbit finding (OrbitFinder::StickSlip, else PureSlipScan and
// PureSlip) and a short continuation in v (stickslip::Continue). Every run must
// end with a result or a clear status: no exception (every input here is
// valid), no crash, no hang, and no NaN or inf in any returned point.
//
// The samples come from a fixed seed (a hand-rolled generator, so the sequence
// is the same with every standard library). Continuations carry a wall-time cap
// through ContinuationOptions::cancelled (reaching the cap is a status, counted);
// simulations and orbit searches carry one through BeltFlow::set_cancel, and reaching
// that is a failure (a hang: nothing there should take seconds). A watchdog
// thread aborts the test, naming the sample, should anything still run on. A
// summary of the statuses, with the first message of each, is printed and
// recorded with RecordProperty.
//
// After the sweep, regression tests: the models the sweep found bugs with.
//
// STICKSLIP_ROBUSTNESS_SAMPLES=N overrides the number of samples per law.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <functional>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/systems/belt/belt_flow.hpp"
#include "stickslip/systems/belt/model.hpp"
#include "stickslip/systems/belt/params.hpp"
#include "wall_bound.hpp"

namespace ss = stickslip;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr double kSlowdown = 2.0;  // instrumented build (measured: ~1.3x here)
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr double kSlowdown = 2.0;
#else
constexpr double kSlowdown = 1.0;
#endif
#else
constexpr double kSlowdown = 1.0;
#endif

// SplitMix64 (Steele, Lea, Flood 2014): small, fast, the same everywhere.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t Next() {
    std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double Uniform(double a, double b) { return a + (b - a) * Uniform(); }
  double LogUniform(double a, double b) { return a * std::pow(b / a, Uniform()); }
  bool Chance(double p) { return Uniform() < p; }

 private:
  std::uint64_t s_;
};

std::string Describe(const ss::Params& p) {
  std::ostringstream os;
  os.precision(17);
  os << "law=" << ss::Name(p.law);
  for (const auto& name : ss::ParameterNames(p.law))
    os << " " << name << "=" << ss::GetParameter(p, name);
  return os.str();
}

// A valid model of the given law: beta in [0, 0.3] (exactly 0 now and then),
// v in [0.01, 1] (log-uniform: small speeds are the hard ones), mu_s in
// [0.2, 1.5], the law's own parameters in ranges that pass Validate.
ss::Params Sample(ss::LawKind law, Rng& rng) {
  ss::Params p;
  p.law = law;
  p.beta = rng.Chance(0.1) ? 0.0 : rng.Uniform(0.0, 0.3);
  p.v = rng.LogUniform(0.01, 1.0);
  p.mu_s = rng.Uniform(0.2, 1.5);
  switch (law) {
    case ss::LawKind::kCubic:
      p.mu_m = p.mu_s * rng.Uniform(0.3, 0.95);
      p.v_m = rng.Uniform(0.2, 1.0);
      break;
    case ss::LawKind::kCoulomb:
      p.mu_k = p.mu_s * rng.Uniform(0.3, 0.95);
      break;
    case ss::LawKind::kStribeck:
      p.mu_k = p.mu_s * rng.Uniform(0.3, 0.95);
      p.v_s = rng.Uniform(0.1, 1.0);
      break;
    case ss::LawKind::kLeine:
      p.delta = rng.Chance(0.1) ? 0.0 : rng.Uniform(0.0, 5.0);
      break;
  }
  return p;
}

bool Finite(double x) { return std::isfinite(x); }

// Non-finite fields of a point, by name; empty if all are finite.
std::string NonFinite(const std::vector<std::pair<const char*, double>>& fields) {
  std::string bad;
  for (const auto& [name, x] : fields)
    if (!Finite(x)) bad += std::string(bad.empty() ? "" : ", ") + name + " = " + std::to_string(x);
  return bad;
}

std::string NonFinite(const ss::Orbit& o) {
  return NonFinite({{"period", o.period},
                    {"t_stick", o.t_stick},
                    {"x_min", o.extrema.x_min},
                    {"x_max", o.extrema.x_max},
                    {"xdot_min", o.extrema.xdot_min},
                    {"xdot_max", o.extrema.xdot_max},
                    {"multiplier", o.multiplier},
                    {"start.x", o.start[0]},
                    {"start.xdot", o.start[1]}});
}

std::string NonFinite(const ss::BranchPoint& pt) {
  std::vector<std::pair<const char*, double>> f = {{"p", pt.p},
                                                   {"x_min", pt.extrema.x_min},
                                                   {"x_max", pt.extrema.x_max},
                                                   {"xdot_min", pt.extrema.xdot_min},
                                                   {"xdot_max", pt.extrema.xdot_max},
                                                   {"multiplier", pt.multiplier},
                                                   {"amplitude", pt.amplitude}};
  if (pt.kind != ss::PointKind::kEquilibrium) f.push_back({"period", pt.period});
  return NonFinite(f);
}

// Counts per stage and outcome, printed at the end with the first message
// (and sample) of each outcome that is not a plain success.
class Tally {
 public:
  void Add(const std::string& stage, const std::string& outcome, const std::string& example = "") {
    ++counts_[stage][outcome];
    if (!example.empty()) examples_.emplace(stage + ": " + outcome, example);
  }
  std::string str() const {
    std::ostringstream os;
    for (const auto& [stage, m] : counts_) {
      os << "  " << stage << ":";
      for (const auto& [outcome, n] : m) os << " " << outcome << "=" << n;
      os << "\n";
    }
    for (const auto& [key, example] : examples_) os << "  first " << key << ": " << example << "\n";
    return os.str();
  }
  std::string Compact(const std::string& stage) const {
    std::string s;
    const auto it = counts_.find(stage);
    if (it == counts_.end()) return s;
    for (const auto& [outcome, n] : it->second)
      s += (s.empty() ? "" : " ") + outcome + "=" + std::to_string(n);
    return s;
  }

 private:
  std::map<std::string, std::map<std::string, int>> counts_;
  std::map<std::string, std::string> examples_;  // the first one only (emplace)
};

// Aborts the process, naming the sample, if one sample runs past its budget:
// an integration that does not end is a hang, and must not stall the suite.
class Watchdog {
 public:
  explicit Watchdog(double budget_s) : budget_(budget_s), thread_([this] { Loop(); }) {}
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(mu_);
      done_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }
  void Start(const std::string& what) {
    std::lock_guard<std::mutex> lock(mu_);
    what_ = what;
    start_ = std::chrono::steady_clock::now();
    bound_ = ss::testing_util::WallBound();  // the budget stretches with the load
    armed_ = true;
  }

 private:
  void Loop() {
    std::unique_lock<std::mutex> lock(mu_);
    while (!done_) {
      cv_.wait_for(lock, std::chrono::milliseconds(200));
      if (done_ || !armed_) continue;
      const double t =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      if (t > bound_.Of(budget_)) {
        std::fprintf(stderr, "robustness_test: HANG: one sample ran %.1f s (budget %.1f s): %s\n",
                     t, bound_.Of(budget_), what_.c_str());
        std::fflush(stderr);
        std::abort();
      }
    }
  }

  double budget_;
  std::mutex mu_;
  std::condition_variable cv_;
  std::string what_;
  std::chrono::steady_clock::time_point start_;
  ss::testing_util::WallBound bound_;
  bool armed_ = false, done_ = false;
  std::thread thread_;
};

// The caps below measure this thread's CPU time, not wall time: a hang is
// work that does not end, and a machine loaded by other jobs must not trip it.
struct CpuClock {
  using duration = std::chrono::nanoseconds;
  using rep = duration::rep;
  using period = duration::period;
  using time_point = std::chrono::time_point<CpuClock>;
  static constexpr bool is_steady = true;
  static time_point now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return time_point(duration(static_cast<rep>(ts.tv_sec) * 1000000000 + ts.tv_nsec));
  }
};

double Seconds(CpuClock::time_point since) {
  return std::chrono::duration<double>(CpuClock::now() - since).count();
}

int SamplesPerLaw() {
  if (const char* env = std::getenv("STICKSLIP_ROBUSTNESS_SAMPLES")) {
    const int n = std::atoi(env);
    if (n > 0) return n;
  }
  return 75;  // 300 models in all
}

// A wall-time cap for one call, through the flow's cancel hook (polled after
// every CVODE return). Simulation and orbit finding have no reason to run long:
// a call that reaches the cap is reported as a hang.
class Cap {
 public:
  explicit Cap(double seconds) : seconds_(seconds) { Restart(); }
  void Restart() { start_ = CpuClock::now(); }
  std::function<bool()> Hook() {
    return [this] { return Seconds(start_) > seconds_; };
  }
  double seconds() const { return seconds_; }

 private:
  double seconds_;
  CpuClock::time_point start_;
};

constexpr double kCallCap = 5.0 * kSlowdown;  // seconds for one Run / StickSlip / PureSlip...

// Tally names of the CVODE runs carry " (cvode)"; Taylor is the default.
std::string Tagged(const std::string& stage, ss::Integrator in) {
  return in == ss::Integrator::kTaylor ? stage : stage + " (cvode)";
}

// (a) Simulation from a random start for a bounded time.
void Simulate(const ss::Model& model, Rng& rng, const std::string& what, Tally& tally,
              ss::Integrator in) {
  ss::FlowOptions fo;
  fo.integrator = in;
  ss::BeltFlow flow(model, fo);
  Cap cap(kCallCap);
  flow.set_cancel(cap.Hook());
  const ss::Params& p = model.params();
  // Half the runs start at the exit point of the stick set, half anywhere
  // near it (on the belt speed now and then: an event at t = 0 is no event).
  ss::Vec2 z0 = model.ExitPoint();
  if (rng.Chance(0.5)) {
    z0[0] = rng.Uniform(-1.5 * p.mu_s, 1.5 * p.mu_s);
    z0[1] = rng.Chance(0.2) ? p.v : rng.Uniform(-1.0, p.v + 1.0);
  }
  ss::StopRule stop;
  stop.t_max = 400.0;  // long enough for a transient to die out on stable sliding
  // Half the runs report samples every 0.05, as ss_simulate does.
  const bool sampled = rng.Chance(0.5);
  long samples = 0, bad_samples = 0;
  const ss::Observer observer = [&](const ss::Sample& smp) {
    ++samples;
    if (!std::isfinite(smp.t) || !smp.z.allFinite()) ++bad_samples;
  };
  const ss::FlowResult r = flow.Run(0.0, z0, model.ModeAt(z0), stop, /*variational=*/false,
                                    sampled ? 0.05 : 0.0, sampled ? observer : nullptr);
  std::ostringstream start;
  start.precision(17);
  start << "from (" << z0[0] << ", " << z0[1] << ") to t = " << stop.t_max;
  tally.Add(Tagged(sampled ? "simulate (sampled)" : "simulate", in), ss::Name(r.status),
            r.ok() ? "" : what + " " + start.str() + ": " + r.message);
  EXPECT_EQ(bad_samples, 0) << what << ": non-finite samples";
  if (r.status == ss::FlowStatus::kCancelled) {
    ADD_FAILURE() << what << ": HANG: simulation to t = " << stop.t_max << " from (" << z0[0]
                  << ", " << z0[1] << ") ran past " << cap.seconds() << " s: " << r.message;
    return;
  }
  if (!r.ok()) {
    EXPECT_FALSE(r.message.empty())
        << what << ": status " << ss::Name(r.status) << " without a message";
    return;
  }
  EXPECT_EQ(r.status, ss::FlowStatus::kTimeLimit) << what;
  EXPECT_DOUBLE_EQ(r.t, stop.t_max) << what;
  const std::string bad = NonFinite({{"t", r.t},
                                     {"x", r.z[0]},
                                     {"xdot", r.z[1]},
                                     {"x_min", r.extrema.x_min},
                                     {"x_max", r.extrema.x_max},
                                     {"xdot_min", r.extrema.xdot_min},
                                     {"xdot_max", r.extrema.xdot_max},
                                     {"t_stick", r.t_stick}});
  EXPECT_TRUE(bad.empty()) << what << ": simulation returned " << bad;
  EXPECT_LE(r.extrema.x_min, r.extrema.x_max) << what;
  EXPECT_LE(r.extrema.xdot_min, r.extrema.xdot_max) << what;
  EXPECT_LE(r.extrema.xdot_min, r.z[1] + 1e-9) << what;
  EXPECT_GE(r.extrema.xdot_max, r.z[1] - 1e-9) << what;
  if (r.mode == ss::Mode::kStick) {
    EXPECT_EQ(r.z[1], p.v) << what;
  }
  if (sampled) {
    EXPECT_GE(samples, 8000) << what;
  }
}

// (b) The stick-slip orbit, or else the pure-slip orbits of a section scan.
void FindOrbits(const ss::Model& model, const std::string& what, Tally& tally, ss::Integrator in) {
  ss::OrbitOptions options;
  options.floquet = true;
  options.flow.integrator = in;
  ss::OrbitFinder finder(model, options);
  Cap cap(kCallCap);
  finder.flow().set_cancel(cap.Hook());
  auto hung = [&](ss::OrbitStatus s, const std::string& call, const std::string& message) {
    if (s != ss::OrbitStatus::kCancelled) return false;
    ADD_FAILURE() << what << ": HANG: " << call << " ran past " << cap.seconds()
                  << " s: " << message;
    return true;
  };
  const ss::OrbitResult ssr = finder.StickSlip();
  tally.Add(Tagged("stick-slip", in), ss::Name(ssr.status),
            ssr.ok() || ssr.status == ss::OrbitStatus::kNoReturn ? "" : what + ": " + ssr.message);
  if (hung(ssr.status, "StickSlip()", ssr.message)) return;
  if (ssr.ok()) {
    const ss::Orbit& o = ssr.orbit;
    const std::string bad = NonFinite(o);
    EXPECT_TRUE(bad.empty()) << what << ": stick-slip orbit with " << bad;
    EXPECT_GT(o.period, 0) << what;
    EXPECT_GE(o.t_stick, 0) << what;
    // The slip phase reaches the belt speed; it may cross into slip above
    // (x' > v) and come back to stick from there.
    if (o.crossings == 0) {
      EXPECT_NEAR(o.extrema.xdot_max, model.v(), 1e-6 * std::max(1.0, model.v())) << what;
    } else {
      EXPECT_GE(o.extrema.xdot_max, model.v()) << what;
    }
    return;
  }
  EXPECT_FALSE(ssr.message.empty())
      << what << ": status " << ss::Name(ssr.status) << " without a message";
  const double a_hi = 1.5 * (model.params().mu_s + model.v());
  cap.Restart();
  const auto scan_start = CpuClock::now();
  const std::vector<ss::Orbit> found = finder.PureSlipScan(0.005, a_hi, 12);
  if (Seconds(scan_start) > cap.seconds()) {  // the scan reports no statuses: its time tells
    ADD_FAILURE() << what << ": HANG: PureSlipScan(0.005, " << a_hi << ", 12) ran past "
                  << cap.seconds() << " s";
    return;
  }
  tally.Add(Tagged("pure-slip scan", in), found.empty() ? "none" : "found");
  for (const ss::Orbit& o : found) {
    const std::string bad = NonFinite(o);
    EXPECT_TRUE(bad.empty()) << what << ": pure-slip orbit with " << bad;
    EXPECT_GT(o.period, 0) << what;
  }
  // One Newton shooting from a middle guess: converged or a clear status.
  cap.Restart();
  const ss::OrbitResult ps = finder.PureSlip(0.3 * a_hi);
  tally.Add(Tagged("pure-slip", in), ss::Name(ps.status), ps.ok() ? "" : what + ": " + ps.message);
  if (hung(ps.status, "PureSlip(" + std::to_string(0.3 * a_hi) + ")", ps.message)) return;
  if (ps.ok()) {
    const std::string bad = NonFinite(ps.orbit);
    EXPECT_TRUE(bad.empty()) << what << ": pure-slip orbit with " << bad;
  } else {
    EXPECT_FALSE(ps.message.empty())
        << what << ": status " << ss::Name(ps.status) << " without a message";
  }
}

// (c) A short continuation in v around the sample, with a wall-time cap.
void ContinueAround(const ss::Params& p, double cap_s, const std::string& what, Tally& tally) {
  ss::ContinuationOptions o;
  o.param = ss::ParameterAxis("v");
  o.from = 0.8 * p.v;
  o.to = 1.25 * p.v;
  o.max_step = 0.05;
  const auto start = CpuClock::now();
  o.cancelled = [&] { return Seconds(start) > cap_s; };
  const ss::ContinuationResult r = ss::Continue(p, o);
  tally.Add("continue", ss::Name(r.status), r.partial() ? what + ": " + r.message : "");
  if (r.partial()) {
    EXPECT_FALSE(r.message.empty())
        << what << ": status " << ss::Name(r.status) << " without a message";
  }
  if (r.status == ss::ContinuationStatus::kOk) {
    EXPECT_FALSE(r.points.empty()) << what;
  }
  for (size_t i = 0; i < r.points.size(); ++i) {
    const std::string bad = NonFinite(r.points[i]);
    EXPECT_TRUE(bad.empty()) << what << ": point " << i << " (" << ss::Name(r.points[i].kind)
                             << ") with " << bad;
    const double p_i = r.points[i].p;
    EXPECT_TRUE(p_i >= o.from - 1e-12 && p_i <= o.to + 1e-12)
        << what << ": point " << i << " at v = " << p_i << " outside the range";
  }
  for (const auto& s : r.special) {
    EXPECT_TRUE(Finite(s.p)) << what << ": special point " << ss::SpecialLabel(s.kind);
    EXPECT_TRUE(s.p >= o.from - 1e-9 && s.p <= o.to + 1e-9)
        << what << ": " << ss::SpecialLabel(s.kind) << " at v = " << s.p << " outside the range";
  }
}

TEST(Robustness, RandomValidModelsEndWithResultOrStatus) {
  const int per_law = SamplesPerLaw();
  const double continuation_cap = 2.0 * kSlowdown;  // seconds per continuation
  Watchdog watchdog(60.0 * kSlowdown);              // seconds per sample, all stages
  Rng rng(0x5eed5117c0ffeeULL);
  Tally tally;
  std::map<std::string, double> worst;  // slowest sample per stage
  const ss::LawKind laws[] = {ss::LawKind::kCubic, ss::LawKind::kCoulomb, ss::LawKind::kStribeck,
                              ss::LawKind::kLeine};
  const auto t0 = CpuClock::now();
  int samples = 0, exceptions = 0;
  for (int i = 0; i < per_law; ++i) {
    for (const ss::LawKind law : laws) {
      const ss::Params p = Sample(law, rng);
      const std::string what = "sample " + std::to_string(samples) + " (" + Describe(p) + ")";
      ++samples;
      ASSERT_EQ(ss::ValidationError(p), "") << what;
      watchdog.Start(what);
      auto stage = [&](const std::string& name, const std::function<void()>& body) {
        const auto s0 = CpuClock::now();
        try {
          body();
        } catch (const ss::InvalidArgument& e) {
          ++exceptions;
          ADD_FAILURE() << what << ": " << name
                        << " threw InvalidArgument on valid input: " << e.what();
        } catch (const std::exception& e) {
          ++exceptions;
          ADD_FAILURE() << what << ": " << name << " threw: " << e.what();
        }
        double& w = worst[name];
        w = std::max(w, Seconds(s0));
      };
      const ss::Model model(p);
      // Both integrators (issue 11): Taylor, the default, and CVODE.
      for (const ss::Integrator in : {ss::Integrator::kTaylor, ss::Integrator::kCvode}) {
        stage(Tagged("simulate", in), [&] { Simulate(model, rng, what, tally, in); });
        stage(Tagged("orbits", in), [&] { FindOrbits(model, what, tally, in); });
      }
      stage("continue", [&] { ContinueAround(p, continuation_cap, what, tally); });
      if (HasFatalFailure()) return;
    }
  }
  const double total = Seconds(t0);
  std::ostringstream summary;
  summary << "robustness: " << samples << " random models (" << per_law << " per law) in " << total
          << " s, " << exceptions << " exceptions\n"
          << tally.str() << "  slowest sample per stage:";
  for (const auto& [name, s] : worst) summary << " " << name << " " << s << " s";
  std::cout << summary.str() << std::endl;
  RecordProperty("samples", samples);
  RecordProperty("seconds", std::to_string(total));
  for (const char* stage :
       {"simulate", "simulate (sampled)", "stick-slip", "pure-slip scan", "pure-slip", "continue",
        "simulate (cvode)", "simulate (sampled) (cvode)", "stick-slip (cvode)",
        "pure-slip scan (cvode)", "pure-slip (cvode)"})
    RecordProperty(stage, tally.Compact(stage));
  EXPECT_EQ(exceptions, 0);
}

// Regressions: models the random sweep found, each a bug of its own.

// Seed set at v = 0.6 > v_max: steady sliding is stable, and a trajectory
// spirals onto it. Once the transient is at the rounding level, x' and x''
// (two of the flow's root functions) vanish together, and the run must still
// reach t_max.
TEST(Robustness, SimulationSettlesOnStableSteadySliding) {
  ss::Params p;
  p.v = 0.6;
  const ss::Model model(p);
  ss::BeltFlow flow(model, ss::FlowOptions{});
  Cap cap(kCallCap);
  flow.set_cancel(cap.Hook());
  ss::StopRule stop;
  stop.t_max = 400;
  // As ss_simulate runs it: a sample every 0.01.
  long samples = 0;
  const ss::FlowResult r =
      flow.Run(0.0, ss::Vec2(0.0, 0.3), model.ModeAt(ss::Vec2(0.0, 0.3)), stop,
               /*variational=*/false, 0.01, [&](const ss::Sample&) { ++samples; });
  EXPECT_EQ(r.status, ss::FlowStatus::kTimeLimit) << ss::Name(r.status) << ": " << r.message;
  if (r.status == ss::FlowStatus::kTimeLimit) {
    EXPECT_NEAR(r.z[0], model.SteadySliding().x, 1e-8);
    EXPECT_NEAR(r.z[1], 0.0, 1e-8);
    EXPECT_GE(samples, 40000);
  }
}

// The same without output samples (BeltFlow::Run as the orbit code calls it):
// here the noise of x' and x'' on steady sliding is ~1e-14, above a band of a
// few ulps, and CVODE's cvRcheck2 refused the chattering root at t ~ 201.
TEST(Robustness, UnsampledSimulationSettlesOnStableSteadySliding) {
  ss::Params p;
  p.beta = 0.29651904127211887;
  p.v = 0.40874467795323149;
  p.mu_s = 0.29121270622642131;
  p.mu_m = 0.20203052220498599;
  p.v_m = 0.47570751723673532;
  const ss::Model model(p);
  ASSERT_TRUE(model.SteadySliding().stable());
  ss::BeltFlow flow(model, ss::FlowOptions{});
  Cap cap(kCallCap);
  flow.set_cancel(cap.Hook());
  ss::StopRule stop;
  stop.t_max = 400;
  const ss::FlowResult r = flow.Run(0.0, ss::Vec2(0.35245194123532653, -0.48918052828254088), stop);
  EXPECT_EQ(r.status, ss::FlowStatus::kTimeLimit) << ss::Name(r.status) << ": " << r.message;
  if (r.status == ss::FlowStatus::kTimeLimit) {
    EXPECT_NEAR(r.z[0], model.SteadySliding().x, 1e-8);
    EXPECT_NEAR(r.z[1], 0.0, 1e-8);
  }
}

// The slip phase from the exit point settles on stable steady sliding and
// never returns to the stick set: that is kNoReturn, not a CVODE failure.
TEST(Robustness, StickSlipOnStableSlidingIsNoReturn) {
  ss::Params p;
  p.beta = 0.051225138141296485;
  p.v = 0.83465216505453088;
  p.mu_s = 0.55309702627732849;
  p.mu_m = 0.3615581302271097;
  p.v_m = 0.45374777957993101;
  const ss::Model model(p);
  ASSERT_TRUE(model.SteadySliding().stable());
  ss::OrbitOptions options;
  options.floquet = true;  // with the variational equations, as for multipliers
  ss::OrbitFinder finder(model, options);
  Cap cap(kCallCap);
  finder.flow().set_cancel(cap.Hook());
  const ss::OrbitResult r = finder.StickSlip();
  EXPECT_EQ(r.status, ss::OrbitStatus::kNoReturn) << ss::Name(r.status) << ": " << r.message;
}

// Another model whose slip phase settles on steady sliding (at x = 1.95):
// the stick-slip search and pure-slip shooting must say kNoReturn (or, for
// shooting, any clear non-ok status but a CVODE failure), not fail in CVODE
// (cvRcheck2, or mxstep at t ~ 1260 while at rest).
TEST(Robustness, OrbitSearchOnStableSlidingDoesNotFailInCvode) {
  ss::Params p;
  p.beta = 0.22629831912800569;
  p.v = 0.83169626572569588;
  p.mu_s = 0.5992211347520231;
  p.mu_m = 0.34000826207137663;
  p.v_m = 0.31529475131037438;
  const ss::Model model(p);
  ASSERT_TRUE(model.SteadySliding().stable());
  ss::OrbitOptions options;
  options.floquet = true;
  ss::OrbitFinder finder(model, options);
  Cap cap(kCallCap);
  finder.flow().set_cancel(cap.Hook());
  const ss::OrbitResult r = finder.StickSlip();
  EXPECT_EQ(r.status, ss::OrbitStatus::kNoReturn) << ss::Name(r.status) << ": " << r.message;
  const double a_hi = 1.5 * (p.mu_s + p.v);
  cap.Restart();
  finder.PureSlipScan(0.005, a_hi, 12);
  cap.Restart();
  const ss::OrbitResult ps = finder.PureSlip(0.3 * a_hi);
  EXPECT_FALSE(ps.ok());
  EXPECT_NE(ps.status, ss::OrbitStatus::kIntegratorFailed) << ps.message;
  EXPECT_NE(ps.status, ss::OrbitStatus::kCancelled) << ps.message;
}

// Overdamped stable sliding (2 beta + mu'(v) > 2): no pure-slip orbit. The
// desingularised map is flat (G = -1, G' ~ 1e-15), and an unbounded Newton
// step sent the shooting to a ~ 1e14, where the flow crawls for ever (x'' is a
// difference of ~1e14-sized terms, so its root function chatters and CVODE
// returns a root every step: max_steps never trips). The same calls as the
// random sweep, in its order, on one finder.
TEST(Robustness, PureSlipNewtonStepStaysBounded) {
  ss::Params p;
  p.beta = 0.20961462820512408;
  p.v = 0.60878222545327898;
  p.mu_s = 1.1067986991720329;
  p.mu_m = 0.61836195697279184;
  p.v_m = 0.40200215585786697;
  const ss::Model model(p);
  ss::OrbitOptions options;
  options.floquet = true;
  ss::OrbitFinder finder(model, options);
  Cap cap(kCallCap);
  finder.flow().set_cancel(cap.Hook());
  const double a_hi = 1.5 * (p.mu_s + p.v);
  finder.StickSlip();
  EXPECT_TRUE(finder.PureSlipScan(0.005, a_hi, 12).empty());
  cap.Restart();
  const ss::OrbitResult r = finder.PureSlip(0.3 * a_hi);
  EXPECT_NE(r.status, ss::OrbitStatus::kCancelled)
      << "PureSlip ran past " << cap.seconds() << " s: " << r.message;
  EXPECT_FALSE(r.ok()) << "a pure-slip orbit where sliding is overdamped and stable";
}

// The pseudo-arclength corrector must stay in the valid parameter range: here
// it stepped to v = -8924 and Continue threw InvalidArgument on valid input.
TEST(Robustness, ContinuePureSlipCorrectorStaysInValidRange) {
  ss::Params p;
  p.law = ss::LawKind::kCoulomb;
  p.beta = 0.15132422918319582;
  p.v = 0.18655448528062843;
  p.mu_s = 1.1177109220907246;
  p.mu_k = 0.77827040034159156;
  ss::ContinuationOptions o;
  o.from = 0.8 * p.v;
  o.to = 1.25 * p.v;
  o.max_step = 0.05;
  const auto start = CpuClock::now();
  o.cancelled = [&] { return Seconds(start) > kCallCap; };
  ss::ContinuationResult r;
  EXPECT_NO_THROW(r = ss::Continue(p, o));
  // A branch, not an empty result: points across [from, to], every one inside.
  ASSERT_FALSE(r.points.empty()) << ss::Name(r.status);
  double lo = o.to, hi = o.from;
  for (const auto& pt : r.points) {
    EXPECT_TRUE(NonFinite(pt).empty()) << NonFinite(pt);
    EXPECT_GE(pt.p, o.from - 1e-12);
    EXPECT_LE(pt.p, o.to + 1e-12);
    lo = std::min(lo, pt.p), hi = std::max(hi, pt.p);
  }
  EXPECT_LE(lo, o.from + 1e-9);
  EXPECT_GE(hi, o.to - 1e-9);
}

// A subcritical Hopf point inside the range: the pure-slip branch starts
// there, and its first corrector step must not leave [from, to] (here it
// returned a point at v = 0.70886 for to = 0.70737).
TEST(Robustness, ContinuePointsStayInRange) {
  ss::Params p;
  p.law = ss::LawKind::kLeine;
  p.beta = 0.23576198726027997;
  p.v = 0.56589657929249459;
  p.mu_s = 1.4956847530126749;
  p.delta = 2.8272583214055014;
  ss::ContinuationOptions o;
  o.from = 0.8 * p.v;
  o.to = 1.25 * p.v;
  o.max_step = 0.05;
  const auto start = CpuClock::now();
  o.cancelled = [&] { return Seconds(start) > kCallCap; };
  const ss::ContinuationResult r = ss::Continue(p, o);
  EXPECT_EQ(r.status, ss::ContinuationStatus::kOk) << r.message;
  for (const auto& pt : r.points)
    EXPECT_TRUE(pt.p >= o.from && pt.p <= o.to) << ss::Name(pt.kind) << " point at v = " << pt.p
                                                << " outside [" << o.from << ", " << o.to << "]";
}

// Options the caller got wrong are the one exception the library may throw.
TEST(Robustness, InvalidInputThrowsInvalidArgument) {
  ss::Params p;
  p.mu_m = 0.5;  // >= mu_s
  EXPECT_THROW(ss::Model{p}, ss::InvalidArgument);
  p = ss::Params();
  p.v = std::nan("");
  EXPECT_THROW(ss::Model{p}, ss::InvalidArgument);
  p = ss::Params();
  ss::ContinuationOptions o;
  EXPECT_THROW(ss::ParameterAxis("gamma"), ss::InvalidArgument);
  o = ss::ContinuationOptions();
  o.from = o.to = 0.3;
  EXPECT_THROW(ss::Continue(p, o), ss::InvalidArgument);
  o = ss::ContinuationOptions();
  o.orbit.flow.rtol = 1.0;
  EXPECT_THROW(ss::Continue(p, o), ss::InvalidArgument);
  ss::FlowOptions f;
  f.atol = -1;
  EXPECT_THROW(ss::BeltFlow(ss::Model(p), f), ss::InvalidArgument);
  ss::OrbitFinder finder(ss::Model(p), ss::OrbitOptions{});
  EXPECT_THROW(finder.PureSlip(std::nan("")), ss::InvalidArgument);
  EXPECT_THROW(finder.PureSlip(-1.0), ss::InvalidArgument);
  EXPECT_THROW(finder.PureSlipScan(0.5, 0.1, 10), ss::InvalidArgument);
}

}  // namespace
