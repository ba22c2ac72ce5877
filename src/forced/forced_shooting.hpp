// The forced oscillator's adapters onto the one flow and the one shooting
// (forced_orbit.cpp).
#pragma once

#include "stickslip/forced/orbit.hpp"
#include "stickslip/orbits/shooting.hpp"

namespace stickslip::forced_detail {

/// The thread's shooting for these options, on `model` (throws
/// InvalidArgument for invalid options).
Shooting& CachedShooting(const ForcedModel& model, const ForcedOrbitOptions& o);
ForcedOrbitStatus FromOrbitStatus(OrbitStatus s);
Extrema ExtremaOf(const PeriodicOrbit& o);

}  // namespace stickslip::forced_detail
