// ss_simulate's range options and forced inputs (simulate_forced.hpp).
#include "cli/simulate_forced.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "cli/about.hpp"
#include "cli/app.hpp"
#include "numerics/numbers.hpp"
#include "numerics/tolerances.hpp"
#include "stickslip/flow/simulate.hpp"
#include "stickslip/io/figure_style.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip::cli {

namespace {

void Positive(const Arguments& args, const char* name) {
  if (!(args.Number(name, 1) > 0))
    throw UsageError("invalid value '" + args.Text(name) + "' for " + args.Source(name) +
                     ": must be > 0");
}

}  // namespace

SimulateRange SimulateRangeFromArguments(const Arguments& args, double default_xdot0) {
  SimulateRange r;
  r.x0 = args.Number("x0", r.x0);
  r.xdot0 = args.Number("xdot0", default_xdot0);
  r.t_end = args.Number("t_end", r.t_end);
  r.dt = args.Number("dt", r.dt);
  Positive(args, "t_end");
  Positive(args, "dt");
  r.max_rows = args.Integer("max_rows", SimulateRange::kMaxRows);
  if (r.max_rows < 1 || r.max_rows > SimulateRange::kMaxRows)
    throw UsageError("invalid value '" + args.Text("max_rows") + "' for " +
                     args.Source("max_rows") + ": must be in [1, 1e7]");
  if (r.t_end / r.dt > r.max_rows)
    throw UsageError("t_end / dt = " + FormatNumber(r.t_end / r.dt) + " rows is more than " +
                     args.Source("max_rows") + " = " + std::to_string(r.max_rows) +
                     "; use a larger --dt");
  return r;
}

void AddRangeMeta(TsvTable& table, const SimulateRange& r) {
  table.AddMeta("x0", FormatNumber(r.x0));
  table.AddMeta("xdot0", FormatNumber(r.xdot0));
  table.AddMeta("t_end", FormatNumber(r.t_end));
  table.AddMeta("dt", FormatNumber(r.dt));
}

ForcedInputs ForcedInputsFromArguments(const Arguments& args) {
  ForcedInputs in;
  ForcedBeltParams& p = in.p;
  for (const char* phys : {"mass", "damping", "stiffness", "belt_speed"})
    if (args.Given(phys))
      throw UsageError(args.Source(phys) + ": the forced oscillator takes dimensionless inputs");
  p.base = UncheckedModelFromArguments(args);
  p.force = args.Number("force", 0);
  p.omega = args.Number("omega", 1);
  CheckForcedBelt(args, p);
  FlowOptions& flow = in.shown;
  flow = FlowOptionsFromArguments(args);
  if (flow.integrator != Integrator::kTaylor)
    throw UsageError(args.Source(args.Given("method") ? "method" : "integrator") +
                     ": the forced oscillator is integrated by Taylor series only");
  // The forced flow's own defaults (rtol = atol = 1e-12, max_steps per row) unless given.
  if (!args.Given("rtol")) flow.rtol = in.flow.rtol;
  if (!args.Given("atol")) flow.atol = in.flow.atol;
  if (!args.Given("max_steps")) flow.max_steps = in.flow.max_steps;
  in.flow.rtol = flow.rtol, in.flow.atol = flow.atol, in.flow.max_steps = flow.max_steps;
  return in;
}

void AddSimulateForcedOptions(po::options_description& d) {
  d.add_options()("section", Value()->value_name("KIND"),
                  "forced, --system or --model: the Poincare section in section.tsv: strobe "
                  "(every forcing period, cos(Omega t) = 1; the default with a forcing), exit "
                  "(every stick exit of any contact) or none (the default without one)")(
      "orbits", po::bool_switch(),
      "forced: instead of a trajectory, every periodic orbit of period multiple m <= max_m at "
      "these parameters (stable or not; FindOrbits), in orbits.tsv, one row per "
      "stroboscopic point")("max_m", Value()->value_name("M"),
                            "with --orbits: the largest period multiple, 1..12 (default 4)");
}

}  // namespace stickslip::cli
