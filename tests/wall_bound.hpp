// Wall-time bounds in tests that hold on a loaded machine (issue 35, "16 tests
// assert wall-time bounds"): a bound measured on a quiet machine is stretched
// by the load per usable CPU seen while the timed run went (the larger of the
// 1-minute load averages before and after, over the CPUs this process may run
// on, at least 1), and by 3 under AddressSanitizer. docs/reliability.md
// ("Timed tests") gives the load at which they were all run.
#pragma once

#include <sched.h>

#include <algorithm>
#include <cstdio>
#include <thread>

namespace stickslip::testing_util {

#if defined(__SANITIZE_ADDRESS__)
constexpr double kSanitizerSlowdown = 3.0;
#else
constexpr double kSanitizerSlowdown = 1.0;
#endif

// The CPUs this process may run on (its affinity: a container's share, not
// the host's count).
inline int UsableCpus() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// The 1-minute load average per usable CPU (0 if /proc/loadavg is unread).
inline double LoadPerThread() {
  double load = 0;
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = 0;
    std::fclose(f);
  }
  return load / UsableCpus();
}

// Made before a timed run; Of(quiet) after it gives the bound to assert.
class WallBound {
 public:
  WallBound() : before_(LoadPerThread()) {}
  double Stretch() const { return kSanitizerSlowdown * std::max({1.0, before_, LoadPerThread()}); }
  double Of(double quiet_seconds) const { return quiet_seconds * Stretch(); }

 private:
  double before_;
};

}  // namespace stickslip::testing_util
