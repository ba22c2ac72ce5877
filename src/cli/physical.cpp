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
  const PhysicalAxis axes[] = {{"belt_speed", "v", 1 / speed, "belt speed V [m/s]"},
                               {"damping", "beta", s.t0 / (2 * s.mass), "damping C [N s/m]"},
                               {"speed_m", "v_m", 1 / speed, "speed of minimum friction V_m [m/s]"},
                               {"speed_s", "v_s", 1 / speed, "Stribeck speed V_s [m/s]"},
                               {"delta_phys", "delta", speed, "friction decay rate δ [s/m]"}};
  for (const auto& a : axes)
    if (name == a.physical || name == a.dimensionless) return a;
  return std::nullopt;
}

FigureUnits FigureUnitsOf(const std::optional<Scales>& s, const std::optional<ParameterAxis>& p1,
                          const std::optional<ParameterAxis>& p2) {
  FigureUnits u;
  if (!s) return u;
  u.si = true, u.length = s->L, u.time = s->t0;
  auto axis = [&](const std::optional<ParameterAxis>& p, FigureAxis* a) {
    if (!p) return;
    if (const auto phys = AxisOf(p->name(), *s))
      a->factor = 1 / phys->factor, a->label = phys->label;
  };
  axis(p1, &u.p1);
  axis(p2, &u.p2);
  return u;
}

}  // namespace stickslip::cli
