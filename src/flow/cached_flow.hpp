// One flow per thread for the options last used: a tool that runs a system
// once per evaluation (a chart's test function, a period of an orbit
// diagram) keeps the flow's steppers and buffers, the system assigned.
#pragma once

#include "stickslip/flow/flow.hpp"

namespace stickslip {

/// The calling thread's flow on `system` with `options` (made anew when the
/// options differ). Valid until the thread's next call: not re-entrant.
/// Throws InvalidArgument as Flow's constructor does.
Flow& CachedFlow(const System& system, const FlowOptions& options);

}  // namespace stickslip
