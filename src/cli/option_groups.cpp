// The option groups every app shares (study.hpp): general, model, system
// and solver options, and the description an app builds from them.
#include "cli/study.hpp"
#include "cli/system_choice.hpp"
#include "stickslip/io/report.hpp"

namespace stickslip::cli {

namespace {

std::string Default(double x) { return " (default " + FormatNumber(x) + ")"; }

}  // namespace

po::typed_value<std::string>* Value() { return po::value<std::string>(); }

po::options_description AppDescription(const po::options_description& app,
                                       const FlowOptions& solver_defaults) {
  po::options_description desc;
  desc.add(GeneralOptions()).add(ModelOptions()).add(SystemOptions());
  desc.add(SolverOptions(solver_defaults)).add(app);
  return desc;
}

const std::vector<std::string>& StudySections() {
  static const std::vector<std::string> sections = {"simulate", "continue", "benchmark",
                                                    "chart",    "basin",    "orbit_diagram"};
  return sections;
}

po::options_description GeneralOptions() {
  po::options_description d("General");
  d.add_options()("help,h", "print this help and exit")(
      "version", po::bool_switch(), "print the version (and git commit) and exit")(
      "study", Value()->value_name("FILE"),
      "read options from a study file (key = value lines; the command line wins); a name "
      "without '/' (seed) is also looked up in the installed studies");
  return d;
}

po::options_description ModelOptions() {
  const Params p;
  po::options_description d("Model, dimensionless (seed eq. 3.5; the defaults are the seed set)");
  d.add_options()("law", Value()->value_name("NAME"),
                  "friction law: cubic (default), coulomb, stribeck, leine")(
      "beta", Value()->value_name("X"), ("damping ratio" + Default(p.beta)).c_str())(
      "v", Value()->value_name("X"), ("belt speed" + Default(p.v)).c_str())(
      "mu_s", Value()->value_name("X"), ("static friction coefficient" + Default(p.mu_s)).c_str())(
      "mu_m", Value()->value_name("X"), ("cubic: minimum friction" + Default(p.mu_m)).c_str())(
      "v_m", Value()->value_name("X"),
      ("cubic: slip speed of the minimum" + Default(p.v_m)).c_str())(
      "mu_k", Value()->value_name("X"),
      ("coulomb, stribeck: kinetic coefficient" + Default(p.mu_k)).c_str())(
      "v_s", Value()->value_name("X"), ("stribeck: decay speed" + Default(p.v_s)).c_str())(
      "delta", Value()->value_name("X"), ("leine: decay rate" + Default(p.delta)).c_str())(
      "k5", Value()->value_name("X"),
      ("cubic: quintic term -k5 s^5, >= 0, mu(v) > 0" + Default(p.k5)).c_str());
  po::options_description phys(
      "Model, physical (any of these selects the physical set: mass, damping, stiffness,\n"
      "belt_speed and the law's speed_m / speed_s / delta_phys are then required, and\n"
      "beta, v, v_m, v_s, delta are not allowed; mu_s, mu_m, mu_k are shared)");
  phys.add_options()("mass", Value()->value_name("KG"), "mass M [kg]")(
      "damping", Value()->value_name("NS/M"), "viscous damping C [N s/m]")(
      "stiffness", Value()->value_name("N/M"), "spring constant K [N/m]")(
      "belt_speed", Value()->value_name("M/S"), "belt speed V [m/s]")(
      "gravity", Value()->value_name("M/S2"), "gravity g [m/s^2] (default 9.81)")(
      "speed_m", Value()->value_name("M/S"), "cubic: slip speed of the minimum [m/s]")(
      "speed_s", Value()->value_name("M/S"), "stribeck: decay speed [m/s]")(
      "delta_phys", Value()->value_name("S/M"), "leine: decay rate [s/m]");
  d.add(phys);
  return d;
}

po::options_description SolverOptions(const FlowOptions& f) {
  po::options_description d("Solver");
  d.add_options()("integrator", Value()->value_name("NAME"),
                  "slip phases by taylor (default: Taylor series) or cvode (CVODE, --method)")(
      "rtol", Value()->value_name("X"),
      ("relative tolerance, in [1e-14, 1e-2]" + Default(f.rtol)).c_str())(
      "atol", Value()->value_name("X"),
      ("absolute tolerance, in [1e-16, 1e-2]" + Default(f.atol)).c_str())(
      "method", Value()->value_name("NAME"), "cvode: adams (default, non-stiff) or bdf (stiff)")(
      "max_steps", Value()->value_name("N"),
      ("steps allowed per output interval, >= 10 (default " + std::to_string(f.max_steps) + ")")
          .c_str());
  return d;
}

}  // namespace stickslip::cli
