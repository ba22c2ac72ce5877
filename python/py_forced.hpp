// Shared pieces of the forced oscillator's bindings (py_forced.cpp, py_chaos.cpp).
#pragma once

#include <optional>

#include "py_common.hpp"
#include "stickslip/chaos/lyapunov.hpp"
#include "stickslip/systems/forced/flow.hpp"

namespace stickslip::python {

// The forced flow's options: its own defaults (1e-12), rtol/atol over them;
// InvalidArgument naming the value if they are not valid.
FlowOptions FlowOf(std::optional<double> rtol, std::optional<double> atol);

// A map's iteration options over `o` as the apps set them: transient and keep
// where given, the tangent aligned over at most the transient, the batches at
// most keep (py_chaos.cpp).
LyapunovOptions IterateOptions(LyapunovOptions o, std::optional<int> transient,
                               std::optional<int> keep, std::optional<double> rtol,
                               std::optional<double> atol);

void BindChaos(py::module_& m);  // py_chaos.cpp

}  // namespace stickslip::python
