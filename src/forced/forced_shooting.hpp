// The forced oscillator's adapters onto the one flow and the one shooting
// (forced_flow.cpp, forced_orbit.cpp).
#pragma once

#include "stickslip/forced/orbit.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip::forced_detail {

/// The thread's shooting for these options, on `model` (throws
/// InvalidArgument for invalid options).
Shooting& CachedShooting(const ForcedModel& model, const ForcedOrbitOptions& o);
ForcedOrbitStatus FromOrbitStatus(OrbitStatus s);
/// The one flow's options for the forced options (forced_flow.cpp), and
/// whether two flows' options are the same (a cached flow is kept).
FlowOptions FlowOptionsOf(const ForcedOptions& o);
bool SameFlowOptions(const FlowOptions& a, const FlowOptions& b);
Extrema ExtremaOf(const PeriodicOrbit& o);

}  // namespace stickslip::forced_detail
