#include "cli/physical.hpp"

#include <cmath>

namespace stickslip::cli {

std::optional<Scales> ScalesFromArguments(const Arguments& args) {
  if (!args.Given("mass")) {
    // Any other physical input without --mass is reported by the model.
    UncheckedModelFromArguments(args);
    return std::nullopt;
  }
  UncheckedModelFromArguments(args);  // all required inputs are there and valid
  const double m = args.Number("mass", 1), k = args.Number("stiffness", 1);
  Scales s;
  s.mass = m;
  s.L = LengthScale(m, k, args.Number("gravity", 9.81));
  s.t0 = TimeScale(m, k);
  return s;
}

std::optional<PhysicalAxis> AxisOf(const std::string& name, const Scales& s) {
  const double speed = s.L / s.t0;  // speeds scale by L / t0
  // 2 beta = C / sqrt(K M) = C t0 / M; delta s is dimensionless.
  const PhysicalAxis axes[] = {{"belt_speed", "v", 1 / speed},
                               {"damping", "beta", s.t0 / (2 * s.mass)},
                               {"speed_m", "v_m", 1 / speed},
                               {"speed_s", "v_s", 1 / speed},
                               {"delta_phys", "delta", speed}};
  for (const auto& a : axes)
    if (name == a.physical || name == a.dimensionless) return a;
  return std::nullopt;
}

}  // namespace stickslip::cli
