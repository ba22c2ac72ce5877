// Wall-time bounds in tests that hold on a loaded machine (issue 35, "16 tests
// assert wall-time bounds"): a bound measured on a quiet machine is stretched
// by the load per hardware thread seen while the timed run went (the larger of
// the 1-minute load averages before and after, per thread, at least 1), and by
// 3 under AddressSanitizer. docs/reliability.md ("Timed tests") gives the
// margins measured at load 10.
#pragma once

#include <algorithm>
#include <cstdio>
#include <thread>

namespace stickslip::testing_util {

#if defined(__SANITIZE_ADDRESS__)
constexpr double kSanitizerSlowdown = 3.0;
#else
constexpr double kSanitizerSlowdown = 1.0;
#endif

// The 1-minute load average per hardware thread (0 if /proc/loadavg is unread).
inline double LoadPerThread() {
  double load = 0;
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = 0;
    std::fclose(f);
  }
  return load / std::max(1u, std::thread::hardware_concurrency());
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
