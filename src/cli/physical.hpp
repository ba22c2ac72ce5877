// Physical units in the outputs: with physical inputs (--mass ...), the
// seed's scales L = M g / K and t0 = sqrt(M / K) (seed section 3), the
// physical counterpart of a dimensionless parameter, and `--param belt_speed`
// (or damping, speed_m, speed_s, delta_phys) continued in physical terms.
#pragma once

#include <optional>
#include <string>

#include "cli/study.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/systems/belt/parameter_axis.hpp"

namespace stickslip::cli {

struct Scales {
  double mass = 1;  // M [kg]
  double L = 1;     // length scale [m]
  double t0 = 1;    // time scale [s]
};

// The scales if physical inputs were given, else nothing. Throws UsageError
// like ModelFromArguments on incomplete physical inputs.
std::optional<Scales> ScalesFromArguments(const Arguments& args);

// A parameter axis in both forms: dimensionless value = factor * physical value.
struct PhysicalAxis {
  std::string physical;       // belt_speed, damping, speed_m, speed_s, delta_phys
  std::string dimensionless;  // v, beta, v_m, v_s, delta
  double factor = 1;
  std::string label;  // the figure's axis words, symbol and SI unit
};

// The axis of a physical name or of a dimensionless name that has a physical
// counterpart; nothing for the others (mu_s, mu_m, mu_k, k5: no units, or
// mass, stiffness, gravity: they change the scales themselves).
std::optional<PhysicalAxis> AxisOf(const std::string& name, const Scales& s);

// A figure's units: SI for a physical run (the parameter axes p1 and p2, by
// their dimensionless names, in physical form where they have units), else
// dimensionless.
FigureUnits FigureUnitsOf(const std::optional<Scales>& s,
                          const std::optional<ParameterAxis>& p1 = std::nullopt,
                          const std::optional<ParameterAxis>& p2 = std::nullopt);

}  // namespace stickslip::cli
