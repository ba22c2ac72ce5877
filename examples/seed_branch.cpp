// The seed's branch in the belt speed v (seed section 4: beta 0.05, mu_s 0.4,
// mu_m 0.25, v_m 0.5) through the library API: its points and its special
// points, GR (grazing-sliding) and HB (Hopf, seed eq. 3.16).
#include <cstdio>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/errors.hpp"
#include "stickslip/version.hpp"

int main() {
  namespace ss = stickslip;
  ss::Params seed;  // the defaults are the seed set
  ss::ContinuationOptions options;
  options.param = ss::ParameterAxis("v");
  options.from = 0.05;
  options.to = 0.5;
  try {
    const ss::ContinuationResult r = ss::Continue(seed, options);
    std::printf("stickslip %s: %zu points, status %s\n", ss::VersionString(), r.points.size(),
                ss::Name(r.status));
    for (const ss::SpecialPoint& s : r.special)
      std::printf("%s  v = %.10f  period %.6f  x in [%.6f, %.6f]\n", ss::SpecialLabel(s.kind), s.p,
                  s.period, s.extrema.x_min, s.extrema.x_max);
    return r.partial() ? 1 : 0;
  } catch (const ss::Error& e) {
    std::fprintf(stderr, "seed_branch: %s\n", e.what());
    return 2;
  }
}
